#include "render/line_pass.h"

#include <cstddef>
#include <glm/gtc/type_ptr.hpp>

#include "render/renderer.h"
#include "render/shader_sources.h"

namespace render {
namespace {

// x: 0 at a, 1 at b; y: side of the axis.
constexpr float kCorners[] = {0.0f, -1.0f, 1.0f, -1.0f, 0.0f, 1.0f, 1.0f, 1.0f};

// OverlayLine is uploaded as it is: its layout is the instance layout.
static_assert(sizeof(OverlayLine) == 32, "OverlayLine must stay tightly packed");

void lineAttribute(GLuint location, GLint size, GLenum type, GLboolean normalized,
                   std::size_t offset) {
    glEnableVertexAttribArray(location);
    glVertexAttribPointer(location, size, type, normalized, sizeof(OverlayLine),
                          reinterpret_cast<const void*>(offset));
    glVertexAttribDivisor(location, 1);
}

}  // namespace

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
    lineAttribute(1, 3, GL_FLOAT, GL_FALSE, offsetof(OverlayLine, a));
    lineAttribute(2, 3, GL_FLOAT, GL_FALSE, offsetof(OverlayLine, b));
    lineAttribute(3, 4, GL_UNSIGNED_BYTE, GL_TRUE, offsetof(OverlayLine, color));
    lineAttribute(4, 1, GL_FLOAT, GL_FALSE, offsetof(OverlayLine, width));
    glBindVertexArray(0);
    return {};
}

void LinePass::destroy() {
    program_.destroy();
    if (vertexArray_ != 0) {
        glDeleteBuffers(1, &cornerBuffer_);
        glDeleteBuffers(1, &instanceBuffer_);
        glDeleteVertexArrays(1, &vertexArray_);
    }
    vertexArray_ = cornerBuffer_ = instanceBuffer_ = 0;
}

void LinePass::draw(const std::vector<OverlayLine>& lines, const FrameContext& frame,
                    bool depthTest, float depthBias) {
    if (lines.empty()) return;
    glBindBuffer(GL_ARRAY_BUFFER, instanceBuffer_);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(lines.size() * sizeof(OverlayLine)),
                 lines.data(), GL_STREAM_DRAW);
    if (depthTest) {
        glEnable(GL_DEPTH_TEST);
    } else {
        glDisable(GL_DEPTH_TEST);
    }
    glDepthMask(GL_FALSE);
    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glUseProgram(program_.id());
    glUniformMatrix4fv(viewProjection_, 1, GL_FALSE, glm::value_ptr(frame.viewProjection));
    glUniform2fv(viewportSize_, 1, glm::value_ptr(frame.viewportSize));
    glUniform1f(widthScale_, frame.style->lineScale);
    glUniform1f(depthBias_, depthBias);
    glBindVertexArray(vertexArray_);
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(lines.size()));
    glBindVertexArray(0);
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
}

}  // namespace render
