#include "app/run/session.h"

#include <chrono>

#include <algorithm>
#include <cmath>
#include <utility>

#include <glm/geometric.hpp>

#include "app/run/scene_source.h"
#include "app/teaching/overlays.h"
#include "physics/diagnostics.h"
#include "physics/step.h"

namespace app {
namespace {

constexpr int kRingSegments = 48;
constexpr float kRingRadius = 1.25f;        // times the sphere's radius
constexpr glm::u8vec4 kRingColor{255, 225, 0, 255};         // the selected sphere: yellow
constexpr glm::u8vec4 kPartnerRingColor{255, 80, 235, 255};  // the other sphere of the explained contact: magenta
constexpr glm::u8vec4 kRingOutline{20, 22, 30, 255};
constexpr float kRingWidth = 4.0f;          // px
constexpr float kOutlineWidth = 8.0f;       // px

// A ring around a sphere, in front of it and facing the eye: seen whenever the sphere's front is.
void addRing(render::FrameSnapshot& snapshot, const render::Camera& camera, const glm::dvec3& position, double radius,
             glm::u8vec4 colour) {
    const glm::vec3 centre(position);
    const float r = float(radius);
    const glm::vec3 toEye = glm::normalize(camera.position() - centre);
    const glm::vec3 side = glm::normalize(glm::cross(toEye, std::abs(toEye.z) < 0.9f ? glm::vec3(0, 0, 1) : glm::vec3(1, 0, 0)));
    const glm::vec3 up = glm::cross(side, toEye);
    const glm::vec3 middle = centre + 0.9f * r * toEye;
    const float ring = kRingRadius * r;
    for (const auto& [color, width] : {std::pair{kRingOutline, kOutlineWidth}, std::pair{colour, kRingWidth}}) {
        for (int s = 0; s < kRingSegments; ++s) {
            const float a0 = 6.2831853f * float(s) / kRingSegments, a1 = 6.2831853f * float(s + 1) / kRingSegments;
            snapshot.addLine(middle + ring * (std::cos(a0) * side + std::sin(a0) * up),
                             middle + ring * (std::cos(a1) * side + std::sin(a1) * up), color, width);
        }
    }
}

}  // namespace

Session::Session(Simulation& primary, std::size_t timelineBytes) : primary_(primary), timelineBytes_(timelineBytes) {
    resizeRuns();
    keep();
}

void Session::resizeRuns() {
    // Two runs keep 10 s each as one did; more share twice one run's memory.
    const std::size_t runs = std::size_t(runCount());
    const std::size_t bytes = runs <= 2 ? timelineBytes_ : 2 * timelineBytes_ / runs;
    rewind_.assign(runs, RewindBuffer(RewindBuffer::kDefaultFrames, bytes));
    stale_.assign(runs, 0);
}

template <class Edit>
void Session::forEachWorld(Edit edit) {
    for (int k = 0; k < runCount(); ++k) edit(run(k).editableWorld());
}

std::string Session::startComparison(const std::vector<std::string>& lists) {
    Variants variants;
    if (const std::string error = overrideVariants(primary_.scene(), lists, variants); !error.empty()) return error;
    try {
        comparison_ = std::make_unique<Comparison>(primary_.scene(), std::move(variants));
    } catch (const std::exception& e) {
        return e.what();
    }
    comparisonFromScene_ = false;
    resizeRuns();
    restart();
    return "";
}

void Session::stopComparison() {
    comparison_.reset();
    comparisonFromScene_ = false;
    rewind_.resize(1);
    stale_.resize(1);
}

void Session::prepareToStep() {
    if (comparison_) comparison_->follow(primary_);
}

int Session::advance(double realSeconds) {
    prepareToStep();
    // Simulation::advance keeps world.contacts of its last step only. To see every
    // step's, feed it slices of half a step: then each call runs at most one step.
    const double scale = primary_.timeScale;
    const bool slice = catchEveryStep_ && selected_ >= 0 && !primary_.paused && scale > 0.0;
    const double piece = slice ? 0.5 * primary_.params().timeStep / scale : realSeconds;  // s
    int steps = 0, otherSteps = 0;
    const auto start = std::chrono::steady_clock::now();
    // The views share the frame's budget: the first steps within its share, and the others
    // then step to its time, so that all show the same instant (a costlier view slows the
    // frame, it never falls behind: the continuous gas of 15 lagged 5 s in 20).
    const double budget = primary_.wallBudget;  // s
    primary_.wallBudget = budget / runCount();
    // Until a step has run the budget does not stop it: a frame whose drawing alone spends
    // the budget still steps once (else a heavy scene would stand still).
    auto withinBudget = [&] {
        return steps == 0 || std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() <= budget;
    };
    for (double left = realSeconds; left > 0.0 && steps < Simulation::kMaxStepsPerFrame && withinBudget();) {
        const double seconds = std::min(piece, left);
        left = slice ? left - seconds : 0.0;
        const int ran = primary_.advance(seconds);
        for (int k = 1; k < runCount(); ++k) otherSteps += run(k).catchUpTo(primary_.world().time);
        steps += ran;
        if (ran > 0) noteContacts();
    }
    primary_.wallBudget = budget;
    if (steps > 0 || otherSteps > 0) {
        std::fill(stale_.begin(), stale_.end(), 0);
        keep();
    }
    return steps;
}

void Session::singleStep() {
    prepareToStep();
    primary_.singleStep();
    for (int k = 1; k < runCount(); ++k) run(k).catchUpTo(primary_.world().time);
    std::fill(stale_.begin(), stale_.end(), 0);
    noteContacts();
    keep();
}

void Session::restart() {
    primary_.restart();
    startAgain();
}

void Session::restartAsOpened() {
    restart();
    if (primary_.scene().opensPaused) primary_.paused = true;
}

void Session::sceneChanged() {
    selected_ = -1;
    const std::vector<std::string>& asked = primary_.scene().compare;
    if (!asked.empty() && startComparison(asked).empty()) {
        comparisonFromScene_ = true;
        return;
    }
    if (comparisonFromScene_) stopComparison();
    startAgain();
}

std::string Session::setParameter(const scenes::Parameter& p, double value) {
    if (p.applies == scenes::Applies::Live) return scenes::setValue(p, primary_.editableScene(), value);
    if (value == p.get(primary_.scene())) return "";  // the same value (a slider let go where it was): no restart
    scenes::Scene scene = primary_.scene();
    if (const std::string error = scenes::setValue(p, scene, value); !error.empty()) return error;
    try {
        const double timeScale = primary_.timeScale;
        primary_.setScene(std::move(scene));
        primary_.timeScale = timeScale;
    } catch (const std::exception& e) {
        return std::string(p.name) + " = " + scenes::formatNumber(value) + " refused (it stays " +
               scenes::formatValue(p, primary_.scene()) + "): " + withoutGenerator(e.what());
    }
    startAgain();
    return "";
}

namespace {

constexpr std::size_t kMostSolvedTogether = 256;

// The events of one step about `selected`, with the step's globally solved contacts.
// Whether every centre and velocity is a number (a step from a state that is not may throw).
bool allFinite(const physics::World& world) {
    const auto finite = [](const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); };
    return std::all_of(world.position.begin(), world.position.end(), finite) &&
           std::all_of(world.velocity.begin(), world.velocity.end(), finite);
}

Session::Contacts contactsOf(const std::vector<physics::ContactEvent>& all, int selected, double time,
                             std::uint64_t steps) {
    Session::Contacts out{{}, {}, time, steps};
    for (const physics::ContactEvent& event : all) {
        if (static_cast<int>(event.i) == selected || event.other == selected) out.events.push_back(event);
        if (event.solvedImpulse >= 0.0 && out.solvedTogether.size() < kMostSolvedTogether) {
            out.solvedTogether.push_back(event);
        }
    }
    return out;
}

}  // namespace

