// Interaction without a window (app/interaction.h, app/session.h): picking the
// sphere under a pixel, dragging and throwing with the mouse's smoothed velocity,
// shooting from the camera and its refusals, editing the selected sphere.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "app/run/interaction.h"
#include "app/views/frame_builder.h"
#include "app/views/interaction_windows.h"
#include "app/run/session.h"
#include "app/views/window_layout.h"
#include "app/run/simulation.h"
#include "physics/diagnostics.h"
#include "render/camera.h"
#include "scenes/presets.h"
#include "scenes/scene_json.h"
#include "scenes/scene.h"

namespace {

constexpr glm::vec2 kViewport{800.0f, 600.0f};  // px

// A 2 m box (floor at z = 0) with the given spheres, nothing else.
physics::World boxWorld(const std::vector<glm::dvec3>& centres, double r = 0.1) {
    scenes::Scene scene;
    scenes::Box box;
    box.size = {2.0, 2.0, 2.0};
    scene.box = box;
    for (const glm::dvec3& p : centres) scene.spheres.push_back({p, glm::dvec3(0.0), r, 1.0});
    return scenes::buildWorld(scene);
}

render::Camera outsideCamera() {
    render::Camera camera;
    camera.target = {0.0f, 0.0f, 1.0f};
    camera.azimuth = -1.2f;
    camera.elevation = 0.35f;
    camera.distance = 5.0f;
    return camera;
}

glm::vec2 pixelOf(const render::Camera& camera, const glm::dvec3& p) {
    const glm::vec3 projected = camera.project(glm::vec3(p), kViewport);
    return {projected.x, projected.y};
}

// ---------------------------------------------------------------- picking

TEST(InteractionPicking, ThePixelOfEachCentrePicksThatSphere) {
    const physics::World world = boxWorld({{0.0, 0.0, 1.0}, {0.6, -0.4, 0.5}, {-0.5, 0.5, 1.5}, {0.3, 0.7, 0.2}});
    const render::Camera camera = outsideCamera();
    for (std::size_t i = 0; i < world.size(); ++i) {
        EXPECT_EQ(app::pickSphere(world, camera, pixelOf(camera, world.position[i]), kViewport), int(i)) << i;
    }
}

TEST(InteractionPicking, TheNearestSphereAlongTheRayWinsAndEmptySpacePicksNothing) {
    const render::Camera camera = outsideCamera();
    const glm::dvec3 far(0.0, 0.0, 1.0);
    const glm::dvec3 toEye = glm::normalize(glm::dvec3(camera.position()) - far);
    const glm::dvec3 near = far + 0.8 * toEye;  // in front of it, on the same line of sight
    const physics::World world = boxWorld({far, near});
    EXPECT_EQ(app::pickSphere(world, camera, pixelOf(camera, far), kViewport), 1);
    // Just outside the far sphere's silhouette, beside the near one: nothing.
    EXPECT_EQ(app::pickSphere(world, camera, {2.0f, 2.0f}, kViewport), -1);
    // The ray from inside a sphere meets it where it leaves.
    const render::Ray inside{glm::vec3(far), glm::vec3(1.0f, 0.0f, 0.0f)};
    ASSERT_TRUE(app::raySphereDistance(inside, far, 0.1).has_value());
    EXPECT_NEAR(*app::raySphereDistance(inside, far, 0.1), 0.1, 1e-6);
}

// ---------------------------------------------------------------- views and the mouse

TEST(InteractionViews, MousePositionsMapToTheirViewAndPixelOnHiDpi) {
    // A 1280 x 800 window at 2 pixels per unit; the panel takes 400 units, the bar 60.
    app::LayoutRequest request;
    request.window = {1280.0f, 800.0f};
    request.pixelsPerUnit = {2.0f, 2.0f};
    request.panelWidth = 400.0f;
    request.barHeight = 60.0f;
    const app::ViewLayout one = app::layoutWindow(request).views;
    EXPECT_EQ(one.count, 1);
    EXPECT_EQ(one.views[0], glm::ivec4(800, 120, 1760, 1480));
    EXPECT_EQ(one.viewAt({300.0f, 100.0f}), -1);  // over the panel
    EXPECT_EQ(one.viewAt({500.0f, 100.0f}), 0);
    EXPECT_EQ(one.viewAt({500.0f, 790.0f}), -1);  // over the timeline bar
    EXPECT_EQ(one.pixelIn(0, {400.0f, 0.0f}), glm::vec2(0.0f, 0.0f));
    EXPECT_EQ(one.pixelIn(0, {500.0f, 100.0f}), glm::vec2(200.0f, 200.0f));

    request.views = 2;
    const app::ViewLayout two = app::layoutWindow(request).views;
    EXPECT_EQ(two.views[0], glm::ivec4(800, 120, 878, 1480));
    EXPECT_EQ(two.views[1], glm::ivec4(1682, 120, 878, 1480));
    EXPECT_EQ(two.viewAt({500.0f, 300.0f}), 0);
    EXPECT_EQ(two.viewAt({840.0f, 300.0f}), -1);  // the gap
    EXPECT_EQ(two.viewAt({900.0f, 300.0f}), 1);
    EXPECT_EQ(two.pixelIn(1, {841.0f, 10.0f}), glm::vec2(0.0f, 20.0f));
    // Through the middle of either view: the camera's forward direction.
    const render::Camera camera = outsideCamera();
    for (int k = 0; k < 2; ++k) {
        const glm::ivec4& v = two.views[k];
        const glm::vec2 middle((float(v.x) + 0.5f * float(v.z)) / 2.0f, (1600.0f - float(v.y + v.w) + 0.5f * float(v.w)) / 2.0f);
        EXPECT_GT(glm::dot(two.ray(camera, k, middle).direction, camera.forward()), 0.99999f) << k;
    }
}

// ---------------------------------------------------------------- drag and throw

// The camera's right and up directions (m per m): the drag plane's axes.
void planeAxes(const render::Camera& camera, glm::dvec3& right, glm::dvec3& up) {
    const glm::dvec3 f = glm::normalize(glm::dvec3(camera.forward()));
    right = glm::normalize(glm::cross(f, glm::dvec3(0.0, 0.0, 1.0)));
    up = glm::cross(right, f);
}

TEST(InteractionDrag, ASyntheticDragThrowsTheSphereWithTheMouseVelocity) {
    physics::World world = boxWorld({{0.0, 0.0, 1.0}});
    const render::Camera camera = outsideCamera();
    glm::dvec3 right, up;
    planeAxes(camera, right, up);
    const glm::dvec3 start = world.position[0];
    const glm::dvec3 velocity = 1.5 * right + 0.8 * up;  // m/s, in the plane facing the camera

    app::SphereDrag drag;
    const double t0 = 10.0;  // s, any clock
    ASSERT_TRUE(drag.begin(world, 0, camera.rayThroughPixel(pixelOf(camera, start), kViewport), camera.forward(), t0));
    for (int frame = 1; frame <= 20; ++frame) {
        const double t = frame / 60.0;
        const glm::dvec3 mouse = start + t * velocity;  // where the mouse points, m
        const auto centre = drag.move(world, camera.rayThroughPixel(pixelOf(camera, mouse), kViewport), t0 + t);
        ASSERT_TRUE(centre.has_value());
        EXPECT_LT(glm::length(*centre - mouse), 1e-4) << frame;  // float pixels: 0.1 mm
        app::placeSphere(world, 0, *centre, drag.velocity());
    }
    const glm::dvec3 thrown = drag.release();
    EXPECT_LT(glm::length(thrown - velocity), 5e-3 * glm::length(velocity));
    EXPECT_FALSE(drag.active());
}

TEST(InteractionDrag, TheThrowUsesOnlyTheLastTenthOfASecond) {
    app::VelocityTracker tracker;
    glm::dvec3 p(0.0);
    double t = 0.0;
    tracker.add(t, p);
    for (int k = 0; k < 30; ++k) {  // 0.5 s at 4 m/s along x
        t += 1.0 / 60.0;
        p.x += 4.0 / 60.0;
        tracker.add(t, p);
    }
    for (int k = 0; k < 12; ++k) {  // 0.2 s at 1 m/s along y
        t += 1.0 / 60.0;
        p.y += 1.0 / 60.0;
        tracker.add(t, p);
    }
    const glm::dvec3 v = tracker.velocity();
    EXPECT_NEAR(v.x, 0.0, 1e-9);
    EXPECT_NEAR(v.y, 1.0, 1e-9);
    tracker.reset();
    EXPECT_EQ(tracker.velocity(), glm::dvec3(0.0));
}

TEST(InteractionDrag, ADraggedSphereStaysInsideTheBox) {
    physics::World world = boxWorld({{0.5, 0.0, 1.0}}, 0.1);
    const render::Camera camera = outsideCamera();
    glm::dvec3 right, up;
    planeAxes(camera, right, up);
    app::SphereDrag drag;
    ASSERT_TRUE(drag.begin(world, 0, camera.rayThroughPixel(pixelOf(camera, world.position[0]), kViewport),
                           camera.forward(), 0.0));
    const glm::dvec3 far = world.position[0] + 3.0 * right - 3.0 * up;  // beyond a wall and the floor
    const auto centre = drag.move(world, camera.rayThroughPixel(pixelOf(camera, far), kViewport), 0.1);
    ASSERT_TRUE(centre.has_value());
    EXPECT_TRUE(app::insideBox(world, *centre, 0.1));
    EXPECT_NEAR(centre->z, 0.1, 1e-9);  // resting on the floor
}

TEST(InteractionDrag, TheSessionThrowsTheSphereInEveryRun) {
    scenes::Scene scene;
    scene.box = scenes::Box{};
    scene.params.gravity = glm::dvec3(0.0);
    scene.spheres.push_back({{0.0, 0.0, 1.0}, glm::dvec3(0.0), 0.1, 1.0});
    scene.spheres.push_back({{0.5, 0.5, 0.5}, glm::dvec3(0.0), 0.1, 1.0});
    app::Simulation simulation(scene);
    simulation.paused = true;
    app::Session session(simulation);
    ASSERT_EQ(session.startComparison({"method=velocity"}), "");
    const render::Camera camera = outsideCamera();
    glm::dvec3 right, up;
    planeAxes(camera, right, up);
    const glm::dvec3 start = simulation.world().position[0];
    ASSERT_TRUE(session.beginDrag(0, 0, camera.rayThroughPixel(pixelOf(camera, start), kViewport), camera.forward(), 0.0));
    EXPECT_EQ(session.selected(), 0);
    for (int frame = 1; frame <= 12; ++frame) {
        const double t = frame / 60.0;
        session.dragTo(camera.rayThroughPixel(pixelOf(camera, start + t * 2.0 * right), kViewport), t);
    }
    const glm::dvec3 thrown = session.endDrag();
    EXPECT_LT(glm::length(thrown - 2.0 * right), 1e-2);
    for (int k = 0; k < 2; ++k) {
        EXPECT_EQ(session.run(k).world().velocity[0], thrown) << k;
        EXPECT_LT(glm::length(session.run(k).world().position[0] - (start + 0.2 * 2.0 * right)), 1e-3) << k;
    }
}

// ---------------------------------------------------------------- shooting

TEST(InteractionShoot, FromAnEyeInsideTheBoxTheSphereStartsAtTheEye) {
    physics::World world = boxWorld({{0.5, 0.5, 0.5}});
    const render::Ray aim{{0.0f, 0.0f, 1.0f}, glm::normalize(glm::vec3(1.0f, 0.0f, -0.2f))};
    app::Shot shot;
    ASSERT_EQ(app::planShot(world, aim, 20.0, 0.05, 0.5, &shot), "");
    app::addShot(world, shot);
    ASSERT_EQ(world.size(), 2u);
    EXPECT_EQ(world.position[1], glm::dvec3(0.0, 0.0, 1.0));
    EXPECT_LT(glm::length(world.velocity[1] - 20.0 * glm::normalize(glm::dvec3(aim.direction))), 1e-12);
    EXPECT_EQ(world.radius[1], 0.05);
    EXPECT_EQ(world.mass[1], 0.5);
}

TEST(InteractionShoot, RefusesAShotThatWouldOverlapASphere) {
    physics::World world = boxWorld({{0.0, 0.0, 1.0}, {0.5, 0.5, 0.5}});
    const render::Ray aim{{0.05f, 0.0f, 1.0f}, {1.0f, 0.0f, 0.0f}};
    const std::string refusal = app::planShot(world, aim, 10.0, 0.1, 1.0, nullptr);
    EXPECT_NE(refusal.find("overlap sphere 0"), std::string::npos) << refusal;
    EXPECT_EQ(refusal.find('\n'), std::string::npos);
    // The session refuses it in both runs and leaves them as they were, saying why.
    scenes::Scene scene;
    scene.box = scenes::Box{};
    scene.spheres.push_back({{0.0, 0.0, 1.0}, glm::dvec3(0.0), 0.1, 1.0});
    app::Simulation simulation(scene);
    app::Session session(simulation);
    ASSERT_EQ(session.startComparison({"order=reversed"}), "");
    EXPECT_NE(session.shoot(aim, 10.0).find("cannot shoot"), std::string::npos);
    EXPECT_EQ(session.run(0).world().size(), 1u);
    EXPECT_EQ(session.run(1).world().size(), 1u);
}

TEST(InteractionShoot, FromOutsideTheBoxItStartsWhereTheRayEntersAndMissesAreRefused) {
    physics::World world = boxWorld({});
    const render::Camera camera = outsideCamera();
    const render::Ray aim{camera.position(), camera.forward()};
    app::Shot shot;
    ASSERT_EQ(app::planShot(world, aim, 10.0, 0.1, 1.0, &shot), "");
    EXPECT_TRUE(app::insideBox(world, shot.position, 0.1));
    // On the line of sight, and touching the near wall's shrunk face (just inside).
    const glm::dvec3 eye(aim.origin), d = glm::normalize(glm::dvec3(aim.direction));
    const glm::dvec3 offset = shot.position - eye;
    EXPECT_LT(glm::length(offset - glm::dot(offset, d) * d), 1e-6);
    double nearest = 1e9;
    for (int k = 0; k < world.boxPlaneCount; ++k) {
        const physics::Plane& plane = world.planes[std::size_t(k)];
        nearest = std::min(nearest, glm::dot(shot.position - plane.point, plane.normal) - 0.1);
    }
    EXPECT_NEAR(nearest, 0.0, 1e-6);
    const render::Ray away{camera.position(), -camera.forward()};
    const std::string refusal = app::planShot(world, away, 10.0, 0.1, 1.0, nullptr);
    EXPECT_NE(refusal.find("misses the box"), std::string::npos) << refusal;
    EXPECT_NE(app::planShot(world, aim, 10.0, -0.1, 1.0, nullptr), "");  // a negative radius
}

// ---------------------------------------------------------------- editing

TEST(InteractionEdit, EditsGoIntoEveryRunAndTheReadoutsAreMeasuredAgain) {
    scenes::Scene scene;
    scene.box = scenes::Box{};
    scene.spheres.push_back({{0.0, 0.0, 1.0}, glm::dvec3(0.0), 0.1, 1.0});
    app::Simulation simulation(scene);
    simulation.paused = true;
    app::Session session(simulation);
    ASSERT_EQ(session.startComparison({"beta=0.5"}), "");
    session.select(0);
    const double before = session.diagnostics(0).potential;
    session.editSelected({{0.2, 0.1, 1.5}, {1.0, 0.0, 0.0}, 0.2, 3.0});
    for (int k = 0; k < 2; ++k) {
        const physics::World& world = session.run(k).world();
        EXPECT_EQ(world.position[0], glm::dvec3(0.2, 0.1, 1.5));
        EXPECT_EQ(world.velocity[0], glm::dvec3(1.0, 0.0, 0.0));
        EXPECT_EQ(world.radius[0], 0.2);
        EXPECT_EQ(world.mass[0], 3.0);
    }
    EXPECT_NEAR(session.diagnostics(0).potential, 3.0 * 9.81 * 1.5, 1e-9);
    EXPECT_NE(session.diagnostics(0).potential, before);
    // Each edit is kept: stepping back undoes it.
    session.stepBack();
    EXPECT_EQ(session.run(0).world().position[0], glm::dvec3(0.0, 0.0, 1.0));
    EXPECT_EQ(session.run(1).world().mass[0], 1.0);
}

}  // namespace

