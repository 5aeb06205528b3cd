#include "app/window/window_app.h"

#include <algorithm>
#include <optional>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <memory>
#include <vector>

#include <glad/gl.h>
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>

#include "app/views/frame_builder.h"
#include "app/window/frame_profile.h"
#include "app/window/interaction_input.h"
#include "app/window/short_key_presses.h"
#include "app/window/still_frames.h"
#include "app/window/window_settings.h"
#include "app/views/interaction_windows.h"
#include "app/run/output_files.h"
#include "app/run/scene_source.h"
#include "app/run/session.h"
#include "app/run/simulation.h"
#include "app/views/view_labels.h"
#include "app/views/window_layout.h"
#include "platform/window.h"
#include "render/camera.h"
#include "render/image_io.h"
#include "render/offscreen_target.h"
#include "render/renderer.h"
#include "scenes/presets.h"
#include "scenes/scene_json.h"
#include "ui/control_panel.h"
#include "ui/imgui_gl_renderer.h"
#include "ui/ui_font.h"

namespace app {
namespace {

constexpr int kViewGap = 4;  // px between the two views side by side
// s: the longest a frame should take. The stepping gets what the last frame's drawing
// and panel left of it (at least one step): a heavy scene then runs in slow motion
// ("behind real time") at 30 frames a second rather than in real time at 16 (the 10k
// pile: one step of 10 ms a frame instead of four).
constexpr double kSlowestFrameSeconds = 1.0 / 30.0;
class WindowApp {
public:
    WindowApp(std::unique_ptr<platform::Window> window, scenes::Scene scene, const WindowAppOptions& options);
    ~WindowApp();
    int run();

private:
    static void onKey(GLFWwindow* w, int key, int scancode, int action, int mods);
    static void onCharacter(GLFWwindow* w, unsigned int codepoint);
    static void onScroll(GLFWwindow* w, double dx, double dy);
    void handleKey(int key, int mods);
    void backOut();
    void handleMouse();
    void frame(double dt);
    void makeLabels();
    void drawScene(const ViewLayout& views);
    void apply(const ui::PanelActions& actions);
    void loadPreset(int index);
    void showSceneTitle();
    void applyKeptSettings();
    // The scene's own colouring (its "color_by"), else the one the viewer chose last.
    void openColoring();
    void keepSettings() const;
    void loadFile(const std::string& path);
    // The preset whose file `path` names (any spelling of its path), or -1.
    int presetIndexOf(const std::string& path) const;
    void notify(ui::PanelState::FileButton at, const std::string& text, bool error);
    template <class Write>
    std::string writeOutput(ui::PanelState::FileButton at, const char* stem, const char* extension, const Write& write);
    void rebuildFont();
    float presentedScale() const;
    void followPresentedScale();
    void togglePresentation();
    void resetCamera();
    void fitCamera();
    void followViewShape(const ViewLayout& views);
    WindowLayout layout() const;  // everything's place: the panel, the dock, the bars and the views
    bool saveScreenshot(const std::string& path);
    void noteWhatWasDrawn();
    void waitForInput();
    void paceFrame(double frameStart);