void Session::noteContacts() {
    const physics::World& world = run(selectedView()).world();
    Contacts contacts = contactsOf(world.contacts, selected_, world.time, world.stepCount);
    if (!contacts.events.empty()) latest_ = std::move(contacts);
}

void Session::startAgain() {
    latest_ = {};
    if (comparison_) {
        try {
            comparison_->restartFrom(primary_.scene());
        } catch (const std::exception& e) {
            note_ = std::string("side by side stopped: ") + e.what();
            stopComparison();
        }
    }
    resizeRuns();
    drag_.release();
    if (selected_ >= 0 && static_cast<std::size_t>(selected_) >= primary_.world().size()) selected_ = -1;
    keep();
}

void Session::select(int index, int view) {
    const int previous = selected_, previousView = selectedView();
    selected_ = index >= 0 && static_cast<std::size_t>(index) < primary_.world().size() ? index : -1;
    selectedView_ = view >= 0 && view < runCount() ? view : 0;
    if (selected_ == previous && selectedView() == previousView) return;
    latest_ = {};
    recallContacts();
}

// Contacts are recorded in a scene of more than a few spheres only while one is selected,
// so a sphere selected while paused had none to explain until the next step (which moves
// the run on from the instant the teacher stopped at). The frame shown is run again from
// the timeline's state before it, contacts recorded: the same steps reach the same state
// (checked by its hash), and their contacts are those the frame had. Nothing is recalled
// (frameRecalled stays false) when the world shown is not the timeline's entry (an edit
// not kept yet: a shot selects its sphere first), when the frame was an edit, when a value
// is not finite (the step that made it may throw again), or when the run differs (a
// setting changed since).
void Session::recallContacts() {
    if (selected_ < 0) return;
    const int view = selectedView();
    const RewindBuffer& timeline = rewind_[std::size_t(view)];
    const physics::World& shown = run(view).world();
    if (timeline.cursor() == 0 || timeline.cursor() >= timeline.size() || shown.size() > kMaxRecordSpheres) return;
    const WorldState& now = timeline.at(timeline.cursor()), &before = timeline.at(timeline.cursor() - 1);
    if (now.stepCount != shown.stepCount || now.position.size() != shown.size() ||
        before.stepCount >= shown.stepCount || !allFinite(shown)) {
        return;
    }
    physics::World replay = shown;  // its planes and seed; the state before the frame:
    restoreState(before, replay);
    replay.recordContacts = true;
    const scenes::Scene& scene = run(view).scene();
    Contacts recalled;
    try {
        while (replay.stepCount < shown.stepCount) {
            physics::step(replay, scene.params);
            scenes::emitDue(scene, replay);  // as Simulation::stepOnce
            Contacts contacts = contactsOf(replay.contacts, selected_, replay.time, replay.stepCount);
            if (!contacts.events.empty()) recalled = std::move(contacts);
        }
    } catch (const std::exception&) {
        return;  // as Simulation::guardedStep: nothing to explain from it
    }
    if (physics::stateHash(replay) != physics::stateHash(shown)) return;
    latest_ = std::move(recalled);
    latest_.frameRecalled = true;
}

