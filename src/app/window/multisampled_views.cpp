#include "app/window/multisampled_views.h"

#include <algorithm>
#include <cstdio>

#include <glad/gl.h>

namespace app {
namespace {

constexpr int kSamples = 4;       // per pixel of a view's content
constexpr int kContentGrid = 64;  // px: the content's target is rounded out to it

}  // namespace

bool antialiasedAt(std::size_t spheres) { return spheres <= kMostSpheresAntialiased; }

glm::ivec4 roundOutToGrid(const glm::ivec4& rect, int width, int height, int grid) {
    if (rect.z <= 0 || rect.w <= 0) return glm::ivec4(0);
    const int x0 = rect.x / grid * grid;
    const int y0 = rect.y / grid * grid;
    const int x1 = std::min((rect.x + rect.z + grid - 1) / grid * grid, width);
    const int y1 = std::min((rect.y + rect.w + grid - 1) / grid * grid, height);
    return glm::ivec4(x0, y0, x1 - x0, y1 - y0);
}

void MultisampledViews::draw(render::Renderer& renderer, const render::FrameSnapshot& snapshot,
                             const render::Camera& camera, int k, const glm::ivec4& view) {
    if (view.z <= 0 || view.w <= 0) return;
    if (!antialiasedAt(snapshot.sphereCount())) {
        renderer.draw(snapshot, camera, view.x, view.y, view.z, view.w);
        return;
    }
    const glm::ivec4 content =
        straightIn_ ? glm::ivec4(0)
                    : roundOutToGrid(renderer.contentRect(snapshot, camera, view.z, view.w), view.z, view.w, kContentGrid);
    render::OffscreenTarget& target = targets_[k];
    if (!straightIn_ && content.z > 0 && (target.width() != content.z || target.height() != content.w)) {
        if (const std::string error = target.resize(content.z, content.w, kSamples); !error.empty()) {
            std::fprintf(stderr, "spheres: %s; the views are drawn without anti-aliasing\n", error.c_str());
            straightIn_ = true;
            glBindFramebuffer(GL_FRAMEBUFFER, 0);
        }
    }
    if (straightIn_) {
        renderer.draw(snapshot, camera, view.x, view.y, view.z, view.w);
        return;
    }
    if (content.z < view.z || content.w < view.w) renderer.drawBackground(view.x, view.y, view.z, view.w, content);
    if (content.z <= 0 || content.w <= 0) return;
    target.bind();
    renderer.draw(snapshot, camera, -content.x, -content.y, view.z, view.w);  // the view, moved: its content lands in the target
    target.copyTo(0, view.x + content.x, view.y + content.y);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace app
