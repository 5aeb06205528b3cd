// Render and platform tests: plane clipping and camera math on the CPU, then
// headless image tests run once per GL backend (OSMesa, EGL). Images are
// checked by properties with tolerances, never exact pixels (Mesa versions differ).
#include <glad/gl.h>
#include <gtest/gtest.h>

#include "image_compare.h"
#include "shaded_colour.h"
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "physics/diagnostics.h"
#include "physics/world.h"
#include "platform/headless_context.h"
#include "platform/window.h"
#include "render/camera.h"
#include "render/frame_snapshot.h"
#include "render/image_io.h"
#include "render/offscreen_target.h"
#include "render/palette.h"
#include "render/plane_clipping.h"
#include "render/renderer.h"
#include "ui/imgui_gl_renderer.h"

// Test names show the backend ("osmesa", "egl") instead of its bytes.
namespace platform {
void PrintTo(HeadlessBackend backend, std::ostream* out) { *out << toString(backend); }
}  // namespace platform

namespace {

using glm::vec3;
using render::Polygon;

// The 2 x 2 x 2 m box of the classroom scenes: floor z = 0, x and y in [-1, 1].
std::vector<render::Plane> boxPlanes() {
    return {{{0, 0, 0}, {0, 0, 1}},  {{0, 0, 2}, {0, 0, -1}}, {{-1, 0, 1}, {1, 0, 0}},
            {{1, 0, 1}, {-1, 0, 0}}, {{0, -1, 1}, {0, 1, 0}}, {{0, 1, 1}, {0, -1, 0}}};
}

render::FrameSnapshot boxSnapshot() {
    render::FrameSnapshot snapshot;
    snapshot.planes = boxPlanes();
    snapshot.boxPlaneCount = 6;
    return snapshot;
}

// Whether every expected vertex is in the polygon (any order), to 1e-4 m.
void expectSameVertices(const Polygon& polygon, const std::vector<vec3>& expected) {
    ASSERT_EQ(polygon.size(), expected.size());
    for (const vec3& e : expected) {
        const bool found = std::any_of(polygon.begin(), polygon.end(),
                                       [&](const vec3& p) { return glm::length(p - e) < 1e-4f; });
        EXPECT_TRUE(found) << "missing vertex (" << e.x << ", " << e.y << ", " << e.z << ")";
    }
}

float polygonArea(const Polygon& polygon) {
    vec3 twiceArea(0.0f);
    for (std::size_t i = 1; i + 1 < polygon.size(); ++i) {
        twiceArea += glm::cross(polygon[i] - polygon[0], polygon[i + 1] - polygon[0]);
    }
    return 0.5f * glm::length(twiceArea);
}

// ---------------------------------------------------------------- plane clipping

TEST(PlaneClipping, FloorOfTwoMetreBoxIsItsFourCorners) {
    const std::vector<Polygon> polygons = render::planePolygons(boxSnapshot());
    ASSERT_EQ(polygons.size(), 6u);
    expectSameVertices(polygons[0], {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}});
    expectSameVertices(polygons[2], {{-1, -1, 0}, {-1, 1, 0}, {-1, 1, 2}, {-1, -1, 2}});
}

TEST(PlaneClipping, InclinedPlaneIsCutByTheWalls) {
    render::FrameSnapshot snapshot = boxSnapshot();
    // z = 1 + y: rises from the floor at y = -1 to the ceiling at y = 1.
    snapshot.planes.push_back({{0, 0, 1}, glm::normalize(vec3(0, -1, 1))});
    const Polygon incline = render::planePolygons(snapshot)[6];
    expectSameVertices(incline, {{-1, -1, 0}, {1, -1, 0}, {1, 1, 2}, {-1, 1, 2}});
    EXPECT_NEAR(polygonArea(incline), 2.0f * 2.0f * std::sqrt(2.0f), 1e-3f);
}

TEST(PlaneClipping, ClipPolygonKeepsTheFreeSide) {
    const Polygon square = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}};
    // Keep x >= 0.5: a 1.5 x 2 rectangle.
    const Polygon kept = render::clipPolygon(square, {{0.5f, 0, 0}, {1, 0, 0}});
    expectSameVertices(kept, {{0.5f, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0.5f, 2, 0}});
    // A diagonal cut keeps a triangle of half the area.
    const Polygon half = render::clipPolygon(square, {{1, 1, 0}, glm::normalize(vec3(-1, -1, 0))});
    EXPECT_EQ(half.size(), 3u);
    EXPECT_NEAR(polygonArea(half), 2.0f, 1e-5f);
    EXPECT_TRUE(render::clipPolygon(square, {{3, 0, 0}, {1, 0, 0}}).empty());
}

TEST(PlaneClipping, WithoutBoxPlanesAreCutByACubeAroundTheSpheres) {
    render::FrameSnapshot snapshot;
    snapshot.planes.push_back({{0, 0, 0}, {0, 0, 1}});
    snapshot.addSphere({0, 0, 0.5f}, 0.5f, {255, 0, 0, 255});
    const Polygon ground = render::planePolygons(snapshot)[0];
    ASSERT_EQ(ground.size(), 4u);
    // Finite, centred on the sphere, larger than its footprint, not absurdly large.
    float extent = 0.0f;
    for (const vec3& p : ground) extent = std::max(extent, std::abs(p.x));
    EXPECT_GT(extent, 1.0f);
    EXPECT_LT(extent, 10.0f);
}

TEST(PlaneClipping, FloorIsTheUpwardBoxPlaneAndNearnessFollowsTheCamera) {
    EXPECT_EQ(render::floorPlaneIndex(boxSnapshot()), 0);
    const render::Plane wall = boxPlanes()[4];  // y = -1, normal +y
    EXPECT_TRUE(render::isNearPlane(wall, {0, -5, 1}));
    EXPECT_FALSE(render::isNearPlane(wall, {0, 0, 1}));
}

// ---------------------------------------------------------------- camera

