// Overlays (app/overlays.h): what each one draws into the snapshot, what spans
// frames (impulses fading over 0.5 s, trails of 1.5 s), that they cost nothing
// when off (no contacts recorded, nothing drawn), and that `capture --overlay`
// puts them in the image where they belong.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>
#include <glm/geometric.hpp>

#include "app/commands/capture_command.h"
#include "app/views/frame_builder.h"
#include "app/teaching/overlays.h"
#include "app/run/scene_source.h"
#include "app/run/simulation.h"
#include "test_capture_support.h"
#include "ui/control_panel.h"

namespace {

using app::OverlayFlags;
using app::Simulation;

constexpr double kRadius = 0.1;  // m

// One sphere of 1 kg dropped from `height` onto the floor of a 2 m box.
scenes::Scene dropScene(double height = 1.5, double beta = 0.8) {
    scenes::Scene scene;
    scene.title = "drop";
    scene.box = scenes::Box{};
    scene.params.beta = beta;
    scene.spheres.push_back({{0.0, 0.0, height}, {0.0, 0.0, 0.0}, kRadius, 1.0});
    return scene;
}

// `count` spheres of radius 0.02 m on a lattice, falling.
scenes::Scene latticeScene(int count) {
    scenes::Scene scene;
    scene.box = scenes::Box{};
    scenes::Generator g;
    g.kind = scenes::GeneratorKind::Lattice;
    g.count = count;
    g.regionMin = {-1.0, -1.0, 0.0};
    g.regionMax = {1.0, 1.0, 2.0};
    g.radiusMin = g.radiusMax = 0.02;
    scene.generators.push_back(g);
    return scene;
}

OverlayFlags only(const char* name) {
    OverlayFlags flags;
    EXPECT_TRUE(app::setOverlayByName(flags, name)) << name;
    return flags;
}

// Steps until the first step whose contacts hold a bounce; false if none in `limit`.
bool stepUntilBounce(Simulation& sim, int limit = 600) {
    for (int k = 0; k < limit; ++k) {
        sim.singleStep();
        for (const physics::ContactEvent& e : sim.world().contacts) {
            if (e.bounce) return true;
        }
    }
    return false;
}

bool sameColor(glm::u8vec4 a, glm::u8vec4 b) { return glm::u8vec3(a) == glm::u8vec3(b); }

std::vector<render::OverlayLine> linesOf(const render::FrameSnapshot& snapshot, glm::u8vec4 color) {
    std::vector<render::OverlayLine> found;
    for (const render::OverlayLine& line : snapshot.lines) {
        if (sameColor(line.color, color)) found.push_back(line);
    }
    return found;
}

}  // namespace

TEST(Overlays, OffTheyDrawNothingAndRecordNoContacts) {
    Simulation sim(latticeScene(50));
    render::FrameSnapshot snapshot;
    app::buildSnapshot(sim, ui::PanelState{}, snapshot);
    for (int k = 0; k < 60; ++k) sim.singleStep();
    app::buildSnapshot(sim, ui::PanelState{}, snapshot);
    EXPECT_TRUE(snapshot.lines.empty());
    EXPECT_TRUE(snapshot.points.empty());
    EXPECT_FALSE(sim.world().recordContacts);  // 50 spheres: no restitution measurement either
    EXPECT_TRUE(sim.world().contacts.empty());
    EXPECT_TRUE(sim.overlays().trails().empty());
    EXPECT_TRUE(sim.overlays().impulses().empty());
}

TEST(Overlays, ContactsAreRecordedOnlyForTheOverlaysThatNeedThem) {
    Simulation sim(latticeScene(50));
    render::FrameSnapshot snapshot;
    for (const char* name : {"velocity", "penetration", "trails"}) {
        app::buildSnapshot(sim, app::viewShowing(only(name)), snapshot);
        EXPECT_FALSE(sim.world().recordContacts) << name;
    }
    for (const char* name : {"contacts", "impulses"}) {
        app::buildSnapshot(sim, app::viewShowing(only(name)), snapshot);
        EXPECT_TRUE(sim.world().recordContacts) << name;
    }
    app::buildSnapshot(sim, ui::PanelState{}, snapshot);
    EXPECT_FALSE(sim.world().recordContacts);

    // Above kMaxRecordSpheres the log would take hundreds of MB per step: never.
    Simulation big(latticeScene(static_cast<int>(app::kMaxRecordSpheres) + 100));
    app::buildSnapshot(big, app::viewShowing(only("contacts")), snapshot);
    EXPECT_FALSE(big.world().recordContacts);
}

