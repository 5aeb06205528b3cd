// Leaving out the spheres no pixel can show (render/hidden_spheres.h): which ones the
// CPU depth buffer finds hidden, and, drawn headless, that the image stays the same
// to the last byte while most of a pile is left out.
#include <glad/gl.h>
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "platform/headless_context.h"
#include "render/camera.h"
#include "render/frame_snapshot.h"
#include "render/hidden_spheres.h"
#include "render/offscreen_target.h"
#include "render/renderer.h"

namespace {

// A 640 x 360 view with the camera's default field of view, the eye at the origin
// looking along -z (view space is world space here).
render::FrameContext frameOf(int width = 640, int height = 360) {
    const render::Camera camera;
    render::FrameContext frame;
    frame.viewportSize = glm::vec2(float(width), float(height));
    frame.pixelSize = 2.0f * std::tan(0.5f * camera.fovY) / float(height);
    frame.nearPlane = 0.1f;
    frame.farPlane = 100.0f;
    return frame;
}

render::ViewSphere sphereAt(const glm::vec3& center, float radius, bool pointSprite = true) {
    render::ViewSphere sphere;
    sphere.center = center;
    sphere.radius = radius;
    sphere.pointSprite = pointSprite;
    return sphere;
}

std::vector<bool> hiddenOf(std::vector<render::ViewSphere> spheres, bool multisampled = false,
                           const render::FrameContext& frame = frameOf(), int threads = 0) {
    render::HiddenSphereFinder finder;
    finder.find(spheres, frame, multisampled, 24, threads);
    std::vector<bool> hidden;
    for (const render::ViewSphere& sphere : spheres) hidden.push_back(sphere.hidden);
    return hidden;
}

TEST(HiddenSpheres, ASphereBehindALargerOneIsHiddenAndTheOneInFrontIsNot) {
    // 0.5 m at 3 m covers about 60 px around the centre; 0.05 m at 5 m about 4 px.
    const auto hidden = hiddenOf({sphereAt({0, 0, -3}, 0.5f), sphereAt({0.1f, -0.1f, -5}, 0.05f)});
    EXPECT_FALSE(hidden[0]);
    EXPECT_TRUE(hidden[1]);
}

TEST(HiddenSpheres, ASpherePeepingPastTheEdgeOrInFrontIsShown) {
    // The small sphere's outline starts 1 cm beyond the outline of the large one, seen
    // from the eye: at 5 m, that is 0.5 px outside.
    const float outline = 0.5f / std::sqrt(9.0f - 0.25f);  // tangent of the large one's outline
    const float edge = outline * 5.0f;                     // m, at 5 m
    const auto hidden = hiddenOf({sphereAt({0, 0, -3}, 0.5f), sphereAt({edge + 0.06f, 0, -5}, 0.05f),
                                  sphereAt({edge - 0.2f, 0, -5}, 0.05f), sphereAt({0, 0, -2}, 0.05f)});
    EXPECT_FALSE(hidden[1]) << "peeps out";
    EXPECT_TRUE(hidden[2]) << "well inside the outline, behind";
    EXPECT_FALSE(hidden[3]) << "in front";
}

TEST(HiddenSpheres, ASphereCloseBehindTheSurfaceIsShown) {
    // A sphere covers its disc at one depth, the deepest its surface reaches there
    // (plus the shader's rounding): a sphere close behind its front is not found hidden,
    // one behind that depth is.
    const auto hidden = hiddenOf({sphereAt({0, 0, -3}, 0.5f), sphereAt({0, 0, -2.601f}, 0.1f),
                                  sphereAt({0, 0.1f, -3.2f}, 0.05f)});
    EXPECT_FALSE(hidden[1]) << "1 mm behind the large sphere's nearest point";
    EXPECT_TRUE(hidden[2]) << "behind the large sphere's centre";
}

TEST(HiddenSpheres, SquaresAndSpheresBehindOnesCutByTheNearPlaneAreShown) {
    const render::FrameContext frame = frameOf();
    // A sphere drawn as a square is never left out, even when covered.
    EXPECT_FALSE(hiddenOf({sphereAt({0, 0, -3}, 0.5f), sphereAt({0, 0, -5}, 0.05f, false)})[1]);
    // The near plane cuts the large sphere: it may not be drawn whole, so it hides nothing.
    EXPECT_FALSE(hiddenOf({sphereAt({0, 0, -0.5f}, 0.45f), sphereAt({0, 0, -5}, 0.05f)}, false, frame)[1]);
    // The far plane (100 m) cuts it: it hides nothing either (the one behind is 5 px wide).
    EXPECT_FALSE(hiddenOf({sphereAt({0, 0, -99.4f}, 1.5f), sphereAt({0, 0, -99.9f}, 0.5f)}, false, frame)[1]);
    // The same, nearer, hides it.
    EXPECT_TRUE(hiddenOf({sphereAt({0, 0, -97.4f}, 1.5f), sphereAt({0, 0, -97.9f}, 0.5f)}, false, frame)[1]);
}

TEST(HiddenSpheres, ASphereBetweenPixelCentresIsHidden) {
    // 0.5 mm at 2 m is 0.12 px: with its centre at a pixel's corner, no pixel centre's
    // ray comes near it and no fragment survives. Centred on a pixel, it shows.
    const render::FrameContext frame = frameOf();
    const float pixel = frame.pixelSize * 2.0f;  // m per px at 2 m
    EXPECT_TRUE(hiddenOf({sphereAt({0, 0, -2}, 0.0005f)}, false, frame)[0]) << "at a corner";
    EXPECT_FALSE(hiddenOf({sphereAt({0.5f * pixel, 0.5f * pixel, -2}, 0.0005f)}, false, frame)[0]) << "at a centre";
}

TEST(HiddenSpheres, EdgesByCoverageNeedMoreOfTheSphereInFront) {
    // In front, a sphere 6 px across; behind, one whose fragments reach 2.5 px from its
    // centre. Without samples the front one covers 2.75 px around its centre, enough;
    // under alpha to coverage only 2 px, and the edges of the one behind may show.
    const render::FrameContext frame = frameOf();
    const float pixel = frame.pixelSize;  // m per px at 1 m
    const std::vector<render::ViewSphere> spheres{sphereAt({0, 0, -2}, 3.0f * pixel * 2.0f),
                                                  sphereAt({0, 0, -4}, 1.5f * pixel * 4.0f)};
    EXPECT_TRUE(hiddenOf(spheres, false)[1]);
    EXPECT_FALSE(hiddenOf(spheres, true)[1]);
}

// Split over threads (covers by ranges of spheres, bands of rows, rows of tiles, tests
// by ranges of spheres), the finder hides exactly the spheres it hides on one: random
// clouds of 20 000 spheres of 0.5-12 px, in viewports from 3 rows high (fewer rows
// than bands) to full HD, with and without MSAA.
TEST(HiddenSpheres, EveryThreadCountHidesTheSameSpheres) {
    unsigned state = 2024u;
    const auto random = [&state] {  // in [0, 1)
        state = state * 1664525u + 1013904223u;
        return float(state >> 8) / float(1u << 24);
    };
    const std::vector<glm::ivec2> viewports{{640, 360}, {200, 3}, {97, 13}, {1920, 1080}, {333, 41}};
    std::size_t hiddenOnOne = 0;
    for (std::size_t v = 0; v < viewports.size(); ++v) {
        const render::FrameContext frame = frameOf(viewports[v].x, viewports[v].y);
        std::vector<render::ViewSphere> spheres;
        for (int k = 0; k < 20000; ++k) {
            const float depth = 2.0f + 8.0f * random();  // m
            const glm::vec3 centre((random() - 0.5f) * depth, (random() - 0.5f) * 0.6f * depth, -depth);
            const float pixels = 0.5f + 12.0f * random() * random();
            spheres.push_back(sphereAt(centre, pixels * depth * frame.pixelSize, random() < 0.95f));
        }
        for (bool multisampled : {false, true}) {
            const std::vector<bool> one = hiddenOf(spheres, multisampled, frame, 1);
            for (bool hidden : one) hiddenOnOne += hidden;
            for (int threads : {2, 3, 8}) {
                const std::vector<bool> several = hiddenOf(spheres, multisampled, frame, threads);
                std::size_t differ = 0;
                for (std::size_t k = 0; k < one.size(); ++k) differ += several[k] != one[k];
                EXPECT_EQ(differ, 0u) << "viewport " << v << ", " << threads << " threads, MSAA " << multisampled;
            }
        }
    }
    EXPECT_GT(hiddenOnOne, 50000u);  // the clouds hide many: the comparison has something to compare
}

// ------------------------------------------------------------ drawn, headless

// A pile in a box: a jittered lattice of across x across x high spheres (6 250 by
// default), radii 1 to 4 cm at the default spacing, some overlapping, coloured by index.
render::FrameSnapshot pile(int across = 25, int high = 10) {
    render::FrameSnapshot snapshot;
    const float half = 0.5f;  // m, half the box
    const std::vector<glm::vec3> normals{{0, 0, 1}, {1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, -1}};
    for (const glm::vec3& n : normals) {
        snapshot.planes.push_back({n.z < 0 ? glm::vec3(0, 0, 2 * half) : -half * glm::vec3(n.x, n.y, 0), n});
    }
    snapshot.boxPlaneCount = 6;
    unsigned state = 12345u;
    const auto random = [&state] {  // in [0, 1)
        state = state * 1664525u + 1013904223u;
        return float(state >> 8) / float(1u << 24);
    };
    const float spacing = 2.0f * half / float(across);  // m
    const float radiusScale = 25.0f / float(across);
    for (int k = 0; k < high; ++k) {
        for (int j = 0; j < across; ++j) {
            for (int i = 0; i < across; ++i) {
                const glm::vec3 jitter(random() - 0.5f, random() - 0.5f, random() - 0.5f);
                const glm::vec3 centre = glm::vec3(-half + (i + 0.5f) * spacing, -half + (j + 0.5f) * spacing,
                                                   (k + 0.5f) * spacing) + 0.3f * spacing * jitter;
                const auto id = std::uint8_t(i * 7 + j * 13 + k * 29);
                snapshot.addSphere(centre, radiusScale * (0.01f + 0.03f * random()),
                                   {id, std::uint8_t(255 - id), 128, 255});
            }
        }
    }
    return snapshot;
}

// The three ways the spheres' outlines are drawn (render::SphereEdges).
struct Edges {
    int samples;
    bool antialiased;
    const char* name;
};
constexpr Edges kHard{0, false, "hard outlines"}, kBlended{0, true, "blended outlines"},
    kSampled{4, true, "4 samples"};
std::ostream& operator<<(std::ostream& out, const Edges& edges) { return out << edges.name; }

class HiddenSpheresDrawn : public ::testing::Test {
  protected:
    void SetUp() override {
        std::string error;
        context_ = platform::createHeadless(platform::HeadlessBackend::Auto, &error);
        if (!context_) GTEST_SKIP() << "no headless GL backend available (OSMesa, EGL): " << error;
        ASSERT_EQ(renderer_.init(), "");
    }