// ---------------------------------------------------------------- the explained contact

// While a contact is explained, both of its spheres are ringed: the selected one
// yellow, the other magenta (the explainer's "ringed" line names them); a plane's
// contact, or no explanation, rings the selected sphere alone.
TEST(InteractionSelection, TheExplainedContactsOtherSphereIsRingedToo) {
    app::Simulation simulation(scenes::loadScene(scenes::presetPath("03_head_on")));
    app::Session session(simulation);
    session.select(0);
    app::ToolWindowsState tools;
    tools.explainer = true;
    EXPECT_EQ(app::explainedPartner(session, tools), -1);  // nothing recorded yet
    session.setCatchEveryStep(true);
    for (int frame = 0; frame < 180 && session.latestContacts().events.empty(); ++frame) session.advance(1.0 / 60.0);
    ASSERT_FALSE(session.latestContacts().events.empty()) << "the head-on spheres never met";
    EXPECT_EQ(app::explainedPartner(session, tools), 1);
    const auto ringed = [&](int partner, glm::u8vec4 colour) {
        render::FrameSnapshot snapshot;
        session.appendSelection(0, outsideCamera(), snapshot, partner);
        return std::count_if(snapshot.lines.begin(), snapshot.lines.end(),
                             [&](const render::OverlayLine& line) { return line.color == colour; });
    };
    const glm::u8vec4 yellow{255, 225, 0, 255}, magenta{255, 80, 235, 255};
    EXPECT_GT(ringed(1, yellow), 0);
    EXPECT_EQ(ringed(1, magenta), ringed(1, yellow));  // a whole ring each
    EXPECT_EQ(ringed(-1, magenta), 0);
    tools.explainer = false;
    EXPECT_EQ(app::explainedPartner(session, tools), -1);
}