TEST(Overlays, VelocityArrowStartsAtTheSurfaceAndIsTheTenthOfASecondPath) {
    scenes::Scene scene = dropScene();
    scene.params.gravity = glm::dvec3(0.0);
    scene.spheres[0].v = {2.0, 0.0, 1.0};  // m/s
    Simulation sim(scene);
    render::FrameSnapshot snapshot;
    app::buildSnapshot(sim, app::viewShowing(only("velocity")), snapshot);
    const auto arrow = linesOf(snapshot, app::kVelocityColor);
    ASSERT_EQ(arrow.size(), 5u);  // shaft and four barbs
    const glm::dvec3 v = scene.spheres[0].v;
    const glm::dvec3 d = glm::normalize(v);
    const glm::dvec3 from = scene.spheres[0].p + kRadius * d;
    EXPECT_LT(glm::distance(glm::dvec3(arrow[0].a), from), 1e-6);
    EXPECT_LT(glm::distance(glm::dvec3(arrow[0].b), from + app::kVelocityArrowSeconds * v), 1e-6);
    EXPECT_NEAR(app::kVelocityArrowSeconds, 0.1, 1e-12);  // the legend's "1 m/s = 10 cm"
    // Each barb goes back from the tip.
    for (std::size_t k = 1; k < arrow.size(); ++k) {
        EXPECT_LT(glm::dot(glm::dvec3(arrow[k].b - arrow[k].a), d), 0.0);
    }
}

TEST(Overlays, ContactsShowThePointUnderTheSphereAndTheFloorNormal) {
    scenes::Scene scene = dropScene(kRadius);  // resting on the floor
    Simulation sim(scene);
    render::FrameSnapshot snapshot;
    app::buildSnapshot(sim, app::viewShowing(only("contacts")), snapshot);
    sim.singleStep();
    app::buildSnapshot(sim, app::viewShowing(only("contacts")), snapshot);
    const auto normals = linesOf(snapshot, app::kNormalColor);
    ASSERT_EQ(normals.size(), 1u);  // one contact, whatever the passes and substeps
    EXPECT_NEAR(normals[0].a.z, 0.0, 1e-3);
    EXPECT_NEAR(normals[0].a.x, 0.0, 1e-9);
    const glm::vec3 n = glm::normalize(normals[0].b - normals[0].a);
    EXPECT_NEAR(n.z, 1.0, 1e-6);
    const auto point = std::find_if(snapshot.points.begin(), snapshot.points.end(), [](const auto& p) {
        return sameColor(p.color, app::kContactPointColor);
    });
    ASSERT_NE(point, snapshot.points.end());
    EXPECT_NEAR(point->position.z, 0.0, 1e-3);
}

// A pile's contacts are too many to draw each normal (a few pixels each, mostly hidden,
// and half of what the overlay cost a software GL): over 50 contacts every point keeps
// its dot and only the selected sphere's contacts keep their normals.
TEST(Overlays, ACrowdOfContactsShowsEveryPointAndTheSelectedSpheresNormals) {
    Simulation sim(latticeScene(400));
    ui::PanelState view = app::viewShowing(only("contacts"));
    render::FrameSnapshot snapshot;
    app::buildSnapshot(sim, view, snapshot);  // the overlay asks the steps to record contacts
    for (int k = 0; k < 120; ++k) sim.singleStep();  // 2 s: on the floor, touching
    app::buildSnapshot(sim, view, snapshot);
    const auto dots = std::count_if(snapshot.points.begin(), snapshot.points.end(), [](const auto& p) {
        return sameColor(p.color, app::kContactPointColor);
    });
    ASSERT_GT(dots, 50);
    EXPECT_TRUE(linesOf(snapshot, app::kNormalColor).empty());

    const int selected = 7;
    view.selectedSphere = selected;  // as a click in the window
    app::buildSnapshot(sim, view, snapshot);
    std::set<std::pair<std::uint32_t, std::int32_t>> touching;  // the last step's contacts of sphere 7
    for (const physics::ContactEvent& e : sim.world().contacts) {
        if (e.i == std::uint32_t(selected) || e.other == selected) touching.insert({e.i, e.other});
    }
    ASSERT_FALSE(touching.empty());
    EXPECT_EQ(linesOf(snapshot, app::kNormalColor).size(), touching.size());
}

