// The classroom sizes, as images: `spheres capture --with-ui` at 1024x768 and
// 1280x720 (projectors), 1920x1080 and a HiDPI screen at 2x, lays the frame out as the
// window does (app/views/window_layout.h). In each, every corner of what the camera fits
// (the preset's box, or its camera's "fits") projects inside a view, no panel, label or bar was drawn over a view (ImGui's own
// draw lists say where it drew), and the pixels at the corners show the scene: no
// panel's dark grey there.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "app/commands/capture_command.h"
#include "render/camera.h"
#include "physics/step.h"
#include "scenes/parameters.h"
#include "scenes/presets.h"
#include "scenes/scene_json.h"
#include "scenes/scene.h"
#include "test_capture_support.h"
#include "ui/control_panel.h"

namespace {

struct Case {
    std::string name, scene, size;
    float uiScale = 1.0f;
    bool present = false;
};

// An ImGui panel's pixel: its window background, a dark neutral grey (the box's edges
// are a dark blue, the sky and the floor light, the spheres coloured).
bool panelPixel(glm::u8vec4 p) {
    const int hi = std::max({int(p.x), int(p.y), int(p.z)}), lo = std::min({int(p.x), int(p.y), int(p.z)});
    return hi < 40 && hi - lo < 8;
}

// x, y, width, height from the top left.
glm::vec4 topLeft(const nlohmann::json& view, int imageHeight) {
    const float x = view[0], y = view[1], w = view[2], h = view[3];
    return {x, float(imageHeight) - (y + h), w, h};
}

// Overlapping by more than ImGui's anti-aliased fringe (1 px around each shape).
bool overlap(const glm::vec4& a, const glm::vec4& b) {
    constexpr float kFringe = 1.5f;  // px
    return a.x < b.x + b.z - kFringe && b.x < a.x + a.z - kFringe && a.y < b.y + b.w - kFringe &&
           b.y < a.y + a.w - kFringe;
}

class LayoutImages : public ::testing::TestWithParam<Case> {
  protected:
    void SetUp() override {
        if (const std::string why = capture_test::unavailableReason(platform::HeadlessBackend::Auto); !why.empty()) {
            GTEST_SKIP() << "no headless GL: " << why;
        }
    }
};

TEST_P(LayoutImages, WhatTheCameraFitsIsInViewAndUncovered) {
    const Case& c = GetParam();
    const std::string out = capture_test::freshFolder("layout_" + c.name);
    app::CaptureOptions options;
    options.scene = c.scene;
    options.out = out;
    options.size = c.size;
    options.at = "30";
    options.withUi = true;
    options.uiScale = c.uiScale;
    options.present = c.present;
    ASSERT_EQ(app::runCapture(options), 0);
    const nlohmann::json manifest = capture_test::readManifest(out);
    const render::Image image = capture_test::readFrame(out, 30);
    const render::Camera camera = capture_test::cameraOf(manifest);
    const scenes::Scene scene = scenes::loadScene(scenes::presetPath(c.scene));
    ASSERT_TRUE(scene.box.has_value());
    // What the camera fits: the preset's camera "fits" (16_bernoulli's three spheres), else the box.
    const glm::vec3 size(scene.box->size);
    const std::optional<scenes::Region>& fits = scene.camera.fits;
    const glm::vec3 lo = fits ? glm::vec3(fits->min) : glm::vec3(-0.5f * size.x, -0.5f * size.y, 0.0f);
    const glm::vec3 hi = fits ? glm::vec3(fits->max) : glm::vec3(0.5f * size.x, 0.5f * size.y, size.z);
    const nlohmann::json& views = manifest.at("layout").at("views");
    ASSERT_GE(views.size(), 1u);
    std::vector<glm::vec4> drawn;
    for (const auto& box : manifest.at("layout").at("ui_drawn")) drawn.push_back({box[0], box[1], box[2], box[3]});
    ASSERT_FALSE(drawn.empty()) << "the panel was not drawn";
    for (std::size_t k = 0; k < views.size(); ++k) {
        const glm::vec4 view = topLeft(views[k], image.height);
        for (const glm::vec4& ui : drawn) {
            EXPECT_FALSE(overlap(view, ui)) << c.name << ": something drawn at (" << ui.x << ", " << ui.y << ", " << ui.z
                                            << ", " << ui.w << ") covers view " << k;
        }
        for (int corner = 0; corner < 8; ++corner) {
            const glm::vec3 p{corner & 1 ? hi.x : lo.x, corner & 2 ? hi.y : lo.y, corner & 4 ? hi.z : lo.z};
            const glm::vec3 pixel = camera.project(p, glm::vec2(view.z, view.w));
            EXPECT_GE(pixel.x, 0.0f) << c.name << " view " << k << " corner " << corner;
            EXPECT_LE(pixel.x, view.z) << c.name << " view " << k << " corner " << corner;
            EXPECT_GE(pixel.y, 0.0f) << c.name << " view " << k << " corner " << corner;
            EXPECT_LE(pixel.y, view.w) << c.name << " view " << k << " corner " << corner;
            // The corner's pixels in the image: the scene, not a panel's background.
            const int x = int(view.x + pixel.x), y = int(view.y + pixel.y);
            int panel = 0;
            for (int dy = -3; dy <= 3; ++dy) {
                for (int dx = -3; dx <= 3; ++dx) {
                    const int px = std::clamp(x + dx, 0, image.width - 1), py = std::clamp(y + dy, 0, image.height - 1);
                    panel += panelPixel(image.pixel(px, py));
                }
            }
            EXPECT_EQ(panel, 0) << c.name << " view " << k << " corner " << corner << " at " << x << ", " << y;
        }
    }
}

INSTANTIATE_TEST_SUITE_P(
    ClassroomSizes, LayoutImages,
    ::testing::Values(Case{"pile_1024x768", "11_pile", "1024x768"}, Case{"pile_1280x720", "11_pile", "1280x720"},
                      Case{"pile_1920x1080", "11_pile", "1920x1080"},
                      Case{"pile_hidpi_2x", "11_pile", "2560x1440", 2.0f},
                      Case{"column_views_1280x720", "21_shock_column", "1280x720"},
                      Case{"bernoulli_views_1024x768", "16_bernoulli", "1024x768"},
                      Case{"present_column_1024x768", "09_column", "1024x768", 1.0f, true},
                      Case{"present_bernoulli_hidpi_2x", "16_bernoulli", "2560x1440", 2.0f, true},
                      Case{"present_three_answers_1920x1080", "14_three_answers", "1920x1080", 1.0f, true}),
    [](const ::testing::TestParamInfo<Case>& tested) { return tested.param.name; });

// Frame 0 of `scene` in the presentation layout with its panel, `size` px, into `out`.
app::CaptureOptions presentedFrameZero(const std::string& scene, const std::string& out, const std::string& size) {
    app::CaptureOptions options;
    options.scene = scene;
    options.out = out;
    options.size = size;
    options.at = "0";
    options.withUi = true;
    options.present = true;
    return options;
}

// The panel's width in a presentation capture (the widest box drawn from the left edge), as a
// share of the image's.
float presentedPanelShare(const std::string& size, float uiScale) {
    const std::string out = capture_test::freshFolder("present_share_" + size);
    app::CaptureOptions options = presentedFrameZero("14_three_answers", out, size);
    options.uiScale = uiScale;
    if (app::runCapture(options) != 0) return -1.0f;
    const nlohmann::json manifest = capture_test::readManifest(out);
    float widest = 0.0f;
    for (const auto& box : manifest.at("layout").at("ui_drawn")) {
        if (float(box[0]) < 1.0f) widest = std::max(widest, float(box[2]));
    }
    return widest / float(manifest.at("size")[0]);
}

// On a projector of 1080 lines the presentation's type carries the share of the screen it
// has at 720 (before, it stayed 1.5 times the UI scale: a third smaller at the back of the
// room); a HiDPI screen of 1440 pixels at scale 2 is 720 of its units.
TEST_F(LayoutImages, ThePresentationsTypeGrowsWithTheScreensHeight) {
    const float at720 = presentedPanelShare("1280x720", 1.0f);
    const float at1080 = presentedPanelShare("1920x1080", 1.0f);
    const float hidpi = presentedPanelShare("2560x1440", 2.0f);
    ASSERT_GT(at720, 0.3f);
    EXPECT_NEAR(at1080, at720, 0.01f);
    EXPECT_NEAR(hidpi, at720, 0.01f);
    EXPECT_FLOAT_EQ(ui::presentedScale(1.0f, 1080.0f), 2.25f);
    EXPECT_FLOAT_EQ(ui::presentedScale(2.0f, 720.0f), 3.0f);
    EXPECT_FLOAT_EQ(ui::presentedScale(1.0f, 600.0f), ui::kPresentScale) << "never below the 720 lines' type";
}

// The presented panel keeps the sliders the text names in sight while they leave the text
// at least 38 % of the panel, and where all would not, the first that fit: 02's long text
// (β, ε, h, the substeps and the method) had taken the whole panel at 1280x720 and at
// 1024x768, its sliders scrolled under it, and a teacher saying "move β" had none to show.
// Counted as the sliders' frames (ImGui's frame colour, 29 47 73) down the panel's left side.
TEST_F(LayoutImages, ThePresentedSlidersStayInSightUnderALongText) {
    const std::pair<const char*, int> sizes[] = {{"1280x720", 5}, {"1024x768", 3}};  // all five; β, ε and h
    for (const auto& [size, least] : sizes) {
        const std::string out = capture_test::freshFolder(std::string("present_sliders_") + size);
        ASSERT_EQ(app::runCapture(presentedFrameZero("02_bounce_projection", out, size)), 0);
        const render::Image image = capture_test::readFrame(out, 0);
        int frames = 0;
        bool inFrame = false;
        for (int y = 0; y < image.height; ++y) {
            const glm::u8vec4 c = image.pixel(60, y);
            const bool frame = std::abs(c.x - 29) < 8 && std::abs(c.y - 47) < 8 && std::abs(c.z - 73) < 8;
            frames += frame && !inFrame;
            inFrame = frame;
        }
        EXPECT_GE(frames, least) << size;
    }
}

// The radius (px) sphere `centre`, `radius` m, is drawn with in a view `viewSize` px.
float drawnRadius(const render::Camera& camera, glm::vec3 centre, float radius, glm::vec2 viewSize) {
    const glm::vec3 right = glm::normalize(glm::cross(camera.forward(), glm::vec3(0.0f, 0.0f, 1.0f)));
    return glm::distance(glm::vec2(camera.project(centre, viewSize)), glm::vec2(camera.project(centre + radius * right, viewSize)));
}

// Slide 14's small presets on a projector: four views of three spheres in a 1.2 m box drew
// each sphere with a radius of about 8 px at 1280x720. Their camera frames the section of
// the box the spheres move in (a slab 0.2 m deep): the layout turns to two rows of wider
// views, and the spheres are drawn a third larger than fitting the whole box would draw
// them (16's with a radius of 13.6 px, 19's in its 2 m box 8.0 px). A tighter frame (16
// from z = 0.45 m, 21 px; 19 from z = 0.4 to 1.6 m) lost spheres through the bottom of the
// views within a second: a teacher's class asked where they went. And it
// looks straight at the mirror plane, so that the answers that keep the symmetry look
// symmetric.
TEST_F(LayoutImages, APresetThatFramesItsSpheresDrawsThemLargeAndKeepsThemInView) {
    const std::pair<const char*, float> presets[] = {{"16_bernoulli", 12.0f}, {"19_symmetric_break", 7.0f}};  // px, the least
    for (const auto& [preset, leastRadius] : presets) {
        const std::string out = capture_test::freshFolder(std::string("present_framed_1280x720_") + preset);
        ASSERT_EQ(app::runCapture(presentedFrameZero(preset, out, "1280x720")), 0);
        const nlohmann::json manifest = capture_test::readManifest(out);
        const render::Camera camera = capture_test::cameraOf(manifest);
        scenes::Scene scene = scenes::loadScene(scenes::presetPath(preset));
        const nlohmann::json& views = manifest.at("layout").at("views");
        ASSERT_EQ(views.size(), 4u);
        EXPECT_NE(float(views[0][1]), float(views[2][1])) << "two rows";
        const glm::vec2 viewSize{float(views[0][2]), float(views[0][3])};
        const glm::vec3 centre(scene.spheres[0].p);
        const float framed = drawnRadius(camera, centre, float(scene.spheres[0].r), viewSize);
        render::Camera boxCamera = camera;
        const glm::vec3 size(scene.box->size);
        boxCamera.fitBox({-0.5f * size.x, -0.5f * size.y, 0.0f}, {0.5f * size.x, 0.5f * size.y, size.z}, viewSize.x / viewSize.y);
        const float boxed = drawnRadius(boxCamera, centre, float(scene.spheres[0].r), viewSize);
        std::printf("%s: sphere 0 drawn with a radius of %.1f px (%.1f with the box fitted in the same view)\n", preset, framed,
                    boxed);
        EXPECT_GT(framed, leastRadius) << preset;
        EXPECT_GT(framed, 1.3f * boxed) << preset;
        // Every solver's spheres stay whole in the views for 10 s, 40 s at the scene's 0.25x.
        for (const char* solver : {"sequential", "simultaneous", "lcp", "generalized-reflections"}) {
            ASSERT_EQ(scenes::applySetting(scene, std::string("solver=") + solver), "");
            physics::World world = scenes::buildWorld(scene);
            float closest = 1e9f;  // px, the least room left between a sphere's edge and the view's
            while (world.time < 10.0) {
                physics::step(world, scene.params);
                for (std::size_t i = 0; i < world.size(); ++i) {
                    const glm::vec3 p(world.position[i]);
                    const glm::vec2 at(camera.project(p, viewSize));
                    const float r = drawnRadius(camera, p, float(world.radius[i]), viewSize);
                    closest = std::min({closest, at.x - r, at.y - r, viewSize.x - at.x - r, viewSize.y - at.y - r});
                }
            }
            EXPECT_GE(closest, 0.0f) << preset << ", " << solver << ": a sphere left the view";
        }
        // Seen straight at its mirror plane (x = 0), the symmetric start looks symmetric: two
        // mirrored spheres on one row, as far left of the view's middle as right of it (a
        // three-quarter view put them 0.3 of their distance apart off the middle).
        const glm::vec3 left = camera.project(glm::vec3(scene.spheres[1].p), viewSize);
        const glm::vec3 right = camera.project(glm::vec3(scene.spheres[std::string(preset) == "16_bernoulli" ? 2 : 3].p),
                                               viewSize);
        if (std::string(preset) == "19_symmetric_break") {
            const glm::vec3 west = camera.project(glm::vec3(scene.spheres[0].p), viewSize);
            EXPECT_NEAR(west.y, right.y, 0.5f) << preset;
            EXPECT_NEAR(0.5f * viewSize.x - west.x, right.x - 0.5f * viewSize.x, 0.5f) << preset;
            continue;
        }
        EXPECT_NEAR(left.y, right.y, 0.5f);
        EXPECT_NEAR(0.5f * viewSize.x - left.x, right.x - 0.5f * viewSize.x, 0.5f);
    }
}

}  // namespace
