#include "app/views/view_layout.h"

#include <algorithm>

#include "app/run/comparison.h"
#include "app/views/frame_builder.h"

namespace app {

int ViewLayout::viewAt(glm::vec2 mouse) const {
    const glm::vec2 pixel(mouse.x * pixelsPerUnit.x, float(framebuffer.y) - mouse.y * pixelsPerUnit.y);  // GL's origin
    for (int k = 0; k < count; ++k) {
        const glm::ivec4& v = views[k];
        if (pixel.x >= float(v.x) && pixel.x < float(v.x + v.z) && pixel.y >= float(v.y) && pixel.y < float(v.y + v.w)) {
            return k;
        }
    }
    return -1;
}

glm::vec2 ViewLayout::pixelIn(int view, glm::vec2 mouse) const {
    const glm::ivec4& v = views[view >= 0 && view < count ? view : 0];
    const float top = float(framebuffer.y - (v.y + v.w));  // the view's top row, from the framebuffer's top
    return {mouse.x * pixelsPerUnit.x - float(v.x), mouse.y * pixelsPerUnit.y - top};
}

render::Ray ViewLayout::ray(const render::Camera& camera, int view, glm::vec2 mouse) const {
    const glm::ivec4& v = views[view >= 0 && view < count ? view : 0];
    return camera.rayThroughPixel(pixelIn(view, mouse), glm::vec2(v.z, v.w));
}

float ViewLayout::aspect() const { return views[0].w > 0 ? float(views[0].z) / float(views[0].w) : 1.0f; }

ViewLayout layoutViews(glm::ivec2 framebuffer, glm::vec2 pixelsPerUnit, float panelUnits, float barUnits, int count,
                       int gap) {
    ViewLayout layout;
    layout.framebuffer = framebuffer;
    layout.pixelsPerUnit = pixelsPerUnit;
    glm::ivec4 scene = viewportRightOf(framebuffer, panelUnits * pixelsPerUnit.x);
    const int bar = std::clamp(static_cast<int>(barUnits * pixelsPerUnit.y + 0.5f), 0, std::max(framebuffer.y - 1, 0));
    scene.y += bar;
    scene.w = std::max(scene.w - bar, 1);
    layout.count = std::clamp(count, 1, kMostViews);
    splitViewport(scene, gap, layout.count, layout.views);
    return layout;
}

}  // namespace app
