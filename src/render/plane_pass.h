#pragma once
// Internal to spheres_render: clipped plane polygons as flat, faintly lit faces.
#include <glm/vec4.hpp>
#include <string>
#include <vector>

#include "render/frame_context.h"
#include "render/gl_program.h"
#include "render/plane_clipping.h"

namespace render {

struct PlaneFace {
    Polygon polygon;                     // m, convex
    glm::vec3 normal{0.0f, 0.0f, 1.0f};  // unit, world
    glm::vec4 color{1.0f};               // rgb and opacity
    bool grid = false;
};

class PlanePass {
  public:
    std::string init();
    void destroy();
    // writeDepth: opaque-ish faces that hide what is behind them (floor, far walls).
    void draw(const std::vector<PlaneFace>& faces, const FrameContext& frame, bool writeDepth);

  private:
    void upload(const std::vector<PlaneFace>& faces);
    void setFaceUniforms(const PlaneFace& face, const FrameContext& frame);

    GlProgram program_;
    GLuint vertexArray_ = 0;
    GLuint vertexBuffer_ = 0;
    GLint viewProjection_ = -1;
    GLint color_ = -1;
    GLint normal_ = -1;
    GLint lightWorld_ = -1;
    GLint grid_ = -1;
    GLint axisU_ = -1;
    GLint axisV_ = -1;
    GLint gridSpacing_ = -1;
    GLint majorEvery_ = -1;
    GLint gridColor_ = -1;
};

}  // namespace render
