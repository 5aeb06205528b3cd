// The live view of the page: one app::Simulation advanced by the page's animation
// frames (the window's clock: a fixed step h and an accumulator), drawn with the
// desktop's renderer into the page's canvas through WebGL 2, and edited through the
// same checks as the window's panel (app::Session). Side by side, up to three more runs
// with overrides step with it (app::Comparison), each in its column of the canvas. The
// page makes its controls from the parameter table (spheres_parameters) and calls these
// entry points.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <memory>
#include <string>

#include <emscripten/emscripten.h>
#include <emscripten/html5.h>
#include <glm/geometric.hpp>
#include <glad/gl.h>
#include "app/run/comparison.h"
#include "app/run/interaction.h"
#include "app/run/session.h"
#include "app/run/simulation.h"
#include "app/teaching/contact_explanation.h"
#include "app/teaching/overlays.h"
#include "app/views/frame_builder.h"
#include "physics/diagnostics.h"
#include "render/camera.h"
#include "render/frame_snapshot.h"
#include "render/renderer.h"
#include "scenes/overrides.h"
#include "scenes/parameters.h"
#include "scenes/scene.h"
#include "ui/control_panel.h"
#include "ui/ui_font.h"
#include "web/web_scenes.h"

namespace {

using web::answer;
using web::Json;

// s of wall time a frame may spend stepping, as in the window: beyond it a heavy scene
// runs in slow motion ("behind real time") and the page stays responsive.
constexpr double kStepBudgetSeconds = 1.0 / 30.0;
// The step-back timeline's memory per run (side by side, at most twice it in all): the
// desktop's 600 frames (10 s) of scenes up to about 850 spheres (65 bytes a sphere a
// frame), fewer of bigger ones; not the desktop's 200 MiB, which a phone's tab would not
// have.
constexpr std::size_t kTimelineBytes = std::size_t(32) << 20;

struct LiveView {
    std::unique_ptr<app::Simulation> simulation;
    std::unique_ptr<app::Session> session;
    render::Renderer renderer;
    render::Camera camera;
    render::FrameSnapshot snapshots[app::kMostViews];  // one per run
    ui::PanelState look;  // the window's colours and overlays (defaults)
    int explainIndex = 0;  // which of the selected sphere's latest contacts is explained
    bool rendererReady = false;
    float aspect = 0.0f;  // the canvas's last width / height: a change keeps the box's fit
    int rows = 1;  // four views side by side: in one row, or two rows of two (the page's choice)
    int labelRoom = 0;  // px, in two rows: the top of each quarter, left to its label
};

LiveView& live() {
    static LiveView view;
    return view;
}

// A WebGL 2 context on the page's <canvas id="view">; "" or why not.
std::string openContext() {
    EmscriptenWebGLContextAttributes attributes;
    emscripten_webgl_init_context_attributes(&attributes);
    attributes.majorVersion = 2;
    attributes.minorVersion = 0;
    // No samples: the spheres' outlines are blended, as in the window (a software WebGL's
    // samples cost as much as the spheres: SwiftShader's 4x took the 1k pile to 29 frames/s).
    attributes.antialias = false;
    attributes.depth = true;
    const EMSCRIPTEN_WEBGL_CONTEXT_HANDLE context = emscripten_webgl_create_context("#view", &attributes);
    if (context <= 0) return "this browser has no WebGL 2";
    emscripten_webgl_make_context_current(context);
    return "";
}

void fitCamera(int width, int height) {
    LiveView& v = live();
    v.aspect = height > 0 ? float(width) / float(height) : 1.0f;
    v.camera = app::openingCamera(*v.simulation, v.aspect);
}

// The canvas changed shape (the page was resized, a phone turned): the camera keeps its
// angles and its zoom relative to the box, as the window's views do.
void followCanvasShape(int width, int height) {
    LiveView& v = live();
    const float aspect = height > 0 ? float(width) / float(height) : 1.0f;
    if (aspect == v.aspect) return;
    glm::vec3 lo, hi;
    app::sceneBounds(*v.simulation, lo, hi);
    v.camera.followAspect(lo, hi, v.aspect, aspect);
    v.aspect = aspect;
}

// The spheres' colourings by name, in render::ColorBy's order (the panel's colorBy).
constexpr const auto& kColorings = scenes::kColorByNames;

// px between the columns side by side, as in the window.
constexpr int kViewGap = 4;

// Each run's view on a canvas of width x height px (x, y from its top-left corner): a
// column each (its label over its sky), or for four views in two rows (LiveView::rows) a
// quarter each, under the room its label takes.
struct Cell {
    int x, y, width, height;
};
Cell cellOf(int k, int runs, int width, int height) {
    const int rows = runs == 4 ? std::clamp(live().rows, 1, 2) : 1;
    const int columns = (runs + rows - 1) / rows;
    const int w = std::max(1, (width - kViewGap * (columns - 1)) / columns);
    const int h = std::max(1, (height - kViewGap * (rows - 1)) / rows);
    const int room = rows == 2 ? std::clamp(live().labelRoom, 0, h / 2) : 0;
    return {(k % columns) * (w + kViewGap), (k / columns) * (h + kViewGap) + room, w, h - room};
}

// A point of the canvas, (x, y) px from its top-left corner (width x height px): the
// view whose cell holds it (or `view`, while a drag keeps to its own) and the ray from
// the camera through it.
struct CanvasPoint {
    int view;
    render::Ray ray;
};
bool onCanvas(float x, float y) { return std::isfinite(x) && std::isfinite(y); }
CanvasPoint canvasPoint(const LiveView& v, float x, float y, int width, int height, int view = -1) {
    const int runs = v.session->runCount();
    int k = std::clamp(view, 0, runs - 1);
    for (int c = 0; view < 0 && c < runs; ++c) {  // the last cell whose top-left the point is past
        const Cell cell = cellOf(c, runs, width, height);
        if (x >= float(cell.x) && y >= float(cell.y)) k = c;
    }
    const Cell cell = cellOf(k, runs, width, height);
    return {k, v.camera.rayThroughPixel(glm::vec2(x - float(cell.x), y - float(cell.y)),
                                        glm::vec2(float(cell.width), float(cell.height)))};
}

// Selects sphere `index` (-1: none) as seen in `view` (side by side, each run has its own)
// and explains its first latest contact.
void selectSphere(LiveView& v, int index, int view = 0) {
    v.session->select(index, view);
    v.look.selectedSphere = index;
    v.explainIndex = 0;
}

// Side by side's views: {"views": [{"lines": [label, readouts...], "presented": [label, E~,
// penetration]}, "compact": [label, E~ and penetration, marks]}, ...]} (none when off;
// "presented": the presentation layout's, as F5; "compact": four views in two rows, where
// the full lines were cut off; "properties": what its marks say, as the window's label tooltip).
Json viewsOf(const LiveView& v) {
    Json views = Json::array();
    if (!v.session->comparison()) return views;
    const app::Comparison& comparison = *v.session->comparison();
    const std::vector<std::string> tips = app::propertiesTooltips(v.session->run(0), comparison);
    for (const app::ViewReadout& view : app::viewReadouts(v.session->run(0), comparison)) {
        views.push_back({{"lines", app::viewReadoutLines(view)},
                         {"presented", app::presentedLines(view)},
                         {"compact", app::compactLines(view)},
                         {"properties", tips[views.size()]}});
    }
    return views;
}

// The selected sphere's latest contacts (Session::latestContacts), the one explained first
// (-1 none): its partner is ringed in magenta, as in the window.
const physics::ContactEvent* explained(LiveView& v) {
    const std::vector<physics::ContactEvent>& events = v.session->latestContacts().events;
    if (v.session->selected() < 0 || events.empty()) return nullptr;
    v.explainIndex = std::clamp(v.explainIndex, 0, int(events.size()) - 1);
    return &events[std::size_t(v.explainIndex)];
}

// The selected sphere, as the window's inspector shows it, in the view it was clicked in:
// {"index", "view" (side by side: its letter, as "B"), "p" (m), "v" (m/s), "speed"
// (|v| in the unit that gives it digits, app::speedText),
// "r" (m), "m" (kg), "state", "level" (the contact graph's, with shock propagation or its
// overlay; -1 none; absent otherwise), "contacts": {"count", "recorded", "frame_recalled"
// (Session::Contacts'), "index", "title", "lines": [{"kind", "text"}]} (the slides' formulas
// with the numbers of one latest contact)}; null when none is selected.
Json selectedOf(LiveView& v) {
    const int i = v.session->selected();
    const app::Simulation& run = v.session->run(v.session->selectedView());
    const physics::World& world = run.world();
    if (i < 0 || std::size_t(i) >= world.size()) return nullptr;
    const auto vec = [](const glm::dvec3& a) { return Json::array({a.x, a.y, a.z}); };
    Json sphere = {{"index", i},
                   {"p", vec(world.position[std::size_t(i)])},
                   {"v", vec(world.velocity[std::size_t(i)])},
                   {"speed", app::speedText(glm::length(world.velocity[std::size_t(i)]))},  // as the window's |v|
                   {"r", world.radius[std::size_t(i)]},
                   {"m", world.mass[std::size_t(i)]},
                   {"state", app::contactStateName(world.contactState[std::size_t(i)])}};
    if (v.session->comparison()) sphere["view"] = std::string(1, char('A' + v.session->selectedView()));
    if (run.params().shock == physics::ShockPropagation::On || run.overlayFlags().graph) {
        sphere["level"] = run.contactGraph().level[std::size_t(i)];
    }
    Json contacts = {{"count", v.session->latestContacts().events.size()}, {"recorded", world.recordContacts},
                     {"frame_recalled", v.session->latestContacts().frameRecalled}};
    if (const physics::ContactEvent* event = explained(v)) {
        const int planes = world.boxPlaneCount;
        std::vector<app::ExplanationLine> lines =
            app::explanationLines(app::explainContact(*event, run.params()), run.params(), planes);
        for (app::ExplanationLine& line : app::solvedWithLines(*event, v.session->latestContacts().solvedTogether, planes)) {
            lines.push_back(std::move(line));
        }
        Json shown = Json::array();
        const char* kinds[] = {"heading", "formula", "result", "note"};  // ExplanationLine::Kind's order
        for (const app::ExplanationLine& line : lines) shown.push_back({{"kind", kinds[int(line.kind)]}, {"text", line.text}});
        contacts["index"] = v.explainIndex;
        contacts["title"] = app::contactTitle(*event, i, planes, run.params().passes);
        contacts["lines"] = shown;
    }
    sphere["contacts"] = contacts;
    return sphere;
}

// The timeline: {"frames" kept, "cursor" (the frame shown), "from_s", "to_s" (their times)}.
Json timelineOf(const app::Session& session) {
    const app::RewindBuffer& timeline = session.timeline();
    if (timeline.empty()) return {{"frames", 0}, {"cursor", 0}, {"from_s", 0.0}, {"to_s", 0.0}};
    return {{"frames", timeline.size()},
            {"cursor", timeline.cursor()},
            {"from_s", timeline.at(0).time},
            {"to_s", timeline.at(timeline.size() - 1).time}};
}

// The scene's text as the runs measured it, as the window's "The text, measured" (the
// same readouts): {"watched" (claims in all), "interrupted" (changed by hand: stopped until
// a restart), "other_settings" (the text's claims are for other settings than the run's),
// "lines": [{"holds", "says", "measured", "view" (side by side: the view's letter, "A" to
// "D", that measured it; else "")}] (those judged so far), "elsewhere" (the text's claims no
// view measures: at other settings, or a ratio of two runs), "last_moment_s" (when the last
// watched claim is judged)}.
Json claimsOf(const app::Simulation& run, const app::Comparison* comparison) {
    ui::Readouts readouts;
    app::addMeasuredClaims(run, comparison, readouts);
    Json lines = Json::array();
    for (const ui::Readouts::ClaimLine& line : readouts.claims) {
        lines.push_back({{"holds", line.holds}, {"says", line.says}, {"measured", line.measured},
                         {"view", line.view ? std::string(1, line.view) : std::string()}});
    }
    return {{"watched", readouts.claimsWatched}, {"interrupted", readouts.claimsInterrupted},
            {"other_settings", readouts.claimsForOtherSettings}, {"lines", lines},
            {"elsewhere", readouts.claimsElsewhere}, {"last_moment_s", readouts.claimsLastMoment}};
}

// The invariant alarms, most serious first, as the window's panel shows them:
// [{"text", "hint", "lit" (recent; else shown dimmed until a restart)}].
Json alarmsOf(const app::Simulation& run) {
    Json alarms = Json::array();
    for (const app::AlarmLine& line : run.alarms().lines(run.world().time)) {
        alarms.push_back({{"text", line.text}, {"hint", line.hint}, {"lit", line.lit}});
    }
    return alarms;
}

}  // namespace

