#include "render/plane_pass.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "render/renderer.h"
#include "render/shader_sources.h"

namespace render {

std::string PlanePass::init() {
    std::string error = program_.build("plane", shaders::kPlaneVert, shaders::kPlaneFrag);
    if (!error.empty()) return error;
    viewProjection_ = program_.uniform("uViewProjection");
    color_ = program_.uniform("uColor");
    normal_ = program_.uniform("uNormal");
    lightWorld_ = program_.uniform("uLightWorld");
    grid_ = program_.uniform("uGrid");
    axisU_ = program_.uniform("uAxisU");
    axisV_ = program_.uniform("uAxisV");
    gridSpacing_ = program_.uniform("uGridSpacing");
    majorEvery_ = program_.uniform("uMajorEvery");
    gridColor_ = program_.uniform("uGridColor");

    glGenVertexArrays(1, &vertexArray_);
    glGenBuffers(1, &vertexBuffer_);
    glBindVertexArray(vertexArray_);
    glBindBuffer(GL_ARRAY_BUFFER, vertexBuffer_);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
    glBindVertexArray(0);
    return {};
}

void PlanePass::destroy() {
    program_.destroy();
    if (vertexArray_ != 0) {
        glDeleteBuffers(1, &vertexBuffer_);
        glDeleteVertexArrays(1, &vertexArray_);
    }
    vertexArray_ = vertexBuffer_ = 0;
}

void PlanePass::upload(const std::vector<PlaneFace>& faces) {
    std::vector<glm::vec3> vertices;
    for (const PlaneFace& face : faces) {
        vertices.insert(vertices.end(), face.polygon.begin(), face.polygon.end());
    }
    glBindBuffer(GL_ARRAY_BUFFER, vertexBuffer_);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(glm::vec3)),
                 vertices.data(), GL_STREAM_DRAW);
}

void PlanePass::setFaceUniforms(const PlaneFace& face, const FrameContext& frame) {
    const RenderStyle& style = *frame.style;
    glUniform4fv(color_, 1, glm::value_ptr(face.color));
    glUniform3fv(normal_, 1, glm::value_ptr(face.normal));
    glUniform1i(grid_, face.grid ? 1 : 0);
    if (!face.grid) return;
    // The grid follows the world axes on a level floor (same basis as planeSquare).
    const glm::vec3 helper =
        std::abs(face.normal.z) < 0.9f ? glm::vec3(0.0f, 0.0f, 1.0f) : glm::vec3(1.0f, 0.0f, 0.0f);
    const glm::vec3 u = glm::normalize(glm::cross(helper, face.normal));
    const glm::vec3 v = glm::cross(face.normal, u);
    glUniform3fv(axisU_, 1, glm::value_ptr(u));
    glUniform3fv(axisV_, 1, glm::value_ptr(v));
    glUniform1f(gridSpacing_, style.gridSpacing);
    glUniform1i(majorEvery_, style.gridMajorEvery);
    glUniform4fv(gridColor_, 1, glm::value_ptr(style.gridColor));
}

void PlanePass::draw(const std::vector<PlaneFace>& faces, const FrameContext& frame,
                     bool writeDepth) {
    if (faces.empty()) return;
    upload(faces);
    glEnable(GL_DEPTH_TEST);
    glDepthMask(writeDepth ? GL_TRUE : GL_FALSE);
    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    // Faces sit behind the lines drawn on them by their depth change over ~3 px,
    // so that a 2 px box edge is not cut by the faces meeting there at a slant.
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(3.0f, 4.0f);
    glUseProgram(program_.id());
    glUniformMatrix4fv(viewProjection_, 1, GL_FALSE, glm::value_ptr(frame.viewProjection));
    glUniform3fv(lightWorld_, 1, glm::value_ptr(frame.lightWorld));
    glBindVertexArray(vertexArray_);
    GLint first = 0;
    for (const PlaneFace& face : faces) {
        const auto count = static_cast<GLsizei>(face.polygon.size());
        setFaceUniforms(face, frame);
        glDrawArrays(GL_TRIANGLE_FAN, first, count);
        first += count;
    }
    glBindVertexArray(0);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDisable(GL_BLEND);
}

}  // namespace render
