#include "render/background_pass.h"

#include <glm/gtc/type_ptr.hpp>

#include "render/renderer.h"
#include "render/shader_sources.h"

namespace render {

std::string BackgroundPass::init() {
    std::string error =
        program_.build("background", shaders::kBackgroundVert, shaders::kBackgroundFrag);
    if (!error.empty()) return error;
    top_ = program_.uniform("uTop");
    bottom_ = program_.uniform("uBottom");
    glGenVertexArrays(1, &vertexArray_);
    return {};
}

void BackgroundPass::destroy() {
    program_.destroy();
    if (vertexArray_ != 0) glDeleteVertexArrays(1, &vertexArray_);
    vertexArray_ = 0;
}

void BackgroundPass::draw(const FrameContext& frame) {
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glDisable(GL_BLEND);
    glUseProgram(program_.id());
    glUniform3fv(top_, 1, glm::value_ptr(frame.style->backgroundTop));
    glUniform3fv(bottom_, 1, glm::value_ptr(frame.style->backgroundBottom));
    glBindVertexArray(vertexArray_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

}  // namespace render
