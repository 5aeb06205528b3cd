#include "render/renderer.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "render/background_pass.h"
#include "render/line_pass.h"
#include "render/plane_clipping.h"
#include "render/plane_pass.h"
#include "render/sphere_pass.h"

namespace render {
namespace {

// Key light from the upper left, slightly behind the viewer (view space).
const glm::vec3 kLightView = glm::normalize(glm::vec3(-0.45f, 0.65f, 0.62f));
// NDC depth by which lines are pulled towards the eye, so lines on faces win.
constexpr float kLineDepthBias = 2e-5f;

FrameContext makeFrameContext(const Camera& camera, int x, int y, int width, int height,
                              const RenderStyle& style) {
    FrameContext frame;
    frame.viewport = glm::vec4(x, y, width, height);
    frame.nearPlane = camera.nearPlane();
    frame.farPlane = camera.farPlane();
    frame.view = camera.view();
    frame.projection = camera.projection(static_cast<float>(width) / static_cast<float>(height));
    frame.viewProjection = frame.projection * frame.view;
    frame.cameraPosition = camera.position();
    frame.viewportSize = glm::vec2(static_cast<float>(width), static_cast<float>(height));
    frame.pixelSize = 2.0f * std::tan(0.5f * camera.fovY) / static_cast<float>(height);
    frame.lightView = kLightView;
    // The view matrix is a rotation plus a translation: its transpose inverts the rotation.
    const glm::mat3 rotation(frame.view);
    frame.lightWorld = glm::transpose(rotation) * kLightView;
    frame.upView = rotation * glm::vec3(0.0f, 0.0f, 1.0f);
    frame.style = &style;
    return frame;
}

void appendOutline(const Polygon& polygon, const RenderStyle& style,
                   std::vector<OverlayLine>& lines) {
    const glm::u8vec4 color(glm::clamp(style.edgeColor, 0.0f, 1.0f) * 255.0f + 0.5f);
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        lines.push_back({polygon[i], polygon[(i + 1) % polygon.size()], color, style.edgeWidth});
    }
}

// The planes sorted by how they are drawn this frame.
struct PlaneDrawList {
    std::vector<PlaneFace> farFaces;    // the floor and the box walls the camera looks at
    std::vector<PlaneFace> extraFaces;  // other planes (an incline): translucent, after spheres
    std::vector<OverlayLine> edges;     // every box edge (near walls included), extra outlines
};

PlaneDrawList collectPlanes(const FrameSnapshot& snapshot, const RenderStyle& style,
                            const glm::vec3& cameraPosition) {
    PlaneDrawList list;
    const std::vector<Polygon> polygons = planePolygons(snapshot);
    const int floor = style.showGrid ? floorPlaneIndex(snapshot) : -1;
    const bool hasBox = snapshot.boxPlaneCount > 0;
    for (std::size_t i = 0; i < polygons.size(); ++i) {
        const bool inBox = static_cast<int>(i) < snapshot.boxPlaneCount;
        const bool isFloor = static_cast<int>(i) == floor;
        if (polygons[i].empty() || (inBox && !style.showBox)) continue;
        const Plane& plane = snapshot.planes[i];
        const glm::vec3 normal = glm::normalize(plane.normal);
        // Without a box, a ground plane's outline is only where the cube cut it.
        if (inBox || hasBox) appendOutline(polygons[i], style, list.edges);
        if (!inBox && !isFloor) {
            list.extraFaces.push_back({polygons[i], normal, style.extraPlaneColor, false});
        } else if (!isNearPlane(plane, cameraPosition)) {
            list.farFaces.push_back(
                {polygons[i], normal, isFloor ? style.floorColor : style.wallColor, isFloor});
        }
    }
    return list;
}

// Confines drawing to the viewport and clears its depth only, so that several
// views can share one framebuffer.
void beginViewport(int x, int y, int width, int height) {
    glViewport(x, y, width, height);
    glEnable(GL_SCISSOR_TEST);
    glScissor(x, y, width, height);
    glDepthMask(GL_TRUE);
    glClear(GL_DEPTH_BUFFER_BIT);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE);
}

// Whether the GL draws on the CPU, by its renderer string.
bool softwareRasterizer() {
    const auto* name = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    if (name == nullptr) return false;
    const std::string renderer = name;
    for (const char* software : {"llvmpipe", "softpipe", "SwiftShader", "Software Rasterizer"}) {
        if (renderer.find(software) != std::string::npos) return true;
    }
    return false;
}

}  // namespace

struct Renderer::Passes {
    BackgroundPass background;
    PlanePass planes;
    SpherePass spheres;
    LinePass lines;
    std::vector<OverlayLine> overlay;   // the last draw's overlay lines, those not hidden
    std::vector<OverlayPoint> dots;     // and its dots
};