void Session::edited() {
    touched();
    keep();
}

void Session::touched() {
    for (int k = 0; k < runCount(); ++k) {
        run(k).markEnergyInjected();  // not the solver's doing: no energy alarm
        stale_[std::size_t(k)] = 1;
    }
}

void Session::keep() {
    for (int k = 0; k < runCount(); ++k) rewind_[std::size_t(k)].push(run(k).world(), selected_);
}

std::string Session::editSelected(const SphereFields& fields) {
    if (selected_ < 0) return "no sphere is selected";
    if (const std::string refusal = checkSphereFields(primary_.world(), fields); !refusal.empty()) return refusal;
    const auto i = static_cast<std::size_t>(selected_);
    forEachWorld([&](physics::World& world) {
        if (i >= world.size()) return;
        placeSphere(world, i, fields.p, fields.v);
        world.radius[i] = fields.r;
        world.mass[i] = fields.m;
    });
    edited();
    return "";
}

bool Session::beginDrag(int view, std::size_t index, const render::Ray& ray, const glm::vec3& facing, double time) {
    dragView_ = view < runCount() ? view : 0;
    if (!drag_.begin(run(dragView_).world(), index, ray, facing, time)) return false;
    select(static_cast<int>(index), view);
    return true;
}

void Session::dragTo(const render::Ray& ray, double time) {
    const auto centre = drag_.move(run(dragView_).world(), ray, time);
    if (!centre) return;
    const glm::dvec3 velocity = drag_.velocity();
    forEachWorld([&](physics::World& world) { placeSphere(world, drag_.index(), *centre, velocity); });
    touched();
}

