#pragma once
// Internal to spheres_render: every sphere as a ray-cast impostor. Small spheres
// well inside the viewport are point sprites (one vertex each); the rest are
// instanced squares. Both use the same fragment shader.
#include <glm/gtc/type_precision.hpp>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "render/frame_context.h"
#include "render/frame_snapshot.h"
#include "render/gl_program.h"
#include "render/hidden_spheres.h"

namespace render {

// One sphere as the GPU reads it (20 bytes, interleaved).
struct SphereInstance {
    glm::vec3 center;  // m, world
    float radius;      // m
    glm::u8vec4 color;
};

// How a sphere's outline meets what is behind it. The fragment shader's alpha is the
// share of the pixel the sphere covers, up to a pixel and a half outside the outline.
enum class SphereEdges {
    Hard,             // a pixel is the sphere's or not (jagged outlines)
    AlphaToCoverage,  // a multisampled target: the alpha picks the samples
    Blended,          // one sample: the alpha blends over what is behind, so the
                      // spheres are drawn from the farthest to the nearest
};

class SpherePass {
  public:
    std::string init();
    void destroy();
    // translucent (Blended only): planes drawn after the spheres, translucent, each (n, d)
    // with n.x + d = 0 (world, m). Then the spheres are drawn where they cover a pixel whole,
    // writing depth, and only the edges of those behind such a plane (seen from the eye) are
    // blended in: the plane goes over them as over the rest. drawFrontEdges, after the
    // planes, blends the edges of the others over the planes. (Edges that wrote depth hid
    // the plane behind them: a ring of the untinted background around a sphere on 07's
    // incline.)
    void draw(const FrameSnapshot& snapshot, const FrameContext& frame, SphereEdges edges,
              const std::vector<glm::vec4>& translucent = {});
    void drawFrontEdges();
    // Spheres sent to the GL by the last draw (the others were hidden or behind the eye).
    std::size_t drawnSpheres() const { return points_.size() + quads_.size(); }

    // Leaves out the spheres no pixel can show (HiddenSphereFinder): the same image,
    // less work for a software rasteriser, a little CPU time per frame.
    bool cullHidden = false;
    // After draw(), with cullHidden: whether an overlay line or dot (world space), drawn
    // depth-tested with `depthBias` as the line pass draws it, is hidden behind the spheres.
    bool hidesMark(const OverlayLine& line, const FrameContext& frame, float depthBias) const;

  private:
    struct Program {
        GlProgram program;
        GLint view = -1, projection = -1, pixelSize = -1, viewportSize = -1, marginPixels = -1,
              viewport = -1, lightDirection = -1, upDirection = -1, coverageAlpha = -1, part = -1;
    };
    std::string buildProgram(Program& program, std::string_view label,
                             std::string_view vertexSource);
    void partition(const FrameSnapshot& snapshot, const FrameContext& frame, float marginPixels,
                   SphereEdges edges, const std::vector<glm::vec4>& translucent);
    void batch(const FrameSnapshot& snapshot, bool inOrder, std::vector<ViewSphere>::const_iterator firstInFront);
    void drawBatch(bool pointSprites, std::size_t first, std::size_t count);
    // Batches [first, end) with sphere.frag's uPart.
    void drawBatches(int part, std::size_t first, std::size_t end);
    void beginState(SphereEdges edges) const;
    void endState() const;
    void setUniforms(const Program& program, const FrameContext& frame, float marginPixels,
                     bool coverageAlpha);

    Program pointProgram_;
    Program quadProgram_;
    GLuint pointArray_ = 0;  // vertex array: one point per sphere
    GLuint quadArray_ = 0;   // vertex array: four corners, one instance per sphere
    GLuint cornerBuffer_ = 0;
    GLuint pointBuffer_ = 0;              // SphereInstance per point sprite
    GLuint quadBuffer_ = 0;               // SphereInstance per square
    std::vector<ViewSphere> inView_;      // reused from frame to frame
    HiddenSphereFinder hiddenSpheres_;
    std::vector<SphereInstance> points_;
    std::vector<SphereInstance> quads_;
    // Runs of the drawing order, each of point sprites or of squares (with Blended,
    // the farthest first; else all points, then all squares).
    struct Batch {
        bool pointSprites = true;
        std::size_t first = 0, count = 0;  // in points_ or quads_
    };
    std::vector<Batch> batches_;
    // With translucent planes: the batches from here on hold the spheres in front of all of
    // them (their edges wait for drawFrontEdges); batches_.size() without.
    std::size_t frontBatches_ = 0;
};

}  // namespace render
