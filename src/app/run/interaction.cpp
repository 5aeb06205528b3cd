#include "app/run/interaction.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <limits>

#include <glm/geometric.hpp>

#include "scenes/parameters.h"

namespace app {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kInsideSlack = 1e-12;  // m
constexpr int kBoxProjectionRounds = 8;  // projections onto the walls; one suffices for a box

// The distance of p from plane k beyond r (m); negative: the sphere crosses it.
double clearance(const physics::Plane& plane, const glm::dvec3& p, double r) {
    return glm::dot(p - plane.point, plane.normal) - r;
}

}  // namespace

std::optional<double> raySphereDistance(const render::Ray& ray, const glm::dvec3& centre, double radius) {
    const glm::dvec3 d = glm::normalize(glm::dvec3(ray.direction));
    const glm::dvec3 oc = glm::dvec3(ray.origin) - centre;
    const double b = glm::dot(oc, d);
    const double c = glm::dot(oc, oc) - radius * radius;
    const double discriminant = b * b - c;
    if (discriminant < 0.0) return std::nullopt;
    const double root = std::sqrt(discriminant);
    if (-b - root >= 0.0) return -b - root;
    if (-b + root >= 0.0) return -b + root;  // the eye is inside the sphere
    return std::nullopt;
}

int pickSphere(const physics::World& world, const render::Ray& ray) {
    int best = -1;
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < world.size(); ++i) {
        const auto t = raySphereDistance(ray, world.position[i], world.radius[i]);
        if (t && *t < nearest) {
            nearest = *t;
            best = static_cast<int>(i);
        }
    }
    return best;
}

int pickSphere(const physics::World& world, const render::Camera& camera, glm::vec2 pixel, glm::vec2 viewportSize) {
    return pickSphere(world, camera.rayThroughPixel(pixel, viewportSize));
}

glm::dvec3 keepInsideBox(const physics::World& world, glm::dvec3 p, double r) {
    // Projections onto the half-spaces in turn: exact for an axis-aligned box in one
    // round, and a tilted box's opposite walls are parallel, so a few rounds settle it.
    for (int round = 0; round < kBoxProjectionRounds; ++round) {
        bool moved = false;
        for (int k = 0; k < world.boxPlaneCount; ++k) {
            const physics::Plane& plane = world.planes[static_cast<std::size_t>(k)];
            const double c = clearance(plane, p, r);
            if (c < 0.0) {
                p -= c * plane.normal;
                moved = true;
            }
        }
        if (!moved) break;
    }
    return p;
}

bool insideBox(const physics::World& world, const glm::dvec3& p, double r) {
    for (int k = 0; k < world.boxPlaneCount; ++k) {
        if (clearance(world.planes[static_cast<std::size_t>(k)], p, r) < -kInsideSlack) return false;
    }
    return true;
}

void VelocityTracker::add(double time, const glm::dvec3& position) {
    samples_.push_back({time, position});
    // Keep one sample at or before the window's start, so the span covers it.
    while (samples_.size() > 2 && samples_[1].time <= time - kWindowSeconds) samples_.pop_front();
}

glm::dvec3 VelocityTracker::velocity() const {
    if (samples_.size() < 2) return glm::dvec3(0.0);
    const Sample& first = samples_.front();
    const Sample& last = samples_.back();
    const double span = last.time - first.time;  // s
    return span > 0.0 ? (last.position - first.position) / span : glm::dvec3(0.0);
}

bool SphereDrag::begin(const physics::World& world, std::size_t index, const render::Ray& ray,
                       const glm::vec3& facing, double time) {
    active_ = false;
    if (index >= world.size()) return false;
    const glm::dvec3 normal = glm::normalize(glm::dvec3(facing));
    const glm::dvec3 direction = glm::normalize(glm::dvec3(ray.direction));
    const double along = glm::dot(direction, normal);
    if (std::abs(along) < 1e-6) return false;
    index_ = index;
    planePoint_ = world.position[index];
    planeNormal_ = normal;
    const double t = glm::dot(planePoint_ - glm::dvec3(ray.origin), normal) / along;
    grabOffset_ = planePoint_ - (glm::dvec3(ray.origin) + t * direction);
    tracker_.reset();
    tracker_.add(time, planePoint_);
    active_ = true;
    return true;
}