TEST(Overlays, ImpulseArrowAtImpactFadesToNothingAfterHalfASecond) {
    Simulation sim(dropScene(1.5, 0.8));
    render::FrameSnapshot snapshot;
    const ui::PanelState view = app::viewShowing(only("impulses"));
    app::buildSnapshot(sim, view, snapshot);
    ASSERT_TRUE(stepUntilBounce(sim));
    ASSERT_EQ(sim.overlays().impulses().size(), 1u);
    const app::ImpulseMark mark = sim.overlays().impulses().front();
    // J = m (1 + beta) s upwards, s the impact speed after a 1.4 m fall (within a step's gravity).
    const double s = std::sqrt(2 * 9.81 * 1.4);
    EXPECT_NEAR(mark.impulse.z, 1.8 * s, 0.05 * 1.8 * s);
    EXPECT_NEAR(glm::length(glm::dvec2(mark.impulse)), 0.0, 1e-9);
    EXPECT_NEAR(mark.point.z, 0.0, 0.05);  // at the floor
    EXPECT_DOUBLE_EQ(app::OverlayState::impulseOpacity(mark, mark.time), 1.0);
    app::buildSnapshot(sim, view, snapshot);
    const auto fresh = linesOf(snapshot, app::kImpulseColor);
    ASSERT_EQ(fresh.size(), 5u);
    EXPECT_EQ(fresh[0].color.w, 255);
    EXPECT_NEAR(fresh[0].b.z - fresh[0].a.z, app::kImpulseMetresPerUnit * mark.impulse.z, 1e-4);

    // A quarter of a second later: half faded.
    const double h = sim.params().timeStep;
    while (sim.world().time < mark.time + 0.25 - 1e-9) sim.singleStep();
    EXPECT_NEAR(app::OverlayState::impulseOpacity(sim.overlays().impulses().front(), sim.world().time), 0.5, h / 0.5);
    app::buildSnapshot(sim, view, snapshot);
    const auto halfway = linesOf(snapshot, app::kImpulseColor);
    ASSERT_FALSE(halfway.empty());
    EXPECT_NEAR(halfway[0].color.w, 128, 255 * h / 0.5 + 1);

    // Half a second after the impact nothing is left (the ball is still in the air).
    while (sim.world().time < mark.time + app::kImpulseFadeSeconds - 1e-9) sim.singleStep();
    EXPECT_TRUE(sim.overlays().impulses().empty());
    app::buildSnapshot(sim, view, snapshot);
    EXPECT_TRUE(snapshot.lines.empty());
    EXPECT_TRUE(snapshot.points.empty());
}

TEST(Overlays, ImpulsesBetweenTwoSpheresAreEqualAndOpposite) {
    scenes::Scene scene;
    scene.box = scenes::Box{};
    scene.params.gravity = glm::dvec3(0.0);
    scene.params.alpha = scene.params.beta = 1.0;
    scene.params.response = physics::ResponseModel::MomentumConserving;
    scene.spheres.push_back({{-0.5, 0.0, 1.0}, {1.0, 0.0, 0.0}, 0.1, 1.0});
    scene.spheres.push_back({{0.5, 0.0, 1.0}, {0.0, 0.0, 0.0}, 0.144, 3.0});
    Simulation sim(scene);
    render::FrameSnapshot snapshot;
    app::buildSnapshot(sim, app::viewShowing(only("impulses")), snapshot);
    ASSERT_TRUE(stepUntilBounce(sim));
    const auto& marks = sim.overlays().impulses();
    ASSERT_EQ(marks.size(), 2u);
    EXPECT_LT(glm::length(marks[0].impulse + marks[1].impulse), 1e-12);
    // Elastic, 1 kg at 1 m/s on 3 kg at rest: the light one leaves at -0.5 m/s, J = 1.5 kg m/s.
    EXPECT_NEAR(glm::length(marks[0].impulse), 1.5, 1e-9);
    EXPECT_EQ(glm::distance(marks[0].point, marks[1].point), 0.0);
}

