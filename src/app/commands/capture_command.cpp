#include "app/commands/capture_command.h"

#include <glad/gl.h>
#include <imgui.h>

#include <algorithm>
#include <iterator>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <deque>
#include <filesystem>
#include <fstream>
#include <future>
#include <glm/trigonometric.hpp>
#include <memory>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string_view>
#include <thread>
#include <type_traits>
#include <utility>

#include "app/commands/capture_comparison.h"
#include "app/commands/progress_line.h"
#include "app/views/frame_builder.h"
#include "app/run/scene_source.h"
#include "app/run/simulation.h"
#include "physics/diagnostics.h"
#include "platform/headless_context.h"
#include "platform/whole_file.h"
#include "render/camera.h"
#include "render/image_io.h"
#include "render/offscreen_target.h"
#include "render/renderer.h"
#include "scenes/parameters.h"
#include "scenes/presets.h"
#include "ui/control_panel.h"
#include "ui/imgui_gl_renderer.h"
#include "ui/ui_font.h"

namespace app {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

constexpr int kMinSide = 16;                             // px
constexpr int kMaxSide = 8192;                           // px
// (kMostCapturedFrames - 1, capture_command.h: six digits in the file names)
constexpr int kMaxFrameIndex = kMostCapturedFrames - 1;
constexpr int kMaxSamples = 16;                          // per pixel
constexpr double kMaxElevationDeg = 88.0;                // the orbit camera must stay off the pole
constexpr double kLeastDistance = 0.1;                   // m: nearer, a box of metres lies past the far plane
constexpr double kMaxDistance = 1000.0;                  // m, render::Camera's zoom limit
constexpr int kUiWarmUpFrames = 3;                       // ImGui frames laid out before frame 0
constexpr int kViewGap = 4;                              // px between views side by side, as the window
constexpr int kSmallestView = 24;                        // px: a view smaller either way is refused, not drawn

// ---------------------------------------------------------------- the options, checked

struct CameraChoice {
    double azimuthDeg = 0.0;         // degrees, around +z from +x
    double elevationDeg = 0.0;       // degrees above the xy plane
    std::optional<double> distance;  // m; none: fit the box at these angles
};

struct CapturePlan {
    std::vector<int> frames;  // indices to write, strictly increasing
    glm::ivec2 size{0};       // px
    std::optional<CameraChoice> camera;
    render::ColorBy colorBy = render::ColorBy::ContactState;
    OverlayFlags overlays;
    platform::HeadlessBackend backend = platform::HeadlessBackend::Auto;
};

std::vector<std::string_view> splitCommas(std::string_view text) {
    std::vector<std::string_view> parts;
    std::size_t start = 0;
    for (std::size_t comma = text.find(','); comma != std::string_view::npos;
         comma = text.find(',', start)) {
        parts.push_back(text.substr(start, comma - start));
        start = comma + 1;
    }
    parts.push_back(text.substr(start));
    return parts;
}

template <typename T>
std::optional<T> parseWhole(std::string_view text) {
    T value{};
    const char* end = text.data() + text.size();
    const auto [ptr, error] = std::from_chars(text.data(), end, value);
    if (error != std::errc() || ptr != end || text.empty()) return std::nullopt;
    if constexpr (std::is_floating_point_v<T>) {
        if (!std::isfinite(value)) return std::nullopt;
    }
    return value;
}

glm::ivec2 parseSize(const std::string& text) {
    const std::size_t x = text.find('x');
    const auto width = parseWhole<int>(std::string_view(text).substr(0, x));
    const auto height = x == std::string::npos
                            ? std::nullopt
                            : parseWhole<int>(std::string_view(text).substr(x + 1));
    if (!width || !height)
        throw UsageError("--size " + text + ": expected WxH in pixels, e.g. 1280x800");
    if (*width < kMinSide || *width > kMaxSide || *height < kMinSide || *height > kMaxSide) {
        throw UsageError("--size " + text + ": width and height must be between " +
                         std::to_string(kMinSide) + " and " + std::to_string(kMaxSide) + " px");
    }
    return {*width, *height};
}

std::optional<CameraChoice> parseCamera(const std::string& text) {
    if (text.empty()) return std::nullopt;
    const std::string why = "--camera " + text + ": ";
    const std::vector<std::string_view> parts = splitCommas(text);
    std::vector<double> values;
    for (std::string_view part : parts) {
        if (const auto value = parseWhole<double>(part)) values.push_back(*value);
    }
    if (values.size() != parts.size() || (values.size() != 2 && values.size() != 3)) {
        throw UsageError(
            why + "expected azimuth,elevation[,distance] (degrees, degrees, m), e.g. -60,25,4");
    }
    if (std::abs(values[1]) > kMaxElevationDeg)
        throw UsageError(why + "the elevation must be within +-88 degrees");
    CameraChoice camera{values[0], values[1], std::nullopt};
    if (values.size() == 3) {
        // Its far plane is 50 distances away: at 1e-9 m it drew nothing but the sky.
        if (!(values[2] >= kLeastDistance) || values[2] > kMaxDistance)
            throw UsageError(why + "the distance must be 0.1 to 1000 m");
        camera.distance = values[2];
    }
    return camera;
}

std::vector<int> parseFrameList(const std::string& text) {
    if (text.empty()) throw UsageError("--at: the list of frames is empty");
    std::vector<int> frames;
    for (std::string_view part : splitCommas(text)) {
        const auto frame = parseWhole<int>(part);
        if (!frame || *frame < 0 || *frame > kMaxFrameIndex) {
            throw UsageError("--at " + text + ": '" + std::string(part) +
                             "' is not a frame index (0 to 999999)");
        }
        if (!frames.empty() && *frame <= frames.back()) {
            throw UsageError("--at " + text +
                             ": frames must be strictly increasing, without duplicates");
        }
        frames.push_back(*frame);
    }
    return frames;
}

std::vector<int> chooseFrames(const CaptureOptions& o) {
    if (o.frames && o.at)
        throw UsageError("give either --frames N [--every K] or --at f1,f2,..., not both");
    if (o.every && !o.frames) throw UsageError("--every needs --frames N");
    if (o.at) return parseFrameList(*o.at);
    if (!o.frames)
        throw UsageError("say which frames to write: --frames N [--every K] or --at f1,f2,...");
    const int count = *o.frames;
    const int every = o.every.value_or(1);
    if (count < 1 || count > kMaxFrameIndex + 1)
        throw UsageError("--frames: must be between 1 and 1000000");
    if (every < 1 || every > kMaxFrameIndex + 1)
        throw UsageError("--every: must be between 1 and 1000000");
    std::vector<int> frames;
    for (int frame = 0; frame < count; frame += every) frames.push_back(frame);
    return frames;
}

render::ColorBy parseColorBy(const std::string& text) {
    if (text.empty()) return render::ColorBy::ContactState;  // not given: contact, unless the scene says
    for (std::size_t k = 0; k < std::size(scenes::kColorByNames); ++k) {
        if (text == scenes::kColorByNames[k]) return render::ColorBy(k);
    }
    throw UsageError("--color-by " + text + ": expected id, speed, contact or penetration");
}

OverlayFlags parseOverlays(const std::string& text) {
    OverlayFlags flags;
    if (text.empty()) return flags;
    for (const std::string_view part : splitCommas(text)) {
        const std::string name(part);
        if (name == "all") {
            for (const char* each : kOverlayNames) setOverlayByName(flags, each);
        } else if (!setOverlayByName(flags, name)) {
            throw UsageError("--overlay " + text + ": unknown overlay '" + name +
                             "'; expected a comma-separated list of velocity, contacts, impulses, "
                             "penetration, trails, graph, or all");
        }
    }
    return flags;
}

// The panel's view options for a capture: the window's defaults, the colouring and the overlays.
ui::PanelState captureView(render::ColorBy colorBy, const OverlayFlags& overlays, float uiScale, bool present,
                           int height) {
    ui::PanelState view = viewShowing(overlays);
    view.colorBy = static_cast<int>(colorBy);
    // As F5 in the window, --ui-scale as the screen's content scale.
    view.uiScale = present ? ui::presentedScale(uiScale, float(height) / uiScale) : uiScale;
    view.present = present;
    return view;
}

CapturePlan planCapture(const CaptureOptions& options) {
    CapturePlan plan;
    plan.frames = chooseFrames(options);
    plan.size = parseSize(options.size);
    plan.camera = parseCamera(options.camera);
    plan.colorBy = parseColorBy(options.colorBy);
    plan.overlays = parseOverlays(options.overlay);
    const auto backend = platform::parseHeadlessBackend(options.gl);
    if (!backend) throw UsageError("--gl " + options.gl + ": expected osmesa, egl or auto");
    plan.backend = *backend;
    if (options.samples < 0 || options.samples > kMaxSamples)
        throw UsageError("--samples: must be between 0 and 16");
    if (options.out.empty()) throw UsageError("--out: give a folder for the frames");
    if (options.uiScale && !(*options.uiScale >= ui::kUiScaleRange[0] && *options.uiScale <= ui::kUiScaleRange[1]))
        throw UsageError("--ui-scale: must be between 0.75 and 3");
    if (options.present && !options.withUi) throw UsageError("--present draws the panel: give --with-ui too");
    return plan;
}

// ---------------------------------------------------------------- GL and the output folder

std::string backendHint(platform::HeadlessBackend backend) {
    switch (backend) {
        case platform::HeadlessBackend::OSMesa:
            return "try --gl egl, or install libosmesa6 (and libosmesa6-dev, then rebuild)";
        case platform::HeadlessBackend::EGL:
            return "try --gl osmesa (install libosmesa6 and libosmesa6-dev, then rebuild)";
        case platform::HeadlessBackend::Auto:
            break;
    }
    return "install libosmesa6 and libosmesa6-dev (software GL, no display needed) and "
           "rebuild, or use --gl egl with a working EGL driver";
}

std::unique_ptr<platform::HeadlessContext> openContext(platform::HeadlessBackend backend,
                                                       glm::ivec2 size) {
    std::string error;
    auto context = platform::createHeadless(backend, &error);
    if (!context) {
        throw UsageError(std::string("--gl ") + platform::toString(backend) +
                         ": no headless GL context; tried " + error + "; " + backendHint(backend));
    }
    GLint maxSide = 0;
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &maxSide);
    if (size.x > maxSide || size.y > maxSide) {
        throw UsageError("--size: " + std::string(context->name()) + " draws at most " +
                         std::to_string(maxSide) + " px per side");
    }
    return context;
}

