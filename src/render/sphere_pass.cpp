#include "render/sphere_pass.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <glm/gtc/type_ptr.hpp>

#include "render/renderer.h"
#include "render/shader_sources.h"

namespace render {
namespace {

// Drawing in the order of distance, the runs of point sprites and squares at most this many
// (each a draw call); beyond, every sphere is drawn as a square.
constexpr std::size_t kMostBatches = 64;

constexpr float kCorners[] = {-1.0f, -1.0f, 1.0f, -1.0f, -1.0f, 1.0f, 1.0f, 1.0f};

static_assert(sizeof(SphereInstance) == 20, "SphereInstance must stay tightly packed");

// The sphere attributes at locations 1..3, from a SphereInstance buffer, starting at
// instance `first`.
void sphereAttributes(GLuint buffer, GLuint divisor, std::size_t first = 0) {
    glBindBuffer(GL_ARRAY_BUFFER, buffer);
    const struct {
        GLuint location;
        GLint size;
        GLenum type;
        GLboolean normalized;
        std::size_t offset;
    } attributes[] = {{1, 3, GL_FLOAT, GL_FALSE, offsetof(SphereInstance, center)},
                      {2, 1, GL_FLOAT, GL_FALSE, offsetof(SphereInstance, radius)},
                      {3, 4, GL_UNSIGNED_BYTE, GL_TRUE, offsetof(SphereInstance, color)}};
    for (const auto& a : attributes) {
        glEnableVertexAttribArray(a.location);
        glVertexAttribPointer(a.location, a.size, a.type, a.normalized, sizeof(SphereInstance),
                              reinterpret_cast<const void*>(first * sizeof(SphereInstance) + a.offset));
        glVertexAttribDivisor(a.location, divisor);
    }
}

void upload(GLuint buffer, const std::vector<SphereInstance>& instances) {
    glBindBuffer(GL_ARRAY_BUFFER, buffer);
    glBufferData(GL_ARRAY_BUFFER,
                 static_cast<GLsizeiptr>(instances.size() * sizeof(SphereInstance)),
                 instances.data(), GL_STREAM_DRAW);
}

// The sphere as the pass sees it, with whether it may be a point sprite. A point
// sprite is dropped whole when its centre leaves the viewport, and is limited in
// size: only spheres whose outline (bounded generously) lies inside the viewport,
// beyond the near plane, and small enough, may be one.
ViewSphere viewSphere(std::uint32_t index, const glm::vec3& viewCenter, float radius,
                      const FrameContext& frame, float marginPixels) {
    ViewSphere sphere;
    sphere.index = index;
    sphere.center = viewCenter;
    sphere.radius = radius;
    const float front = -viewCenter.z - radius;  // m, depth of the nearest point
    if (front <= frame.nearPlane * 1.01f) return sphere;
    const glm::vec2 tangent = glm::vec2(viewCenter) / -viewCenter.z;
    // Off-axis outlines stretch by up to 1 / cos^2 of the angle from the axis.
    const float stretch =
        1.0f + glm::dot(glm::vec2(viewCenter), glm::vec2(viewCenter)) / (front * front);
    const float reach = radius / front / frame.pixelSize * stretch + marginPixels + 1.0f;
    const glm::vec2 pixel = tangent / frame.pixelSize + 0.5f * frame.viewportSize;
    sphere.pointSprite = 2.0f * reach <= kMaxPointPixels && pixel.x >= reach && pixel.y >= reach &&
                         pixel.x <= frame.viewportSize.x - reach && pixel.y <= frame.viewportSize.y - reach;
    return sphere;
}

// Bits of the bound draw framebuffer's depth buffer, 0 without one (asked first: the
// size of a missing attachment is a GL error).
int depthBitsOfTarget() {
    GLint framebuffer = 0, type = GL_NONE, bits = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framebuffer);
    const GLenum attachment = framebuffer == 0 ? GL_DEPTH : GL_DEPTH_ATTACHMENT;
    glGetFramebufferAttachmentParameteriv(GL_DRAW_FRAMEBUFFER, attachment,
                                          GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
    if (type == GL_NONE) return 0;
    glGetFramebufferAttachmentParameteriv(GL_DRAW_FRAMEBUFFER, attachment,
                                          GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE, &bits);
    return bits;
}

}  // namespace

std::string SpherePass::buildProgram(Program& p, std::string_view label,
                                     std::string_view vertexSource) {
    std::string error = p.program.build(label, vertexSource, shaders::kSphereFrag);
    if (!error.empty()) return error;
    p.view = p.program.uniform("uView");
    p.projection = p.program.uniform("uProjection");
    p.pixelSize = p.program.uniform("uPixelSize");
    p.viewportSize = p.program.uniform("uViewportSize");
    p.marginPixels = p.program.uniform("uMarginPixels");
    p.viewport = p.program.uniform("uViewport");
    p.lightDirection = p.program.uniform("uLightDirection");
    p.upDirection = p.program.uniform("uUpDirection");
    p.coverageAlpha = p.program.uniform("uCoverageAlpha");
    p.part = p.program.uniform("uPart");
    return {};
}

std::string SpherePass::init() {
    std::string error = buildProgram(pointProgram_, "sphere point", shaders::kSpherePointVert);
    if (error.empty()) error = buildProgram(quadProgram_, "sphere square", shaders::kSphereVert);
    if (!error.empty()) return error;

    GLuint arrays[2];
    GLuint buffers[3];
    glGenVertexArrays(2, arrays);
    glGenBuffers(3, buffers);
    pointArray_ = arrays[0];
    quadArray_ = arrays[1];
    cornerBuffer_ = buffers[0];
    pointBuffer_ = buffers[1];
    quadBuffer_ = buffers[2];

    glBindVertexArray(pointArray_);
    sphereAttributes(pointBuffer_, 0);
    glBindVertexArray(quadArray_);
    glBindBuffer(GL_ARRAY_BUFFER, cornerBuffer_);
    glBufferData(GL_ARRAY_BUFFER, sizeof kCorners, kCorners, GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, nullptr);
    sphereAttributes(quadBuffer_, 1);
    glBindVertexArray(0);
    return {};
}

void SpherePass::destroy() {
    pointProgram_.program.destroy();
    quadProgram_.program.destroy();
    const GLuint arrays[] = {pointArray_, quadArray_};
    const GLuint buffers[] = {cornerBuffer_, pointBuffer_, quadBuffer_};
    if (pointArray_ != 0) {
        glDeleteBuffers(3, buffers);
        glDeleteVertexArrays(2, arrays);
    }
    pointArray_ = quadArray_ = cornerBuffer_ = pointBuffer_ = quadBuffer_ = 0;
}

// Distance from the eye, squared, less the radius squared (m^2): the power of the eye
// with respect to the sphere. Spheres that do not overlap are seen in front of each
// other in the order of it, whatever their radii.
// A sphere not finite (a blow-up, paused by its alarm) goes first: a NaN key would break
// the sort's order for the others.
float powerFromEye(const ViewSphere& sphere) {
    const float power = glm::dot(sphere.center, sphere.center) - sphere.radius * sphere.radius;
    return std::isfinite(power) ? power : INFINITY;
}

void SpherePass::partition(const FrameSnapshot& snapshot, const FrameContext& frame,
                           float marginPixels, SphereEdges edges, const std::vector<glm::vec4>& translucent) {
    inView_.clear();
    const std::size_t count =
        std::min({snapshot.centers.size(), snapshot.radii.size(), snapshot.colors.size()});
    for (std::size_t i = 0; i < count; ++i) {
        const glm::vec3 viewCenter(frame.view * glm::vec4(snapshot.centers[i], 1.0f));
        if (viewCenter.z + snapshot.radii[i] >= 0.0f) continue;  // wholly behind the eye
        inView_.push_back(viewSphere(std::uint32_t(i), viewCenter, snapshot.radii[i], frame, marginPixels));
    }
    if (cullHidden) hiddenSpheres_.find(inView_, frame, edges != SphereEdges::Hard, depthBitsOfTarget());
    const bool inOrder = edges == SphereEdges::Blended;
    if (inOrder) {
        // The power's order is a strict one on distinct spheres; equal keys keep the
        // snapshot's order, so the image does not depend on the sort.
        std::stable_sort(inView_.begin(), inView_.end(), [](const ViewSphere& a, const ViewSphere& b) {
            return powerFromEye(a) > powerFromEye(b);
        });
    }
    // Behind a translucent plane: the eye and the centre on its two sides. Those first.
    const auto behind = [&](const ViewSphere& sphere) {
        const glm::vec4 c(snapshot.centers[sphere.index], 1.0f), eye(frame.cameraPosition, 1.0f);
        return std::any_of(translucent.begin(), translucent.end(),
                           [&](const glm::vec4& plane) { return glm::dot(plane, c) * glm::dot(plane, eye) < 0.0f; });
    };
    const auto firstInFront =
        inOrder ? std::stable_partition(inView_.begin(), inView_.end(), behind) : inView_.end();
    batch(snapshot, inOrder, firstInFront);
}

// points_, quads_ and batches_ from inView_'s spheres not hidden: in inView_'s order, in runs
// of point sprites and squares (inOrder), else all the points, then all the squares.
void SpherePass::batch(const FrameSnapshot& snapshot, bool inOrder, std::vector<ViewSphere>::const_iterator firstInFront) {
    const auto instance = [&](const ViewSphere& sphere) {
        return SphereInstance{snapshot.centers[sphere.index], snapshot.radii[sphere.index], snapshot.colors[sphere.index]};
    };
    points_.clear();
    quads_.clear();
    batches_.clear();
    frontBatches_ = 0;
    for (auto it = inView_.cbegin(); it != inView_.cend(); ++it) {
        if (it == firstInFront) frontBatches_ = batches_.size();
        if (it->hidden) continue;
        std::vector<SphereInstance>& instances = it->pointSprite ? points_ : quads_;
        if (inOrder && (batches_.empty() || batches_.back().pointSprites != it->pointSprite || it == firstInFront)) {
            batches_.push_back({it->pointSprite, instances.size(), 0});
        }
        if (inOrder) ++batches_.back().count;
        instances.push_back(instance(*it));
    }
    if (!inOrder) batches_ = {{true, 0, points_.size()}, {false, 0, quads_.size()}};
    if (firstInFront == inView_.cend()) frontBatches_ = batches_.size();
    if (batches_.size() <= kMostBatches) return;
    // Points and squares alternate in the order (a close view, spheres across the viewport's
    // edge): every sphere a square, in the same order, in two draws at most.
    points_.clear();
    quads_.clear();
    std::size_t behindCount = 0;
    for (auto it = inView_.cbegin(); it != inView_.cend(); ++it) {
        if (it->hidden) continue;
        behindCount += it < firstInFront;
        quads_.push_back(instance(*it));
    }
    batches_ = {{false, 0, behindCount}, {false, behindCount, quads_.size() - behindCount}};
    frontBatches_ = 1;
}

bool SpherePass::hidesMark(const OverlayLine& line, const FrameContext& frame, float depthBias) const {
    if (!cullHidden) return false;
    const glm::vec3 a(frame.view * glm::vec4(line.a, 1.0f)), b(frame.view * glm::vec4(line.b, 1.0f));  // m
    const float reach = 0.5f * line.width * frame.style->lineScale + 1.0f;  // px, as line.vert's
    return hiddenSpheres_.hidesMark(a, b, reach, depthBias);
}

void SpherePass::setUniforms(const Program& p, const FrameContext& frame, float marginPixels,
                             bool coverageAlpha) {
    glUseProgram(p.program.id());
    glUniformMatrix4fv(p.view, 1, GL_FALSE, glm::value_ptr(frame.view));
    glUniformMatrix4fv(p.projection, 1, GL_FALSE, glm::value_ptr(frame.projection));
    glUniform1f(p.pixelSize, frame.pixelSize);
    glUniform2fv(p.viewportSize, 1, glm::value_ptr(frame.viewportSize));
    glUniform1f(p.marginPixels, marginPixels);
    glUniform4fv(p.viewport, 1, glm::value_ptr(frame.viewport));
    glUniform3fv(p.lightDirection, 1, glm::value_ptr(frame.lightView));
    glUniform3fv(p.upDirection, 1, glm::value_ptr(frame.upView));
    glUniform1i(p.coverageAlpha, coverageAlpha ? 1 : 0);
    glUniform1i(p.part, 0);
}

void SpherePass::drawBatch(bool pointSprites, std::size_t first, std::size_t count) {
    if (count == 0) return;
    if (pointSprites) {
        glDrawArrays(GL_POINTS, GLint(first), GLsizei(count));
    } else {  // GL 3.3 has no base instance: the attributes start at the first
        sphereAttributes(quadBuffer_, 1, first);
        glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, GLsizei(count));
    }
}