TEST(Camera, TargetProjectsToTheViewportCentreAndRaysInvertProjection) {
    render::Camera camera;
    const glm::vec2 size(640, 360);
    const vec3 centre = camera.project(camera.target, size);
    EXPECT_NEAR(centre.x, 320.0f, 1e-3f);
    EXPECT_NEAR(centre.y, 180.0f, 1e-3f);
    const vec3 point(0.3f, -0.2f, 0.9f);
    const vec3 pixel = camera.project(point, size);
    const render::Ray ray = camera.rayThroughPixel(glm::vec2(pixel), size);
    // The point lies on the ray: its distance to the line is ~0.
    const vec3 toPoint = point - ray.origin;
    EXPECT_NEAR(glm::length(toPoint - glm::dot(toPoint, ray.direction) * ray.direction), 0.0f,
                1e-4f);
    // Up in the world is up on the screen (smaller y).
    EXPECT_LT(camera.project(camera.target + vec3(0, 0, 0.1f), size).y, centre.y);
}

TEST(Camera, FitBoxKeepsEveryCornerInsideAndIsTight) {
    render::Camera camera;
    const glm::vec2 size(1280, 720);
    camera.reset({-1, -1, 0}, {1, 1, 2}, size.x / size.y);
    float closestToEdge = 1e9f;
    for (int c = 0; c < 8; ++c) {
        const vec3 corner(c & 1 ? 1 : -1, c & 2 ? 1 : -1, c & 4 ? 2 : 0);
        const vec3 p = camera.project(corner, size);
        EXPECT_GT(p.x, 0.0f);
        EXPECT_LT(p.x, size.x);
        EXPECT_GT(p.y, 0.0f);
        EXPECT_LT(p.y, size.y);
        closestToEdge = std::min({closestToEdge, p.x, size.x - p.x, p.y, size.y - p.y});
    }
    EXPECT_LT(closestToEdge, 0.06f * size.y);  // fills the view up to the margin
}

TEST(Camera, OrbitZoomAndPanMoveAsTheAppExpects) {
    render::Camera camera;
    const float distance = camera.distance;
    camera.zoom(1.0f);
    EXPECT_NEAR(camera.distance, 0.9f * distance, 1e-5f);
    const float elevation = camera.elevation;
    camera.orbit(0.0f, 10000.0f);
    EXPECT_GT(camera.elevation, elevation);
    EXPECT_LT(camera.elevation, 1.5708f);  // clamped short of the pole
    render::Camera panned;
    const glm::vec2 size(800, 600);
    const vec3 before = panned.project(vec3(0, 0, 0.5f), size);
    panned.pan(50.0f, 0.0f, size.y);
    // Dragging right by 50 px moves what was under the cursor right by 50 px.
    EXPECT_NEAR(panned.project(vec3(0, 0, 0.5f), size).x - before.x, 50.0f, 0.5f);
}

// ---------------------------------------------------------------- colours and snapshot

int channelSpread(glm::u8vec4 a, glm::u8vec4 b) {
    return std::max({std::abs(a.x - b.x), std::abs(a.y - b.y), std::abs(a.z - b.z)});
}

float luminance(glm::u8vec4 c) { return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z; }

TEST(Palette, ContactStatesAndNeighbouringIdsAreDistinct) {
    using physics::ContactState;
    const auto free = render::contactColor(ContactState::Free);
    const auto colliding = render::contactColor(ContactState::Colliding);
    const auto resting = render::contactColor(ContactState::Static);
    EXPECT_GT(channelSpread(free, colliding), 100);
    EXPECT_GT(channelSpread(free, resting), 60);
    EXPECT_GT(channelSpread(colliding, resting), 100);
    for (std::uint32_t id = 0; id < 50; ++id) {
        EXPECT_GT(channelSpread(render::idColor(id), render::idColor(id + 1)), 40) << id;
    }
}

TEST(Palette, SpeedColormapBrightensMonotonicallyAndClamps) {
    float previous = -1.0f;
    for (int i = 0; i <= 10; ++i) {
        const float l = luminance(render::speedColor(0.3f * static_cast<float>(i), 3.0f));
        EXPECT_GT(l, previous) << i;
        previous = l;
    }
    EXPECT_EQ(render::speedColor(30.0f, 3.0f), render::speedColor(3.0f, 3.0f));
    EXPECT_GT(luminance(render::speedColor(0.0f, 3.0f)), 30.0f);  // slow spheres stay visible
}

TEST(Snapshot, CopiesSpheresPlanesAndContactColours) {
    physics::World world;
    world.addSphere({0.1, 0.2, 0.3}, {0, 0, 0}, 0.05, 1.0);
    world.addSphere({-0.4, 0.0, 1.0}, {3, 0, 4}, 0.1, 1.0);
    world.contactState[1] = physics::ContactState::Colliding;
    world.planes.push_back({{0, 0, 0}, {0, 0, 1}});
    world.boxPlaneCount = 1;
    render::FrameSnapshot snapshot;
    render::snapshotSpheres(world, render::ColorBy::ContactState, snapshot);
    render::snapshotPlanes(world, snapshot);
    ASSERT_EQ(snapshot.sphereCount(), 2u);
    EXPECT_FLOAT_EQ(snapshot.centers[0].y, 0.2f);
    EXPECT_FLOAT_EQ(snapshot.radii[1], 0.1f);
    EXPECT_EQ(snapshot.colors[0], render::contactColor(physics::ContactState::Free));
    EXPECT_EQ(snapshot.colors[1], render::contactColor(physics::ContactState::Colliding));
    EXPECT_EQ(snapshot.boxPlaneCount, 1);
    ASSERT_EQ(snapshot.planes.size(), 1u);
    render::snapshotSpheres(world, render::ColorBy::Speed, snapshot, 5.0f);  // |v1| = 5 m/s
    EXPECT_EQ(snapshot.colors[1], render::speedColor(5.0f, 5.0f));
}