// Creates the folder when missing and checks that a file can be written in it.
void prepareOutFolder(const std::string& out) {
    const fs::path folder(out);
    std::error_code error;
    if (fs::exists(folder, error) && !fs::is_directory(folder, error)) {
        throw UsageError("--out " + out + ": exists and is not a folder");
    }
    const bool created = fs::create_directories(folder, error);
    if (error)
        throw UsageError("--out " + out + ": cannot create the folder (" + error.message() + ")");
    const fs::path probe = folder / ".spheres_write_probe";
    const bool writable = std::ofstream(probe).good();
    fs::remove(probe, error);
    if (writable) return;
    if (created) fs::remove(folder, error);
    throw UsageError("--out " + out + ": cannot write files in this folder");
}

std::string glText(GLenum name) {
    const GLubyte* text = glGetString(name);
    return text ? reinterpret_cast<const char*>(text) : "?";
}

// ---------------------------------------------------------------- the window's panel, headless

// The window's ImGui panel and readouts, with no input, where the layout puts them.
// Timings (FPS, draw and step ms) are shown as 0 so that equal runs give equal images.
class UiOverlay {
  public:
    UiOverlay(glm::ivec2 size, const ui::PanelState& view, const std::string& scenePath);
    ~UiOverlay();
    UiOverlay(const UiOverlay&) = delete;
    UiOverlay& operator=(const UiOverlay&) = delete;

