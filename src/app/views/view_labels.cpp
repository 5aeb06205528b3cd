#include "app/views/view_labels.h"

#include <stdexcept>

#include <imgui.h>

#include "app/teaching/impact_report.h"
#include "ui/imgui_gl_renderer.h"
#include "ui/ui_font.h"

namespace app {

std::vector<ViewLabel> comparisonLabels(const Simulation& primary, const Comparison& comparison,
                                        const glm::ivec4 views[kMostViews], glm::ivec2 framebufferSize,
                                        glm::vec2 pixelsPerUnit, glm::vec2 offset, bool atBottom) {
    std::vector<ViewLabel> labels;
    for (int k = 0; k <= comparison.count(); ++k) {
        const Simulation& run = k == 0 ? primary : comparison.simulation(k - 1);
        const std::string title = std::string(1, char('A' + k)) + "   " +
                                  (k == 0 ? comparison.primaryLabel(primary.scene()) : comparison.label(k - 1));
        const physics::World& world = run.world();
        ViewReadout readout{title, physics::measure(world, run.params()), world.time, world.stepCount, ""};
        if (run.impacts().total.contacts > 0) {
            std::vector<physics::MirrorAsymmetry> mirrors;
            for (const physics::Plane& m : run.scene().mirrors) mirrors.push_back(physics::mirrorAsymmetry(world, m));
            readout.properties = propertiesMarks(judgeProperties(run.impacts(), mirrors, run.params()));
        }
        const glm::ivec4& view = views[k];
        const float top = float(framebufferSize.y - (view.y + view.w));  // px from the framebuffer's top
        const glm::vec2 corner(float(view.x), atBottom ? top + float(view.w) : top);
        labels.push_back({corner / pixelsPerUnit + offset, glm::vec2(0.0f, atBottom ? 1.0f : 0.0f),
                          viewReadoutLines(readout), kViewColors[k]});
    }
    return labels;
}

struct HeadlessViewLabels::Impl {
    ImGuiContext* context = nullptr;
    ui::ImGuiGlRenderer renderer;
};

namespace {

// Makes `context` current for a scope, then puts the previous one back.
class CurrentContext {
public:
    explicit CurrentContext(ImGuiContext* context) : previous_(ImGui::GetCurrentContext()) {
        ImGui::SetCurrentContext(context);
    }
    ~CurrentContext() { ImGui::SetCurrentContext(previous_); }
    CurrentContext(const CurrentContext&) = delete;
    CurrentContext& operator=(const CurrentContext&) = delete;

private:
    ImGuiContext* previous_;
};

}  // namespace

HeadlessViewLabels::HeadlessViewLabels(glm::ivec2 size) : impl_(std::make_unique<Impl>()) {
    impl_->context = ImGui::CreateContext();
    CurrentContext current(impl_->context);
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.DisplaySize = ImVec2(float(size.x), float(size.y));
    io.DisplayFramebufferScale = ImVec2(1.0f, 1.0f);
    io.DeltaTime = 1.0f / 60.0f;
    ui::applyStyle(1.0f);
    if (const std::string error = impl_->renderer.init(); !error.empty()) throw std::runtime_error("ImGui: " + error);
}

HeadlessViewLabels::~HeadlessViewLabels() {
    CurrentContext current(impl_->context);
    impl_->renderer.shutdown();
    ImGui::DestroyContext(impl_->context);
}

void HeadlessViewLabels::draw(const std::vector<ViewLabel>& labels) {
    CurrentContext current(impl_->context);
    for (int layout = 0; layout < 2; ++layout) {
        impl_->renderer.newFrame();
        if (!impl_->renderer.error().empty()) throw std::runtime_error("ImGui: " + impl_->renderer.error());
        ImGui::NewFrame();
        drawViewLabels(labels);
        ImGui::Render();
    }
    impl_->renderer.render(ImGui::GetDrawData());
}

}  // namespace app