TEST(Overlays, TrailsKeepTheLastSecondAndAHalfOfTheCentre) {
    Simulation sim(dropScene(1.5, 0.8));
    render::FrameSnapshot snapshot;
    const ui::PanelState view = app::viewShowing(only("trails"));
    app::buildSnapshot(sim, view, snapshot);
    const double h = sim.params().timeStep;  // 1/60 s: one point per step
    ASSERT_NEAR(h, app::kTrailSampleSeconds, 1e-12);
    for (int k = 0; k < 30; ++k) sim.singleStep();
    ASSERT_EQ(sim.overlays().trails().size(), 1u);
    EXPECT_EQ(sim.overlays().trails()[0].points.size(), 30u);
    for (int k = 0; k < 150; ++k) sim.singleStep();  // 3 s in all
    const app::Trail& trail = sim.overlays().trails()[0];
    const std::size_t expected = static_cast<std::size_t>(std::lround(app::kTrailSeconds / h)) + 1;  // 91
    EXPECT_EQ(expected, 91u);
    EXPECT_EQ(trail.points.size(), expected);
    EXPECT_NEAR(trail.times.back() - trail.times.front(), app::kTrailSeconds, 1e-9);
    EXPECT_EQ(trail.points.back(), sim.world().position[0]);
    app::buildSnapshot(sim, view, snapshot);
    // One segment per pair of points (over a dark rim), the newest the most opaque;
    // steps shorter than kShortestTrailSegment (about the apexes) are joined.
    const glm::u8vec4 colour = snapshot.colors[0];
    const auto segments = linesOf(snapshot, colour);
    ASSERT_LT(segments.size(), expected - 1);
    ASSERT_GE(segments.size(), expected - 10);
    for (const render::OverlayLine& segment : segments) {
        EXPECT_GE(glm::distance(segment.a, segment.b), app::kShortestTrailSegment * (1.0 - 1e-5));
    }
    EXPECT_EQ(snapshot.lines.size(), 2 * segments.size());
    EXPECT_GT(segments.back().color.w, segments.front().color.w);
    EXPECT_LE(segments.back().color.w, 230);
    EXPECT_LT(glm::distance(glm::dvec3(segments.back().b), sim.world().position[0]), 1e-6);

    // Off: the trail goes; on again: it starts afresh.
    app::buildSnapshot(sim, ui::PanelState{}, snapshot);
    sim.singleStep();
    EXPECT_TRUE(sim.overlays().trails().empty());
}

TEST(Overlays, TrailsFollowTheFirstSpheresOrTheSelectedOne) {
    Simulation sim(latticeScene(300));
    render::FrameSnapshot snapshot;
    ui::PanelState view = app::viewShowing(only("trails"));
    app::buildSnapshot(sim, view, snapshot);
    sim.singleStep();
    ASSERT_EQ(sim.overlays().trails().size(), app::kMaxTrailSpheres);
    EXPECT_EQ(sim.overlays().trails().back().sphere, app::kMaxTrailSpheres - 1);
    view.selectedSphere = 250;
    app::buildSnapshot(sim, view, snapshot);
    sim.singleStep();
    ASSERT_EQ(sim.overlays().trails().size(), 1u);
    EXPECT_EQ(sim.overlays().trails()[0].sphere, 250u);
}