    // What the layout needs of the panel: the font, its width, the readouts' line.
    void measure(LayoutRequest& request);
    void place(const WindowLayout& layout) { layout_ = layout; }
    // Lays out one ImGui frame (ends with ImGui::Render); draws nothing yet.
    void layout(Simulation& simulation, const Comparison* comparison);
    // Draws the last layout into the bound framebuffer; returns what it drew (px).
    std::vector<glm::vec4> draw();

  private:
    ImGuiContext* context_ = nullptr;
    ui::ImGuiGlRenderer renderer_;
    ui::PanelState panel_;
    std::vector<std::string> presets_;
    WindowLayout layout_;
};

UiOverlay::UiOverlay(glm::ivec2 size, const ui::PanelState& view, const std::string& scenePath)
    : context_(ImGui::CreateContext()), panel_(view), presets_(scenes::listPresets()) {
    ImGui::SetCurrentContext(context_);  // CreateContext makes it current only when none is
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.DisplaySize = ImVec2(float(size.x), float(size.y));
    io.DisplayFramebufferScale = ImVec2(1.0f, 1.0f);
    io.DeltaTime = float(kCaptureFrameSeconds);
    ui::applyStyle(panel_.uiScale);
    if (const std::string error = renderer_.init(); !error.empty())
        throw std::runtime_error("ImGui: " + error);
    panel_.scenePath = scenePath;
    for (std::size_t k = 0; k < presets_.size(); ++k) {
        if (scenes::presetPath(presets_[k]) == scenePath) panel_.presetIndex = static_cast<int>(k);
    }
    // A preset shows as "assets/scenes/...": images made on one machine do not carry its folders.
    if (panel_.presetIndex >= 0) {
        const fs::path root = fs::path(scenes::assetDirectory()).parent_path();
        panel_.scenePath = fs::path(scenePath).lexically_relative(root).string();
    }
}

