#pragma once
// Draws a FrameSnapshot with an orbit camera into a viewport of the bound
// framebuffer (a window's or an OffscreenTarget): background gradient, the box
// (far faces shaded, floor grid, every edge drawn), spheres as ray-cast
// impostors, extra planes, then overlay lines and dots.
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <cstddef>
#include <memory>
#include <string>

#include "render/camera.h"
#include "render/frame_snapshot.h"

namespace render {

// How things look; every field may change between frames.
struct RenderStyle {
    glm::vec3 backgroundTop{0.80f, 0.84f, 0.89f};
    glm::vec3 backgroundBottom{0.50f, 0.55f, 0.62f};
    glm::vec4 floorColor{0.93f, 0.94f, 0.95f, 0.92f};  // rgb, opacity
    glm::vec4 wallColor{0.93f, 0.95f, 0.98f, 0.45f};   // far walls
    glm::vec4 extraPlaneColor{0.95f, 0.80f, 0.55f, 0.55f};
    glm::vec4 gridColor{0.35f, 0.40f, 0.48f, 0.45f};  // rgb, strength of minor lines
    glm::vec4 edgeColor{0.16f, 0.20f, 0.27f, 0.90f};  // box edges
    bool showBox = true;
    bool showGrid = true;
    float gridSpacing = 0.1f;    // m between minor grid lines
    int gridMajorEvery = 10;     // minor lines per major line (1 m at 0.1 m)
    float edgeWidth = 2.0f;      // px, box edges
    float lineScale = 1.0f;      // multiplies every width: the content scale on HiDPI
    bool overlayOnTop = false;   // overlay lines ignore depth (seen through spheres)
    bool antialiasEdges = true;  // sphere outlines: alpha to coverage on MSAA targets, else blended
};

class Renderer {
  public:
    Renderer();
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    // Needs a current GL 3.3 core context. Returns "" on success, else why not.
    std::string init();
    void shutdown();

    // (x, y) is the viewport's lower-left corner in framebuffer pixels, as in glViewport.
    // Clears depth (and paints the background) inside the viewport only, so that
    // several views can share one framebuffer. Leaves blending, depth test and
    // scissor test disabled.
    void draw(const FrameSnapshot& snapshot, const Camera& camera, int x, int y, int width,
              int height);

    RenderStyle style;

    // Leave out the spheres (and the depth-tested overlay marks) no pixel can show: the
    // same image, drawn faster by a software rasteriser, for a little CPU time per frame.
    // init() turns it on when the GL is one (llvmpipe, softpipe, SwiftShader), where it pays.
    bool cullHiddenSpheres = false;
    // With it, leave out the hidden overlay marks too (off: every mark is sent, to compare).
    bool cullHiddenMarks = true;
    // Spheres the last draw() sent to the GL.
    std::size_t drawnSpheres() const;
    // Overlay lines and dots the last draw() sent to the GL (the others were hidden).
    std::size_t drawnMarks() const;

  private:
    struct Passes;
    std::unique_ptr<Passes> passes_;
};

// Index of the box plane whose normal is closest to +z (the floor), or -1 when
// no box plane faces upwards; without a box, the same among all planes.
int floorPlaneIndex(const FrameSnapshot& snapshot);
// Whether the camera is behind a box plane: then the wall stands between the
// camera and the spheres and is drawn as edges only.
bool isNearPlane(const Plane& plane, const glm::vec3& cameraPosition);

}  // namespace render