TEST(Overlays, RestartClearsImpulsesAndTrails) {
    Simulation sim(dropScene());
    render::FrameSnapshot snapshot;
    OverlayFlags flags;
    flags.impulses = flags.trails = true;
    app::buildSnapshot(sim, app::viewShowing(flags), snapshot);
    ASSERT_TRUE(stepUntilBounce(sim));
    EXPECT_FALSE(sim.overlays().impulses().empty());
    EXPECT_FALSE(sim.overlays().trails().empty());
    // A rewind or a teleport: the trails start afresh.
    sim.resetOverlays();
    EXPECT_TRUE(sim.overlays().trails().empty());
    sim.singleStep();
    ASSERT_EQ(sim.overlays().trails().size(), 1u);
    EXPECT_EQ(sim.overlays().trails()[0].points.size(), 1u);
    // A rewind: the world's clock goes back, the trails start afresh by themselves.
    const physics::World earlier = sim.world();
    for (int k = 0; k < 10; ++k) sim.singleStep();
    EXPECT_EQ(sim.overlays().trails()[0].points.size(), 11u);
    sim.editableWorld() = earlier;
    sim.singleStep();
    EXPECT_EQ(sim.overlays().trails()[0].points.size(), 1u);
    ASSERT_TRUE(stepUntilBounce(sim));
    sim.restart();
    EXPECT_TRUE(sim.overlays().impulses().empty());
    EXPECT_TRUE(sim.overlays().trails().empty());
    EXPECT_TRUE(sim.world().recordContacts);  // still shown after the restart
}

TEST(Overlays, PenetrationIsARedSegmentTenTimesTheDepthAlongTheNormal) {
    scenes::Scene scene = dropScene();
    scene.params.gravity = glm::dvec3(0.0);
    scene.spheres.push_back({{0.5, 0.0, 1.0}, {0.0, 0.0, 0.0}, kRadius, 1.0});
    Simulation sim(scene);
    // Overlap the two by 2 cm along x, through the world (a scene refuses overlaps).
    sim.editableWorld().position[0] = {0.5 - 2 * kRadius + 0.02, 0.0, 1.0};
    render::FrameSnapshot snapshot;
    app::buildSnapshot(sim, app::viewShowing(only("penetration")), snapshot);
    const auto red = linesOf(snapshot, app::kPenetrationColor);
    ASSERT_EQ(red.size(), 1u);
    const glm::vec3 segment = red[0].b - red[0].a;
    EXPECT_NEAR(glm::length(segment), app::kPenetrationExaggeration * 0.02, 1e-5);
    EXPECT_NEAR(std::abs(segment.x), glm::length(segment), 1e-6);  // along the normal, x
    // Centred on the middle of the overlap.
    EXPECT_NEAR(0.5f * (red[0].a.x + red[0].b.x), float(0.5 - kRadius + 0.01), 1e-5);
}

TEST(Overlays, LegendStatesEachScale) {
    OverlayFlags all;
    for (const char* name : app::kOverlayNames) app::setOverlayByName(all, name);
    const auto legend = app::overlayLegend(all, 1000, -1);
    ASSERT_EQ(legend.size(), 6u);
    EXPECT_NE(legend[0].text.find("1 m/s = 10 cm"), std::string::npos) << legend[0].text;
    EXPECT_NE(legend[2].text.find("1 kg m/s = 5 cm"), std::string::npos) << legend[2].text;
    EXPECT_NE(legend[3].text.find("× 10"), std::string::npos) << legend[3].text;
    EXPECT_NE(legend[4].text.find("first 200 spheres"), std::string::npos) << legend[4].text;
    EXPECT_NE(legend[5].text.find("0 red, 1 orange"), std::string::npos) << legend[5].text;
    EXPECT_TRUE(app::overlayLegend(OverlayFlags{}, 1000, -1).empty());
    EXPECT_EQ(app::overlayNames(all).size(), 6u);
}

