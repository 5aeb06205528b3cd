#include "app/views/frame_builder.h"

#include <algorithm>
#include <cstdio>
#include <string>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "app/run/interaction.h"
#include "scenes/scene.h"

namespace app {

OverlayFlags overlayFlags(const ui::PanelState& view) {
    OverlayFlags flags;
    flags.velocity = view.showVelocity;
    flags.contacts = view.showContacts;
    flags.impulses = view.showImpulses;
    flags.penetration = view.showPenetration;
    flags.trails = view.showTrails;
    flags.graph = view.showGraph;
    return flags;
}

ui::PanelState viewShowing(const OverlayFlags& flags) {
    ui::PanelState view;
    view.showVelocity = flags.velocity;
    view.showContacts = flags.contacts;
    view.showImpulses = flags.impulses;
    view.showPenetration = flags.penetration;
    view.showTrails = flags.trails;
    view.showGraph = flags.graph;
    return view;
}

bool overlaysOnTop(const ui::PanelState& view, std::size_t sphereCount) {
    const std::size_t most = view.showGraph ? kGraphOnTopMaxSpheres : kOverlaysOnTopMaxSpheres;
    return view.overlaysOnTop && sphereCount <= most;
}

void buildSnapshot(Simulation& simulation, const ui::PanelState& view, render::FrameSnapshot& snapshot) {
    const OverlayFlags flags = overlayFlags(view);
    if (!(flags == simulation.overlayFlags())) simulation.setOverlayFlags(flags);
    if (view.selectedSphere != simulation.selectedSphere()) simulation.setSelectedSphere(view.selectedSphere);
    const physics::World& world = simulation.world();
    snapshot.clear();
    render::snapshotSpheres(world, static_cast<render::ColorBy>(view.colorBy), snapshot);
    render::snapshotPlanes(world, snapshot);
    const std::optional<ContactGhost>& ghost = simulation.contactGhosts().latest();
    if (ghost && simulation.selectedSphere() >= 0) appendContactGhost(*ghost, snapshot);
    if (!flags.any()) return;
    // Under the arrows: trails, then overlaps; the arrows and points last, on top.
    if (flags.trails) appendTrails(simulation.overlays(), world, snapshot);
    if (flags.graph) appendContactGraph(world, simulation.contactGraph(), snapshot);
    if (flags.penetration && !simulation.alarms().nonFinite()) {
        physics::Workspace scratch;
        appendPenetration(currentOverlaps(world, scratch), snapshot);
    }
    if (flags.velocity) appendVelocityArrows(world, simulation.selectedSphere(), snapshot);
    if (flags.contacts && world.recordContacts) appendContacts(world, simulation.selectedSphere(), snapshot);
    if (flags.impulses) appendImpulses(simulation.overlays(), world, snapshot);
}

namespace {

std::string restitutionNote(const Simulation& simulation) {
    const physics::World& world = simulation.world();
    if (floorPlane(world, simulation.params()) < 0) return "(no floor under gravity)";
    if (measuredSpheres(world, simulation.selectedSphere()).empty()) {
        // More spheres than the meter follows (the tooltip: or the selected sphere): the value
        // beside is the β² set, not a measure.
        return "(over " + std::to_string(kMaxMeasuredSpheres) + " spheres: select one to measure)";
    }
    if (!world.recordContacts) return "(not measured above " + std::to_string(kMaxRecordSpheres) + " spheres)";
    const std::optional<BounceMeasurement>& latest = simulation.restitution().latest();
    if (simulation.restitution().tooSlowCount() > 0 && latest && latest->beta == simulation.params().beta) {
        // A large h: one step's travel is a fair part of the height, the ratio measures h
        // as much as beta. Said with its value: comparing methods at one h is a lesson too.
        const physics::Params& params = simulation.params();
        char text[200];
        std::snprintf(text, sizeof text,
                      "(last bounce %.3f: the method's error at this h shows in it too; the measured β² "
                      "takes impacts above %.0f g h%s = %.3g m/s)",
                      latest->ratio(), kMinImpactSpeedInGH, params.substeps > 1 ? " / substeps" : "",
                      kMinImpactSpeedInGH * glm::length(params.gravity) * params.solverStep());
        return text;
    }
    return "(no floor bounce yet)";
}

}  // namespace

void addMeasuredClaims(const Simulation& simulation, const Comparison* comparison, ui::Readouts& r) {
    const int runs = comparison ? 1 + comparison->count() : 1;
    for (int k = 0; k < runs; ++k) {
        const Simulation& run = k == 0 ? simulation : comparison->simulation(k - 1);
        const char view = runs > 1 ? char('A' + k) : 0;
        for (const scenes::ClaimCheck& check : run.measuredClaims()) {
            r.claims.push_back({scenes::withCount(check.claim->says, run.scene()), check.measured, check.holds, view});
        }
        r.claimsWatched += run.claimsWatched();
        r.claimsLastMoment = std::max(r.claimsLastMoment, run.claimsLastMoment());
    }
    const auto inText = std::count_if(simulation.scene().claims.begin(), simulation.scene().claims.end(),
                                      [](const scenes::Claim& c) { return c.in == scenes::ClaimSource::Description; });
    r.claimsElsewhere = std::size_t(inText) > r.claimsWatched ? std::size_t(inText) - r.claimsWatched : 0;
    r.claimsForOtherSettings = simulation.claimsForOtherSettings();
    r.claimsInterrupted = simulation.claimsInterrupted();
}

std::string selectedSpeedLine(const Session& session) {
    const int sphere = session.selected();
    const physics::World& world = session.run(session.selectedView()).world();
    if (sphere < 0 || std::size_t(sphere) >= world.size()) return "";
    const std::string view = session.comparison() ? std::string(" in view ") + char('A' + session.selectedView()) : "";
    return "sphere #" + std::to_string(sphere) + view + ": |v|\u00a0" + speedText(glm::length(world.velocity[std::size_t(sphere)]));
}

ui::Readouts makeReadouts(const Simulation& simulation, const ui::FrameTimes& timing, const Comparison* comparison) {
    ui::Readouts r;
    r.timing = timing;
    r.paused = simulation.paused;
    r.behindRealTime = simulation.behindRealTime();
    r.time = simulation.world().time;
    r.timeScale = simulation.timeScale;
    r.steps = simulation.world().stepCount;
    r.sphereCount = simulation.world().size();
    r.stats = simulation.lastStepStats();
    r.diagnostics = simulation.diagnostics();
    const History& history = simulation.history();
    for (Series s : {Series::Kinetic, Series::Potential, Series::Modified, Series::InContact}) {
        r.plots.emplace_back(History::name(s), &history.values(s));
    }
    r.plotTimes = &history.times();
    r.bouncesSinceRestart = simulation.bouncesSinceRestart();
    r.continuous = simulation.params().method == physics::Method::Continuous;
    r.untilConverged = simulation.params().solver == physics::Solver::UntilConverged;
    r.passCap = simulation.params().passes;
    r.globalSolve = physics::solvesGlobally(simulation.params().solver);
    r.reflections = simulation.params().solver == physics::Solver::GeneralizedReflections;
    r.shock = simulation.params().shock == physics::ShockPropagation::On && physics::sweepsLevels(simulation.params().method);
    r.cappedSinceRestart = simulation.alarms().count(AlarmKind::EventCap);
    // Shown once contacts were measured, and under the continuous method, which says it
    // measures none of them (its symmetry is the state's).
    if (simulation.impacts().total.contacts > 0 || simulation.params().method == physics::Method::Continuous) {
        std::vector<physics::MirrorAsymmetry> mirrors;
        for (const physics::Plane& m : simulation.scene().mirrors) {
            mirrors.push_back(physics::mirrorAsymmetry(simulation.world(), m));
        }
        for (const PropertyVerdict& v : judgeProperties(simulation.impacts(), mirrors, simulation.params())) {
            r.properties.push_back({v.name, v.value, v.meaning, static_cast<int>(v.verdict)});
        }
    }
    addMeasuredClaims(simulation, comparison, r);
    for (const AlarmLine& line : simulation.alarms().lines(simulation.world().time)) {
        r.alarms.push_back({line.text, line.hint, line.lit});
    }
    r.betaSquared = simulation.params().beta * simulation.params().beta;
    // The bounces of the β set now: after a move of its slider the ratios of the old β,
    // beside the new β², read as if β did nothing (02 at rest: no bounce comes to replace them).
    bool otherBeta = false;
    for (const BounceMeasurement& m : simulation.restitution().last()) {
        if (m.beta == simulation.params().beta) {
            r.measuredBetaSquared.push_back(m.ratio());
        } else {
            otherBeta = true;
        }
    }
    if (r.measuredBetaSquared.empty()) {
        r.restitutionNote = otherBeta ? "(no floor bounce since β was changed: R drops it again)" : restitutionNote(simulation);
    }
    r.bouncesMeasured = followsBounces(simulation.world(), simulation.params(), simulation.selectedSphere());
    std::vector<LegendLine> legend =
        overlayLegend(simulation.overlayFlags(), simulation.world().size(), simulation.selectedSphere());
    if (const auto& ghost = simulation.contactGhosts().latest(); ghost && simulation.selectedSphere() >= 0) {
        char text[200];
        std::snprintf(text, sizeof text, "slide 7: green, the sphere at the instant of contact, t* = %.2f ms into "
                      "the step; orange, where projection would have put it", 1e3 * ghost->instant);
        legend.push_back({text, kGhostAtContactColor});
    }
    for (const LegendLine& line : legend) {
        r.legend.push_back({line.text,
                            {line.color.x / 255.0f, line.color.y / 255.0f, line.color.z / 255.0f, 1.0f}});
    }
    return r;
}

void sceneBounds(const Simulation& simulation, glm::vec3& lo, glm::vec3& hi) {
    const scenes::Scene& scene = simulation.scene();
    if (scene.camera.fits) {
        lo = glm::vec3(scene.camera.fits->min);
        hi = glm::vec3(scene.camera.fits->max);
        return;
    }
    if (scene.box) {
        const glm::dvec3 size = scene.box->size;
        lo = glm::vec3(-size.x / 2, -size.y / 2, 0.0);
        hi = glm::vec3(size.x / 2, size.y / 2, size.z);
        return;
    }
    lo = glm::vec3(-1.0f);
    hi = glm::vec3(1.0f);
    const physics::World& world = simulation.world();
    for (std::size_t i = 0; i < world.size(); ++i) {
        lo = glm::min(lo, glm::vec3(world.position[i]) - float(world.radius[i]));
        hi = glm::max(hi, glm::vec3(world.position[i]) + float(world.radius[i]));
    }
}

render::Camera sceneCameraAngles(const scenes::Scene& scene) {
    render::Camera camera;
    if (scene.camera.azimuthDeg) camera.azimuth = float(glm::radians(*scene.camera.azimuthDeg));
    if (scene.camera.elevationDeg) camera.elevation = float(glm::radians(*scene.camera.elevationDeg));
    return camera;
}

render::Camera openingCamera(const Simulation& simulation, float aspect) {
    render::Camera camera = sceneCameraAngles(simulation.scene());
    glm::vec3 lo, hi;
    sceneBounds(simulation, lo, hi);
    camera.fitBox(lo, hi, aspect);
    return camera;
}

}  // namespace app
