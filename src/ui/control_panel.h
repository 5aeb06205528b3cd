#pragma once
// The one ImGui panel: the lecture's parameters (read from scenes::parameterTable,
// so the UI, the CLI and the JSON agree), the run controls, the scene and the
// readouts. It edits the scene's live parameters in place and returns the actions
// that the app must carry out (restart, step, load a preset, ...).
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <glm/vec4.hpp>

#include "physics/diagnostics.h"
#include "physics/step.h"
#include "scenes/parameters.h"
#include "scenes/scene.h"

namespace ui {

// The presentation layout's type: this times the screen's UI scale in a window 720 high (in
// the screen's units: pixels over its content scale), and as much larger as the window is
// taller, so that a projector's 1080 lines carry the same share of the height as 720 do.
constexpr float kPresentScale = 1.5f;
constexpr float kPresentHeight = 720.0f;
inline float presentedScale(float screenScale, float heightInScreenUnits) {
    return kPresentScale * screenScale * std::max(1.0f, heightInScreenUnits / kPresentHeight);
}
// The time scale's range (simulated seconds per real second): slow motion to 4x.
using scenes::kTimeScaleRange;
// The UI scale's slider (the panel's font multiplier), which capture's --ui-scale and the
// window's kept settings hold to.
constexpr float kUiScaleRange[2] = {0.75f, 3.0f};

// The panel's own settings, kept between frames.
// An invariant alarm as the panel shows it (Readouts::alarms).
struct Alarm {
    std::string text;
    std::string hint;  // why: shown under it
    bool lit = false;  // fired recently: bright red; else dimmed
};

struct PanelState {
    bool visible = true;
    // The presentation layout (F5, --present): large type, only the scene's title, text
    // and the sliders it names, and the view; everything else one key away.
    bool present = false;
    // Presenting with a contact explained: the explanation takes the panel's place, so that
    // the views keep their size on a projector (set by the window each frame).
    bool yieldsToExplainer = false;
    bool readoutsOpen = false;  // the readouts unfolded (numbers and plots); folded: one line
    float presentedContentHeight = 1e9f;  // px, the presented text's scrolled content in the last frame
    float presentedSlidersTop = 0.0f;     // px from the display's top: where the sliders under it began
    float uiScale = 1.0f;      // multiplies the font size
    int colorBy = 2;           // render::ColorBy: 0 id, 1 speed, 2 contact state, 3 penetration
    bool showBox = true;
    bool showGrid = true;
    // Overlays (View section), drawn over the scene through the snapshot's lines and
    // dots (app/overlays.h), so that they appear in captures too. Off: they cost nothing.
    bool showVelocity = false;     // velocity arrows
    bool showContacts = false;     // contact points and normals of the last step
    bool showImpulses = false;     // impulse arrows at impact, fading over 0.5 s
    bool showPenetration = false;  // overlap depth as a red segment, exaggerated
    bool showTrails = false;       // fading trails of the centres
    bool showGraph = false;        // slide 14's contact graph, coloured by level
    bool overlaysOnTop = true;     // seen through spheres in small scenes (app::overlaysOnTop)
    int selectedSphere = -1;       // a picked sphere, -1 none: overlays and measured beta^2 follow it
    std::string scenePath;     // the load field
    int presetIndex = -1;      // into the preset list; -1: a file
    bool scrollToTop = false;  // a new scene: show its title and text
    // Page Down (+1) and Page Up (-1), as a presenter's remote sends them: the scene's text
    // (presenting) or the panel moves by this many pages in the next frame.
    int pagesToScroll = 0;
    float textScrollY = 0.0f;  // px: where the text's scroll stood at the end of the last frame
    // A restart parameter while its slider is held: the value shown, applied on release.
    std::string pendingName;
    double pendingValue = 0.0;
    // A number being typed into a slider (Ctrl+click): whose, and its text so far.
    std::string typedName;
    std::string typedText;
    int typedFrame = -1;  // ImGui's frame count when it was last typed into
    bool typedChanged = false;  // its text is not the one it opened with
    // The last refused edit, shown under the parameter it was about.
    std::string refusedName;
    std::string refusal;
    // The last file written or read, or why not, shown under the button that did it;
    // files are written into outputFolder (a full path).
    enum class FileButton { None, Scene, Plots, Screenshot };
    FileButton noticeAt = FileButton::None;
    std::string notice;
    bool noticeIsError = false;
    std::string outputFolder;
    // Whether the pointer was over the panel in the last frame, and the alarms it showed
    // then: they stay while the pointer is there (drawControlPanel).
    bool pointerOverPanel = false;
    std::vector<Alarm> alarmsShown;
    // The unfolded claims' lines shown, kept the same way (a claim measured under the pointer
    // had pushed every slider below down a line or two): the text and whether it holds
    // (0 no, 1 yes, 2 a grey note).
    std::vector<std::pair<std::string, int>> claimLinesShown;
    bool claimsWereOpen = false;                               // unfolded last frame
    std::size_t claimsMeasuredShown = 0, claimsWatchedShown = 0;  // what claimLinesShown were made from
    std::size_t claimsPendingShown = std::size_t(-1);  // the index of its "more are measured" line, or none
    // Side by side: the parameters every other view sets itself, whose sliders move view A
    // alone (said under them).
    std::vector<std::string> onlyViewA;
    int views = 1;  // side by side: how many; presented with three or more, the panel is narrower
};

// Where the last frame's wall time went. A software GL draws after the draw calls
// return, so drawMs runs until the GL has finished the scene.
struct FrameTimes {
    double fps = 0.0;       // 0: timings are not shown (capture mode, for reproducible images)
    // ms advancing the runs: every step of the frame, a side-by-side run's too, and the
    // measurements after them.
    double steppingMs = 0.0;
    std::uint64_t stepsThisFrame = 0;  // solver steps (h / substeps each) of the main run
    // ms from the start of drawing (snapshots, hidden spheres, draw calls) until the GL
    // has finished the scene.
    double drawMs = 0.0;
    // Above this many spheres a view is drawn without anti-aliasing (0: every view had it).
    std::size_t antialiasedUpTo = 0;
};

// The run section's line while the run falls behind real time: what took the frame, the
// steps or everything else (drawing, the panel, the swap), since the remedy differs:
// "slow motion: the drawing takes 80 of 95 ms a frame". Empty when fps is 0 (a capture).
std::string behindRealTimeLine(const FrameTimes& timing);
// The tooltip under it: the remedy for that cause.
const char* behindRealTimeRemedy(const FrameTimes& timing);

// What the app shows in the readouts; plain numbers, filled each frame.
struct Readouts {
    FrameTimes timing;
    bool paused = false;
    bool behindRealTime = false;
    double time = 0.0;      // s, simulated
    double timeScale = 1.0;  // simulated seconds per real second
    std::uint64_t steps = 0;
    std::size_t sphereCount = 0;
    // "sphere #12: |v| 0.59 cm/s" while a sphere is selected, else empty: presented, under the
    // sliders (07's text points to the inspector's |v|, and that layout has no inspector).
    std::string selected;
    physics::StepStats stats;
    physics::Diagnostics diagnostics;
    std::vector<std::pair<const char*, const std::vector<float>*>> plots;  // name, samples
    const std::vector<double>* plotTimes = nullptr;  // s, the samples' times, oldest first

