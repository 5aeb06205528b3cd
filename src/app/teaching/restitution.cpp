#include "app/teaching/restitution.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace app {
namespace {

constexpr double kFloorAlignment = 0.999;  // cos of 2.6 degrees between the normal and -g

bool contains(const std::vector<std::uint32_t>& spheres, std::uint32_t i) {
    return std::find(spheres.begin(), spheres.end(), i) != spheres.end();
}

}  // namespace

int floorPlane(const physics::World& world, const physics::Params& params) {
    const double g = glm::length(params.gravity);
    if (!(g > 0.0)) return -1;
    const glm::dvec3 up = -params.gravity / g;
    int best = -1;
    double bestAlignment = kFloorAlignment;
    for (std::size_t k = 0; k < world.planes.size(); ++k) {
        const physics::Plane& plane = world.planes[k];
        if (plane.thickness > 0.0) continue;  // a thin wall, not a floor
        const double alignment = glm::dot(plane.normal, up);
        if (alignment > bestAlignment) {
            bestAlignment = alignment;
            best = static_cast<int>(k);
        }
    }
    return best;
}

double normalEnergy(const physics::World& world, const physics::Params& params, std::size_t i, int floor) {
    const physics::Plane& plane = world.planes[static_cast<std::size_t>(floor)];
    const double gn = glm::dot(params.gravity, plane.normal);  // m/s^2, < 0
    const double height = glm::dot(world.position[i] - plane.point, plane.normal) - world.radius[i];  // m
    const double vn = glm::dot(world.velocity[i], plane.normal) + 0.5 * params.solverStep() * gn;  // m/s
    return -gn * height + 0.5 * vn * vn;
}

std::vector<std::uint32_t> measuredSpheres(const physics::World& world, int selected) {
    if (selected >= 0 && static_cast<std::size_t>(selected) < world.size()) {
        return {static_cast<std::uint32_t>(selected)};
    }
    std::vector<std::uint32_t> spheres;
    if (world.size() > kMaxMeasuredSpheres) return spheres;
    for (std::size_t i = 0; i < world.size(); ++i) spheres.push_back(static_cast<std::uint32_t>(i));
    return spheres;
}

bool followsBounces(const physics::World& world, const physics::Params& params, int selected) {
    return world.recordContacts && floorPlane(world, params) >= 0 && !measuredSpheres(world, selected).empty();
}

void RestitutionMeter::reset() {
    tracks_.clear();
    judged_.clear();
    droppedMeasured_ = droppedTooSlow_ = droppedLabelled_ = labelled_ = 0;
    last_.clear();
    latest_.reset();
    measured_ = 0;
    tooSlow_ = 0;
    floor_ = -2;
}

void RestitutionMeter::afterStep(const physics::World& world, const physics::Params& params, int selected) {
    const int floor = floorPlane(world, params);
    if (floor != floor_) tracks_.clear();
    floor_ = floor;
    const std::vector<std::uint32_t> spheres = measuredSpheres(world, selected);
    if (floor < 0 || !world.recordContacts || spheres.empty()) {
        tracks_.clear();
        return;
    }
    if (tracks_.size() != world.size()) tracks_.assign(world.size(), Track{});

    // What touched each measured sphere in this step.
    std::vector<char> touched(world.size(), 0), floorBounce(world.size(), 0), other(world.size(), 0);
    const std::int32_t floorCode = -1 - floor;  // ContactEvent::other of the floor
    for (const physics::ContactEvent& e : world.contacts) {
        if (e.i < world.size() && contains(spheres, e.i)) {
            touched[e.i] = 1;
            if (e.other == floorCode && e.bounce) {
                floorBounce[e.i] = 1;
            } else {
                other[e.i] = 1;  // another sphere, a wall, or a static contact (mu damps it)
            }
        }
        if (!e.isPlane() && static_cast<std::size_t>(e.other) < world.size() &&
            contains(spheres, static_cast<std::uint32_t>(e.other))) {
            touched[static_cast<std::size_t>(e.other)] = 1;
            other[static_cast<std::size_t>(e.other)] = 1;
        }
    }

    const double gn = std::abs(glm::dot(params.gravity, world.planes[static_cast<std::size_t>(floor)].normal));
    const double minImpactSpeed = kMinImpactSpeedInGH * gn * params.solverStep();  // m/s
    for (const std::uint32_t i : spheres) {
        Track& t = tracks_[i];
        if (touched[i]) {
            if (!t.inContact) {
                t.inContact = true;
                t.beforeKnown = t.flightKnown;
                t.energyBefore = t.energyInFlight;
                t.floorBounce = false;
                t.otherContact = false;
            }
            t.floorBounce = t.floorBounce || floorBounce[i];
            t.otherContact = t.otherContact || other[i];
            continue;
        }
        const double energy = normalEnergy(world, params, i, floor);  // J/kg
        if (t.inContact && t.floorBounce && !t.otherContact && t.beforeKnown && t.energyBefore > 0.0 &&
            std::isfinite(energy)) {
            const double impactSpeed = std::sqrt(2.0 * t.energyBefore);  // m/s
            judge({{i, world.time, t.energyBefore / gn, energy / gn, params.beta},
                   impactSpeed >= kMinLabelledImpactSpeedInGH * gn * params.solverStep(),
                   impactSpeed < minImpactSpeed});
        }
        t.inContact = false;
        t.flightKnown = std::isfinite(energy);
        t.energyInFlight = energy;
    }
}

void RestitutionMeter::judge(const Judged& judged) {
    show(judged);
    if (judged_.size() == kMostJudgedKept) {  // the oldest half goes: no frame of the timeline is that old
        for (auto k = judged_.begin(); k != judged_.begin() + kMostJudgedKept / 2; ++k) {
            ++(k->tooSlow ? droppedTooSlow_ : droppedMeasured_);
            droppedLabelled_ += k->labelled;
        }
        judged_.erase(judged_.begin(), judged_.begin() + kMostJudgedKept / 2);
    }
    judged_.push_back(judged);
}

void RestitutionMeter::show(const Judged& judged) {
    if (judged.labelled) {
        latest_ = judged.bounce;
        ++labelled_;
    }
    if (judged.tooSlow) {
        ++tooSlow_;
        return;
    }
    last_.push_back(judged.bounce);
    ++measured_;
    while (last_.size() > kMeasurementsKept) last_.pop_front();
}

void RestitutionMeter::showAt(double time) {
    last_.clear();
    latest_.reset();
    measured_ = droppedMeasured_;
    tooSlow_ = droppedTooSlow_;
    labelled_ = droppedLabelled_;
    for (const Judged& judged : judged_) {
        if (judged.bounce.time <= time) show(judged);
    }
}

void RestitutionMeter::forgetAfter(double time) {
    while (!judged_.empty() && judged_.back().bounce.time > time) judged_.pop_back();
    showAt(time);
}

}  // namespace app