extern "C" {

// Opens the scene (as --scene names it) with `settings` ("name=value" lines) in the
// canvas of width x height px: {"title", "preset" (its name in the preset list), "sliders"
// (those its text names: the presentation layout's), "time_scale" (its range),
// "opening_time_scale" (the scene's own, which the run starts at), "slide",
// "description", "compare" (the overrides the scene opens side by side with, as the
// desktop does; "" none)} or {"error"}.
EMSCRIPTEN_KEEPALIVE const char* spheres_open(const char* name, const char* settings, int width, int height) {
    LiveView& v = live();
    try {
        if (!v.rendererReady) {
            if (const std::string error = openContext(); !error.empty()) return answer({{"error", error}});
            if (const std::string error = v.renderer.init(); !error.empty()) return answer({{"error", error}});
            v.rendererReady = true;
        }
        // Made aside, then swapped in: a scene that cannot be built leaves the open one as it was.
        auto simulation = std::make_unique<app::Simulation>(web::sceneWithSettings(name, settings));
        simulation->wallBudget = kStepBudgetSeconds;
        simulation->timeScale = simulation->scene().timeScale;  // a scene may open in slow motion
        simulation->paused = simulation->scene().opensPaused;   // or paused at its start
        if (simulation->scene().colorBy >= 0) v.look.colorBy = simulation->scene().colorBy;
        auto session = std::make_unique<app::Session>(*simulation, kTimelineBytes);
        const scenes::Scene& s = simulation->scene();
        if (!s.compare.empty()) {
            if (const std::string error = session->startComparison(s.compare); !error.empty()) {
                return answer({{"error", error}});
            }
        }
        v.session = std::move(session);
        v.simulation = std::move(simulation);
        const Cell first = cellOf(0, v.session->runCount(), width, height);
        fitCamera(first.width, first.height);
        return answer({{"title", scenes::withCount(s.title, s)},
                       {"preset", web::presetName(name)},
                       {"sliders", scenes::slidersToMove(s)},
                       {"time_scale", {ui::kTimeScaleRange[0], ui::kTimeScaleRange[1]}},
                       {"opening_time_scale", s.timeScale},
                       {"color_by", kColorings[v.look.colorBy]},
                       {"slide", s.slide},
                       {"description", scenes::describedText(s)},
                       {"compare", app::joinedOverrides(s.compare)}});
    } catch (const std::exception& e) {
        return answer({{"error", e.what()}});
    }
}

// Four views side by side in `rows` rows (1 or 2), in two rows each under `labelRoom` px
// left to its label (at most half its quarter): the page lays the labels out alike.
EMSCRIPTEN_KEEPALIVE void spheres_set_rows(int rows, int labelRoom) {
    live().rows = std::clamp(rows, 1, 2);
    live().labelRoom = std::max(0, labelRoom);
}

// Advances the runs by `seconds` of real time and draws them into the canvas: the whole
// of it, or side by side a cell each, seen by the same camera.
EMSCRIPTEN_KEEPALIVE void spheres_frame(double seconds, int width, int height) {
    LiveView& v = live();
    if (!v.simulation || !v.session || !v.rendererReady) return;
    v.session->advance(seconds);
    const int runs = v.session->runCount();
    const Cell first = cellOf(0, runs, width, height);
    followCanvasShape(first.width, first.height);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, width, height);
    glClearColor(ui::kBackdropColor[0], ui::kBackdropColor[1], ui::kBackdropColor[2], 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    v.look.selectedSphere = v.session->selected();  // a restart or a new scene deselects
    v.session->setCatchEveryStep(v.look.selectedSphere >= 0);  // a contact in any step of a frame, as the window
    v.renderer.style.overlayOnTop = app::overlaysOnTop(v.look, v.simulation->world().size());  // as the window
    for (int k = 0; k < runs; ++k) {
        const Cell cell = cellOf(k, runs, width, height);
        app::buildSnapshot(v.session->run(k), v.look, v.snapshots[k]);
        const physics::ContactEvent* event = explained(v);
        v.session->appendSelection(k, v.camera, v.snapshots[k], event ? app::contactPartner(*event, v.session->selected()) : -1);
        v.renderer.style.antialiasEdges = app::outlinesAntialiased(v.snapshots[k].sphereCount());  // as the window
        v.renderer.draw(v.snapshots[k], v.camera, cell.x, height - cell.y - cell.height, cell.width, cell.height);
    }
}

// Side by side with `overrides` ("name=value[,name=value]", as the desktop's bar; several
// values of one name make a view each), every run restarted from the scene's initial
// state; "" ends it. {"views", "same" (the overrides change nothing)}, or {"error",
// "views"}: the runs stay as they were.
EMSCRIPTEN_KEEPALIVE const char* spheres_compare(const char* overrides) {
    LiveView& v = live();
    if (!v.session) return answer({{"error", "no scene is open"}});
    if (*overrides == 0) {
        v.session->stopComparison();
        return answer({{"views", Json::array()}, {"same", false}});
    }
    if (const std::string error = v.session->startComparison({overrides}); !error.empty()) {
        return answer({{"error", error}, {"views", viewsOf(v)}});
    }
    return answer({{"views", viewsOf(v)}, {"same", v.session->comparison()->changesNothing(v.simulation->scene())}});
}

// A click at (x, y) px from the canvas's top-left corner (width x height px): selects the
// sphere under it in the view there, or none. {"selected": its number or -1}.
EMSCRIPTEN_KEEPALIVE const char* spheres_pick(float x, float y, int width, int height) {
    LiveView& v = live();
    if (!v.session || !onCanvas(x, y)) return answer({{"selected", -1}});
    const CanvasPoint at = canvasPoint(v, x, y, width, height);
    const int hit = app::pickSphere(v.session->run(at.view).world(), at.ray);
    selectSphere(v, hit, at.view);
    return answer({{"selected", hit}});
}

// The mouse grabs the sphere under (x, y) px (Ctrl+drag, as in the window; `seconds`: the
// page's clock): it follows the pointer in the plane through its centre facing the camera,
// in every run, until spheres_throw. {"grabbed": its number, or -1 where none is there}.
EMSCRIPTEN_KEEPALIVE const char* spheres_grab(float x, float y, int width, int height, double seconds) {
    LiveView& v = live();
    if (!v.session || !onCanvas(x, y)) return answer({{"grabbed", -1}});
    const CanvasPoint at = canvasPoint(v, x, y, width, height);
    const int hit = app::pickSphere(v.session->run(at.view).world(), at.ray);
    if (hit < 0 || !v.session->beginDrag(at.view, std::size_t(hit), at.ray, v.camera.forward(), seconds)) {
        return answer({{"grabbed", -1}});
    }
    selectSphere(v, hit, at.view);
    return answer({{"grabbed", hit}});
}

// The grabbed sphere follows the pointer at (x, y) px, kept inside the box.
EMSCRIPTEN_KEEPALIVE void spheres_drag(float x, float y, int width, int height, double seconds) {
    LiveView& v = live();
    if (!v.session || !v.session->dragging() || !onCanvas(x, y)) return;
    v.session->dragTo(canvasPoint(v, x, y, width, height, v.session->dragView()).ray, seconds);
}

// The grabbed sphere is let go with the pointer's velocity of the last 0.1 s:
// {"thrown": its number (-1: none was grabbed), "speed" (m/s)}.
EMSCRIPTEN_KEEPALIVE const char* spheres_throw() {
    LiveView& v = live();
    if (!v.session || !v.session->dragging()) return answer({{"thrown", -1}, {"speed", 0.0}});
    const int sphere = v.session->draggedSphere();
    const glm::dvec3 velocity = v.session->endDrag();
    return answer({{"thrown", sphere}, {"speed", glm::length(velocity)}});
}

// A new sphere shot at `speed` (m/s) through the pointer at (x, y) px, or along the
// camera's view where x < 0 (the window's Shoot and F), in every run, selected; the
// world's last sphere gives its size. {"shot": its number} or {"error": why not}.
EMSCRIPTEN_KEEPALIVE const char* spheres_shoot(float x, float y, int width, int height, double speed) {
    LiveView& v = live();
    if (!v.session) return answer({{"error", "no scene is open"}});
    if (!onCanvas(x, y)) return answer({{"error", "cannot shoot: the pointer is not on the view"}});
    const render::Ray aim =
        x < 0.0f ? render::Ray{v.camera.position(), v.camera.forward()} : canvasPoint(v, x, y, width, height).ray;
    if (!(speed >= 0.0 && speed <= app::kEditSpeed)) {
        return answer({{"error", "a shot's speed is from 0 to " + std::to_string(int(app::kEditSpeed)) + " m/s"}});
    }
    if (const std::string refusal = v.session->shoot(aim, speed); !refusal.empty()) return answer({{"error", refusal}});
    selectSphere(v, v.session->selected(), v.session->selectedView());
    return answer({{"shot", v.session->selected()}});
}

// The selected sphere's numbers, as the window's inspector edits them: p (m), v (m/s),
// r (m), m (kg), in every run. "" or why refused (the spheres stay as they were).
EMSCRIPTEN_KEEPALIVE const char* spheres_edit(double px, double py, double pz, double vx, double vy, double vz,
                                              double r, double m) {
    LiveView& v = live();
    static std::string refusal;
    refusal = !v.session ? "no scene is open" : v.session->editSelected({{px, py, pz}, {vx, vy, vz}, r, m});
    return refusal.c_str();
}

// Back to frame `index` of the timeline (0: the oldest kept), every run: the run pauses
// there, and running again recomputes the same future from it, as the window's timeline.
EMSCRIPTEN_KEEPALIVE void spheres_scrub(int index) {
    LiveView& v = live();
    if (v.session && index >= 0) v.session->scrubTo(std::size_t(index));
}

// Selects sphere `index` (-1: none), as --select does: "" or why not (the selection stays).
EMSCRIPTEN_KEEPALIVE const char* spheres_select(int index) {
    LiveView& v = live();
    static std::string refusal;
    refusal.clear();
    if (!v.session) return (refusal = "no scene is open").c_str();
    const std::size_t count = v.simulation->world().size();
    if (index < -1 || (index >= 0 && std::size_t(index) >= count)) {
        return (refusal = "select=" + std::to_string(index) + ": the scene has " + std::to_string(count) +
                          " spheres, numbered from 0").c_str();
    }
    selectSphere(v, index);
    return refusal.c_str();
}

// The next (+1) or previous (-1) of the selected sphere's latest contacts to explain.
EMSCRIPTEN_KEEPALIVE void spheres_explain(int step) {
    LiveView& v = live();
    if (!v.session) return;
    const int count = int(v.session->latestContacts().events.size());
    if (count > 0) v.explainIndex = ((v.explainIndex + step) % count + count) % count;
}

// The mouse: drag to orbit (px), wheel to zoom (steps, positive closer).
EMSCRIPTEN_KEEPALIVE void spheres_orbit(float dx, float dy) { live().camera.orbit(dx, dy); }
EMSCRIPTEN_KEEPALIVE void spheres_zoom(float steps) { live().camera.zoom(steps); }
// The camera as the scene opened it, for a canvas of width x height px (the desktop's C).
EMSCRIPTEN_KEEPALIVE void spheres_reset_camera(int width, int height) {
    LiveView& v = live();
    if (!v.session) return;
    const Cell first = cellOf(0, v.session->runCount(), width, height);
    fitCamera(first.width, first.height);
}

// Pause or run; one time step h (every run, paused or not); restart from the scene's
// initial state.
EMSCRIPTEN_KEEPALIVE void spheres_pause(int paused) {
    if (live().simulation) live().simulation->paused = paused != 0;
}
EMSCRIPTEN_KEEPALIVE void spheres_step() {
    if (live().session) live().session->singleStep();
}
EMSCRIPTEN_KEEPALIVE void spheres_restart() {
    if (live().session) live().session->restartAsOpened();
}

// Simulated seconds per real second (below 1: slow motion; h does not change), within
// ui::kTimeScaleRange: "" or why refused (the scale stays).
EMSCRIPTEN_KEEPALIVE const char* spheres_time_scale(double scale) {
    LiveView& v = live();
    static std::string refusal;
    refusal.clear();
    if (!v.simulation) return (refusal = "no scene is open").c_str();
    if (!(scale >= ui::kTimeScaleRange[0] && scale <= ui::kTimeScaleRange[1])) {
        char text[96];
        std::snprintf(text, sizeof text, "time scale %g: from %g to %g", scale, ui::kTimeScaleRange[0], ui::kTimeScaleRange[1]);
        return (refusal = text).c_str();
    }
    v.simulation->timeScale = scale;
    return refusal.c_str();
}

// The readouts' last samples, as the window's plots (app::History, the first run's):
// {"times": [s, oldest first], "series": [{"name" (with its unit), "values"}]}.
EMSCRIPTEN_KEEPALIVE const char* spheres_plots() {
    LiveView& v = live();
    Json series = Json::array();
    if (!v.simulation) return answer({{"times", Json::array()}, {"series", series}});
    const app::History& history = v.simulation->history();
    for (int s = 0; s < int(app::Series::Count); ++s) {
        series.push_back({{"name", app::History::name(app::Series(s))}, {"values", history.values(app::Series(s))}});
    }
    return answer({{"times", history.times()}, {"series", series}});
}

// One parameter, as --set names it and through the panel's checks: "" or why refused
// (the run keeps its value).
EMSCRIPTEN_KEEPALIVE const char* spheres_set(const char* name, double value) {
    LiveView& v = live();
    static std::string refusal;
    const scenes::Parameter* p = scenes::findParameter(name);
    refusal = !v.session ? "no scene is open" : !p ? std::string("no parameter ") + name : v.session->setParameter(*p, value);
    return refusal.c_str();
}

// The parameter table with the open scene's values: what the page's controls show.
EMSCRIPTEN_KEEPALIVE const char* spheres_parameters() {
    LiveView& v = live();
    Json list = Json::array();
    if (!v.simulation) return answer(list);
    const scenes::Scene& scene = v.simulation->scene();
    for (const scenes::Parameter& p : scenes::parameterTable()) {
        if (!p.availableIn(scene)) continue;
        Json choices = Json::array();
        Json shown = Json::array();
        for (std::size_t k = 0; k < p.choices.size(); ++k) {
            choices.push_back(std::string(p.choices[k]));
            shown.push_back(p.choiceShown(k));
        }
        list.push_back({{"name", std::string(p.name)},
                        {"label", std::string(p.label)},
                        {"unit", std::string(p.unit)},
                        {"tooltip", std::string(p.tooltip)},
                        {"min", p.min},
                        {"max", p.max},
                        {"kind", p.kind == scenes::ParameterKind::Choice    ? "choice"
                                 : p.kind == scenes::ParameterKind::Integer ? "integer"
                                                                            : "real"},
                        {"restarts", p.applies == scenes::Applies::Restart},
                        {"zero_means", std::string(p.zeroMeans)},  // "auto": what 0 is shown as
                        {"as_fraction", p.shownAsFraction},         // h: "1/60" where it is one
                        {"choices", choices},
                        {"choices_shown", shown},
                        {"value", p.get(scene)}});
    }
    return answer(list);
}

// The view's look, as the window's View section: name "color-by" with value "contact",
// "speed" or "id"; or an overlay (velocity, contacts, impulses, penetration, trails,
// graph) with "on" or "off". "" or why refused (the look stays as it was).
EMSCRIPTEN_KEEPALIVE const char* spheres_look(const char* name, const char* value) {
    LiveView& v = live();
    static std::string refusal;
    const std::string what = name, to = value;
    refusal.clear();
    if (what == "color-by") {
        const auto at = std::find(std::begin(kColorings), std::end(kColorings), to);
        if (at == std::end(kColorings)) return (refusal = "color-by " + to + ": expected contact, speed, id or penetration").c_str();
        v.look.colorBy = int(at - std::begin(kColorings));
        return refusal.c_str();
    }
    if (to != "on" && to != "off") return (refusal = what + "=" + to + ": expected on or off").c_str();
    app::OverlayFlags flags, probe;
    if (!app::setOverlayByName(probe, what)) {
        refusal = "no overlay '" + what + "'; overlays:";
        for (const char* each : app::kOverlayNames) refusal += std::string(each == app::kOverlayNames[0] ? " " : ", ") + each;
        return refusal.c_str();
    }
    for (const std::string& shown : app::overlayNames(app::overlayFlags(v.look))) {
        if (shown != what) app::setOverlayByName(flags, shown);
    }
    if (to == "on") app::setOverlayByName(flags, what);
    const int colorBy = v.look.colorBy;
    v.look = app::viewShowing(flags);
    v.look.colorBy = colorBy;
    return refusal.c_str();
}

// The overlays' names, in the window's order (what spheres_look and a link's overlay= take).
EMSCRIPTEN_KEEPALIVE const char* spheres_overlays() {
    Json names = Json::array();
    for (const char* name : app::kOverlayNames) names.push_back(name);
    return answer(names);
}

}  // extern "C"