// A teacher pauses the pile, selects a sphere, then steps back (←) to the frame before, to
// explain the contact there: that frame was kept before the sphere was selected, so it
// holds no contacts of it; the frame is run again, and its contacts are explained (before,
// "No contact of sphere #… recorded since it was selected" while the inspector said static).
TEST(InteractionSelection, SteppingBackExplainsTheContactsOfTheFrameShown) {
    scenes::Scene scene = scenes::loadScene(scenes::presetPath("11_pile"));
    ASSERT_EQ(scenes::applySetting(scene, "count=200"), "");  // more than are always recorded
    app::Simulation simulation(scene);
    app::Session session(simulation);
    for (int frame = 0; frame < 180; ++frame) session.advance(1.0 / 60.0);
    simulation.paused = true;
    const physics::World& world = simulation.world();
    ASSERT_FALSE(world.recordContacts);
    const int lowest = int(std::find(world.contactState.begin(), world.contactState.end(), physics::ContactState::Static) -
                           world.contactState.begin());
    ASSERT_LT(std::size_t(lowest), world.size());
    session.select(lowest);
    const std::size_t shown = session.timeline().cursor();
    ASSERT_GT(shown, 1u);
    session.stepBack();
    ASSERT_EQ(session.timeline().cursor(), shown - 1);
    EXPECT_EQ(world.stepCount, session.timeline().at(shown - 1).stepCount);
    EXPECT_FALSE(session.latestContacts().events.empty()) << "sphere " << lowest << " rests on something";
    EXPECT_TRUE(session.latestContacts().frameRecalled);
    EXPECT_EQ(session.latestContacts().steps, world.stepCount);
}