    std::uint64_t bouncesSinceRestart = 0;  // contacts answered as a bounce, all passes
    bool continuous = false;                // the continuous method: its impacts are shown
    bool untilConverged = false;            // slide 14's until-converged solver: its passes are shown
    bool globalSolve = false;               // slide 14's lcp solver: its sweeps and residual are shown
    bool reflections = false;               // generalized reflections: their rounds too
    bool shock = false;                     // shock propagation: its levels and rounds are shown
    int passCap = 0;                        // K
    std::uint64_t cappedSinceRestart = 0;   // continuous solver steps that reached the impact cap
    // Slide 14: Smith et al.'s five properties since restart (app/teaching/impact_report.h);
    // empty until a contact has been measured.
    struct Property {
        std::string name, value, meaning;
        int verdict = 2;  // 0 kept, 1 broken, 2 untested
    };
    std::vector<Property> properties;
    // Invariant alarms (app/alarms.h), most serious first.
    using Alarm = ui::Alarm;
    std::vector<Alarm> alarms;
    // Measured restitution of floor bounces (app/restitution.h), shown by the beta slider.
    double betaSquared = 0.0;
    std::vector<double> measuredBetaSquared;  // the last few, oldest first
    bool bouncesMeasured = false;  // the meter follows this scene's floor bounces (presented: β²'s line)
    std::string restitutionNote;              // when there is nothing to show, why
    // One line per shown overlay: its scale, in its colour (rgba 0..1).
    struct LegendLine {
        std::string text;
        float color[4] = {1.0f, 1.0f, 1.0f, 1.0f};
    };
    std::vector<LegendLine> legend;
    // The claims of the scene's text this run has measured (app::Simulation::measuredClaims),
    // shown under the text, of claimsWatched in all; claimsInterrupted: the run was changed
    // by hand, so they stopped. Side by side, each view measures the claims made at its
    // settings ("B, four passes, still leaves 3.1 %" in view B), and `view` names it.
    struct ClaimLine {
        std::string says, measured;
        bool holds = false;
        char view = 0;  // 'A' to 'D' side by side; 0: one run
    };
    std::vector<ClaimLine> claims;
    std::size_t claimsWatched = 0;
    bool claimsInterrupted = false;
    bool claimsForOtherSettings = false;  // the text claims things at other settings than the run's
    double claimsLastMoment = 0.0;    // s: when the last watched claim is judged (the views' latest)
    std::size_t claimsElsewhere = 0;  // the text's claims no view measures: other settings, or a ratio of two runs
};

struct PanelActions {
    // A table parameter set in the panel: Live ones while dragged, Restart ones on release.
    struct Edit {
        const scenes::Parameter* parameter = nullptr;
        double value = 0.0;
    };
    std::vector<Edit> edits;
    bool restart = false;       // the button
    bool togglePause = false;
    bool step = false;
    bool resetCamera = false;
    bool screenshot = false;
    bool exportCsv = false;
    bool fontChanged = false;   // uiScale changed: rebuild the font
    int preset = -1;            // load this preset
    std::string loadPath;       // load this scene file
    bool saveState = false;     // save the current state (into the output folder)
};

// The parameters panel, docked on the left; returns what the app must do (it never
// changes the scene itself: the app applies the edits, and may refuse them).
PanelActions drawControlPanel(const scenes::Scene& scene, double& timeScale, const Readouts& readouts,
                              PanelState& state, const std::vector<std::string>& presetNames);

// The readouts: folded, one title line in `line` that reads the frame rate, the
// energies and the hash; unfolded (state.readoutsOpen), their numbers and plots
// filling `open`. Rectangles are x, y, width, height in ImGui units; a click on the
// title's arrow folds or unfolds them (from the next frame on).
void drawReadouts(const Readouts& readouts, PanelState& state, PanelActions& actions, const glm::vec4& line,
                  const glm::vec4& open);

// Width of the docked panel in ImGui units (window coordinates) for a display of
// `displayWidth`, at the current font size; 0 when the panel is hidden.
// The panel's width at most, as a share of the window's, presented with three or four views.
constexpr float kPresentedPanelShareManyViews = 0.36f;
float panelWidth(const PanelState& state, float displayWidth);

}  // namespace ui