// Colour by penetration: each sphere's deepest overlap, with a sphere over the smaller
// radius, with a plane over its own; the colormap over the decades 0.01 % to 10 % of r.
TEST(Snapshot, ColourByPenetrationShowsEachSpheresDeepestOverlap) {
    physics::World world;
    world.addSphere({0.0, 0.0, 0.1 - 1e-4}, {0, 0, 0}, 0.1, 1.0);   // 0.1 % of r into the floor
    world.addSphere({0.0, 0.0, 0.3 - 2e-3}, {0, 0, 0}, 0.1, 1.0);   // 1 % of r into the one below
    world.addSphere({1.0, 0.0, 0.5}, {0, 0, 0}, 0.1, 1.0);          // touches nothing
    world.planes.push_back({{0, 0, 0}, {0, 0, 1}});
    world.boxPlaneCount = 1;
    const std::vector<double> deepest = physics::deepestOverlaps(world);
    EXPECT_NEAR(deepest[0], 0.019, 1e-9) << "the sphere above, over the smaller radius";
    EXPECT_NEAR(deepest[1], 0.019, 1e-9);
    EXPECT_EQ(deepest[2], 0.0);
    render::FrameSnapshot snapshot;
    render::snapshotSpheres(world, render::ColorBy::Penetration, snapshot);
    EXPECT_EQ(snapshot.colors[0], render::penetrationColor(0.019));
    EXPECT_EQ(snapshot.colors[2], render::speedColor(0.0f, 1.0f)) << "none: the darkest";
    EXPECT_EQ(render::penetrationColor(1e-5), render::speedColor(0.0f, 1.0f));
    EXPECT_EQ(render::penetrationColor(0.5), render::speedColor(1.0f, 1.0f)) << "10 % of r and deeper: the brightest";
    EXPECT_EQ(render::penetrationColor(std::pow(10.0, -2.5)), render::speedColor(0.5f, 1.0f)) << "a log scale";
    EXPECT_LT(luminance(render::penetrationColor(1e-3)), luminance(render::penetrationColor(1e-2)));
}

TEST(ImageIo, PngRoundTripKeepsEveryByte) {
    const int width = 7;
    const int height = 3;
    std::vector<std::uint8_t> rgba(width * height * 4);
    for (std::size_t i = 0; i < rgba.size(); ++i) rgba[i] = static_cast<std::uint8_t>(i * 37);
    const std::string path = ::testing::TempDir() + "spheres_roundtrip.png";
    ASSERT_TRUE(render::writePng(path, width, height, rgba));
    render::Image image;
    ASSERT_TRUE(render::readPng(path, &image));
    EXPECT_EQ(image.width, width);
    EXPECT_EQ(image.height, height);
    EXPECT_EQ(image.rgba, rgba);
    EXPECT_EQ(image.pixel(1, 2), glm::u8vec4(rgba[60], rgba[61], rgba[62], rgba[63]));
    EXPECT_FALSE(render::readPng(path + ".missing", &image));
}

// ---------------------------------------------------------------- platform

// Restores an environment variable when the test ends.
class ScopedUnsetEnv {
  public:
    explicit ScopedUnsetEnv(const char* name) : name_(name) {
        if (const char* value = std::getenv(name)) saved_ = std::make_unique<std::string>(value);
        unsetenv(name);
    }
    ~ScopedUnsetEnv() {
        if (saved_) setenv(name_, saved_->c_str(), 1);
    }
    ScopedUnsetEnv(const ScopedUnsetEnv&) = delete;
    ScopedUnsetEnv& operator=(const ScopedUnsetEnv&) = delete;

  private:
    const char* name_;
    std::unique_ptr<std::string> saved_;
};

TEST(PlatformWindow, WithoutADisplayCreateReturnsAnErrorInsteadOfCrashing) {
    ScopedUnsetEnv display("DISPLAY");
    ScopedUnsetEnv wayland("WAYLAND_DISPLAY");
    std::string error;
    const auto window = platform::Window::create({}, &error);
    EXPECT_EQ(window, nullptr);
    EXPECT_NE(error.find("GLFW error"), std::string::npos) << error;
}

TEST(PlatformHeadless, BackendNamesParseBothWays) {
    using platform::HeadlessBackend;
    for (HeadlessBackend b :
         {HeadlessBackend::Auto, HeadlessBackend::OSMesa, HeadlessBackend::EGL}) {
        EXPECT_EQ(platform::parseHeadlessBackend(platform::toString(b)), b);
    }
    EXPECT_FALSE(platform::parseHeadlessBackend("glx").has_value());
}

TEST(PlatformHeadless, AutoGivesAContextWhenEitherBackendWorks) {
    std::string error;
    const auto context = platform::createHeadless(platform::HeadlessBackend::Auto, &error);
    if (!context) GTEST_SKIP() << "no headless GL backend available (OSMesa, EGL): " << error;
    const std::string name = context->name();
    EXPECT_TRUE(name == "osmesa" || name == "egl") << name;
    // Auto tries OSMesa first.
    if (platform::headlessBackendCompiled(platform::HeadlessBackend::OSMesa)) {
        std::string osmesaError;
        if (platform::createHeadless(platform::HeadlessBackend::OSMesa, &osmesaError)) {
            EXPECT_EQ(name, "osmesa");
        }
    }
}

// ---------------------------------------------------------------- headless images

// One GL context per test, made with the backend of the test's parameter.
class Headless : public ::testing::TestWithParam<platform::HeadlessBackend> {
  protected:
    void SetUp() override {
        std::string error;
        context_ = platform::createHeadless(GetParam(), &error);
        if (!context_) {
            GTEST_SKIP() << platform::toString(GetParam()) << " is not available here: " << error;
        }
        GLint major = 0;
        GLint minor = 0;
        glGetIntegerv(GL_MAJOR_VERSION, &major);
        glGetIntegerv(GL_MINOR_VERSION, &minor);
        ASSERT_GE(major * 10 + minor, 33);
        RecordProperty("backend", context_->name());
        std::cout << "[ backend  ] " << context_->name() << ": "
                  << reinterpret_cast<const char*>(glGetString(GL_RENDERER)) << ", GL "
                  << reinterpret_cast<const char*>(glGetString(GL_VERSION)) << "\n";
    }

    // Renders the snapshot into a fresh target of width x height pixels.
    render::Image draw(const render::FrameSnapshot& snapshot, const render::Camera& camera,
                       int width, int height, const render::RenderStyle& style = {}, int samples = 0) {
        render::OffscreenTarget target;
        EXPECT_EQ(target.resize(width, height, samples), "");
        render::Renderer renderer;
        EXPECT_EQ(renderer.init(), "");
        renderer.style = style;
        renderer.draw(snapshot, camera, 0, 0, width, height);
        EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
        return target.read();
    }