    struct Drawn {
        render::Image image;
        std::size_t spheres = 0;  // sent to the GL
        std::size_t marks = 0;    // overlay lines and dots sent to the GL
    };
    Drawn draw(const render::FrameSnapshot& snapshot, const render::Camera& camera, glm::ivec2 size,
               const Edges& edges, bool cull, bool cullMarks = true) {
        EXPECT_EQ(target_.resize(size.x, size.y, edges.samples), "");
        target_.bind();
        renderer_.style.antialiasEdges = edges.antialiased;
        renderer_.cullHiddenSpheres = cull;
        renderer_.cullHiddenMarks = cullMarks;
        renderer_.draw(snapshot, camera, 0, 0, size.x, size.y);
        EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
        return {target_.read(), renderer_.drawnSpheres(), renderer_.drawnMarks()};
    }

    std::unique_ptr<platform::HeadlessContext> context_;
    render::Renderer renderer_;
    render::OffscreenTarget target_;
};

// The number of pixels whose colour differs.
int differingPixels(const render::Image& a, const render::Image& b) {
    int differ = 0;
    for (std::size_t k = 0; k + 3 < a.rgba.size() && k + 3 < b.rgba.size(); k += 4) {
        differ += a.rgba[k] != b.rgba[k] || a.rgba[k + 1] != b.rgba[k + 1] || a.rgba[k + 2] != b.rgba[k + 2];
    }
    return differ;
}

TEST_F(HiddenSpheresDrawn, LeavingOutTheHiddenSpheresKeepsEveryPixel) {
    const render::FrameSnapshot snapshot = pile();
    struct View {
        render::Camera camera;
        glm::ivec2 size{480, 270};  // px
    };
    std::vector<View> views(8);
    views[0].camera.reset({-0.5f, -0.5f, 0}, {0.5f, 0.5f, 1}, 16.0f / 9.0f);  // the default view
    for (View& view : views) view.camera = views[0].camera;
    views[1].camera.elevation = 1.5f;   // from above
    views[2].camera.elevation = -0.3f;  // from below the floor
    views[3].camera.distance = 0.9f;    // close: some spheres are squares, some behind the eye
    views[4].camera.distance = 6.0f;    // far: spheres of a few pixels
    views[5].size = {1920, 1080};       // the default view in full HD: small pixels
    // From 100 m through a narrow lens, the pile filling the frame: far from the eye, where
    // single precision in the fragment shader has the least to spare.
    views[6].camera.distance = 100.0f;
    views[6].camera.fovY = 0.012f;  // rad
    views[7].camera.distance = 40.0f;  // spheres of 1-3 px in full HD
    views[7].camera.fovY = 0.25f;
    views[7].size = {1920, 1080};
    std::size_t mostHidden = 0;
    for (std::size_t v = 0; v < views.size(); ++v) {
        for (const Edges& edges : {kHard, kBlended, kSampled}) {
            const Drawn all = draw(snapshot, views[v].camera, views[v].size, edges, false);
            const Drawn seen = draw(snapshot, views[v].camera, views[v].size, edges, true);
            EXPECT_EQ(differingPixels(all.image, seen.image), 0) << "view " << v << ", " << edges;
            EXPECT_LE(seen.spheres, all.spheres);
            if (!edges.antialiased) mostHidden = std::max(mostHidden, all.spheres - seen.spheres);
        }
    }
    // From above only the top layer or two show: most of the pile is left out.
    EXPECT_GT(mostHidden, snapshot.sphereCount() / 2);
}

// The contacts overlay on a pile, depth-tested as the window draws it above 50 spheres:
// on each sphere a dot where it would touch its neighbour below and a normal 0.9 r long
// into it, and dots floating in front of the pile. Leaving out the marks no pixel can show
// keeps every pixel, in every view of the test above and with or without samples; from
// above most marks are left out.
TEST_F(HiddenSpheresDrawn, LeavingOutTheHiddenOverlayMarksKeepsEveryPixel) {
    render::FrameSnapshot snapshot = pile();
    const std::size_t spheres = snapshot.sphereCount();
    for (std::size_t i = 0; i < spheres; ++i) {
        const glm::vec3 c = snapshot.centers[i];
        const float r = snapshot.radii[i];
        const glm::vec3 point = c - glm::vec3(0.0f, 0.0f, r), tip = point + glm::vec3(0.0f, 0.0f, 0.9f * r);
        snapshot.addLine(point, tip, {80, 220, 255, 255}, 2.0f);
        snapshot.addPoint(point, {255, 230, 60, 255}, i % 2 ? 4.0f : 8.0f);
        if (i % 50 == 0) snapshot.addPoint(c + glm::vec3(0.3f, -0.4f, 0.6f), {255, 255, 255, 255}, 6.0f);
    }
    renderer_.style.overlayOnTop = false;
    render::Camera camera;
    camera.reset({-0.5f, -0.5f, 0}, {0.5f, 0.5f, 1}, 16.0f / 9.0f);
    std::vector<render::Camera> cameras(4, camera);
    cameras[1].elevation = 1.5f;
    cameras[2].distance = 0.9f;
    cameras[3].distance = 6.0f;
    std::size_t leftOutFromAbove = 0;
    const std::size_t marks = snapshot.lines.size() + snapshot.points.size();
    for (std::size_t v = 0; v < cameras.size(); ++v) {
        for (const Edges& edges : {kHard, kBlended, kSampled}) {
            const Drawn every = draw(snapshot, cameras[v], {480, 270}, edges, true, false);
            const Drawn seen = draw(snapshot, cameras[v], {480, 270}, edges, true, true);
            EXPECT_EQ(differingPixels(every.image, seen.image), 0) << "view " << v << ", " << edges;
            EXPECT_EQ(every.marks, marks);
            EXPECT_LE(seen.marks, every.marks);
            if (v == 1 && !edges.antialiased) leftOutFromAbove = every.marks - seen.marks;
        }
    }
    EXPECT_GT(leftOutFromAbove, marks / 2);
}

// From 8 192 spheres on the finder runs on the hardware's threads (the thread team):
// bands of rows, ranges of spheres. A pile of 20 000 from the default view and from
// above. (EveryThreadCountHidesTheSameSpheres asks for thread counts by number.)
TEST_F(HiddenSpheresDrawn, OnSeveralThreadsEveryPixelIsKeptToo) {
    const render::FrameSnapshot snapshot = pile(50, 8);
    ASSERT_GE(snapshot.sphereCount(), 8192u);
    render::Camera camera;
    camera.reset({-0.5f, -0.5f, 0}, {0.5f, 0.5f, 1}, 16.0f / 9.0f);
    for (float elevation : {camera.elevation, 1.5f}) {
        camera.elevation = elevation;
        for (const Edges& edges : {kHard, kBlended, kSampled}) {
            const Drawn all = draw(snapshot, camera, {640, 360}, edges, false);
            const Drawn seen = draw(snapshot, camera, {640, 360}, edges, true);
            EXPECT_EQ(differingPixels(all.image, seen.image), 0) << "elevation " << elevation << ", " << edges;
            // With hard outlines most of the pile is left out (with soft ones its spheres
            // of a few pixels are too small to hide others).
            if (!edges.antialiased) {
                EXPECT_LT(seen.spheres, all.spheres / 2) << "elevation " << elevation;
            }
            EXPECT_LE(seen.spheres, all.spheres);
        }
    }
}

}  // namespace