// A sphere selected while paused has the contacts of the frame shown at once (the frame run
// again from the timeline): the same as had it been selected before that frame, and the run
// not moved on. A sphere selected after an edit (no step in the frame) has none.
TEST(InteractionSelection, ASphereSelectedWhilePausedHasTheContactsOfTheFrameShown) {
    scenes::Scene scene = scenes::loadScene(scenes::presetPath("11_pile"));
    ASSERT_EQ(scenes::applySetting(scene, "count=200"), "");  // more than are always recorded
    const auto landed = [&](app::Simulation& simulation, app::Session& session, int frames) {
        for (int frame = 0; frame < frames; ++frame) session.advance(1.0 / 60.0);
        simulation.paused = true;
    };
    app::Simulation simulation(scene);
    app::Session session(simulation);
    landed(simulation, session, 180);
    const physics::World& world = simulation.world();
    ASSERT_FALSE(world.recordContacts);
    const int lowest = int(std::find(world.contactState.begin(), world.contactState.end(), physics::ContactState::Static) -
                           world.contactState.begin());  // in static contact in the last step: the inspector says so
    ASSERT_LT(std::size_t(lowest), world.size());
    const std::uint64_t hash = physics::stateHash(world);
    session.select(lowest);
    EXPECT_EQ(physics::stateHash(world), hash);
    const std::vector<physics::ContactEvent>& recalled = session.latestContacts().events;
    ASSERT_FALSE(recalled.empty()) << "sphere " << lowest;

    app::Simulation before(scene);  // the same run, the sphere selected before the last frame
    app::Session selectedFirst(before);
    landed(before, selectedFirst, 179);
    selectedFirst.select(lowest);
    before.setSelectedSphere(lowest);  // as the window's frame does: its contacts recorded
    before.paused = false;
    selectedFirst.advance(1.0 / 60.0);
    ASSERT_EQ(physics::stateHash(before.world()), hash);
    const std::vector<physics::ContactEvent>& recorded = selectedFirst.latestContacts().events;
    ASSERT_EQ(recalled.size(), recorded.size());
    for (std::size_t k = 0; k < recorded.size(); ++k) {
        EXPECT_EQ(recalled[k].other, recorded[k].other);
        EXPECT_EQ(recalled[k].velocityBefore[0], recorded[k].velocityBefore[0]);
        EXPECT_EQ(recalled[k].velocityAfter[0], recorded[k].velocityAfter[0]);
        EXPECT_EQ(recalled[k].solverStep, recorded[k].solverStep);
    }
    EXPECT_EQ(session.latestContacts().steps, selectedFirst.latestContacts().steps);

    EXPECT_TRUE(session.latestContacts().frameRecalled);
    // An edit, then another sphere that was in static contact in the frame: the frame shown
    // is now the edit, so nothing is recalled, and the explainer says so.
    const int other = int(std::find(world.contactState.begin() + lowest + 1, world.contactState.end(),
                                    physics::ContactState::Static) - world.contactState.begin());
    ASSERT_LT(std::size_t(other), world.size());
    const std::size_t i = std::size_t(lowest);
    const app::SphereFields fields{world.position[i], world.velocity[i] + glm::dvec3(0.01, 0.0, 0.0), world.radius[i],
                                   world.mass[i]};
    ASSERT_EQ(session.editSelected(fields), "");
    session.select(other);
    EXPECT_TRUE(session.latestContacts().events.empty());
    EXPECT_FALSE(session.latestContacts().frameRecalled);
}