UiOverlay::~UiOverlay() {
    renderer_.shutdown();
    ImGui::DestroyContext(context_);
}

void UiOverlay::measure(LayoutRequest& request) {
    renderer_.newFrame();
    if (!renderer_.error().empty()) throw std::runtime_error("ImGui: " + renderer_.error());
    ImGui::NewFrame();  // the font's size is known inside a frame
    request.font = ImGui::GetFontSize();
    request.panelWidth = ui::panelWidth(panel_, ImGui::GetIO().DisplaySize.x);
    request.readoutsLine = panel_.present ? 0.0f : ImGui::GetFrameHeight();
    ImGui::EndFrame();
}

void UiOverlay::layout(Simulation& simulation, const Comparison* comparison) {
    renderer_.newFrame();
    if (!renderer_.error().empty()) throw std::runtime_error("ImGui: " + renderer_.error());
    ImGui::NewFrame();
    // No wall times: they would make equal runs differ.
    ui::Readouts readouts = makeReadouts(simulation, ui::FrameTimes{}, comparison);
    ui::PanelActions actions =
        ui::drawControlPanel(simulation.scene(), simulation.timeScale, readouts, panel_, presets_);
    const auto box = [](const Rect& r) { return glm::vec4(r.min, r.size); };
    if (!panel_.present) ui::drawReadouts(readouts, panel_, actions, box(layout_.readoutsLine), box(layout_.readouts));
    ImGui::Render();
}

std::vector<glm::vec4> UiOverlay::draw() {
    renderer_.render(ImGui::GetDrawData());
    return ui::drawnRectangles(*ImGui::GetDrawData());
}

// ---------------------------------------------------------------- the capture

Json parameterValues(const scenes::Scene& scene) {
    Json values = Json::object();
    for (const scenes::Parameter& p : scenes::parameterTable()) {
        if (!p.availableIn(scene)) continue;  // an emitter's period in a scene without one, ...
        const std::string name(p.name);
        const double value = p.get(scene);
        if (p.kind == scenes::ParameterKind::Choice) {
            values[name] = std::string(p.choices.at(static_cast<std::size_t>(value)));
        } else if (p.kind == scenes::ParameterKind::Integer) {
            values[name] = static_cast<long long>(value);
        } else {
            values[name] = value;
        }
    }
    return values;
}

std::string hashText(std::uint64_t hash) {
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
    return text;
}

std::string frameFileName(int index) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%06d.png", index);
    return name;
}

// Encodes PNG files on worker threads while the next frames are drawn: encoding
// takes most of a frame's time. The files' bytes do not depend on the threads.
class PngWriter {
  public:
    explicit PngWriter(std::size_t imageBytes);
    ~PngWriter() { finish(); }
    PngWriter(const PngWriter&) = delete;
    PngWriter& operator=(const PngWriter&) = delete;

    void write(std::string path, render::Image image);
    // Waits for every file; returns the first that could not be written whole, or "".
    std::string finish();
    // Whether a file waited for so far could not be written (the capture then stops: a full
    // disk had a line said for each of the frames left).
    bool failed() const { return !failed_.empty(); }

  private:
    void waitOldest();

    std::deque<std::pair<std::string, std::future<bool>>> pending_;  // path, written
    std::size_t maxPending_ = 1;
    std::string failed_;  // the first file not written
};

