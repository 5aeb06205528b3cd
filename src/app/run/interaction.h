#pragma once
// What the mouse and the keyboard do to the spheres, as plain functions of a
// world, a camera ray and a time, so that tests drive them without a window:
// pick a sphere under a pixel, drag it in the plane through its centre facing
// the camera (kept inside the box) and throw it with the mouse's velocity, shoot
// a new sphere from the camera. The window turns ImGui's mouse state into these calls.
#include <cstddef>
#include <deque>
#include <optional>
#include <string>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "physics/world.h"
#include "render/camera.h"

namespace app {

// Distance (m) along the ray to the first point of the sphere it meets, or none.
// A ray starting inside the sphere meets it where it leaves.
std::optional<double> raySphereDistance(const render::Ray& ray, const glm::dvec3& centre, double radius);

// The sphere hit first by the ray (nearest along it), or -1.
int pickSphere(const physics::World& world, const render::Ray& ray);

// The same for the pixel of a viewport (top-left origin, i + 0.5 is a centre).
int pickSphere(const physics::World& world, const render::Camera& camera, glm::vec2 pixel, glm::vec2 viewportSize);

// Moves a centre the least so that a sphere of radius r lies inside the box:
// (p - a).n >= r for every box plane (the first world.boxPlaneCount planes).
glm::dvec3 keepInsideBox(const physics::World& world, glm::dvec3 p, double r);

// Whether a sphere of radius r centred at p lies inside the box (to 1e-12 m).
bool insideBox(const physics::World& world, const glm::dvec3& p, double r);

// The mouse's velocity (m/s), smoothed: the displacement over the last
// kWindowSeconds of samples divided by their time span.
class VelocityTracker {
public:
    static constexpr double kWindowSeconds = 0.1;  // s

    void reset() { samples_.clear(); }
    void add(double time, const glm::dvec3& position);  // s, m
    glm::dvec3 velocity() const;                        // m/s; 0 with fewer than two samples

private:
    struct Sample {
        double time;          // s
        glm::dvec3 position;  // m
    };
    std::deque<Sample> samples_;
};

// Dragging one sphere: it follows the mouse in the plane through its centre
// facing the camera (the point grabbed stays under the cursor), inside the box,
// and on release it keeps the mouse's smoothed velocity.
class SphereDrag {
public:
    // Grabs `index` where `ray` meets the plane through its centre with normal
    // `facing` (the camera's forward direction). False when the ray is parallel to it.
    bool begin(const physics::World& world, std::size_t index, const render::Ray& ray,
               const glm::vec3& facing, double time);
    // The centre (m) the sphere must have for this ray, inside the box; none when the
    // ray misses the plane. Records the sample for the velocity.
    std::optional<glm::dvec3> move(const physics::World& world, const render::Ray& ray, double time);
    // Ends the drag; the velocity (m/s) to throw the sphere with.
    glm::dvec3 release();

    bool active() const { return active_; }
    std::size_t index() const { return index_; }
    glm::dvec3 velocity() const { return tracker_.velocity(); }  // m/s, while dragging

private:
    bool active_ = false;
    std::size_t index_ = 0;
    glm::dvec3 planePoint_{0.0};   // m
    glm::dvec3 planeNormal_{0.0};  // unit
    glm::dvec3 grabOffset_{0.0};   // m, centre minus the grabbed point on the plane
    VelocityTracker tracker_;
};

// The fields of one sphere, as the inspector edits them.
struct SphereFields {
    glm::dvec3 p{0.0};  // m
    glm::dvec3 v{0.0};  // m/s
    double r = 0.05;    // m
    double m = 1.0;     // kg
};

// The ranges an edited sphere must keep: the radius parameter's (m), a mass (kg) the
// impulses stay well within double precision for, and the fastest shot (m/s).
constexpr double kEditRadius[2] = {0.005, 0.5};
constexpr double kEditMass[2] = {1e-3, 1e3};
constexpr double kEditSpeed = 100.0;

// "" when `fields` may be put into a sphere of `world`: finite numbers within the
// ranges above, and the sphere wholly inside the box; else one line naming the value
// and its limit ("r = 5 m does not fit at p: at most 1.2 m there").
std::string checkSphereFields(const physics::World& world, const SphereFields& fields);

// Puts sphere `index` at p with velocity v (a drag, an edit) and makes the next
// step rebuild its candidate pairs.
void placeSphere(physics::World& world, std::size_t index, const glm::dvec3& p, const glm::dvec3& v);

// Shooting a sphere from the camera.
struct Shot {
    glm::dvec3 position{0.0};  // m, centre of the new sphere
    glm::dvec3 velocity{0.0};  // m/s
    double radius = 0.05;      // m
    double mass = 1.0;         // kg
};

// Where a shot along `aim` starts: at the eye when a sphere of radius r fits there
// inside the box, else where the ray enters the box (shrunk by r). Returns none
// with `why` set when the ray never passes through the box.
std::optional<glm::dvec3> shotStart(const physics::World& world, const render::Ray& aim, double r, std::string* why);

// The shot along `aim` at `speed` (m/s), checked against `world`: returns "" when it
// may be added, else one line saying why not (it would overlap sphere k, or lie outside
// the box, or the ray misses the box).
std::string planShot(const physics::World& world, const render::Ray& aim, double speed, double radius,
                     double mass, Shot* shot);

// Adds the shot to the world (at the end: every existing index stays valid).
void addShot(physics::World& world, const Shot& shot);

// A typical sphere of the world for the next shot: the radius (m) and mass (kg)
// of its last sphere, or 0.05 m of water when it has none.
void typicalSphere(const physics::World& world, double* radius, double* mass);

// The inspector's |v| (the window's and the page's), three digits in the unit that shows them: "2.35 m/s", "0.6 cm/s",
// "0.015 mm/s", "2.10 µm/s" (07's text quotes 0.6 cm/s, 22's 0.015 mm/s and 2 µm/s, and
// 09's column a small stored speed: all 0.000 in m/s at three decimals), "0 m/s" at rest,
// "under 0.001 µm/s" below.
std::string speedText(double metresPerSecond);

}  // namespace app
