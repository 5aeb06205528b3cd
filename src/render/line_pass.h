#pragma once
// Internal to spheres_render: segments and dots as anti-aliased screen-space quads.
#include <string>
#include <vector>

#include "render/frame_context.h"
#include "render/frame_snapshot.h"
#include "render/gl_program.h"

namespace render {

class LinePass {
  public:
    std::string init();
    void destroy();
    // depthBias: NDC depth pulled towards the eye; depthTest false draws on top of all.
    void draw(const std::vector<OverlayLine>& lines, const FrameContext& frame, bool depthTest,
              float depthBias);

  private:
    GlProgram program_;
    GLuint vertexArray_ = 0;
    GLuint cornerBuffer_ = 0;
    GLuint instanceBuffer_ = 0;  // OverlayLine per instance
    GLint viewProjection_ = -1;
    GLint viewportSize_ = -1;
    GLint widthScale_ = -1;
    GLint depthBias_ = -1;
};

// A dot as a zero-length round-capped segment.
OverlayLine pointAsLine(const OverlayPoint& point);

}  // namespace render