    std::unique_ptr<platform::HeadlessContext> context_;
};

std::string backendName(const ::testing::TestParamInfo<platform::HeadlessBackend>& info) {
    return platform::toString(info.param);
}

glm::u8vec4 pixelAt(const render::Image& image, const vec3& projected) {
    return image.pixel(static_cast<int>(projected.x), static_cast<int>(projected.y));
}

render::Camera frontCamera(const vec3& target, float distance) {
    render::Camera camera;
    camera.target = target;
    camera.azimuth = -1.5708f;  // eye on the -y side, looking along +y
    camera.elevation = 0.0f;
    camera.distance = distance;
    return camera;
}

constexpr glm::u8vec4 kRed{220, 40, 30, 255};
constexpr glm::u8vec4 kBlue{40, 80, 220, 255};

TEST_P(Headless, SphereCentrePixelHasTheSpheresShadedColour) {
    render::FrameSnapshot snapshot;
    snapshot.addSphere({0.2f, 0, 0.6f}, 0.25f, kRed);
    const render::Camera camera = frontCamera({0, 0, 0.5f}, 4.0f);
    const int width = 200;
    const int height = 150;
    const render::Image image = draw(snapshot, camera, width, height);
    const render::Image empty = draw({}, camera, width, height);

    const glm::vec2 size(width, height);
    const vec3 centre = camera.project({0.2f, 0, 0.6f}, size);
    expectShadedVersionOf(pixelAt(image, centre), kRed);
    // The outline matches the projection: 0.8 r inside is sphere, 1.25 r outside is background.
    const float radiusPixels = camera.project({0.2f + 0.25f, 0, 0.6f}, size).x - centre.x;
    ASSERT_GT(radiusPixels, 5.0f);
    for (float side : {-1.0f, 1.0f}) {
        const vec3 inside = centre + vec3(side * 0.8f * radiusPixels, 0, 0);
        const vec3 outside = centre + vec3(side * 1.25f * radiusPixels, 0, 0);
        EXPECT_GT(pixelAt(image, inside).x, 2 * pixelAt(image, inside).z) << "inside " << side;
        EXPECT_LE(channelSpread(pixelAt(image, outside), pixelAt(empty, outside)), 2)
            << "outside " << side;
    }
}

TEST_P(Headless, IntersectingSpheresMeetWhereTheirSurfacesCross) {
    // Two overlapping spheres seen from the front: left of the middle the left
    // sphere's surface is nearer, right of it the right one's, whatever the draw
    // order. Only a per-pixel depth from the ray-sphere hit gets this right.
    const render::Camera camera = frontCamera({0, 0, 0}, 5.0f);
    const glm::vec2 size(240, 160);
    for (bool leftFirst : {true, false}) {
        render::FrameSnapshot snapshot;
        if (leftFirst) snapshot.addSphere({-0.3f, 0, 0}, 0.5f, kRed);
        snapshot.addSphere({0.3f, 0, 0}, 0.5f, kBlue);
        if (!leftFirst) snapshot.addSphere({-0.3f, 0, 0}, 0.5f, kRed);
        const render::Image image = draw(snapshot, camera, 240, 160);
        const glm::u8vec4 left = pixelAt(image, camera.project({-0.12f, 0, 0}, size));
        const glm::u8vec4 right = pixelAt(image, camera.project({0.12f, 0, 0}, size));
        EXPECT_GT(left.x, left.z + 60) << "left of the seam is red, leftFirst=" << leftFirst;
        EXPECT_GT(right.z, right.x + 60) << "right of the seam is blue, leftFirst=" << leftFirst;
    }
}

TEST_P(Headless, FloorIsDrawnInFrontOfASphereResting) {
    render::FrameSnapshot snapshot = boxSnapshot();
    snapshot.addSphere({0, 0, 0.2f}, 0.2f, kRed);
    render::Camera camera;
    camera.reset({-1, -1, 0}, {1, 1, 2}, 4.0f / 3.0f);
    const glm::vec2 size(200, 150);
    const render::Image image = draw(snapshot, camera, 200, 150);
    render::FrameSnapshot spheresOnly = snapshot;
    spheresOnly.planes.clear();
    spheresOnly.boxPlaneCount = 0;
    const render::Image bare = draw(spheresOnly, camera, 200, 150);

    // A floor point between the sphere and the eye, half a radius beyond its foot.
    const vec3 towardsEye = glm::normalize(vec3(camera.position().x, camera.position().y, 0));
    const vec3 floorPoint = towardsEye * 0.3f;
    const glm::u8vec4 withFloor = pixelAt(image, camera.project(floorPoint, size));
    const glm::u8vec4 background = pixelAt(bare, camera.project(floorPoint, size));
    EXPECT_GT(luminance(withFloor), luminance(background) + 25.0f) << "the floor is light";
    EXPECT_GT(channelSpread(withFloor, background), 25);
    // The sphere still shows on the floor.
    expectShadedVersionOf(pixelAt(image, camera.project({0, 0, 0.2f}, size)), kRed);
}

TEST_P(Headless, FloorGridHasALineEveryTenthOfAMetre) {
    render::FrameSnapshot snapshot = boxSnapshot();
    render::Camera camera;
    camera.target = {0, 0, 0};
    camera.elevation = 1.55f;  // looking almost straight down
    camera.azimuth = -1.5708f;
    camera.distance = 3.0f;
    const int width = 400;
    const int height = 400;
    const render::Image image = draw(snapshot, camera, width, height);
    // Walk along the x axis of the floor, from x = -0.95 to 0.95 m, and count dark runs.
    const glm::vec2 size(width, height);
    const int y = static_cast<int>(camera.project({0, 0.05f, 0}, size).y);
    const int x0 = static_cast<int>(camera.project({-0.95f, 0.05f, 0}, size).x);
    const int x1 = static_cast<int>(camera.project({0.95f, 0.05f, 0}, size).x);
    float brightest = 0.0f;
    for (int x = x0; x <= x1; ++x) brightest = std::max(brightest, luminance(image.pixel(x, y)));
    int lines = 0;
    bool inLine = false;
    for (int x = x0; x <= x1; ++x) {
        const bool dark = luminance(image.pixel(x, y)) < brightest - 20.0f;
        if (dark && !inLine) ++lines;
        inLine = dark;
    }
    EXPECT_EQ(lines, 19) << "lines at x = -0.9, -0.8, ..., 0.9 m";
}