// The window gives the stepping what the last frame's drawing left of 1/30 s: a scene whose
// drawing alone takes longer gets a budget of 0, and must still step once a frame (it stood
// still at 100k), in one piece and in half-step slices (while explaining a contact) alike.
TEST(InteractionSession, AFrameWithNoStepBudgetLeftStillStepsOnce) {
    for (const bool slices : {false, true}) {
        scenes::Scene scene;
        scene.box = scenes::Box{};
        scene.spheres.push_back({{0.0, 0.0, 1.0}, glm::dvec3(0.0), 0.1, 1.0});
        app::Simulation simulation(scene);
        app::Session session(simulation);
        if (slices) {
            session.select(0);
            session.setCatchEveryStep(true);
        }
        simulation.wallBudget = 0.0;  // s
        const double h = simulation.params().timeStep;
        EXPECT_EQ(session.advance(4 * h), 1) << (slices ? "in slices" : "in one piece");
        EXPECT_EQ(session.advance(4 * h), 1) << (slices ? "in slices" : "in one piece");
    }
}

// The inspector's |v| in the unit the texts quote it in: 07's creeping spheres "0.6 cm/s",
// 22's "0.015 mm/s" and "2 µm/s" read 0.006, 0.000 and 0.000 in m/s at three decimals.
TEST(InspectorNumbers, ASpeedIsShownInTheUnitThatGivesItsDigits) {
    EXPECT_EQ(app::speedText(2.345), "2.35 m/s");
    EXPECT_EQ(app::speedText(-0.126), "0.126 m/s");
    EXPECT_EQ(app::speedText(0.1), "0.1 m/s");
    EXPECT_EQ(app::speedText(0.099), "9.90 cm/s");
    EXPECT_EQ(app::speedText(0.006), "0.6 cm/s");
    EXPECT_EQ(app::speedText(1.5e-5), "0.015 mm/s");
    EXPECT_EQ(app::speedText(2e-6), "2.00 µm/s");
    EXPECT_EQ(app::speedText(3.4e-9), "0.0034 µm/s");
    EXPECT_EQ(app::speedText(1e-12), "under 0.001 µm/s");
    EXPECT_EQ(app::speedText(250.0), "250 m/s");
    EXPECT_EQ(app::speedText(0.0), "0 m/s");
    EXPECT_EQ(app::speedText(-0.0), "0 m/s");
    EXPECT_EQ(app::speedText(std::nan("")), "not finite");
}