// Slide 14's contact graph on a column of five: a line from the foot sphere to the floor
// (level 0, red), and one per touching pair in the colour of the upper sphere's level
// (1 orange, 2 yellow, 3 green, 4 cyan); the simulation's graph gives each its level.
TEST(Overlays, TheContactGraphShowsEachLevelInItsColour) {
    scenes::Scene scene;
    scene.box = scenes::Box{};
    scene.params.shock = physics::ShockPropagation::On;
    for (int k = 0; k < 5; ++k) scene.spheres.push_back({{0.0, 0.0, kRadius + 2 * kRadius * k}, {0.0, 0.0, 0.0}, kRadius, 1.0});
    Simulation sim(scene);
    for (int k = 0; k < 10; ++k) sim.singleStep();
    EXPECT_EQ(sim.contactGraph().level, (std::vector<std::int32_t>{0, 1, 2, 3, 4}));
    render::FrameSnapshot snapshot;
    app::buildSnapshot(sim, app::viewShowing(only("graph")), snapshot);
    ASSERT_EQ(snapshot.lines.size(), 5u);
    for (int level = 0; level < 5; ++level) {
        const auto lines = linesOf(snapshot, app::levelColor(level));
        ASSERT_EQ(lines.size(), 1u) << "level " << level;
        const float top = std::max(lines[0].a.z, lines[0].b.z);  // the upper end: the level's own sphere
        EXPECT_NEAR(top, float(kRadius + 2 * kRadius * level), 1e-4) << "level " << level;
    }
    for (int level = 0; level < 5; ++level) {  // the spheres take their level's colour too
        EXPECT_TRUE(sameColor(snapshot.colors[std::size_t(level)], app::levelColor(level))) << "sphere " << level;
    }
    // The hues repeat every six levels, darker from 6, paler from 12, palest from 18: each of
    // the column of twenty's levels has a colour of its own, and only level 0 is its red.
    for (int a = 0; a < 24; ++a) {
        for (int b = a + 1; b < 24; ++b) EXPECT_FALSE(sameColor(app::levelColor(a), app::levelColor(b))) << a << " " << b;
        EXPECT_FALSE(sameColor(app::levelColor(a), app::kNoLevelColor)) << a;
    }
    EXPECT_TRUE(sameColor(app::levelColor(24), app::levelColor(0)));
    EXPECT_TRUE(sameColor(app::levelColor(-1), app::kNoLevelColor));
}

// ---------------------------------------------------------------- capture --overlay

namespace {

// A sphere crossing the box at 2 m/s along +x, no gravity: its velocity arrow is
// horizontal, to the right in a front view.
std::string writeMovingSphereScene(const std::string& folder) {
    capture_test::fs::create_directories(folder);
    const std::string path = (capture_test::fs::path(folder) / "moving.json").string();
    std::ofstream(path) << R"({"title": "moving", "box": {"size": [2, 2, 2], "tilt": 0},
        "parameters": {"gravity": 0}, "seed": 1,
        "spheres": [{"p": [-0.5, 0, 1], "v": [2, 0, 0], "r": 0.1, "m": 1}]})";
    return path;
}

}  // namespace

TEST(OverlayCapture, VelocityArrowColourLiesAlongTheProjectedVelocity) {
    const platform::HeadlessBackend backend = platform::HeadlessBackend::Auto;
    if (const std::string why = capture_test::unavailableReason(backend); !why.empty()) {
        GTEST_SKIP() << "no headless GL here: " << why;
    }
    const std::string scenePath = writeMovingSphereScene(capture_test::freshFolder("overlay_scene"));
    app::CaptureOptions options = capture_test::smallCapture(scenePath, "", backend);
    options.size = "480x300";
    options.at = "0";
    options.camera = "-90,0";  // from the front, looking along +y: +x is to the right
    options.overlay = "velocity";
    options.out = capture_test::freshFolder("overlay_velocity");
    ASSERT_EQ(app::runCapture(options), 0);
    app::CaptureOptions plain = options;
    plain.overlay.clear();
    plain.out = capture_test::freshFolder("overlay_none");
    ASSERT_EQ(app::runCapture(plain), 0);

    const nlohmann::json manifest = capture_test::readManifest(options.out);
    EXPECT_EQ(manifest.at("overlays"), nlohmann::json::array({"velocity"}));
    EXPECT_EQ(capture_test::readManifest(plain.out).at("overlays"), nlohmann::json::array());
    const render::Camera camera = capture_test::cameraOf(manifest);
    const render::Image image = capture_test::readFrame(options.out, 0);
    const render::Image without = capture_test::readFrame(plain.out, 0);
    const glm::vec2 size(image.width, image.height);
    // Along the shaft, from the surface (x = -0.4) to the barbs (tip at -0.2): magenta.
    int along = 0;
    for (float x = -0.38f; x <= -0.27f; x += 0.01f) {
        const glm::vec3 p = camera.project({x, 0.0f, 1.0f}, size);
        const glm::u8vec4 pixel = image.pixel(int(p.x), int(p.y));
        EXPECT_LE(capture_test::channelSpread(pixel, app::kVelocityColor), 12) << "x = " << x;
        EXPECT_GT(capture_test::channelSpread(without.pixel(int(p.x), int(p.y)), app::kVelocityColor), 60);
        ++along;
    }
    EXPECT_GE(along, 10);
    // Behind the sphere (against the velocity) and above the arrow: no magenta.
    for (const glm::vec3 q : {glm::vec3(-0.65f, 0.0f, 1.0f), glm::vec3(-0.3f, 0.0f, 1.1f)}) {
        const glm::vec3 p = camera.project(q, size);
        EXPECT_GT(capture_test::channelSpread(image.pixel(int(p.x), int(p.y)), app::kVelocityColor), 60);
    }
    // The rest of the frame is untouched: only the arrow's pixels differ.
    int differing = 0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) differing += image.pixel(x, y) != without.pixel(x, y);
    }
    EXPECT_GT(differing, 100);
    EXPECT_LT(differing, 3000);
}