namespace {

// What the view's colours and marks mean: the colouring's legend, then a line per overlay
// (the window's legend lines). The contact graph paints the spheres by level: then its line
// alone says what their colours are (the speed colouring's legend had stood beside grey spheres).
std::string legendOf(const LiveView& v, std::size_t spheres) {
    const app::OverlayFlags flags = app::overlayFlags(v.look);
    std::string legend = flags.graph ? "" : scenes::kColorByLegends[v.look.colorBy];
    for (const app::LegendLine& line : app::overlayLegend(flags, spheres, v.look.selectedSphere)) {
        legend += (legend.empty() ? "" : "\n") + line.text;
    }
    return legend;
}

}  // namespace

extern "C" {

// The run now: {"time_s", "steps", "spheres", "emits" (the scene has an emitter: its count
// grows), "hash", "paused" (by the page, or by an
// alarm: a value not finite), "time_scale", "camera": {"azimuth_rad", "elevation_rad",
// "distance_m"}, "kinetic_J", "potential_J", "momentum_kg_m_s" ([x, y, z], physics::momentumShown), "penetration_r",
// "behind_real_time", "views" (side by side: each view's label lines and its presented ones, viewsOf), "only_view_a"
// (side by side: the parameters every other view sets, Comparison::setInEveryView), "selected"
// (selectedOf), "timeline" (timelineOf), "claims" (claimsOf), "suggested_compare" (what the
// side-by-side field offers, app::suggestedOverrides), "alarms" (alarmsOf), "look":
// {"color_by", "legend" (what its colours and overlays mean, legendOf), "overlays"}}.
EMSCRIPTEN_KEEPALIVE const char* spheres_state() {
    LiveView& v = live();
    if (!v.simulation || !v.session) return answer(Json::object());
    const physics::World& world = v.simulation->world();
    const physics::Diagnostics& d = v.session->diagnostics(0);
    const glm::dvec3 shown = physics::momentumShown(d);  // kg m/s, rounding read as 0
    return answer({{"time_s", world.time},
                   {"steps", world.stepCount},
                   {"spheres", world.size()},
                   {"emits", !v.simulation->scene().emitters.empty()},
                   {"hash", web::hexHash(d.hash)},
                   {"paused", v.simulation->paused},
                   {"time_scale", v.simulation->timeScale},
                   {"camera", {{"azimuth_rad", v.camera.azimuth}, {"elevation_rad", v.camera.elevation},
                               {"distance_m", v.camera.distance}}},
                   {"kinetic_J", d.kinetic},
                   {"potential_J", d.potential},
                   {"momentum_kg_m_s", {shown.x, shown.y, shown.z}},  // as the window's readouts show it
                   {"penetration_r", d.maxPenetration},
                   {"behind_real_time", v.simulation->behindRealTime()},
                   {"views", viewsOf(v)},
                   {"only_view_a", v.session->comparison() ? v.session->comparison()->setInEveryView()
                                                           : std::vector<std::string>{}},
                   {"selected", selectedOf(v)},
                   {"timeline", timelineOf(*v.session)},
                   {"claims", claimsOf(*v.simulation, v.session->comparison())},
                   {"suggested_compare", app::suggestedOverrides(v.simulation->scene())},
                   {"alarms", alarmsOf(*v.simulation)},
                   {"look", {{"color_by", kColorings[v.look.colorBy]},
                             {"legend", legendOf(v, world.size())},
                             {"overlays", app::overlayNames(app::overlayFlags(v.look))}}}});
}

}  // extern "C"
