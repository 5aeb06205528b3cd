#include "render/hidden_spheres.h"

#include <algorithm>
#include <cmath>
#include <thread>

#include <glm/geometric.hpp>

#include "physics/params.h"
#include "physics/thread_team.h"

namespace render {
namespace {

// sphere.frag works in single precision: the depth it writes may be off by this
// fraction of the distance to the sphere, on either side. Generous: a rounding of
// 1e-7 of |c|^2 under its square root would give 3e-4.
constexpr float kShaderDepthNoise = 1e-3f;

// Pixels' widths (at the sphere) by which sphere.frag's edge may differ from the
// outline. Without samples a fragment is kept while its centre ray meets the sphere:
// the margin is for rounding. With soft edges (alpha to coverage or blending), coverage is 1 from half of
// fwidth(miss) inside the outline and 0 from as far outside; fwidth adds two
// finite differences of at most a pixel's width each.
constexpr float kEdgeMarginPixels = 0.25f;
constexpr float kEdgeMarginSoftPixels = 1.0f;
// Pixels by which the spans of pixels within a distance of a centre are narrowed
// (covered) or widened (tested), for the rounding of the ray through a pixel centre.
constexpr float kSpanSlackPixels = 0.02f;
// Below one sphere in this many covering a pixel whole, none is tested.
constexpr std::size_t kFewestCovering = 8;

// From this many spheres on, the finder runs on the thread team (unless told a
// number), each thread taking this many tasks as they come (bands of rows hold more
// or fewer spheres). Tasks never wait for each other, and none throws: the covers'
// room is reserved before they run.
constexpr std::size_t kParallelMinSpheres = 8192;
constexpr int kTasksPerThread = 4;
constexpr int kMostThreads = 8;

int threadsFor(std::size_t spheres, int asked) {
    static const int cores = physics::usableCores();
    if (asked > 0) return std::min(asked, physics::kMostSolverThreads);
    return spheres < kParallelMinSpheres ? 1 : std::clamp(cores, 1, kMostThreads);
}

int tasksFor(int threads) { return threads == 1 ? 1 : kTasksPerThread * threads; }

// [0, n) cut into tasksFor(threads) ranges: task(t, begin, end) for range t, on the team.
template <class Task>
void forEachRange(int threads, std::size_t n, const Task& task) {
    const auto tasks = std::size_t(tasksFor(threads));
    physics::runTasks(threads, int(tasks), [&](int t) {
        task(t, n * std::size_t(t) / tasks, n * std::size_t(t + 1) / tasks);
    });
}

// The pixels [first, end) of a row (or the rows of a column) of `size` whose centre
// (i + 0.5) lies within [lo, hi] px.
struct Span {
    int first, end;
};
Span pixelsBetween(float lo, float hi, int size) {
    // floor(v) for v clamped to [-size - 1, size + 1]: truncation, which rounds towards 0,
    // corrected (std::floor is a call without SSE 4.1).
    const auto floorOf = [size](float v) {
        v = std::clamp(v, -1.0f - float(size), 1.0f + float(size));
        const int i = int(v);
        return float(i) > v ? i - 1 : i;
    };
    const int first = -floorOf(0.5f - lo);  // ceil(lo - 0.5)
    const int last = floorOf(hi - 0.5f);
    return {std::max(first, 0), std::min(last + 1, size)};
}

// The pixels of row y (of a viewport `width` wide) whose centre lies within `radius` px of `center`.
Span rowSpan(int y, const glm::vec2& center, float radius, int width) {
    const float dy = float(y) + 0.5f - center.y;
    const float half2 = radius * radius - dy * dy;
    if (half2 < 0.0f) return {0, 0};
    const float half = std::sqrt(half2);
    return pixelsBetween(center.x - half, center.x + half, width);
}

}  // namespace

// Where the rays that pass within `reach` (m) of c meet the screen, as circles around
// the centre's projection p (px): a cone of half-angle beta = asin(reach / |c|) whose
// axis is theta off the view axis meets the screen in an ellipse. Along its major axis
// it spans tan(theta -+ beta) - tan(theta): p is within u (1 + t^2) / (1 - t u) of every
// point of it (t = tan theta, u = tan beta, tangent of a sum). Across, its half-width b
// is at least u, and its centre is d = u^2 t (1 + t^2) / (1 - t^2 u^2) beyond p: it
// holds the circle of radius u - d around p.
HiddenSphereFinder::Disc HiddenSphereFinder::discOf(const glm::vec3& c, float reach,
                                                   float pixelSize) const {
    const float distance2 = glm::dot(c, c);  // m^2
    const float depth = -c.z;                // m
    Disc disc;
    disc.center = glm::vec2(c) / depth / pixelSize + 0.5f * glm::vec2(float(width_), float(height_));
    if (depth <= 0.0f || reach * reach >= distance2) return disc;  // empty
    const float t = std::sqrt(c.x * c.x + c.y * c.y) / depth;
    const float u = reach / std::sqrt(distance2 - reach * reach);
    if (t * u >= 0.5f) return disc;  // far off axis and wide: not worth it
    const float stretch = (1.0f + t * t) * u;
    // Rounding: a little less inside, a little more outside.
    disc.inside = (u - stretch * t * u / (1.0f - t * t * u * u)) / pixelSize * (1.0f - 1e-4f) - kSpanSlackPixels;
    disc.outside = stretch / (1.0f - t * u) / pixelSize * (1.0f + 1e-4f) + kSpanSlackPixels;
    return disc;
}

// The pixels whose centre ray passes within radius - margin of the centre are covered
// whole; the ray meets the sphere there at less than |c| - sqrt(r^2 - inner^2) from
// the eye. Depths in this file are distances from the eye along the pixel's ray:
// at one pixel they order fragments as the depth buffer does.
HiddenSphereFinder::Cover HiddenSphereFinder::coverOf(const ViewSphere& sphere, float edgeMarginPixels,
                                                      float pixelSize) const {
    Cover cover;
    const glm::vec3 c = sphere.center;                                  // m
    const float distance = glm::length(c);                              // m
    const float inner = sphere.radius - edgeMarginPixels * distance * pixelSize;  // m
    if (inner <= 0.0f) return cover;
    cover.depth = distance - std::sqrt(sphere.radius * sphere.radius - inner * inner) +
                  kShaderDepthNoise * distance;  // m
    cover.disc = discOf(c, inner, pixelSize);
    if (!(cover.disc.inside > 0.0f)) return cover;
    const Span rows = pixelsBetween(cover.disc.center.y - cover.disc.inside, cover.disc.center.y + cover.disc.inside,
                                    height_);
    cover.firstRow = rows.first;
    cover.endRow = rows.end;
    return cover;
}

bool HiddenSphereFinder::coversAPixel(const Cover& cover) const {
    for (int y = cover.firstRow; y < cover.endRow; ++y) {
        const Span span = rowSpan(y, cover.disc.center, cover.disc.inside, width_);
        if (span.first < span.end) return true;
    }
    return false;
}

// nearestCover_ on rows [firstRow, endRow) within box_: the nearest of the covers there.
void HiddenSphereFinder::coverRows(int firstRow, int endRow) {
    for (int y = firstRow; y < endRow; ++y) {
        const auto row = nearestCover_.begin() + std::ptrdiff_t(y) * width_;
        std::fill(row + box_.x0, row + box_.x1, INFINITY);
    }
    for (const std::vector<Cover>& covers : covers_) {
        for (const Cover& cover : covers) {
            const int end = std::min(cover.endRow, endRow);
            for (int y = std::max(cover.firstRow, firstRow); y < end; ++y) {
                float* row = &nearestCover_[std::size_t(y) * std::size_t(width_)];
                const Span span = rowSpan(y, cover.disc.center, cover.disc.inside, width_);
                for (int x = span.first; x < span.end; ++x) row[x] = std::min(row[x], cover.depth);
            }
        }
    }
}

// Whether every pixel where the sphere may leave a fragment is covered in front of
// it. Its fragments lie within `outer` of its centre: on the sphere, or for edge
// fragments whose ray misses it (alpha to coverage), at the ray's closest approach.
bool HiddenSphereFinder::behindCover(const ViewSphere& sphere, float edgeMarginPixels,
                                     float pixelSize, float depthQuantum) const {
    const glm::vec3 c = sphere.center;      // m
    const float distance = glm::length(c);  // m
    const float outer = sphere.radius + edgeMarginPixels * distance * pixelSize;  // m
    float nearest = distance - outer - kShaderDepthNoise * distance;             // m
    nearest -= 4.0f * nearest * nearest * depthQuantum;  // two depth-buffer steps, and rounding
    const Disc disc = discOf(c, outer, pixelSize);
    if (!(disc.outside > 0.0f)) return false;
    return discBehindCover(disc, nearest);
}

bool HiddenSphereFinder::discBehindCover(const Disc& disc, float nearest) const {
    if (tilesBehindCover(disc, nearest)) return true;
    const Span rows = pixelsBetween(disc.center.y - disc.outside, disc.center.y + disc.outside, height_);
    for (int y = rows.first; y < rows.end; ++y) {
        const float* row = &nearestCover_[std::size_t(y) * std::size_t(width_)];
        const Span span = rowSpan(y, disc.center, disc.outside, width_);
        if (span.first >= span.end) continue;
        if (y < box_.y0 || y >= box_.y1 || span.first < box_.x0 || span.end > box_.x1) return false;  // +infinity
        for (int x = span.first; x < span.end; ++x) {
            if (!(row[x] < nearest)) return false;
        }
    }
    return true;
}

// Tiles of kTile x kTile pixels: the farthest cover of each, so that most hidden
// spheres are found hidden by the few tiles under them, without their pixels.
// Rows of tiles [firstTileRow, endTileRow); farthestCover_ starts at 0. A tile with
// a pixel outside box_ holds +infinity.
void HiddenSphereFinder::findFarthestCoverOfTiles(int firstTileRow, int endTileRow) {
    const int firstColumn = (box_.x0 + kTile - 1) / kTile;  // tiles inside box_, columns
    const int endColumn = std::max(firstColumn, box_.x1 == width_ ? tilesX_ : box_.x1 / kTile);
    for (int ty = firstTileRow; ty < endTileRow; ++ty) {
        float* tiles = &farthestCover_[std::size_t(ty) * std::size_t(tilesX_)];
        const int y0 = ty * kTile, y1 = std::min(y0 + kTile, height_);
        const bool inside = y0 >= box_.y0 && y1 <= box_.y1;
        for (int tx = 0; tx < tilesX_; ++tx) {
            if (!inside || tx < firstColumn || tx >= endColumn) tiles[tx] = INFINITY;
        }
        if (!inside) continue;
        for (int y = y0; y < y1; ++y) {
            const float* row = &nearestCover_[std::size_t(y) * std::size_t(width_)];
            for (int x = firstColumn * kTile; x < std::min(endColumn * kTile, width_); ++x) {
                tiles[x / kTile] = std::max(tiles[x / kTile], row[x]);
            }
        }
    }
}

bool HiddenSphereFinder::tilesBehindCover(const Disc& disc, float nearest) const {
    const Span columns = pixelsBetween(disc.center.x - disc.outside, disc.center.x + disc.outside, width_);
    const Span rows = pixelsBetween(disc.center.y - disc.outside, disc.center.y + disc.outside, height_);
    // No pixel centre within reach (a sphere between them, or off the viewport): no fragment.
    if (columns.first >= columns.end || rows.first >= rows.end) return true;
    for (int ty = rows.first / kTile; ty <= (rows.end - 1) / kTile; ++ty) {
        for (int tx = columns.first / kTile; tx <= (columns.end - 1) / kTile; ++tx) {
            if (!(farthestCover_[std::size_t(ty) * std::size_t(tilesX_) + std::size_t(tx)] < nearest)) return false;
        }
    }
    return true;
}

// covers_ <- where each sphere covers whole pixels: only spheres drawn whole between
// the near and far planes hide others. Returns how many cover a pixel.
std::size_t HiddenSphereFinder::findCovers(const std::vector<ViewSphere>& spheres, const FrameContext& frame,
                                           float edgeMarginPixels, int threads) {
    const std::size_t tasks = std::size_t(tasksFor(threads));
    covers_.resize(tasks);
    for (std::size_t t = 0; t < tasks; ++t) {
        covers_[t].clear();
        covers_[t].reserve(spheres.size() * (t + 1) / tasks - spheres.size() * t / tasks);
    }
    forEachRange(threads, spheres.size(), [&](int t, std::size_t begin, std::size_t end) {
        std::vector<Cover>& covers = covers_[std::size_t(t)];
        for (std::size_t k = begin; k < end; ++k) {
            const ViewSphere& sphere = spheres[k];
            const float front = -sphere.center.z - sphere.radius, back = -sphere.center.z + sphere.radius;  // m
            if (!(front > frame.nearPlane * 1.01f && back < frame.farPlane * 0.99f)) continue;
            const Cover cover = coverOf(sphere, edgeMarginPixels, frame.pixelSize);
            if (coversAPixel(cover)) covers.push_back(cover);
        }
    });
    std::size_t covering = 0;
    for (const std::vector<Cover>& covers : covers_) covering += covers.size();
    return covering;
}

void HiddenSphereFinder::find(std::vector<ViewSphere>& spheres, const FrameContext& frame,
                              bool softEdges, int depthBits, int threadsAsked) {
    for (ViewSphere& sphere : spheres) sphere.hidden = false;
    covered_ = false;
    width_ = int(frame.viewportSize.x);
    height_ = int(frame.viewportSize.y);
    if (width_ <= 0 || height_ <= 0 || depthBits <= 0) return;
    const int threads = threadsFor(spheres.size(), threadsAsked);
    const float margin = softEdges ? kEdgeMarginSoftPixels : kEdgeMarginPixels;
    // Spheres too small on the screen to cover a pixel whole (a million under MSAA):
    // few could be hidden, and testing them all would cost more than it saves.
    if (findCovers(spheres, frame, margin, threads) < spheres.size() / kFewestCovering) return;
    box_ = Box{width_, 0, height_, 0};
    for (const std::vector<Cover>& covers : covers_) {
        for (const Cover& cover : covers) {
            const Span columns = pixelsBetween(cover.disc.center.x - cover.disc.inside,
                                               cover.disc.center.x + cover.disc.inside, width_);
            box_ = Box{std::min(box_.x0, columns.first), std::max(box_.x1, columns.end),
                       std::min(box_.y0, cover.firstRow), std::max(box_.y1, cover.endRow)};
        }
    }
    if (box_.x0 >= box_.x1 || box_.y0 >= box_.y1) box_ = Box{};
    nearestCover_.resize(std::size_t(width_) * std::size_t(height_));
    forEachRange(threads, std::size_t(box_.y1 - box_.y0), [&](int, std::size_t begin, std::size_t end) {
        coverRows(box_.y0 + int(begin), box_.y0 + int(end));
    });
    tilesX_ = (width_ + kTile - 1) / kTile;
    tilesY_ = (height_ + kTile - 1) / kTile;
    farthestCover_.assign(std::size_t(tilesX_) * std::size_t(tilesY_), 0.0f);
    forEachRange(threads, std::size_t(tilesY_), [&](int, std::size_t begin, std::size_t end) {
        findFarthestCoverOfTiles(int(begin), int(end));
    });
    // A depth d is stored as about 1 - near / d in steps of 2^-depthBits: d^2 times this, m.
    const float depthQuantum = std::ldexp(1.0f, -depthBits) / frame.nearPlane;  // 1/m
    covered_ = true;
    pixelSize_ = frame.pixelSize;
    nearPlane_ = frame.nearPlane;
    depthQuantum_ = depthQuantum;
    forEachRange(threads, spheres.size(), [&](int, std::size_t begin, std::size_t end) {
        for (std::size_t k = begin; k < end; ++k) {
            ViewSphere& sphere = spheres[k];
            sphere.hidden = sphere.pointSprite && behindCover(sphere, margin, frame.pixelSize, depthQuantum);
        }
    });
}

// The mark's pixels lie within reach of the segment between its ends' projections: in the
// disc around their midpoint. Its fragments' depths lie between its ends' (line.vert
// interpolates them across the quad), less the bias: 1/d' = 1/d + bias / (2 near) is nearer
// than what the depth buffer holds (the far plane's share only moves it away). A cover's
// distance along a pixel's ray is at least its view depth there, so a cover nearer than d'
// along the ray is in front of every fragment of the mark at that pixel.
bool HiddenSphereFinder::hidesMark(const glm::vec3& a, const glm::vec3& b, float reachPixels, float depthBias) const {
    if (!covered_) return false;
    const float depth = std::min(-a.z, -b.z);  // m, view depth of the nearer end
    if (!(depth > nearPlane_)) return false;
    const glm::vec2 half = 0.5f * glm::vec2(float(width_), float(height_));
    const glm::vec2 pa = glm::vec2(a) / -a.z / pixelSize_ + half, pb = glm::vec2(b) / -b.z / pixelSize_ + half;  // px
    Disc disc;
    disc.center = 0.5f * (pa + pb);
    disc.outside = 0.5f * glm::length(pa - pb) + reachPixels + kSpanSlackPixels;
    float nearest = 1.0f / (1.0f / depth + 0.5f * depthBias / nearPlane_);  // m
    nearest -= kShaderDepthNoise * nearest;
    nearest -= 4.0f * nearest * nearest * depthQuantum_;  // two depth-buffer steps, and rounding
    return discBehindCover(disc, nearest);
}

}  // namespace render