TEST_P(Headless, NearWallsAreEdgesOnlyAndFarWallsAreShaded) {
    const render::FrameSnapshot box = boxSnapshot();
    render::FrameSnapshot withoutNearWall = box;
    withoutNearWall.planes.erase(withoutNearWall.planes.begin() + 4);  // y = -1, faces the eye
    withoutNearWall.boxPlaneCount = 5;
    const render::Camera camera = frontCamera({0, 0, 1}, 5.0f);
    const glm::vec2 size(200, 200);
    const render::Image image = draw(box, camera, 200, 200);
    const render::Image open = draw(withoutNearWall, camera, 200, 200);
    const render::Image empty = draw({}, camera, 200, 200);
    // Through the middle of the near wall one sees the far wall (y = +1) as in the open box.
    const vec3 middle = camera.project({0.3f, 1, 1.2f}, size);
    EXPECT_LE(channelSpread(pixelAt(image, middle), pixelAt(open, middle)), 2);
    // The far wall is a face: it differs from the background.
    EXPECT_GE(channelSpread(pixelAt(image, middle), pixelAt(empty, middle)), 8);
}

TEST_P(Headless, OverlayLinesAndPointsAreDrawnWithTheirColour) {
    render::FrameSnapshot snapshot;
    snapshot.addLine({-0.5f, 0, 0}, {0.5f, 0, 0}, {255, 0, 255, 255}, 4.0f);
    snapshot.addPoint({0, 0, 0.4f}, {0, 255, 0, 255}, 12.0f);
    const render::Camera camera = frontCamera({0, 0, 0}, 3.0f);
    const glm::vec2 size(160, 120);
    const render::Image image = draw(snapshot, camera, 160, 120);
    EXPECT_LE(channelSpread(pixelAt(image, camera.project({0.2f, 0, 0}, size)), {255, 0, 255, 255}),
              10);
    EXPECT_LE(channelSpread(pixelAt(image, camera.project({0, 0, 0.4f}, size)), {0, 255, 0, 255}),
              10);
    // Beyond the segment's end (and its round cap) the background shows.
    EXPECT_GT(channelSpread(pixelAt(image, camera.project({0.7f, 0, 0}, size)), {255, 0, 255, 255}),
              100);
}

// A dot is drawn as one point (dot.vert): a round disc of its diameter, anti-aliased at
// its rim. A point whose centre leaves the viewport would be clipped whole: a dot whose
// disc crosses the viewport's edge is drawn as a zero-length segment, its inner part shown.
TEST_P(Headless, ADotIsARoundDiscOfItsSizeAndShowsAtTheViewportsEdgeToo) {
    const render::Camera camera = frontCamera({0, 0, 0}, 3.0f);
    const glm::vec2 size(160, 120);
    const float x0 = camera.project({0, 0, 0}, size).x, perMetre = camera.project({1, 0, 0}, size).x - x0;  // px
    const glm::u8vec4 green{0, 255, 0, 255};
    render::FrameSnapshot snapshot;
    snapshot.addPoint({0, 0, 0}, green, 12.0f);                           // radius 6 px, in the middle
    snapshot.addPoint({(-2.0f - x0) / perMetre, 0, 0.3f}, green, 16.0f);  // centre 2 px left of the edge
    const render::Image image = draw(snapshot, camera, 160, 120);
    const vec3 centre = camera.project({0, 0, 0}, size);
    for (const float angle : {0.0f, 0.8f, 1.6f, 2.4f, 3.9f, 5.5f}) {
        const glm::vec2 along(std::cos(angle), std::sin(angle));
        const auto at = [&](float pixels) { return pixelAt(image, centre + vec3(pixels * along, 0.0f)); };
        EXPECT_LE(channelSpread(at(4.5f), green), 10) << "inside the disc, angle " << angle;
        EXPECT_GT(channelSpread(at(8.0f), green), 100) << "outside it, angle " << angle;
    }
    const int edgeRow = static_cast<int>(camera.project({0, 0, 0.3f}, size).y);
    EXPECT_LE(channelSpread(image.pixel(1, edgeRow), green), 10) << "the inner part of the dot at the edge";
}

