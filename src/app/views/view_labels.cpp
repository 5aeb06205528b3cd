#include "app/views/view_labels.h"

#include <stdexcept>

#include <imgui.h>

#include "ui/imgui_gl_renderer.h"
#include "ui/ui_font.h"

namespace app {

std::vector<ViewLabel> comparisonLabels(const Simulation& primary, const Comparison& comparison, LabelLines lines) {
    std::vector<ViewLabel> labels;
    std::vector<std::vector<std::string>> readouts = comparisonReadouts(primary, comparison, lines);
    std::vector<std::string> tips = propertiesTooltips(primary, comparison);
    for (std::size_t k = 0; k < readouts.size(); ++k) {
        labels.push_back({glm::vec2(0.0f), glm::vec2(1e6f), std::move(readouts[k]), kViewColors[k], std::move(tips[k])});
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

HeadlessViewLabels::HeadlessViewLabels(glm::ivec2 size, float uiScale) : impl_(std::make_unique<Impl>()) {
    ImGuiContext* previous = ImGui::GetCurrentContext();
    impl_->context = ImGui::CreateContext();
    ImGui::SetCurrentContext(previous);  // CreateContext makes it current when none is
    CurrentContext current(impl_->context);
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.DisplaySize = ImVec2(float(size.x), float(size.y));
    io.DisplayFramebufferScale = ImVec2(1.0f, 1.0f);
    io.DeltaTime = 1.0f / 60.0f;
    ui::applyStyle(uiScale);
    if (const std::string error = impl_->renderer.init(); !error.empty()) throw std::runtime_error("ImGui: " + error);
}

HeadlessViewLabels::~HeadlessViewLabels() {
    ImGuiContext* previous = ImGui::GetCurrentContext();
    ImGui::SetCurrentContext(impl_->context);
    impl_->renderer.shutdown();
    ImGui::DestroyContext(impl_->context);
    ImGui::SetCurrentContext(previous == impl_->context ? nullptr : previous);  // never a destroyed one
}

float HeadlessViewLabels::width(const std::vector<ViewLabel>& labels) {
    CurrentContext current(impl_->context);
    impl_->renderer.newFrame();  // a frame, so that the font is built
    ImGui::NewFrame();
    const float width = labelsWidth(labels);
    ImGui::EndFrame();
    return width;
}

float HeadlessViewLabels::height(const std::vector<ViewLabel>& labels, float width) {
    CurrentContext current(impl_->context);
    impl_->renderer.newFrame();
    ImGui::NewFrame();
    const float height = labelsHeight(labels, width);
    ImGui::EndFrame();
    return height;
}

std::vector<glm::vec4> HeadlessViewLabels::draw(const std::vector<ViewLabel>& labels) {
    CurrentContext current(impl_->context);
    for (int layout = 0; layout < 2; ++layout) {
        impl_->renderer.newFrame();
        if (!impl_->renderer.error().empty()) throw std::runtime_error("ImGui: " + impl_->renderer.error());
        ImGui::NewFrame();
        drawn_ = drawViewLabels(labels);  // the second layout's count: the first measured the frame before
        ImGui::Render();
    }
    impl_->renderer.render(ImGui::GetDrawData());
    return ui::drawnRectangles(*ImGui::GetDrawData());
}

}  // namespace app