TEST(OverlayCapture, UnknownOverlayIsRefused) {
    app::CaptureOptions options = capture_test::smallCapture("02_head_on", "", platform::HeadlessBackend::Auto);
    options.at = "0";
    options.overlay = "velocity,sparks";
    options.out = capture_test::freshFolder("overlay_refused");
    try {
        app::runCapture(options);
        FAIL() << "an unknown overlay must be refused";
    } catch (const app::UsageError& e) {
        EXPECT_NE(std::string(e.what()).find("sparks"), std::string::npos) << e.what();
    }
    EXPECT_FALSE(capture_test::fs::exists(options.out));
}

// Slide 7's ghosts: with the continuous method and the ball selected, its bounce leaves
// a green wire sphere touching the floor (the instant of contact) and an orange one where
// projection would have put it at the end of that step: on the floor too, further down
// the fall. Another method leaves none.
TEST(Overlays, ContinuousBounceLeavesGhostsAtTheContactAndWhereProjectionPutsIt) {
    scenes::Scene scene = dropScene();
    scene.params.method = physics::Method::Continuous;
    scene.params.timeStep = 1.0 / 30.0;
    scene.params.substeps = 1;
    Simulation sim(scene);
    ui::PanelState view;
    view.selectedSphere = 0;
    render::FrameSnapshot snapshot;
    app::buildSnapshot(sim, view, snapshot);  // selects the sphere: contacts are recorded
    ASSERT_TRUE(stepUntilBounce(sim));
    const auto& ghost = sim.contactGhosts().latest();
    ASSERT_TRUE(ghost);
    EXPECT_NEAR(ghost->atContact.z, kRadius, 1e-12);  // touching, not inside
    EXPECT_GE(ghost->instant, 0.0);
    EXPECT_LE(ghost->instant, 1.0 / 30.0);
    EXPECT_NEAR(ghost->projected.z, kRadius, 1e-12);  // projected back onto the floor
    EXPECT_NEAR(ghost->projected.x, 0.0, 1e-12);
    app::buildSnapshot(sim, view, snapshot);
    EXPECT_EQ(linesOf(snapshot, app::kGhostAtContactColor).size(), 120u);  // three circles of 40
    EXPECT_EQ(linesOf(snapshot, app::kGhostProjectedColor).size(), 120u);
    for (int k = 0; k < 5; ++k) sim.singleStep();
    EXPECT_TRUE(sim.contactGhosts().latest());  // it stays until the next contact

    scene.params.method = physics::Method::PositionBased;
    Simulation projected(scene);
    app::buildSnapshot(projected, view, snapshot);
    ASSERT_TRUE(stepUntilBounce(projected));
    EXPECT_FALSE(projected.contactGhosts().latest());
}
