#pragma once
// Internal to spheres_render: finds the spheres that no pixel can show, so that the
// sphere pass does not send them. A software rasteriser pays for every sphere it is
// sent, seen or not, and most of a pile is hidden behind its surface.
//
// A depth buffer on the CPU, conservative: each sphere writes, at each pixel whose
// centre ray meets it far enough inside its outline that its fragment surely covers
// the whole pixel (every sample under MSAA), the deepest its surface reaches there
// (as a distance from the eye along the pixel's ray). A sphere drawn as a point
// sprite is hidden when every pixel where it may leave a fragment holds a distance
// surely in front of its nearest point. Its fragments would all fail
// the depth test: the image is the same, pixel for pixel, with or without it.
//
// From a few thousand spheres on, it runs on the solver's thread team (the GL's own
// threads are idle while it runs): covering by bands of rows, testing by ranges of
// spheres. Every pixel keeps the nearest cover, so the result is the same on any
// number of threads.
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "render/frame_context.h"

namespace render {

// A sphere in front of the eye, as the sphere pass sees it this frame.
struct ViewSphere {
    std::uint32_t index = 0;  // in the snapshot
    glm::vec3 center{0.0f};   // m, view space (the eye looks along -z)
    float radius = 0.0f;      // m
    bool pointSprite = false;  // drawn as a point sprite, else as a square (never hidden)
    bool hidden = false;       // set by HiddenSphereFinder
};

class HiddenSphereFinder {
  public:
    // Sets `hidden` on the point-sprite spheres that no pixel can show. softEdges:
    // sphere.frag's alpha is the edge's coverage (alpha to coverage on a multisampled
    // target, or blended over what is behind, the spheres drawn farthest first;
    // either way a pixel is the sphere's alone where its coverage is 1); depthBits: of the
    // target's depth buffer (0: none, nothing is hidden); threads: 0 for the hardware's
    // (one below a few thousand spheres). The result is the same on any number.
    void find(std::vector<ViewSphere>& spheres, const FrameContext& frame, bool softEdges,
              int depthBits, int threads = 0);

    // After find(), for the same frame: whether an overlay mark no pixel can show is hidden
    // too. The mark is a segment from a to b (view space, m; a dot when a = b) that line.vert
    // draws reachPixels wide around it, its depth pulled towards the eye by depthBias (NDC).
    // It is hidden when every pixel within reach holds a cover surely in front of its
    // nearest end; false whenever find() found no covers.
    bool hidesMark(const glm::vec3& a, const glm::vec3& b, float reachPixels, float depthBias) const;

  private:
    // Circles on the screen around the projection of a centre (px, from the viewport's
    // lower left): inside one, every pixel centre's ray passes within a distance of the
    // centre; outside the other, none does. Radii <= 0: nothing inside.
    struct Disc {
        glm::vec2 center{0.0f};
        float inside = 0.0f, outside = 0.0f;
    };
    Disc discOf(const glm::vec3& c, float reach, float pixelSize) const;
    // Where a sphere covers whole pixels: inside `disc`, rows [firstRow, endRow), the
    // distance `depth` (m) along each pixel's ray. No rows: it covers none.
    struct Cover {
        Disc disc;
        float depth = 0.0f;
        int firstRow = 0, endRow = 0;
    };
    Cover coverOf(const ViewSphere& sphere, float edgeMarginPixels, float pixelSize) const;
    bool coversAPixel(const Cover& cover) const;
    std::size_t findCovers(const std::vector<ViewSphere>& spheres, const FrameContext& frame,
                           float edgeMarginPixels, int threads);
    void coverRows(int firstRow, int endRow);
    bool behindCover(const ViewSphere& sphere, float edgeMarginPixels, float pixelSize,
                     float depthQuantum) const;
    // Every pixel within disc.outside of disc.center covered nearer than `nearest` (m).
    bool discBehindCover(const Disc& disc, float nearest) const;
    void findFarthestCoverOfTiles(int firstTileRow, int endTileRow);
    bool tilesBehindCover(const Disc& disc, float nearest) const;

    int width_ = 0, height_ = 0;  // px, the viewport
    // The last find()'s frame, for hidesMark: whether it found covers, the size of a pixel
    // at 1 m (m), the near plane (m) and a depth-buffer step (1/m, times d^2: m).
    bool covered_ = false;
    float pixelSize_ = 0.0f, nearPlane_ = 0.0f, depthQuantum_ = 0.0f;
    // Pixels [x0, x1) x [y0, y1) that some cover reaches: outside, nearestCover_ is not
    // written and stands for +infinity (a few spheres cost as few pixels).
    struct Box {
        int x0 = 0, x1 = 0, y0 = 0, y1 = 0;
    } box_;
    std::vector<std::vector<Cover>> covers_;  // per range of spheres: those that cover a pixel
    // Per pixel (row 0 at the bottom): the distance from the eye along the pixel's ray
    // (m) in front of which some sphere covers the whole pixel; +infinity where none does.
    std::vector<float> nearestCover_;
    static constexpr int kTile = 8;  // px
    int tilesX_ = 0, tilesY_ = 0;
    std::vector<float> farthestCover_;  // per tile: the largest nearestCover_ of its pixels
};

}  // namespace render
