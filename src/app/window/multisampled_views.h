#pragma once
// The window's views, anti-aliased at a software GL's price. The window itself has no
// multisampling (the panel needs none, and a software GL resolves every pixel of a
// multisampled window at each swap); each view paints its background straight into
// the window and draws only the part that holds more (planes, spheres, lines) into a
// 4x multisampled target of that size, resolved into place. A view of more than
// kMostSpheresAntialiased spheres is drawn straight in: a software GL's samples cost
// as much again as the spheres at 10k (llvmpipe, 1280 x 720: 7 ms a frame without,
// 15 ms with 4 samples), and the window is to keep 30 frames per second there.
#include <cstddef>
#include <string>

#include <glm/vec4.hpp>

#include "app/run/comparison.h"
#include "render/camera.h"
#include "render/frame_snapshot.h"
#include "render/offscreen_target.h"
#include "render/renderer.h"

namespace app {

constexpr std::size_t kMostSpheresAntialiased = 5000;
// Whether a view of this many spheres is drawn anti-aliased (multisampled).
bool antialiasedAt(std::size_t spheres);

class MultisampledViews {
public:
    // View k's snapshot into `view` (px, GL's lower-left origin) of the window's
    // framebuffer, which must be bound. Without a multisampled target (the GL cannot
    // make one) every view is drawn straight in, once said on stderr.
    void draw(render::Renderer& renderer, const render::FrameSnapshot& snapshot, const render::Camera& camera, int k,
              const glm::ivec4& view);

private:
    render::OffscreenTarget targets_[kMostViews];
    bool straightIn_ = false;  // no target could be made
};

// `rect` (px in a view of width x height) rounded out to a grid of `grid` px: the target
// is made again only when the content crosses a line of it, and it starts on even
// pixels, as the shaders' 2 x 2 blocks do. A zero rectangle stays zero.
glm::ivec4 roundOutToGrid(const glm::ivec4& rect, int width, int height, int grid);

}  // namespace app