TEST_P(Headless, DrawTouchesOnlyItsViewport) {
    render::OffscreenTarget target;
    ASSERT_EQ(target.resize(200, 100), "");
    glClearColor(1.0f, 0.0f, 1.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    render::Renderer renderer;
    ASSERT_EQ(renderer.init(), "");
    render::FrameSnapshot snapshot;
    snapshot.addSphere({0, 0, 0}, 0.5f, kBlue);
    renderer.draw(snapshot, frontCamera({0, 0, 0}, 4.0f), 0, 0, 100, 100);  // left half
    const render::Image image = target.read();
    EXPECT_EQ(image.pixel(150, 50), glm::u8vec4(255, 0, 255, 255));
    EXPECT_EQ(image.pixel(199, 0), glm::u8vec4(255, 0, 255, 255));
    expectShadedVersionOf(image.pixel(50, 50), kBlue);
}

// A white sphere on black, a row through its centre: the pixels at each edge are
// blends, darker than their inner neighbour and brighter than the background.
int blendedEdgePixels(int samples, bool antialiasEdges = true) {
    render::FrameSnapshot snapshot;
    snapshot.addSphere({0, 0, 0}, 0.5f, {255, 255, 255, 255});
    render::OffscreenTarget target;
    if (!target.resize(160, 160, samples).empty()) return -1;
    render::Renderer renderer;
    if (!renderer.init().empty()) return -1;
    renderer.style.backgroundTop = renderer.style.backgroundBottom = glm::vec3(0.0f);
    renderer.style.antialiasEdges = antialiasEdges;
    renderer.draw(snapshot, frontCamera({0, 0, 0}, 4.0f), 0, 0, 160, 160);
    const render::Image image = target.read();
    int blended = 0;
    for (int x = 1; x + 1 < 160; ++x) {
        const glm::u8vec4 p = image.pixel(x, 80);
        EXPECT_EQ(p.w, 255) << x << ": alpha stays 1";
        const int inner = std::max(image.pixel(x - 1, 80).x, image.pixel(x + 1, 80).x);
        if (p.x > 10 && p.x < 0.85f * static_cast<float>(inner)) ++blended;
    }
    return blended;
}

// Alpha to coverage on a multisampled target, blending on one without samples (the
// window's views); and hard outlines when the style asks for them.
TEST_P(Headless, SphereOutlinesAreBlendedWithAndWithoutSamples) {
    EXPECT_EQ(blendedEdgePixels(4), 2) << "one blended pixel at each edge, 4 samples";
    EXPECT_EQ(blendedEdgePixels(0), 2) << "one blended pixel at each edge, no samples";
    EXPECT_EQ(blendedEdgePixels(0, false), 0) << "hard outlines";
}

// A translucent plane (07's incline, 13's thin wall) is drawn after the spheres. Blended, a
// sphere's edge must neither hide it (edges that wrote depth left a dark ring, the
// background untinted, around every sphere in front of the incline: 98 pixels here) nor
// escape the tint of a plane in front of it. A white sphere on black, a half-opaque red
// plane behind the sphere or in front of it: around the outline, the picture without
// samples is the 4-sample one's but for the samples' steps of a quarter (up to 64 of 255).
// Returns the pixels there that differ by more.
int edgePixelsUnlikeSampled(float planeY) {
    render::FrameSnapshot snapshot;
    snapshot.addSphere({0, 0, 0}, 0.5f, {255, 255, 255, 255});
    snapshot.planes.push_back({{0, planeY, 0}, {0, -1, 0}});  // facing the eye
    const render::Camera camera = frontCamera({0, 0, 0}, 4.0f);
    const int width = 200, height = 160;
    render::Renderer renderer;
    if (!renderer.init().empty()) return -1;
    renderer.style.backgroundTop = renderer.style.backgroundBottom = glm::vec3(0.0f);
    renderer.style.extraPlaneColor = glm::vec4(1.0f, 0.0f, 0.0f, 0.5f);
    render::Image images[2];
    for (int samples : {0, 4}) {
        render::OffscreenTarget target;
        if (!target.resize(width, height, samples).empty()) return -1;
        renderer.draw(snapshot, camera, 0, 0, width, height);
        images[samples > 0] = target.read();
    }
    const glm::vec2 size(width, height);
    const vec3 centre = camera.project({0, 0, 0}, size);
    const float radius = camera.project({0.5f, 0, 0}, size).x - centre.x;  // px
    int unlike = 0;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const float off = std::hypot(x + 0.5f - centre.x, y + 0.5f - centre.y) - radius;  // px
            if (std::abs(off) <= 1.0f) unlike += channelSpread(images[0].pixel(x, y), images[1].pixel(x, y)) > 64;
        }
    }
    return unlike;
}

TEST_P(Headless, ASpheresBlendedEdgeMeetsATranslucentPlaneAsWithSamples) {
    EXPECT_EQ(edgePixelsUnlikeSampled(0.8f), 0) << "the plane behind the sphere";
    EXPECT_EQ(edgePixelsUnlikeSampled(-0.8f), 0) << "the plane in front of it";
}

// Without samples an outline blends over what was drawn before it, so the spheres are
// drawn from the farthest to the nearest whatever their order in the snapshot (a nearer
// sphere drawn first would blend its outline over the background and hide the farther
// one there: a dark ring). Large and small, near and far, squares (across the viewport's
// edge, or large) and point sprites in turn: the picture is the 4-sample one's but for the
// samples' steps.
TEST_P(Headless, BlendedOutlinesDoNotDependOnTheSpheresOrder) {
    const render::Camera camera = frontCamera({0, 0, 0}, 4.0f);
    std::vector<std::pair<glm::vec3, float>> spheres = {
        {{0.0f, 0.0f, 0.0f}, 0.5f},      {{0.45f, -0.6f, 0.1f}, 0.3f},  {{-0.3f, -1.2f, -0.2f}, 0.15f},
        {{-0.6f, 0.8f, 0.3f}, 0.6f},     {{0.3f, -1.5f, 0.35f}, 0.08f}, {{-1.9f, 0.0f, 0.0f}, 0.4f},
        {{0.05f, -0.9f, -0.05f}, 0.12f}, {{0.9f, 0.5f, -0.4f}, 0.5f},  {{0.35f, -3.0f, -0.3f}, 0.25f},
        {{1.15f, -1.0f, 0.3f}, 0.3f}};
    const glm::u8vec4 colors[] = {kRed, kBlue, {40, 200, 60, 255}, {230, 220, 40, 255}};
    const auto drawInOrder = [&](bool reversed, int samples = 0) {
        render::FrameSnapshot snapshot;
        for (std::size_t k = 0; k < spheres.size(); ++k) {
            const std::size_t i = reversed ? spheres.size() - 1 - k : k;
            snapshot.addSphere(spheres[i].first, spheres[i].second, colors[i % 4]);
        }
        render::RenderStyle black;
        black.backgroundTop = black.backgroundBottom = glm::vec3(0.0f);
        return draw(snapshot, camera, 200, 160, black, samples);
    };
    const render::Image forward = drawInOrder(false), backward = drawInOrder(true), sampled = drawInOrder(false, 4);
    int differ = 0, unlikeSampled = 0;
    for (int y = 0; y < 160; ++y) {
        for (int x = 0; x < 200; ++x) {
            differ += forward.pixel(x, y) != backward.pixel(x, y);
            unlikeSampled += channelSpread(forward.pixel(x, y), sampled.pixel(x, y)) > 64;
        }
    }
    EXPECT_EQ(differ, 0);
    EXPECT_EQ(unlikeSampled, 0) << "pixels unlike the 4-sample picture by more than 64 of 255";
    // Where the blue sphere's outline crosses the red one (the row of the blue centre),
    // the pixels are blends of blue and red, not of blue and the black between.
    const glm::vec2 size(200, 160);
    const vec3 blue = camera.project({0.45f, -0.6f, 0.1f}, size);
    const vec3 red = camera.project({0.0f, 0.0f, 0.0f}, size);
    const int row = static_cast<int>(blue.y);
    for (const render::Image* image : {&forward, &backward}) {
        for (int x = static_cast<int>(red.x); x < static_cast<int>(blue.x); ++x) {
            const glm::u8vec4 p = image->pixel(x, row);
            EXPECT_GT(p.x + p.z, 120) << x << ": no dark ring between the red and the blue sphere";
        }
    }
}