PngWriter::PngWriter(std::size_t imageBytes) {
    constexpr std::size_t kMaxPendingBytes = std::size_t(512) << 20;  // images waiting in memory
    const std::size_t threads = std::clamp<std::size_t>(std::thread::hardware_concurrency(), 1, 8);
    maxPending_ = std::clamp<std::size_t>(kMaxPendingBytes / std::max<std::size_t>(imageBytes, 1),
                                          1, threads);
}

void PngWriter::write(std::string path, render::Image image) {
    while (pending_.size() >= maxPending_) waitOldest();
    auto written = std::async(std::launch::async, [path, image = std::move(image)] {
        return render::writePng(path, image.width, image.height, image.rgba);
    });
    pending_.emplace_back(std::move(path), std::move(written));
}

void PngWriter::waitOldest() {
    auto [path, written] = std::move(pending_.front());
    pending_.pop_front();
    if (!written.get() && failed_.empty()) failed_ = path;
}

std::string PngWriter::finish() {
    while (!pending_.empty()) waitOldest();
    return failed_;
}

class Capturer {
  public:
    Capturer(const CaptureOptions& options, const CapturePlan& plan,
             std::unique_ptr<platform::HeadlessContext> context, Simulation simulation);
    int run();

  private:
    render::Image drawFrame();
    void place(const WindowLayout& layout);
    void refuseViewsTooSmall() const;
    void followLabels();
    void writeFrame(int index);
    const Comparison* comparedRuns() const { return compare_ ? &compare_->comparison() : nullptr; }
    Json manifest() const;
    Json cameraJson() const;
    Json overlayList() const;

    // Declared first: destroyed last, after every GL object below.
    std::unique_ptr<platform::HeadlessContext> context_;
    const CaptureOptions& options_;
    const CapturePlan& plan_;
    render::ColorBy colorBy_ = render::ColorBy::ContactState;  // plan_'s, or the scene's where --color-by was not given
    std::string scenePath_;
    Simulation simulation_;
    render::OffscreenTarget target_;
    render::Renderer renderer_;
    render::FrameSnapshot snapshot_;
    std::unique_ptr<UiOverlay> ui_;
    std::unique_ptr<CaptureComparison> compare_;  // --compare: views B, C, D
    LayoutRequest request_;  // what layout_ was laid out from; the labels measured again each frame
    WindowLayout layout_;
    glm::ivec4 view_{0};  // x, y, width, height in px (GL's lower-left origin)
    std::vector<glm::vec4> uiDrawn_;  // px from the top left: what the panels and labels covered
    render::Camera camera_;
    Json frames_ = Json::array();
    std::unique_ptr<PngWriter> writer_;  // last: its threads finish before the rest goes
};

Capturer::Capturer(const CaptureOptions& options, const CapturePlan& plan,
                   std::unique_ptr<platform::HeadlessContext> context, Simulation simulation)
    : context_(std::move(context)),
      options_(options),
      plan_(plan),
      scenePath_(resolveScenePath(options.scene)),
      simulation_(std::move(simulation)) {
    // Without --color-by, the scene's own colouring, as the window opens it (else contact).
    const int scenes = simulation_.scene().colorBy;
    colorBy_ = options.colorBy.empty() && scenes >= 0 ? render::ColorBy(scenes) : plan.colorBy;
    if (const std::string error = target_.resize(plan.size.x, plan.size.y, options.samples);
        !error.empty()) {
        throw std::runtime_error(error);
    }
    if (const std::string error = renderer_.init(); !error.empty())
        throw std::runtime_error("renderer: " + error);
    // Contacts and trails are recorded from the first step on, as in a window whose
    // overlays were switched on before the run.
    simulation_.setOverlayFlags(plan.overlays);
    LayoutRequest& request = request_;  // kept: the labels are measured again at every frame
    request.window = plan.size;
    request.gap = kViewGap;
    ui::PanelState view = captureView(colorBy_, plan.overlays, options.uiScale.value_or(1.0f), options.present,
                                      plan.size.y);
    // --compare, or else the scene's own "compare".
    const std::vector<std::string>& compare = options.compare.empty() ? simulation_.scene().compare : options.compare;
    if (!compare.empty()) {
        compare_ = std::make_unique<CaptureComparison>(simulation_, compare, plan.size, view.uiScale, view.present);
        view.views = request.views = compare_->views();
    }
    if (options.withUi) {
        ui_ = std::make_unique<UiOverlay>(plan.size, view, scenePath_);
        ui_->measure(request);
    }
    if (compare_) compare_->sizeLabels(simulation_, request);
    camera_ = sceneCameraAngles(simulation_.scene());
    if (plan.camera) {
        camera_.azimuth = float(glm::radians(plan.camera->azimuthDeg));
        camera_.elevation = float(glm::radians(plan.camera->elevationDeg));
    }
    glm::vec3 lo, hi;
    sceneBounds(simulation_, lo, hi);
    request.boxAspect = boxAspectOnScreen(camera_, lo, hi);
    place(layoutWindow(request));
    refuseViewsTooSmall();
}

