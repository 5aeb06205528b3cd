#include "render/line_pass.h"

#include <cstddef>
#include <glm/gtc/type_ptr.hpp>

#include "render/renderer.h"
#include "render/shader_sources.h"

namespace render {
namespace {

// x: 0 at a, 1 at b; y: side of the axis.
constexpr float kCorners[] = {0.0f, -1.0f, 1.0f, -1.0f, 0.0f, 1.0f, 1.0f, 1.0f};

// OverlayLine and OverlayPoint are uploaded as they are: their layouts are the instance
// layouts.
static_assert(sizeof(OverlayLine) == 32, "OverlayLine must stay tightly packed");
static_assert(sizeof(OverlayPoint) == 20, "OverlayPoint must stay tightly packed");

template <typename Instance>
void instanceAttribute(GLuint location, GLint size, GLenum type, GLboolean normalized, std::size_t offset) {
    glEnableVertexAttribArray(location);
    glVertexAttribPointer(location, size, type, normalized, sizeof(Instance), reinterpret_cast<const void*>(offset));
    glVertexAttribDivisor(location, 1);
}

// Blending over the scene, depth-tested (or on top of all), the depth never written.
void beginMarks(bool depthTest) {
    if (depthTest) {
        glEnable(GL_DEPTH_TEST);
    } else {
        glDisable(GL_DEPTH_TEST);
    }
    glDepthMask(GL_FALSE);
    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
}

void endMarks() {
    glBindVertexArray(0);
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
}

}  // namespace

bool fitsAsPoint(const OverlayPoint& dot, const FrameContext& frame) {
    const glm::vec4 clip = frame.viewProjection * glm::vec4(dot.position, 1.0f);
    if (!(clip.w > frame.nearPlane)) return false;
    const float reach = 0.5f * dot.size * frame.style->lineScale + 1.0f;  // px, dot.vert's half size
    const glm::vec2 pixel = (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * frame.viewportSize;
    return 2.0f * reach <= kMaxPointPixels && pixel.x >= reach && pixel.y >= reach &&
           pixel.x <= frame.viewportSize.x - reach && pixel.y <= frame.viewportSize.y - reach;
}

OverlayLine pointAsLine(const OverlayPoint& point) {
    return {point.position, point.position, point.color, point.size};
}

std::string LinePass::init() {
    std::string error = program_.build("line", shaders::kLineVert, shaders::kLineFrag);
    if (!error.empty()) return error;
    viewProjection_ = program_.uniform("uViewProjection");
    viewportSize_ = program_.uniform("uViewportSize");
    widthScale_ = program_.uniform("uWidthScale");
    depthBias_ = program_.uniform("uDepthBias");

    glGenVertexArrays(1, &vertexArray_);
    glGenBuffers(1, &cornerBuffer_);
    glGenBuffers(1, &instanceBuffer_);
    glBindVertexArray(vertexArray_);
    glBindBuffer(GL_ARRAY_BUFFER, cornerBuffer_);
    glBufferData(GL_ARRAY_BUFFER, sizeof kCorners, kCorners, GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, nullptr);
    glBindBuffer(GL_ARRAY_BUFFER, instanceBuffer_);
    instanceAttribute<OverlayLine>(1, 3, GL_FLOAT, GL_FALSE, offsetof(OverlayLine, a));
    instanceAttribute<OverlayLine>(2, 3, GL_FLOAT, GL_FALSE, offsetof(OverlayLine, b));
    instanceAttribute<OverlayLine>(3, 4, GL_UNSIGNED_BYTE, GL_TRUE, offsetof(OverlayLine, color));
    instanceAttribute<OverlayLine>(4, 1, GL_FLOAT, GL_FALSE, offsetof(OverlayLine, width));
    glBindVertexArray(0);
    return initDots();
}

std::string LinePass::initDots() {
    std::string error = dotProgram_.build("dot", shaders::kDotVert, shaders::kDotFrag);
    if (!error.empty()) return error;
    dotViewProjection_ = dotProgram_.uniform("uViewProjection");
    dotWidthScale_ = dotProgram_.uniform("uWidthScale");
    dotDepthBias_ = dotProgram_.uniform("uDepthBias");
    glGenVertexArrays(1, &dotVertexArray_);
    glGenBuffers(1, &dotBuffer_);
    glBindVertexArray(dotVertexArray_);
    glBindBuffer(GL_ARRAY_BUFFER, dotBuffer_);
    instanceAttribute<OverlayPoint>(1, 3, GL_FLOAT, GL_FALSE, offsetof(OverlayPoint, position));
    instanceAttribute<OverlayPoint>(2, 4, GL_UNSIGNED_BYTE, GL_TRUE, offsetof(OverlayPoint, color));
    instanceAttribute<OverlayPoint>(3, 1, GL_FLOAT, GL_FALSE, offsetof(OverlayPoint, size));
    glBindVertexArray(0);
    return {};
}

void LinePass::destroy() {
    program_.destroy();
    dotProgram_.destroy();
    if (vertexArray_ != 0) {
        glDeleteBuffers(1, &cornerBuffer_);
        glDeleteBuffers(1, &instanceBuffer_);
        glDeleteVertexArrays(1, &vertexArray_);
    }
    if (dotVertexArray_ != 0) {
        glDeleteBuffers(1, &dotBuffer_);
        glDeleteVertexArrays(1, &dotVertexArray_);
    }
    vertexArray_ = cornerBuffer_ = instanceBuffer_ = dotVertexArray_ = dotBuffer_ = 0;
}

void LinePass::draw(const std::vector<OverlayLine>& lines, const FrameContext& frame,
                    bool depthTest, float depthBias) {
    if (lines.empty()) return;
    glBindBuffer(GL_ARRAY_BUFFER, instanceBuffer_);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(lines.size() * sizeof(OverlayLine)),
                 lines.data(), GL_STREAM_DRAW);
    beginMarks(depthTest);
    glUseProgram(program_.id());
    glUniformMatrix4fv(viewProjection_, 1, GL_FALSE, glm::value_ptr(frame.viewProjection));
    glUniform2fv(viewportSize_, 1, glm::value_ptr(frame.viewportSize));
    glUniform1f(widthScale_, frame.style->lineScale);
    glUniform1f(depthBias_, depthBias);
    glBindVertexArray(vertexArray_);
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(lines.size()));
    endMarks();
}

void LinePass::drawDots(const std::vector<OverlayPoint>& dots, const FrameContext& frame, bool depthTest,
                        float depthBias) {
    if (dots.empty()) return;
    glBindBuffer(GL_ARRAY_BUFFER, dotBuffer_);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(dots.size() * sizeof(OverlayPoint)), dots.data(),
                 GL_STREAM_DRAW);
    beginMarks(depthTest);
#ifndef __EMSCRIPTEN__  // WebGL 2: a vertex shader always sets the point size
    glEnable(GL_PROGRAM_POINT_SIZE);
#endif
    glUseProgram(dotProgram_.id());
    glUniformMatrix4fv(dotViewProjection_, 1, GL_FALSE, glm::value_ptr(frame.viewProjection));
    glUniform1f(dotWidthScale_, frame.style->lineScale);
    glUniform1f(dotDepthBias_, depthBias);
    glBindVertexArray(dotVertexArray_);
    glDrawArraysInstanced(GL_POINTS, 0, 1, static_cast<GLsizei>(dots.size()));
    endMarks();
}

}  // namespace render