// Enter on an inspector field left as shown, or its shown digits typed again, changes
// nothing: it had rounded p to the millimetre and r to four digits, set a tiny negative
// to 0, and counted as an edit (the text's claims stopped). A number typed differently
// is taken as typed.
TEST(InspectorNumbers, EnterOnAFieldAsShownChangesNothing) {
    EXPECT_EQ(app::valueAfterEnter(1.235, 1.23456, "%.3f"), 1.23456);
    EXPECT_EQ(app::valueAfterEnter(1.236, 1.23456, "%.3f"), 1.236);
    EXPECT_EQ(app::valueAfterEnter(0.0, -1e-9, "%.3f"), -1e-9) << "shown as 0.000";
    EXPECT_EQ(app::valueAfterEnter(0.0, 0.0004, "%.3f"), 0.0004);
    EXPECT_EQ(app::valueAfterEnter(0.001, 0.0004, "%.3f"), 0.001);
    EXPECT_EQ(app::valueAfterEnter(0.01235, 0.0123456, "%.4g"), 0.0123456);
    EXPECT_EQ(app::valueAfterEnter(0.0124, 0.0123456, "%.4g"), 0.0124);
    EXPECT_EQ(app::valueAfterEnter(2.0, 2.0, "%.4g"), 2.0);
}