Renderer::Renderer() = default;
Renderer::~Renderer() { shutdown(); }

std::string Renderer::init() {
    shutdown();
    passes_ = std::make_unique<Passes>();
    for (std::string error : {passes_->background.init(), passes_->planes.init(),
                              passes_->spheres.init(), passes_->lines.init()}) {
        if (!error.empty()) {
            shutdown();
            return error;
        }
    }
    cullHiddenSpheres = softwareRasterizer();
    return {};
}

std::size_t Renderer::drawnSpheres() const { return passes_ ? passes_->spheres.drawnSpheres() : 0; }
std::size_t Renderer::drawnMarks() const { return passes_ ? passes_->overlay.size() + passes_->dots.size() : 0; }

void Renderer::shutdown() {
    if (!passes_) return;
    passes_->background.destroy();
    passes_->planes.destroy();
    passes_->spheres.destroy();
    passes_->lines.destroy();
    passes_.reset();
}

int floorPlaneIndex(const FrameSnapshot& snapshot) {
    const int count = snapshot.boxPlaneCount > 0 ? snapshot.boxPlaneCount
                                                 : static_cast<int>(snapshot.planes.size());
    int best = -1;
    float bestUp = 0.5f;  // a floor must face upwards at least 60 degrees from vertical
    for (int i = 0; i < count && i < static_cast<int>(snapshot.planes.size()); ++i) {
        const float up = glm::normalize(snapshot.planes[static_cast<std::size_t>(i)].normal).z;
        if (up > bestUp) {
            bestUp = up;
            best = i;
        }
    }
    return best;
}

bool isNearPlane(const Plane& plane, const glm::vec3& cameraPosition) {
    return glm::dot(cameraPosition - plane.point, plane.normal) < 0.0f;
}

void Renderer::draw(const FrameSnapshot& snapshot, const Camera& camera, int x, int y, int width,
                    int height) {
    if (!passes_ || width <= 0 || height <= 0) return;
    const FrameContext frame = makeFrameContext(camera, x, y, width, height, style);
    beginViewport(x, y, width, height);
    passes_->background.draw(frame);

    PlaneDrawList planes = collectPlanes(snapshot, style, frame.cameraPosition);
    GLint sampleBuffers = 0;
    glGetIntegerv(GL_SAMPLE_BUFFERS, &sampleBuffers);
    passes_->planes.draw(planes.farFaces, frame, true);
    passes_->spheres.cullHidden = cullHiddenSpheres;
    const SphereEdges edges = !style.antialiasEdges ? SphereEdges::Hard
                              : sampleBuffers > 0   ? SphereEdges::AlphaToCoverage
                                                    : SphereEdges::Blended;
    // The translucent planes (an incline, a thin wall) go between the edges of the spheres
    // behind them and the edges of the others (SpherePass::draw).
    std::vector<glm::vec4> translucent;  // (n, d), m
    for (const PlaneFace& face : planes.extraFaces) {
        if (!face.polygon.empty()) translucent.emplace_back(face.normal, -glm::dot(face.normal, face.polygon[0]));
    }
    passes_->spheres.draw(snapshot, frame, edges, translucent);
    passes_->planes.draw(planes.extraFaces, frame, false);
    passes_->spheres.drawFrontEdges();
    passes_->lines.draw(planes.edges, frame, true, kLineDepthBias);

    // Depth-tested marks that no pixel can show (contacts deep in a pile) are left out,
    // as the hidden spheres are: the same image, fewer quads for a software rasteriser.
    const bool depthTested = !style.overlayOnTop, cullMarks = depthTested && cullHiddenMarks;
    const auto shown = [&](const OverlayLine& line) {
        return !cullMarks || !passes_->spheres.hidesMark(line, frame, kLineDepthBias);
    };
    std::vector<OverlayLine>& overlay = passes_->overlay;
    overlay.clear();
    for (const OverlayLine& line : snapshot.lines) {
        if (shown(line)) overlay.push_back(line);
    }
    std::vector<OverlayPoint>& dots = passes_->dots;
    dots.clear();
    for (const OverlayPoint& point : snapshot.points) {
        const OverlayLine asLine = pointAsLine(point);
        if (!shown(asLine)) continue;
        if (fitsAsPoint(point, frame)) {
            dots.push_back(point);
        } else {
            // Drawn before the dots: a dot's outline, larger and at the same place, is
            // never a point where the dot itself is not.
            overlay.push_back(asLine);
        }
    }
    passes_->lines.draw(overlay, frame, depthTested, kLineDepthBias);
    passes_->lines.drawDots(dots, frame, depthTested, kLineDepthBias);

    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_SCISSOR_TEST);
    glUseProgram(0);
}

}  // namespace render