void SpherePass::drawBatches(int part, std::size_t first, std::size_t end) {
    for (std::size_t b = first; b < end; ++b) {
        const Batch& batch = batches_[b];
        const Program& program = batch.pointSprites ? pointProgram_ : quadProgram_;
        glUseProgram(program.program.id());
        glUniform1i(program.part, part);
        glBindVertexArray(batch.pointSprites ? pointArray_ : quadArray_);
        drawBatch(batch.pointSprites, batch.first, batch.count);
    }
}

void SpherePass::beginState(SphereEdges edges) const {
    glEnable(GL_DEPTH_TEST);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
#ifndef __EMSCRIPTEN__  // WebGL 2: a vertex shader always sets the point size
    glEnable(GL_PROGRAM_POINT_SIZE);
#endif
    // The target keeps the background's alpha of 1.
    if (edges != SphereEdges::Hard) glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);
    if (edges == SphereEdges::AlphaToCoverage) glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    if (edges == SphereEdges::Blended) {
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    }
}

void SpherePass::endState() const {
    glBindVertexArray(0);
#ifndef __EMSCRIPTEN__
    glDisable(GL_PROGRAM_POINT_SIZE);
#endif
    glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

void SpherePass::draw(const FrameSnapshot& snapshot, const FrameContext& frame, SphereEdges edges,
                      const std::vector<glm::vec4>& translucent) {
    // Coverage needs fragments up to a pixel and a half outside the outline, px.
    const bool coverage = edges != SphereEdges::Hard;
    const float marginPixels = coverage ? 1.5f : 0.5f;
    const bool split = edges == SphereEdges::Blended && !translucent.empty();
    partition(snapshot, frame, marginPixels, edges, split ? translucent : std::vector<glm::vec4>{});
    if (!split) frontBatches_ = batches_.size();  // every edge now
    if (points_.empty() && quads_.empty()) return;
    beginState(edges);
    upload(pointBuffer_, points_);
    upload(quadBuffer_, quads_);
    setUniforms(pointProgram_, frame, marginPixels, coverage);
    setUniforms(quadProgram_, frame, marginPixels, coverage);
    if (split) {
        drawBatches(1, 0, batches_.size());  // the whole pixels, writing depth
        glDepthMask(GL_FALSE);               // then the edges behind the planes, depth-tested only
        drawBatches(2, 0, frontBatches_);
    } else {
        drawBatches(0, 0, batches_.size());
    }
    endState();
}

void SpherePass::drawFrontEdges() {
    if (frontBatches_ >= batches_.size()) return;
    beginState(SphereEdges::Blended);  // the uniforms stay set since draw()
    glDepthMask(GL_FALSE);
    drawBatches(2, frontBatches_, batches_.size());
    endState();
}

}  // namespace render