    std::unique_ptr<platform::Window> window_;
    Simulation simulation_;
    Session session_;
    WindowAppOptions options_;
    render::Renderer renderer_;
    render::Camera camera_;
    render::FrameSnapshot snapshots_[kMostViews];  // one per view
    ui::ImGuiGlRenderer imguiRenderer_;
    ui::Backdrop backdrop_;  // what the scene left beneath the UI this frame
    ui::PanelState panel_;
    InteractionInput input_;
    ShortKeyPresses shortPresses_;  // a key pressed and let go between two frames still reaches ImGui
    StillFrames stillFrames_;       // paused and unchanged: wait for input
    std::vector<std::string> presets_;
    ui::FrameTimes timing_;
    ui::FrameTimes shownTiming_;  // timing_ as the readouts show it: the last running frame's while paused
    double frameSeconds_ = 0.0;  // s, a running average of the real frame time
    bool screenshotRequested_ = false;
    bool cameraFitted_ = false;  // fitted in the first frame, once the panel's width is known
    std::string shownTitle_;     // the window title set last
    float screenScale_ = 1.0f;   // the screen's content scale: UI scale 1 there
    float scaleBeforePresenting_ = 1.0f;
    std::vector<ViewLabel> labels_;  // side by side: this frame's labels, measured for the layout
    float viewAspect_ = 0.0f;    // of the views last frame: a change refits the camera's distance
    int chosenColorBy_ = 2;      // the viewer's colouring (kept between sessions), not a scene's
    int openedColorBy_ = 2;      // the colouring openColoring() set: a change from it is the viewer's
    FrameProfile profile_;       // --frames N only
    double refreshRate_ = 60.0;  // frames a second the display shows: paceFrame's most
};

WindowApp::WindowApp(std::unique_ptr<platform::Window> window, scenes::Scene scene, const WindowAppOptions& options)
    : window_(std::move(window)),
      simulation_(std::move(scene)),
      session_(simulation_),
      options_(options),
      input_(session_),
      presets_(scenes::listPresets()) {
    simulation_.paused = options.paused || simulation_.scene().opensPaused;
    simulation_.timeScale = simulation_.scene().timeScale;  // a scene may open in slow motion
    simulation_.wallBudget = kSlowestFrameSeconds;
    refreshRate_ = window_->refreshRate();
    panel_.scenePath = resolveScenePath(options.scene);
    panel_.outputFolder = outputFolder();
    panel_.presetIndex = presetIndexOf(panel_.scenePath);
    showSceneTitle();
    // --compare, or else the scene's own "compare" (checked by the loader).
    if (const std::string error = input_.openFirstScene(options.compare); !error.empty()) throw UsageError("--compare " + error);
    if (options.select >= 0) {
        if (static_cast<std::size_t>(options.select) >= simulation_.world().size()) {
            const std::size_t count = simulation_.world().size();
            throw UsageError("--select " + std::to_string(options.select) + ": the scene has " + std::to_string(count) +
                             (count == 1 ? " sphere" : " spheres") + ", numbered from 0");
        }
        session_.select(options.select);
        if (options.explain) input_.toggleExplainer();
    }
    GLFWwindow* handle = window_->handle();
    glfwSetWindowUserPointer(handle, this);
    // Ours first: ImGui's backend chains to the callbacks installed before it.
    glfwSetKeyCallback(handle, onKey);
    glfwSetCharCallback(handle, onCharacter);
    glfwSetScrollCallback(handle, onScroll);
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini left in the working directory
    ImGui_ImplGlfw_InitForOpenGL(handle, true);
    imguiRenderer_.init();
    screenScale_ = std::max(1.0f, window_->contentScale().x);
    panel_.uiScale = screenScale_;
    applyKeptSettings();
    openColoring();
    rebuildFont();
    if (options.present) togglePresentation();
}

WindowApp::~WindowApp() {
    imguiRenderer_.shutdown();
    renderer_.shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
}

void WindowApp::rebuildFont() {
    ui::applyStyle(panel_.uiScale);
    imguiRenderer_.invalidateFontTexture();
}

// Large type, the scene's text and its sliders, the view; F5 again puts back the rest.
void WindowApp::togglePresentation() {
    panel_.present = !panel_.present;
    if (panel_.present) {
        scaleBeforePresenting_ = panel_.uiScale;
        panel_.uiScale = presentedScale();
    } else {
        panel_.uiScale = scaleBeforePresenting_;
    }
    panel_.scrollToTop = true;
    rebuildFont();
}

// Presenting: the large type for the window's height (ui::presentedScale), never smaller
// than the scale chosen before.
float WindowApp::presentedScale() const {
    const float height = float(window_->windowSize().y) * window_->framebufferScale().y / screenScale_;
    return std::max(scaleBeforePresenting_, ui::presentedScale(screenScale_, height));
}

// Presenting, the type follows the window's height as it is resized or made full screen.
void WindowApp::followPresentedScale() {
    if (!panel_.present) return;
    const float wanted = presentedScale();
    if (std::abs(wanted - panel_.uiScale) < 0.01f * wanted) return;
    panel_.uiScale = wanted;
    rebuildFont();
}

// The panel on the left, the bar at the bottom, the readouts' line at the top, the
// dock for the inspector, the explainer and the unfolded readouts, and the views in
// the rest (ImGui must be inside a frame for the sizes; before, the views take all).
WindowLayout WindowApp::layout() const {
    LayoutRequest q;
    q.window = window_->windowSize();
    q.pixelsPerUnit = window_->framebufferScale();
    q.views = session_.runCount();
    q.gap = kViewGap;
    glm::vec3 lo, hi;
    sceneBounds(simulation_, lo, hi);
    q.boxAspect = boxAspectOnScreen(sceneCameraAngles(simulation_.scene()), lo, hi);  // at the opening angles: orbiting moves nothing
    if (!ImGui::GetCurrentContext()) return layoutWindow(q);
    const bool present = panel_.present;
    const ToolWindowsState& tools = input_.tools();
    const bool selected = session_.selected() >= 0;
    q.font = ImGui::GetFontSize();
    q.panelWidth = ui::panelWidth(panel_, q.window.x);
    q.barHeight = present ? 0.0f : timelineBarHeight();
    q.readoutsLine = present || panel_.readoutsOpen ? 0.0f : ImGui::GetFrameHeight();
    q.readouts = !present && panel_.readoutsOpen;
    q.inspectorHeight = selected && !present ? std::max(tools.inspectorHeight, q.font) : 0.0f;
    q.explainer = selected && tools.explainer;
    if (!labels_.empty()) {
        q.labelWidth = labelsWidth(labels_);
        q.labelHeight = [this](float width) { return labelsHeight(labels_, width); };
    }
    return layoutWindow(q);
}

void WindowApp::resetCamera() {
    viewAspect_ = layout().views.aspect();
    camera_ = openingCamera(simulation_, viewAspect_);
}

// The same angles, the box fitted again (the views changed shape).
void WindowApp::fitCamera() {
    glm::vec3 lo, hi;
    sceneBounds(simulation_, lo, hi);
    viewAspect_ = layout().views.aspect();
    camera_.fitBox(lo, hi, viewAspect_);
}

// The views changed shape (a window opened in the dock, the window was resized).
void WindowApp::followViewShape(const ViewLayout& views) {
    const float aspect = views.aspect();
    if (aspect == viewAspect_) return;
    glm::vec3 lo, hi;
    sceneBounds(simulation_, lo, hi);
    camera_.followAspect(lo, hi, viewAspect_, aspect);
    viewAspect_ = aspect;
}

// GLFW names keys by where they sit on a US keyboard. The printable ones go by what the
// keyboard's layout types on them: a key that types a letter is that letter's key (on a
// French keyboard, Ctrl+Q is where a US one has A; on a Dvorak one, V is where it has .),
// and one a US keyboard has a letter on that types some other character is no letter's.
// A key that types no single ASCII character (Cyrillic, say) keeps its US letter.
int keyAsTyped(int key, int scancode) {
    if (key < GLFW_KEY_APOSTROPHE || key > GLFW_KEY_WORLD_2) return key;  // not printable: as it is
    const char* typed = glfwGetKeyName(key, scancode);
    if (!typed || typed[0] == '\0' || typed[1] != '\0' || static_cast<unsigned char>(typed[0]) >= 128) return key;
    const char c = typed[0];
    if (c >= 'a' && c <= 'z') return GLFW_KEY_A + (c - 'a');
    return key >= GLFW_KEY_A && key <= GLFW_KEY_Z ? GLFW_KEY_UNKNOWN : key;
}

void WindowApp::onKey(GLFWwindow* w, int key, int scancode, int action, int mods) {
    if (action == GLFW_PRESS) static_cast<WindowApp*>(glfwGetWindowUserPointer(w))->shortPresses_.pressed(key);
    if (action != GLFW_PRESS && action != GLFW_REPEAT) return;
    if (ImGui::GetCurrentContext() && ImGui::GetIO().WantTextInput) return;
    static_cast<WindowApp*>(glfwGetWindowUserPointer(w))->handleKey(keyAsTyped(key, scancode), mods);
}

// [ and ] open the previous and next preset by the character typed, not the key: many
// keyboards type them with AltGr or Option (a German one with AltGr+8 and AltGr+9).
void WindowApp::onCharacter(GLFWwindow* w, unsigned int codepoint) {
    if (codepoint != '[' && codepoint != ']') return;
    if (ImGui::GetCurrentContext() && ImGui::GetIO().WantTextInput) return;
    auto* app = static_cast<WindowApp*>(glfwGetWindowUserPointer(w));
    const int count = static_cast<int>(app->presets_.size()), at = app->panel_.presetIndex;
    if (count == 0) return;
    if (at < 0) {  // a scene file: ] the first preset, [ the last
        app->loadPreset(codepoint == ']' ? 0 : count - 1);
    } else {
        app->loadPreset((at + (codepoint == ']' ? 1 : count - 1)) % count);
    }
}

void WindowApp::onScroll(GLFWwindow* w, double, double dy) {
    if (ImGui::GetCurrentContext() && ImGui::GetIO().WantCaptureMouse) return;
    static_cast<WindowApp*>(glfwGetWindowUserPointer(w))->camera_.zoom(float(dy));
}

void WindowApp::handleKey(int key, int mods) {
    if (key == GLFW_KEY_Q && (mods & GLFW_MOD_CONTROL)) {
        window_->requestClose();
        return;
    }
    switch (key) {
        case GLFW_KEY_P: case GLFW_KEY_SPACE: simulation_.paused = !simulation_.paused; break;
        case GLFW_KEY_O: case GLFW_KEY_N: session_.singleStep(); break;
        case GLFW_KEY_R: session_.restartAsOpened(); break;
        case GLFW_KEY_LEFT: session_.stepBack(); break;
        case GLFW_KEY_RIGHT: session_.stepForward(); break;
        case GLFW_KEY_F: input_.shoot(layout().views, camera_, true, window_->time()); break;
        case GLFW_KEY_V: if (input_.toggleCompare(window_->time())) fitCamera(); break;
        case GLFW_KEY_E: input_.toggleExplainer(window_->time()); break;
        case GLFW_KEY_TAB: panel_.visible = !panel_.visible; break;
        case GLFW_KEY_F5: togglePresentation(); break;
        case GLFW_KEY_F12: screenshotRequested_ = true; break;
        case GLFW_KEY_C: resetCamera(); break;
        case GLFW_KEY_PAGE_DOWN: ++panel_.pagesToScroll; break;
        case GLFW_KEY_PAGE_UP: --panel_.pagesToScroll; break;
        case GLFW_KEY_ESCAPE: backOut(); break;
        default: break;
    }
}

// Esc backs out one level, as it does in a slide show: the presentation layout, then
// the explainer, then the selection. It never quits: a teacher leaving the presentation
// with it must not lose the session in front of the class (Ctrl+Q quits).
void WindowApp::backOut() {
    if (panel_.present) {
        togglePresentation();
    } else if (!input_.backOut()) {
        input_.say(window_->time(), "Esc: nothing open to close; Ctrl+Q or the window's close button quits");
    }
}

// Clicks, grabs and throws first (InteractionInput); then left drag orbits, right
// drag (or shift + left drag) pans: unless ImGui has the mouse.
void WindowApp::handleMouse() {
    if (input_.handleMouse(layout().views, camera_, window_->time())) return;
    const ImGuiIO& io = ImGui::GetIO();
    if (io.WantCaptureMouse) return;
    // The press's frame: its delta is the move before the press (a jump, when the
    // pointer moved and clicked within one frame), not a drag.
    if (ImGui::IsMouseClicked(ImGuiMouseButton_Left) || ImGui::IsMouseClicked(ImGuiMouseButton_Right)) return;
    const glm::vec2 scale = window_->framebufferScale();
    const float dx = io.MouseDelta.x * scale.x, dy = io.MouseDelta.y * scale.y;
    const bool shift = io.KeyShift;
    if ((ImGui::IsMouseDragging(ImGuiMouseButton_Left, 0.0f) && shift) || ImGui::IsMouseDragging(ImGuiMouseButton_Right, 0.0f)) {
        camera_.pan(dx, dy, float(window_->framebufferSize().y));
    } else if (ImGui::IsMouseDragging(ImGuiMouseButton_Left, 0.0f)) {
        camera_.orbit(dx, dy);
    }
}

void WindowApp::loadPreset(int index) {
    if (index < 0 || index >= static_cast<int>(presets_.size())) return;
    loadFile(scenes::presetPath(presets_[static_cast<std::size_t>(index)]));
    panel_.presetIndex = index;
}

// The window's title names the scene: in the taskbar, and for a screen reader.
// The scene's title as the panel shows it ("A pile of 1000 spheres"), set again only when it
// changes (a new scene, or its count set).
void WindowApp::showSceneTitle() {
    const scenes::Scene& scene = simulation_.scene();
    const std::string title = scene.title.empty() ? "Rigid Spheres" : "Rigid Spheres: " + scenes::withCount(scene.title, scene);
    if (title == shownTitle_) return;
    window_->setTitle(title);
    shownTitle_ = title;
}

int WindowApp::presetIndexOf(const std::string& path) const {
    for (std::size_t k = 0; k < presets_.size(); ++k) {
        std::error_code error;
        if (std::filesystem::equivalent(scenes::presetPath(presets_[k]), path, error)) return static_cast<int>(k);
    }
    return -1;
}

void WindowApp::loadFile(const std::string& path) {
    try {
        simulation_.openScene(scenes::loadScene(path));  // paused or running as the scene opens
        openColoring();
        showSceneTitle();
        panel_.scenePath = path;
        panel_.presetIndex = presetIndexOf(path);  // a preset's file by any path: [ and ] go on from it
        panel_.scrollToTop = true;
        panel_.refusal.clear();
        panel_.pendingName.clear();  // a slider held while the scene changed edits nothing
        input_.sceneChanged();
        notify(ui::PanelState::FileButton::Scene, "loaded " + path, false);
        resetCamera();
    } catch (const std::exception& e) {
        // A broken file is reported under the Load button; the demo goes on with the scene it had.
        notify(ui::PanelState::FileButton::Scene, e.what(), true);
    }
}

void WindowApp::notify(ui::PanelState::FileButton at, const std::string& text, bool error) {
    panel_.noticeAt = at;
    panel_.notice = text;
    panel_.noticeIsError = error;
}

// A new file in the output folder, written by `write(path)` (false: it failed); the
// notice goes under the button `at`. Returns the path, or "" when nothing was written.
template <class Write>
std::string WindowApp::writeOutput(ui::PanelState::FileButton at, const char* stem, const char* extension,
                                   const Write& write) {
    std::string error;
    const std::string path = freshPath(panel_.outputFolder, stem, extension, error);
    if (path.empty()) {
        notify(at, error, true);
        return "";
    }
    try {
        if (!write(path)) {
            notify(at, "cannot write " + path, true);
            return "";
        }
    } catch (const std::exception& e) {
        notify(at, e.what(), true);
        return "";
    }
    notify(at, "wrote " + path, false);
    return path;
}

void WindowApp::apply(const ui::PanelActions& a) {
    if (a.togglePause) simulation_.paused = !simulation_.paused;
    if (a.step) session_.singleStep();
    if (a.restart) session_.restartAsOpened();
    for (const ui::PanelActions::Edit& edit : a.edits) {
        // Refused: the slider shows the value it had, and why under it.
        panel_.refusal = session_.setParameter(*edit.parameter, edit.value);
        panel_.refusedName = std::string(edit.parameter->name);
    }
    if (!a.edits.empty()) input_.suggestOverrides();  // the method may have changed
    if (a.resetCamera) resetCamera();
    if (a.fontChanged) rebuildFont();
    if (a.screenshot) screenshotRequested_ = true;
    if (a.preset >= 0) loadPreset(a.preset);
    if (!a.loadPath.empty()) loadFile(a.loadPath);
    if (a.saveState) {
        const std::string saved = writeOutput(ui::PanelState::FileButton::Scene, "state", "json", [&](const std::string& path) {
            scenes::saveScene(path, simulation_.scene(), simulation_.world());
            return true;
        });
        if (!saved.empty()) panel_.scenePath = saved;  // Load reads it back
    }
    if (a.exportCsv) {
        writeOutput(ui::PanelState::FileButton::Plots, "plots", "csv",
                    [&](const std::string& path) { return simulation_.history().writeCsv(path); });
    }
}

// The views side by side: their labels with this step's numbers (none for one view);
// short ones beside a dock (a selected sphere's, or the unfolded readouts, which hold the
// numbers) when three or four views share the rest.
void WindowApp::makeLabels() {
    labels_.clear();
    if (const Comparison* comparison = session_.comparison()) {
        const bool docked = session_.selected() >= 0 || (panel_.readoutsOpen && !panel_.present);
        const bool crowded = session_.runCount() >= 3 && docked;
        labels_ = comparisonLabels(simulation_, *comparison,
                                   panel_.present ? LabelLines::Presented
                                   : crowded      ? LabelLines::Compact
                                                  : LabelLines::Full);
    }
}

void WindowApp::drawScene(const ViewLayout& views) {
    const auto start = std::chrono::steady_clock::now();
    renderer_.style.showBox = panel_.showBox;
    renderer_.style.showGrid = panel_.showGrid;
    renderer_.style.overlayOnTop = overlaysOnTop(panel_, simulation_.world().size());  // as capture draws them
    renderer_.style.lineScale = window_->contentScale().x;
    panel_.selectedSphere = session_.selected();
    panel_.onlyViewA = session_.comparison() ? session_.comparison()->setInEveryView() : std::vector<std::string>{};
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    const glm::ivec2 size = window_->framebufferSize();
    glViewport(0, 0, size.x, size.y);
    glClearColor(ui::kBackdropColor[0], ui::kBackdropColor[1], ui::kBackdropColor[2], 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    timing_.antialiasedUpTo = 0;
    backdrop_.colour = glm::vec3(ui::kBackdropColor[0], ui::kBackdropColor[1], ui::kBackdropColor[2]);
    backdrop_.drawn.clear();  // where the views are, from the top left: the panel is kept drawn beside them
    for (int k = 0; k < views.count; ++k) {
        const glm::ivec4& view = views.views[k];
        backdrop_.drawn.emplace_back(view.x, size.y - view.y - view.w, view.z, view.w);
    }
    for (int k = 0; k < views.count; ++k) {
        const glm::ivec4& view = views.views[k];
        buildSnapshot(session_.run(k), panel_, snapshots_[k]);
        session_.appendSelection(k, camera_, snapshots_[k], explainedPartner(session_, input_.tools()));
        // Straight into the window, which has no samples: the spheres' outlines are blended.
        renderer_.style.antialiasEdges = outlinesAntialiased(snapshots_[k].sphereCount());
        if (!renderer_.style.antialiasEdges) timing_.antialiasedUpTo = kMostSpheresAntialiased;
        renderer_.draw(snapshots_[k], camera_, view.x, view.y, view.z, view.w);
    }
    // A software GL draws after the calls return: time the drawing, not the calls. (On a
    // GPU this costs the overlap of one frame's GL work with the next one's CPU work.)
    glFinish();
    timing_.drawMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

void WindowApp::frame(double dt) {
    window_->pollEvents();
    followPresentedScale();  // before the frame: it rebuilds the font
    shortPresses_.beforeNewFrame(ImGui::GetIO());
    imguiRenderer_.newFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    if (!cameraFitted_) {  // fitted to the views the labels leave
        makeLabels();
        resetCamera();
    }
    cameraFitted_ = true;
    showSceneTitle();
    input_.expireMessage(window_->time());
    handleMouse();
    panel_.yieldsToExplainer = panel_.present && session_.selected() >= 0 && input_.tools().explainer;
    session_.setCatchEveryStep(input_.tools().explainer);
    profile_.lap(FrameProfile::Events);
    const auto stepping = std::chrono::steady_clock::now();
    const std::uint64_t stepsBefore = simulation_.world().stepCount;
    simulation_.wallBudget = std::max(0.0, kSlowestFrameSeconds - 1e-3 * profile_.lastFrameWithout(FrameProfile::Stepping));
    session_.advance(dt);
    const std::uint64_t stepsAfter = simulation_.world().stepCount;
    timing_.stepsThisFrame = stepsAfter >= stepsBefore ? stepsAfter - stepsBefore : 0;
    timing_.steppingMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - stepping).count();
    profile_.lap(FrameProfile::Stepping);
    if (input_.takeFoldReadouts()) panel_.readoutsOpen = false;  // the views' labels carry them
    panel_.views = session_.runCount();  // this frame's: presented, the panel narrows with three views or more
    makeLabels();  // once a frame: the layout measures them, the windows draw them
    const WindowLayout placed = layout();
    followViewShape(placed.views);
    drawScene(placed.views);
    profile_.lap(FrameProfile::Draw);
    if (!simulation_.paused) shownTiming_ = timing_;  // paused, the readouts hold still (StillFrames can wait)
    ui::Readouts readouts = makeReadouts(simulation_, shownTiming_, session_.comparison());
    readouts.diagnostics = session_.diagnostics(0);  // measured again after an edit or a step back
    readouts.selected = selectedSpeedLine(session_);
    ui::PanelActions actions = ui::drawControlPanel(simulation_.scene(), simulation_.timeScale, readouts, panel_, presets_);
    const auto box = [](const Rect& r) { return glm::vec4(r.min, r.size); };
    if (!panel_.present) ui::drawReadouts(readouts, panel_, actions, box(placed.readoutsLine), box(placed.readouts));
    const ToolActions tools = drawInteractionWindows(session_, placed, labels_, input_.tools());
    ImGui::Render();
    profile_.lap(FrameProfile::Layout);
    imguiRenderer_.render(ImGui::GetDrawData(), &backdrop_);
    if (options_.frames > 0) glFinish();  // measured: the UI's drawing, not only its calls
    profile_.lap(FrameProfile::UiRender);
    apply(actions);
    if (panel_.colorBy != openedColorBy_) chosenColorBy_ = openedColorBy_ = panel_.colorBy;  // chosen in the panel
    if (input_.apply(tools, layout().views, camera_, window_->time())) fitCamera();
    if (const std::string note = session_.takeNote(); !note.empty()) {  // side by side stopped: one view again
        input_.say(window_->time(), "%s", note.c_str());
        fitCamera();
    }
    if (screenshotRequested_) {
        const std::string path = writeOutput(ui::PanelState::FileButton::Screenshot, "screenshot", "png",
                                             [&](const std::string& p) { return saveScreenshot(p); });
        // F12: the panel may be folded or presented, so the views say it, briefly; the folder is
        // the Screenshot button's note.
        if (!path.empty()) input_.sayBriefly(window_->time(), "saved " + std::filesystem::path(path).filename().string());
        screenshotRequested_ = false;
    }
}

// Paused, with nothing held: the frame is compared with the last (StillFrames); a scripted
// run (--frames) draws every frame.
void WindowApp::noteWhatWasDrawn() {
    const ImGuiIO& io = ImGui::GetIO();
    bool held = shortPresses_.holding();
    for (const bool down : io.MouseDown) held = held || down;
    for (const bool down : io.KeysDown) held = held || down;
    const bool quiet = simulation_.paused && timing_.stepsThisFrame == 0 && !held && options_.frames == 0;
    const std::uint64_t scene = simulation_.world().stepCount * 1000003u + std::uint64_t(session_.selected() + 1);
    stillFrames_.after(quiet, *ImGui::GetDrawData(), camera_, scene);
}

// Until input comes or StillFrames::kWaitSeconds pass; input draws a few frames again.
void WindowApp::waitForInput() {
    const double start = window_->time();
    window_->waitEvents(StillFrames::kWaitSeconds);
    if (window_->time() - start < 0.9 * StillFrames::kWaitSeconds) stillFrames_.woken();
}

// At most the display's frames a second. Where the swap does not wait for the display (a
// driver that ignores the swap interval, or a virtual display such as Xvfb) the loop drew as
// fast as it could: 113 frames a second of the bounce (02) took 1.6 cores under Xvfb, 59 took 1.2.
// The rest of a frame waits for input, which ends the wait at once. A scripted run (--frames)
// draws as fast as it can: its frame rate is what it measures.
void WindowApp::paceFrame(double frameStart) {
    if (options_.frames > 0) return;
    const double left = 1.0 / refreshRate_ - (window_->time() - frameStart);  // s
    if (left > 0.0) window_->waitEvents(left);
}

bool WindowApp::saveScreenshot(const std::string& path) {
    const glm::ivec2 size = window_->framebufferSize();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glReadBuffer(GL_BACK);
    return render::writePng(path, size.x, size.y, render::readPixelsRGBA(size.x, size.y));
}

int WindowApp::run() {
    if (const std::string error = renderer_.init(); !error.empty()) {
        std::fprintf(stderr, "spheres: the renderer could not start: %s\n", error.c_str());
        return 1;
    }
    double last = window_->time();
    auto timedFrom = std::chrono::steady_clock::now();
    int drawn = 0;
    for (int frames = 0; !window_->shouldClose(); ++frames) {
        if (frames == 1) timedFrom = std::chrono::steady_clock::now();
        const bool waits = stillFrames_.waits();
        if (waits) waitForInput();
        profile_.begin();
        const double now = window_->time();
        // s; a stall (dragging the window) is not simulated, nor a wait (paused)
        const double dt = waits ? 0.0 : std::min(now - last, 0.25);
        // Averaged in time, not in rate, so one near-instant first frame cannot inflate it.
        if (!waits) frameSeconds_ = frames == 0 ? 0.0 : (frames == 1 ? now - last : 0.9 * frameSeconds_ + 0.1 * (now - last));
        timing_.fps = frameSeconds_ > 0.0 ? 1.0 / frameSeconds_ : 0.0;
        last = now;
        const bool lastFrame = options_.frames > 0 && frames + 1 >= options_.frames;
        frame(dt);
        if (lastFrame && !options_.screenshot.empty() && !saveScreenshot(options_.screenshot)) {
            std::fprintf(stderr, "spheres: --screenshot %s: cannot write the file\n", options_.screenshot.c_str());
            return 1;
        }
        profile_.lap(FrameProfile::Other);
        noteWhatWasDrawn();
        window_->swapBuffers();
        paceFrame(now);
        profile_.lap(FrameProfile::Present);
        profile_.endFrame(options_.frames > 0 && frames > 0);
        ++drawn;
        if (lastFrame) break;
    }
    if (options_.frames > 0) {
        const std::chrono::duration<double> timed = std::chrono::steady_clock::now() - timedFrom;
        profile_.print(drawn, timed.count());
    } else {
        keepSettings();
    }
    return 0;
}

void WindowApp::openColoring() {
    const int scenes = simulation_.scene().colorBy;
    panel_.colorBy = openedColorBy_ = scenes >= 0 ? scenes : chosenColorBy_;
}

// The view settings the last session kept (window_settings.h). A broken file is said in one
// line; the session opens as it would without it.
void WindowApp::applyKeptSettings() {
    if (options_.frames > 0) return;  // scripted runs (tests, benchmarks) look the same everywhere
    std::string warning;
    const WindowSettings kept = readWindowSettings(windowSettingsPath(), warning);
    if (!warning.empty()) std::fprintf(stderr, "spheres: settings: %s\n", warning.c_str());
    if (kept.uiScale > 0.0f) panel_.uiScale = kept.uiScale;
    chosenColorBy_ = kept.colorBy;
    panel_.showBox = kept.showBox;
    panel_.showGrid = kept.showGrid;
}

// The UI scale is kept only where the user chose one (not the screen's own, which another
// screen may not share), and as it was before the presentation layout enlarged it.
// Nothing is kept where there is no home to keep it in.
void WindowApp::keepSettings() const {
    const std::filesystem::path path = windowSettingsPath();
    if (path.empty()) return;
    const float chosen = panel_.present ? scaleBeforePresenting_ : panel_.uiScale;
    const std::string error =
        writeWindowSettings(path, {chosen == screenScale_ ? 0.0f : chosen, chosenColorBy_, panel_.showBox, panel_.showGrid});
    if (!error.empty()) std::fprintf(stderr, "spheres: settings not kept: %s\n", error.c_str());
}

}  // namespace

int runWindowApp(const WindowAppOptions& options) {
    scenes::Scene scene = loadSceneWithSettings(options.scene, options.settings);
    checkWritable("--screenshot", options.screenshot, ".png");
    checkCompareOption(scene, options.compare);
    if (options.explain && options.select < 0) throw UsageError("--explain needs --select INDEX");
    std::string error;
    platform::WindowOptions windowOptions;
    windowOptions.width = options.width;
    windowOptions.height = options.height;
    windowOptions.growToScreen = !options.sizeGiven;
    auto window = platform::Window::create(windowOptions, &error);
    if (!window) {
        // A display whose GL gives no 3.3 core context is another fault than no display.
        const char* x11 = std::getenv("DISPLAY");
        const char* wayland = std::getenv("WAYLAND_DISPLAY");
        const bool display = (x11 && *x11) || (wayland && *wayland);
        std::fprintf(stderr,
                     display ? "spheres: cannot open a window (%s). The display is there, its GL driver gave no "
                               "OpenGL 3.3 core context: update the graphics driver, or try Mesa's software GL "
                               "(LIBGL_ALWAYS_SOFTWARE=1), or run headless: `%s capture --scene %s --frames 60 "
                               "--out frames/`\n"
                             : "spheres: cannot open a window (%s). Without a display, run headless: "
                               "`%s capture --scene %s --frames 60 --out frames/` or `xvfb-run -a %s`\n",
                     error.c_str(), options.program.c_str(), options.scene.c_str(), options.program.c_str());
        return 2;
    }
    std::optional<WindowApp> app;
    builtWithSettings(options.settings, [&] { app.emplace(std::move(window), std::move(scene), options); });
    return app->run();
}

}  // namespace app
