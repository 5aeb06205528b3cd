#pragma once
// Internal to spheres_render: segments as anti-aliased screen-space quads, dots as
// anti-aliased points.
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
    // Dots, one point each (dot.vert), with the same blending and depth as draw().
    void drawDots(const std::vector<OverlayPoint>& dots, const FrameContext& frame, bool depthTest,
                  float depthBias);

  private:
    std::string initDots();

    GlProgram program_;
    GLuint vertexArray_ = 0;
    GLuint cornerBuffer_ = 0;
    GLuint instanceBuffer_ = 0;  // OverlayLine per instance
    GLint viewProjection_ = -1;
    GLint viewportSize_ = -1;
    GLint widthScale_ = -1;
    GLint depthBias_ = -1;
    GlProgram dotProgram_;
    GLuint dotVertexArray_ = 0;
    GLuint dotBuffer_ = 0;  // OverlayPoint per instance
    GLint dotViewProjection_ = -1;
    GLint dotWidthScale_ = -1;
    GLint dotDepthBias_ = -1;
};

// Whether a dot may be drawn as a point: its whole disc inside the viewport (a point whose
// centre leaves it is clipped whole) and not larger than kMaxPointPixels.
bool fitsAsPoint(const OverlayPoint& dot, const FrameContext& frame);
// A dot as a zero-length round-capped segment: where it does not fit as a point, and for
// the culling of hidden marks.
OverlayLine pointAsLine(const OverlayPoint& point);

}  // namespace render