// Presented, the layout has no inspector, but 07's text points to its |v|: the panel shows
// the selected sphere's speed in a line, as the inspector writes it; none while none is.
TEST(InspectorNumbers, TheSelectedSpheresSpeedIsALineOfThePresentedPanel) {
    app::Simulation simulation(scenes::loadScene(scenes::presetPath("07_inclined_plane")));
    app::Session session(simulation);
    EXPECT_EQ(app::selectedSpeedLine(session), "");
    session.select(2);
    const double speed = glm::length(simulation.world().velocity[2]);
    EXPECT_EQ(app::selectedSpeedLine(session), "sphere #2: |v|\u00a0" + app::speedText(speed));
    app::Simulation other(scenes::loadScene(scenes::presetPath("02_bounce_projection")));
    app::Session fewer(other);
    fewer.select(0);
    other.editableWorld().velocity[0] = {0.0, 0.0, -0.006};
    EXPECT_EQ(app::selectedSpeedLine(fewer), "sphere #0: |v|\u00a00.6 cm/s");
    // Side by side, the sphere as the view it was clicked in runs it, and that view named.
    ASSERT_EQ(fewer.startComparison({"beta=0.5"}), "");
    fewer.run(1).editableWorld().velocity[0] = {0.0, 0.0, -0.05};
    fewer.select(0, 1);
    EXPECT_EQ(app::selectedSpeedLine(fewer), "sphere #0 in view B: |v|\u00a05.00 cm/s");
}