// A size that leaves a view a sliver (four views and their labels at 320x200 had views 1 px
// high) is refused in one line, not written as blank frames.
void Capturer::refuseViewsTooSmall() const {
    const int count = compare_ ? compare_->comparison().count() + 1 : 1;
    if (count == 1 && !options_.withUi) return;  // the whole image: --size's own range holds
    for (int k = 0; k < count; ++k) {
        const glm::ivec4& v = layout_.views.views[k];
        if (v.z >= kSmallestView && v.w >= kSmallestView) continue;
        const std::string views = count == 1 ? "the view" : std::to_string(count) + " views side by side";
        const std::string beside = !options_.withUi ? "their labels" : count == 1 ? "the panel" : "the panel and their labels";
        throw UsageError("--size " + options_.size + ": too small for " + views + " with " + beside + " (a view would be " +
                         std::to_string(v.z) + " x " + std::to_string(v.w) + " px); give a larger --size, e.g. 1280x720");
    }
}

// Everything where `layout` puts it, and the camera fitted to the first view: the scene's
// region (or --camera's distance), from the layout alone, so that a frame does not depend
// on the frames before it.
void Capturer::place(const WindowLayout& layout) {
    layout_ = layout;
    view_ = layout_.views.views[0];
    if (compare_) compare_->place(layout_);
    if (ui_) {
        ui_->place(layout_);
        // ImGui settles in a few frames (auto-sized windows, scrollbars and wrapped
        // text measure the previous frame), so every captured frame looks the same
        // whichever frames came before it.
        for (int frame = 0; frame < kUiWarmUpFrames; ++frame) ui_->layout(simulation_, comparedRuns());
    }
    glm::vec3 lo, hi;
    sceneBounds(simulation_, lo, hi);
    camera_.fitBox(lo, hi, float(view_.z) / float(view_.w));
    if (plan_.camera && plan_.camera->distance) camera_.distance = float(*plan_.camera->distance);
}

bool sameViews(const WindowLayout& a, const WindowLayout& b) {
    for (int k = 0; k < kMostViews; ++k) {
        if (a.views.views[k] != b.views.views[k] || a.labels[k].min != b.labels[k].min || a.labels[k].size != b.labels[k].size) {
            return false;
        }
    }
    return a.views.count == b.views.count;
}

// Side by side, a label gains a line when a value first wraps (C's "most in one step: 20
// shock levels, 80 rounds" at 2 s, empty at 0): the labels are measured again at every
// frame and the views laid out again where they changed, as the window does, so that no
// label is cut. The manifest gives each frame's views and camera distance.
void Capturer::followLabels() {
    if (!compare_) return;
    compare_->sizeLabels(simulation_, request_);
    const WindowLayout layout = layoutWindow(request_);
    if (!sameViews(layout, layout_)) place(layout);
}