std::optional<glm::dvec3> SphereDrag::move(const physics::World& world, const render::Ray& ray, double time) {
    if (!active_ || index_ >= world.size()) return std::nullopt;
    const glm::dvec3 direction = glm::normalize(glm::dvec3(ray.direction));
    const double along = glm::dot(direction, planeNormal_);
    if (std::abs(along) < 1e-6) return std::nullopt;
    const double t = glm::dot(planePoint_ - glm::dvec3(ray.origin), planeNormal_) / along;
    if (t <= 0.0) return std::nullopt;  // the plane is behind the eye
    const glm::dvec3 centre = keepInsideBox(world, glm::dvec3(ray.origin) + t * direction + grabOffset_,
                                            world.radius[index_]);
    if (!std::isfinite(centre.x) || !std::isfinite(centre.y) || !std::isfinite(centre.z)) return std::nullopt;  // no mouse
    tracker_.add(time, centre);
    return centre;
}

glm::dvec3 SphereDrag::release() {
    active_ = false;
    return tracker_.velocity();
}

std::string checkSphereFields(const physics::World& world, const SphereFields& f) {
    const auto finite = [](const glm::dvec3& x) { return std::isfinite(x.x) && std::isfinite(x.y) && std::isfinite(x.z); };
    const auto number = [](double x) { return scenes::formatNumber(x); };
    if (!finite(f.p) || !finite(f.v) || !std::isfinite(f.r) || !std::isfinite(f.m)) {
        return "cannot edit: every value must be a finite number";
    }
    if (f.r < kEditRadius[0] || f.r > kEditRadius[1]) {
        return "cannot edit: r = " + number(f.r) + " m is outside " + number(kEditRadius[0]) + " to " +
               number(kEditRadius[1]) + " m";
    }
    if (f.m < kEditMass[0] || f.m > kEditMass[1]) {
        return "cannot edit: m = " + number(f.m) + " kg is outside " + number(kEditMass[0]) + " to " +
               number(kEditMass[1]) + " kg";
    }
    if (glm::length(f.v) > kEditSpeed) {
        return "cannot edit: |v| = " + number(glm::length(f.v)) + " m/s is above " + number(kEditSpeed) + " m/s";
    }
    double room = std::numeric_limits<double>::infinity();  // m: the largest radius that fits at p
    for (int k = 0; k < world.boxPlaneCount; ++k) room = std::min(room, clearance(world.planes[std::size_t(k)], f.p, 0.0));
    const auto rounded = [](double x) {  // what the fields show
        char text[32];
        std::snprintf(text, sizeof text, "%.3f", x);
        return std::string(text);
    };
    const std::string at = "p = (" + rounded(f.p.x) + ", " + rounded(f.p.y) + ", " + rounded(f.p.z) + ")";
    if (room <= 0.0) return "cannot edit: " + at + " lies outside the box";
    if (f.r > room + kInsideSlack) {
        return "cannot edit: at " + at + " a sphere of r = " + number(f.r) + " m crosses a wall; at most r = " +
               rounded(room) + " m fits there";
    }
    return "";
}

void placeSphere(physics::World& world, std::size_t index, const glm::dvec3& p, const glm::dvec3& v) {
    if (index >= world.size()) return;
    world.position[index] = p;
    world.velocity[index] = v;
    world.workspace.cached = false;
}