glm::dvec3 Session::endDrag() {
    if (!drag_.active()) return glm::dvec3(0.0);
    const std::size_t index = drag_.index();
    const glm::dvec3 velocity = drag_.release();
    forEachWorld([&](physics::World& world) {
        if (index < world.size()) placeSphere(world, index, world.position[index], velocity);
    });
    edited();
    return velocity;
}

std::string Session::shoot(const render::Ray& aim, double speed) {
    double radius = 0.0, mass = 0.0;
    typicalSphere(primary_.world(), &radius, &mass);
    std::vector<Shot> shots(static_cast<std::size_t>(runCount()));
    for (int k = 0; k < runCount(); ++k) {
        const std::string refusal = planShot(run(k).world(), aim, speed, radius, mass, &shots[std::size_t(k)]);
        if (!refusal.empty()) return runCount() > 1 ? std::string(1, char('A' + k)) + ": " + refusal : refusal;
    }
    for (int k = 0; k < runCount(); ++k) addShot(run(k).editableWorld(), shots[std::size_t(k)]);
    select(static_cast<int>(primary_.world().size() - 1));
    edited();
    return "";
}

void Session::scrubTo(std::size_t index) {
    if (timeline().empty()) return;
    for (int k = 0; k < runCount(); ++k) {
        run(k).paused = true;
        rewind_[std::size_t(k)].restore(index, run(k).editableWorld());
        run(k).restoredFromTimeline();
    }
    touched();
    if (selected_ >= 0 && static_cast<std::size_t>(selected_) >= primary_.world().size()) selected_ = -1;
    // The latest contacts at or before the frame shown (frames keep the selected sphere's
    // while one is selected); none kept (the sphere was selected later, in a scene whose
    // contacts are recorded only for it): the frame shown run again (recallContacts).
    latest_ = {};
    for (std::size_t k = timeline().cursor() + 1; k-- > 0;) {
        const WorldState& state = timeline().at(k);
        if (state.contacts.empty()) continue;
        latest_ = contactsOf(state.contacts, selected_, state.time, state.stepCount);
        if (latest_.events.empty()) continue;
        break;
    }
    if (latest_.events.empty()) recallContacts();
}

physics::Diagnostics Session::diagnostics(int k) const {
    const Simulation& simulation = run(k);
    return stale_[std::size_t(k)] ? physics::measure(simulation.world(), simulation.params()) : simulation.diagnostics();
}

void Session::appendSelection(int k, const render::Camera& camera, render::FrameSnapshot& snapshot, int partner) const {
    const physics::World& world = run(k).world();
    if (selected_ < 0 || static_cast<std::size_t>(selected_) >= world.size()) return;
    const auto i = static_cast<std::size_t>(selected_);
    addRing(snapshot, camera, world.position[i], world.radius[i], kRingColor);
    if (partner >= 0 && static_cast<std::size_t>(partner) < world.size()) {
        addRing(snapshot, camera, world.position[std::size_t(partner)], world.radius[std::size_t(partner)],
                kPartnerRingColor);
    }
    const glm::vec3 centre(world.position[i]);
    // While dragging: a plumb line to the floor, so that the height reads at a glance.
    if (drag_.active() && world.boxPlaneCount > 0) {
        const physics::Plane& floor = world.planes[0];
        const double height = glm::dot(world.position[i] - floor.point, floor.normal);
        const glm::vec3 foot(world.position[i] - height * floor.normal);
        snapshot.addLine(centre, foot, kRingColor, 2.0f);
        snapshot.addPoint(foot, kRingColor, 10.0f);
    }
}

}  // namespace app