render::Image Capturer::drawFrame() {
    followLabels();
    target_.bind();
    glClearColor(ui::kBackdropColor[0], ui::kBackdropColor[1], ui::kBackdropColor[2], 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    const ui::PanelState view = captureView(colorBy_, plan_.overlays, options_.uiScale.value_or(1.0f),
                                              options_.present, plan_.size.y);
    renderer_.style.overlayOnTop = overlaysOnTop(view, simulation_.world().size());
    // Without samples the outlines are blended as in the window: up to its count of spheres.
    renderer_.style.antialiasEdges = target_.samples() > 0 || outlinesAntialiased(simulation_.world().size());
    buildSnapshot(simulation_, view, snapshot_);
    renderer_.draw(snapshot_, camera_, view_.x, view_.y, view_.z, view_.w);
    uiDrawn_.clear();
    if (compare_) {
        compare_->draw(renderer_, camera_, view, simulation_);
        uiDrawn_ = compare_->labelsDrawn();
    }
    if (ui_) {
        ui_->layout(simulation_, comparedRuns());
        target_.bind();
        for (const glm::vec4& box : ui_->draw()) uiDrawn_.push_back(box);
    }
    if (const GLenum error = glGetError(); error != GL_NO_ERROR) {
        throw std::runtime_error("GL error " + std::to_string(error) + " while drawing a frame");
    }
    return target_.read();
}

void Capturer::writeFrame(int index) {
    const std::string name = frameFileName(index);
    writer_->write((fs::path(options_.out) / name).string(), drawFrame());
    const physics::World& world = simulation_.world();
    frames_.push_back(Json{{"index", index},
                           {"time_s", world.time},
                           {"steps", world.stepCount},
                           {"hash", hashText(physics::stateHash(world))},
                           {"file", name}});
    if (compare_) {  // view B's, and every other view's in order
        const physics::World& other = compare_->comparison().simulation().world();
        frames_.back()["compare_hash"] = hashText(physics::stateHash(other));
        frames_.back()["compare_steps"] = other.stepCount;
        Json hashes = Json::array();
        for (int k = 0; k < compare_->comparison().count(); ++k) {
            hashes.push_back(hashText(physics::stateHash(compare_->comparison().simulation(k).world())));
        }
        frames_.back()["compare_hashes"] = hashes;
        frames_.back()["labels_cut"] = compare_->labelsCut();  // 0: every label's lines in its room
        frames_.back()["label_words_broken"] = compare_->labelWordsBroken();  // 0: every word whole
        Json viewports = Json::array();  // the labels may have moved them since the frame before
        for (int k = 0; k <= compare_->comparison().count(); ++k) {
            const glm::ivec4& v = compare_->view(k);
            viewports.push_back({v.x, v.y, v.z, v.w});
        }
        frames_.back()["viewports"] = viewports;
        frames_.back()["camera_distance_m"] = camera_.distance;
    }
}

Json Capturer::cameraJson() const {
    return Json{{"azimuth_deg", glm::degrees(double(camera_.azimuth))},
                {"elevation_deg", glm::degrees(double(camera_.elevation))},
                {"distance_m", camera_.distance},
                {"target_m", {camera_.target.x, camera_.target.y, camera_.target.z}},
                {"fov_y_deg", glm::degrees(double(camera_.fovY))}};
}

Json Capturer::overlayList() const {
    Json names = Json::array();
    for (const std::string& name : overlayNames(plan_.overlays)) names.push_back(name);
    return names;
}

Json Capturer::manifest() const {
    const scenes::Scene& scene = simulation_.scene();
    Json json{{"scene", scenePath_.empty() ? options_.scene : scenePath_},
                {"title", scenes::withCount(scene.title, scene)},
                {"settings", options_.settings},
                {"parameters", parameterValues(scene)},
                {"seed", scene.seed},
                {"size", {plan_.size.x, plan_.size.y}},
                {"viewport", {view_.x, view_.y, view_.z, view_.w}},
                {"samples", target_.samples()},
                {"with_ui", options_.withUi},
                {"color_by", scenes::kColorByNames[int(colorBy_)]},
                {"overlays", overlayList()},
                {"camera", cameraJson()},
                {"gl",
                 {{"backend", context_->name()},
                  {"renderer", glText(GL_RENDERER)},
                  {"version", glText(GL_VERSION)}}},
                {"frame_s", kCaptureFrameSeconds},
                {"time_scale", simulation_.timeScale},
                {"frames", frames_}};
    Json views = Json::array(), drawn = Json::array();
    for (int k = 0; k < layout_.views.count; ++k) {
        const glm::ivec4& v = layout_.views.views[k];
        views.push_back({v.x, v.y, v.z, v.w});
    }
    for (const glm::vec4& box : uiDrawn_) drawn.push_back({box.x, box.y, box.z, box.w});
    // Every view (px, GL's lower-left origin) and what the panels and labels drew over
    // the last frame (px from the top left): no view may lie under a panel.
    json["layout"] = Json{{"ui_scale", options_.uiScale.value_or(1.0f)}, {"present", options_.present}, {"views", views},
                          {"ui_drawn", drawn}};
    if (compare_) {
        const Comparison& comparison = compare_->comparison();
        const auto viewport = [&](int k) {
            const glm::ivec4& v = compare_->view(k);
            return Json{v.x, v.y, v.z, v.w};
        };
        Json labels = Json::array({comparison.primaryLabel(scene)}), viewports = Json::array({viewport(0)});
        for (int k = 0; k < comparison.count(); ++k) {
            labels.push_back(comparison.label(k));
            viewports.push_back(viewport(k + 1));
        }
        // View B's keys, and every view's (A first) in the lists.
        json["compare"] = Json{{"settings", comparison.overrides()},
                               {"label_a", comparison.primaryLabel(scene)},
                               {"label_b", comparison.label()},
                               {"viewport_b", viewport(1)},
                               {"labels", labels},
                               {"viewports", viewports}};
    }
    return json;
}

int Capturer::run() {
    const auto start = std::chrono::steady_clock::now();
    if (target_.samples() != options_.samples) {  // the manifest records what the images have
        std::printf("samples: %d per pixel (asked %d: %s)\n", target_.samples(), options_.samples,
                    target_.samples() < options_.samples ? "the most this GL gives" : "the nearest count this GL gives");
    }
    int frame = 0;  // frames advanced so far; frame 0 is the initial state
    writer_ = std::make_unique<PngWriter>(std::size_t(4) * plan_.size.x * plan_.size.y);
    {
        ProgressLine progress("frames", static_cast<std::uint64_t>(plan_.frames.back()) + 1);
        for (const int index : plan_.frames) {
            for (; frame < index; ++frame) {
                simulation_.advance(kCaptureFrameSeconds);
                if (compare_) compare_->advance(simulation_, kCaptureFrameSeconds);
                progress.update(static_cast<std::uint64_t>(frame) + 1);
            }
            writeFrame(index);
            progress.update(static_cast<std::uint64_t>(index) + 1);
            if (writer_->failed()) break;
        }
    }
    // A frame or the manifest that cannot be written ends the capture in one line, without
    // a manifest: its absence marks the frames as incomplete.
    const auto notWritten = [](const std::string& path) {
        std::fprintf(stderr, "spheres: %s: cannot be written whole (is the disk full?); the capture stopped\n", path.c_str());
        return 2;
    };
    if (const std::string failed = writer_->finish(); !failed.empty()) return notWritten(failed);
    const std::string path = (fs::path(options_.out) / "manifest.json").string();
    // A file name that is not UTF-8 is written with U+FFFD in its place, not thrown.
    if (!platform::writeWholeFile(path, manifest().dump(2, ' ', false, Json::error_handler_t::replace) + '\n')) {
        return notWritten(path);
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("wrote %zu frame%s to %s in %.2f s (%.1f frames/s)\n", plan_.frames.size(), plan_.frames.size() == 1 ? "" : "s",
                options_.out.c_str(), seconds,
                double(plan_.frames.size()) / std::max(seconds, 1e-9));
    return 0;
}

}  // namespace

int runCapture(const CaptureOptions& options) {
    const CapturePlan plan = planCapture(options);
    scenes::Scene scene = loadSceneWithSettings(options.scene, options.settings);
    checkCompareOption(scene, options.compare);
    // The scale is that of the panel and of the views' labels (the scene's own side by side too).
    if (options.uiScale && !options.withUi && options.compare.empty() && scene.compare.empty())
        throw UsageError("--ui-scale sizes the panel and the views' labels, and this capture draws neither: give --with-ui");
    // A scene it cannot build opens no GL and leaves no folder.
    Simulation simulation = builtWithSettings(options.settings, [&] { return Simulation(std::move(scene)); });
    auto context = openContext(plan.backend, plan.size);
    const std::string backend = std::string(context->name()) + " (" + glText(GL_RENDERER) + ")";
    Capturer capturer(options, plan, std::move(context), std::move(simulation));  // refuses a size too small
    prepareOutFolder(options.out);
    std::printf("GL backend: %s\n", backend.c_str());
    std::fflush(stdout);
    return capturer.run();
}

}  // namespace app