// Renders one ImGui frame with a window at (20, 30) of size 100 x 80 (ImGui
// units) whose background is orange, into a target scaled by framebufferScale.
render::Image renderImGuiWindow(float framebufferScale, bool checkState) {
    const int width = 160;
    const int height = 120;
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.DisplaySize = ImVec2(width, height);
    io.DisplayFramebufferScale = ImVec2(framebufferScale, framebufferScale);
    io.DeltaTime = 1.0f / 60.0f;
    ui::ImGuiGlRenderer imguiRenderer;
    EXPECT_EQ(imguiRenderer.init(), "");

    render::OffscreenTarget target;
    const int pixelsWide = static_cast<int>(width * framebufferScale);
    const int pixelsHigh = static_cast<int>(height * framebufferScale);
    EXPECT_EQ(target.resize(pixelsWide, pixelsHigh), "");
    // Two frames: a new window may skip drawing on its very first one.
    for (int frame = 0; frame < 2; ++frame) {
        imguiRenderer.newFrame();
        EXPECT_EQ(imguiRenderer.error(), "");
        ImGui::NewFrame();
        ImGui::SetNextWindowPos(ImVec2(20, 30));
        ImGui::SetNextWindowSize(ImVec2(100, 80));
        ImGui::PushStyleColor(ImGuiCol_WindowBg, ImVec4(0.9f, 0.5f, 0.1f, 1.0f));
        ImGui::Begin("probe", nullptr,
                     ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoResize |
                         ImGuiWindowFlags_NoSavedSettings);
        ImGui::Text("Rigid Spheres");
        ImGui::End();
        ImGui::PopStyleColor();
        ImGui::Render();
    }
    target.bind();
    glClearColor(0.0f, 0.0f, 0.5f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    // State the renderer must leave as it found it.
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    glViewport(3, 4, 50, 60);
    glScissor(1, 2, 30, 40);
    imguiRenderer.render(ImGui::GetDrawData());
    if (checkState) {
        EXPECT_TRUE(glIsEnabled(GL_DEPTH_TEST));
        EXPECT_TRUE(glIsEnabled(GL_CULL_FACE));
        EXPECT_FALSE(glIsEnabled(GL_BLEND));
        EXPECT_FALSE(glIsEnabled(GL_SCISSOR_TEST));
        GLint viewport[4];
        GLint scissor[4];
        GLint program = -1;
        glGetIntegerv(GL_VIEWPORT, viewport);
        glGetIntegerv(GL_SCISSOR_BOX, scissor);
        glGetIntegerv(GL_CURRENT_PROGRAM, &program);
        EXPECT_EQ(viewport[2], 50);
        EXPECT_EQ(viewport[3], 60);
        EXPECT_EQ(scissor[0], 1);
        EXPECT_EQ(scissor[3], 40);
        EXPECT_EQ(program, 0);
    }
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    const render::Image image = target.read();
    imguiRenderer.shutdown();
    ImGui::DestroyContext();
    return image;
}

TEST_P(Headless, ImGuiWindowIsDrawnWithItsBackgroundColour) {
    const render::Image image = renderImGuiWindow(1.0f, true);
    // Inside the window, away from its text: the orange background (230, 128, 26).
    EXPECT_LE(channelSpread(image.pixel(100, 100), {230, 128, 26, 255}), 3);
    // Outside it: the clear colour.
    EXPECT_EQ(image.pixel(10, 10), glm::u8vec4(0, 0, 128, 255));
    EXPECT_EQ(image.pixel(130, 60), glm::u8vec4(0, 0, 128, 255));
    // The text is drawn from the font texture: some pixels of the first line are light.
    int light = 0;
    for (int y = 30; y < 50; ++y) {
        for (int x = 20; x < 120; ++x) light += luminance(image.pixel(x, y)) > 200.0f ? 1 : 0;
    }
    EXPECT_GT(light, 20);
}

TEST_P(Headless, ImGuiFollowsDisplayFramebufferScale) {
    const render::Image image = renderImGuiWindow(2.0f, false);
    ASSERT_EQ(image.width, 320);
    // The window spans (40, 60)-(240, 220) framebuffer pixels.
    EXPECT_LE(channelSpread(image.pixel(200, 200), {230, 128, 26, 255}), 3);
    EXPECT_LE(channelSpread(image.pixel(46, 200), {230, 128, 26, 255}), 3);
    EXPECT_EQ(image.pixel(36, 200), glm::u8vec4(0, 0, 128, 255));
    EXPECT_EQ(image.pixel(250, 200), glm::u8vec4(0, 0, 128, 255));
}

// An ImGui context, our renderer and a target of width x height px at a framebuffer
// scale, for the panel layer's tests. draw() clears the target to the backdrop, the view
// (x, y, width, height px from the top left) red as the scene would, and draws ImGui's
// last frame through the layer or straight in.
struct PanelLayerRig {
    PanelLayerRig(int w, int h, float scale, glm::ivec4 sceneView) : width(w), height(h), view(sceneView) {
        ImGui::CreateContext();
        ImGuiIO& io = ImGui::GetIO();
        io.IniFilename = nullptr;
        io.DisplaySize = ImVec2(float(w) / scale, float(h) / scale);
        io.DisplayFramebufferScale = ImVec2(scale, scale);
        io.DeltaTime = 1.0f / 60.0f;
        EXPECT_EQ(renderer.init(), "");
        EXPECT_EQ(target.resize(w, h), "");
    }
    ~PanelLayerRig() {
        renderer.shutdown();
        ImGui::DestroyContext();
    }
    void beginWindow(ImVec2 position, ImVec2 size) {  // in ImGui units
        renderer.newFrame();
        ImGui::NewFrame();
        ImGui::SetNextWindowPos(position);
        ImGui::SetNextWindowSize(size);
        ImGui::Begin("panel", nullptr, ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoSavedSettings);
    }
    void endWindow() {
        ImGui::End();
        ImGui::Render();
    }
    render::Image draw(bool layered) {
        target.bind();
        glClearColor(backdrop.x, backdrop.y, backdrop.z, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        glEnable(GL_SCISSOR_TEST);
        glScissor(view.x, height - view.y - view.w, view.z, view.w);
        glClearColor(1.0f, 0.0f, 0.0f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        glDisable(GL_SCISSOR_TEST);
        const ui::Backdrop beneath{backdrop, {glm::vec4(view)}};
        renderer.render(ImGui::GetDrawData(), layered ? &beneath : nullptr);
        return target.read();
    }
    const ui::PanelLayerStats& stats() const { return renderer.panelLayerStats(); }

    const int width, height;  // px
    const glm::ivec4 view;
    const glm::vec3 backdrop{0.09f, 0.10f, 0.12f};
    ui::ImGuiGlRenderer renderer;
    render::OffscreenTarget target;
};

// The panel layer: the first window is kept drawn in a texture and copied, and only what
// changed is drawn again. Frames where one line of text changes, then nothing, then a
// line is added above the last: each image is the one drawn straight in, pixel for
// pixel, the view beside the window (drawn by "the scene", here a red clear) is left as
// it was, and the texture is drawn again only around the changed line. A line on top
// moves all of it: then it is drawn straight in.
TEST_P(Headless, ThePanelLayerDrawsWhatDrawingStraightInDrawsAndOnlyTheChangedLineAgain) {
    PanelLayerRig rig(240, 160, 1.0f, glm::ivec4(120, 0, 120, 160));
    const auto frame = [&](const char* time, bool extraLine, bool lineOnTop = false) {
        rig.beginWindow(ImVec2(0, 0), ImVec2(120, 160));  // its border reaches into the view's first column
        if (lineOnTop) ImGui::Text("MID-AIR");
        ImGui::Text("Rigid spheres");
        ImGui::Text("t = %s s", time);
        ImGui::Button("Pause (P)");
        for (int line = 1; line <= 4; ++line) ImGui::Text("line %d", line);
        if (extraLine) ImGui::Text("one more line");
        rig.endWindow();
    };
    frame("1.000", false);
    frame("1.000", false);  // a new window may skip drawing on its very first frame
    const render::Image first = rig.draw(true);
    EXPECT_EQ(differingPixels(first, rig.draw(false)), 0);
    rig.draw(true);  // an empty layer first, then the same frame: nothing drawn again
    EXPECT_EQ(rig.stats().redrawn.w, 0.0f);
    frame("2.517", false);
    const render::Image layered = rig.draw(true);
    const ui::PanelLayerStats changed = rig.stats();
    EXPECT_EQ(differingPixels(layered, rig.draw(false)), 0);
    EXPECT_TRUE(changed.copied);
    EXPECT_GT(changed.redrawn.z * changed.redrawn.w, 0.0f);
    EXPECT_LT(changed.redrawn.w, 0.25f * rig.height) << "only the time's line";
    EXPECT_EQ(layered.pixel(200, 80), glm::u8vec4(255, 0, 0, 255)) << "the view left as the scene drew it";
    rig.draw(true);  // the same frame again: nothing drawn again
    EXPECT_TRUE(rig.stats().copied);
    EXPECT_EQ(rig.stats().redrawn.z * rig.stats().redrawn.w, 0.0f);
    frame("2.517", true);  // a line more at the end
    const render::Image grown = rig.draw(true);
    const ui::PanelLayerStats added = rig.stats();
    EXPECT_EQ(differingPixels(grown, rig.draw(false)), 0);
    EXPECT_TRUE(added.copied);
    EXPECT_GT(added.redrawn.y, changed.redrawn.y + changed.redrawn.w) << "the lines above stay";
    EXPECT_LT(added.redrawn.w, 0.5f * rig.height);
    rig.renderer.invalidateFontTexture();  // then all of it again
    frame("2.517", true);
    rig.draw(true);
    EXPECT_EQ(rig.stats().redrawn, glm::vec4(0, 0, rig.width, rig.height));
    frame("2.517", true, true);  // a line on top moves all below it: drawn straight in
    const render::Image moved = rig.draw(true);
    EXPECT_FALSE(rig.stats().copied);
    EXPECT_EQ(differingPixels(moved, rig.draw(false)), 0);
    // A view beneath the window's left edge: drawn straight in, no layer.
    const ui::Backdrop covered{rig.backdrop, {glm::vec4(0, 40, 40, 40)}};
    rig.target.bind();
    rig.renderer.render(ImGui::GetDrawData(), &covered);
    EXPECT_FALSE(rig.stats().copied);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// At a framebuffer scale of 1.5 the window's edges fall between pixels: the parts drawn
// again still give the frame drawn straight in. (renderList cuts each command's whole
// pixels to the part drawn again, so that a clip rectangle whose fractions differ at
// its two ends covers the same columns either way; this window does not show that case.)
TEST_P(Headless, ThePanelLayerAtAFractionalScaleDrawsWhatDrawingStraightInDraws) {
    PanelLayerRig rig(240, 160, 1.5f, glm::ivec4(0));
    for (int step = 0; step < 5; ++step) {
        rig.beginWindow(ImVec2(3, 7), ImVec2(101, 95));  // from 4.5, 10.5 px
        ImGui::Text("Rigid spheres");
        ImGui::Text("%d solver steps", 1000 + 37 * step);
        ImGui::Button("Pause (P)");
        rig.endWindow();
        const render::Image layered = rig.draw(true);
        const ui::PanelLayerStats stats = rig.stats();
        EXPECT_EQ(differingPixels(layered, rig.draw(false)), 0) << "step " << step;
        EXPECT_TRUE(stats.copied) << "step " << step;
        if (step >= 2) {
            EXPECT_LT(stats.redrawn.w, 0.3f * rig.height) << "step " << step;
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Backends, Headless,
                         ::testing::Values(platform::HeadlessBackend::OSMesa,
                                           platform::HeadlessBackend::EGL),
                         backendName);

}  // namespace