std::optional<glm::dvec3> shotStart(const physics::World& world, const render::Ray& aim, double r, std::string* why) {
    const glm::dvec3 eye(aim.origin);
    const glm::dvec3 d = glm::normalize(glm::dvec3(aim.direction));
    if (world.boxPlaneCount == 0 || insideBox(world, eye, r)) return eye;
    // The box shrunk by r is an intersection of half-spaces: clip the ray by each.
    double enter = 0.0, leave = std::numeric_limits<double>::infinity();
    for (int k = 0; k < world.boxPlaneCount; ++k) {
        const physics::Plane& plane = world.planes[static_cast<std::size_t>(k)];
        const double c = clearance(plane, eye, r);  // grows by d.n per metre
        const double rate = glm::dot(d, plane.normal);
        if (rate == 0.0) {
            if (c < 0.0) leave = -1.0;
        } else if (rate > 0.0) {
            enter = std::max(enter, -c / rate);
        } else {
            leave = std::min(leave, -c / rate);
        }
    }
    if (enter > leave) {
        if (why) *why = "the view ray misses the box: aim at the box (or move the camera into it)";
        return std::nullopt;
    }
    // Just inside, so that rounding does not leave it touching a wall.
    const glm::dvec3 start = eye + (enter + 1e-9) * d;
    return keepInsideBox(world, start, r);
}

std::string planShot(const physics::World& world, const render::Ray& aim, double speed, double radius,
                     double mass, Shot* shot) {
    if (!(radius > 0.0) || !(mass > 0.0) || !std::isfinite(radius) || !std::isfinite(mass) || !std::isfinite(speed)) {
        return "cannot shoot: the radius and the mass must be positive numbers";
    }
    std::string why;
    const auto start = shotStart(world, aim, radius, &why);
    if (!start) return "cannot shoot: " + why;
    if (!insideBox(world, *start, radius)) return "cannot shoot: the new sphere would lie outside the box";
    for (std::size_t i = 0; i < world.size(); ++i) {
        const double reach = radius + world.radius[i];
        const glm::dvec3 delta = *start - world.position[i];
        if (glm::dot(delta, delta) < reach * reach) {
            return "cannot shoot: the new sphere would overlap sphere " + std::to_string(i) +
                   " (aim elsewhere or move the camera)";
        }
    }
    if (shot) *shot = {*start, speed * glm::normalize(glm::dvec3(aim.direction)), radius, mass};
    return "";
}

void addShot(physics::World& world, const Shot& shot) {
    world.addSphere(shot.position, shot.velocity, shot.radius, shot.mass);
    world.workspace.cached = false;
}

void typicalSphere(const physics::World& world, double* radius, double* mass) {
    constexpr double kWaterDensity = 1000.0;  // kg/m^3
    *radius = world.size() ? world.radius.back() : 0.05;
    *mass = world.size() ? world.mass.back() : kWaterDensity * 4.0 / 3.0 * kPi * std::pow(*radius, 3);
}

std::string speedText(double metresPerSecond) {
    struct Unit {
        double from, scale;  // m/s at and above which it is used; its size in m/s
        const char* name;
    };
    static constexpr Unit kUnits[] = {{0.1, 1.0, "m/s"}, {1e-3, 1e-2, "cm/s"}, {1e-5, 1e-3, "mm/s"}, {0.0, 1e-6, "µm/s"}};
    const double speed = std::abs(metresPerSecond);
    if (speed == 0.0 || !std::isfinite(speed)) return speed == 0.0 ? "0 m/s" : "not finite";
    const Unit& unit = *std::find_if(std::begin(kUnits), std::end(kUnits), [&](const Unit& u) { return speed >= u.from; });
    const double shown = speed / unit.scale;
    if (shown < 1e-3) return "under 0.001 µm/s";  // "1e-06 µm/s" said nothing a class reads
    char text[48];
    std::snprintf(text, sizeof text, shown >= 100.0 ? "%.0f %s" : shown >= 10.0 ? "%.1f %s" : shown >= 1.0 ? "%.2f %s" : "%.3g %s",
                  shown, unit.name);
    return text;
}

}  // namespace app
