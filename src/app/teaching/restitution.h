#pragma once
// The measured restitution of floor bounces: the apex ratio of a sphere before and
// after a bounce, from the modified energy of its motion along the floor's normal,
//   e = -g_n y + 1/2 (v_n + h g_n / 2)^2   (per kg; y the height above touching),
// which semi-implicit Euler keeps exactly in free flight, so e / |g_n| is the apex
// height whichever step it is read at. Slide 4: the ratio should be beta^2.
//
// It reads the contact events of each step (world.contacts), so it needs
// world.recordContacts: Simulation turns it on for scenes of up to
// kMaxMeasuredSpheres spheres, or for the selected sphere.
#include <cstddef>
#include <cstdint>
#include <deque>
#include <optional>
#include <vector>

#include "physics/params.h"
#include "physics/world.h"

namespace app {

constexpr std::size_t kMaxMeasuredSpheres = 10;  // scenes up to this size measure every sphere
constexpr std::size_t kMeasurementsKept = 4;     // the last ones, shown in the panel
// Bounces slower than this many g h are not measured: one step's travel would be
// more than 1/10 of the height, and the ratio would say more about h than about beta.
constexpr double kMinImpactSpeedInGH = 20.0;
// The views' labels compare the methods at one coarse h, where the step's error is the
// lesson, down to this: slower hops would measure little but the step (a ratio of 3.8 from
// a hop of a few millimetres, slide 7's reflection one kick late).
constexpr double kMinLabelledImpactSpeedInGH = 4.0;

struct BounceMeasurement {
    std::uint32_t sphere = 0;
    double time = 0.0;          // s, simulated, when the sphere left the floor
    double heightBefore = 0.0;  // m, apex above touching before the bounce
    double heightAfter = 0.0;   // m, after
    double beta = 0.0;          // the β it was answered with (a slider moved since makes it another's)
    double ratio() const { return heightAfter / heightBefore; }  // measured beta^2
};

// Index of the plane the spheres fall onto (its normal against gravity, within 2.6
// degrees), or -1 without gravity or without such a plane.
int floorPlane(const physics::World& world, const physics::Params& params);

// J/kg: the modified energy of sphere i's motion along the floor's normal (above).
double normalEnergy(const physics::World& world, const physics::Params& params, std::size_t i, int floor);

// The spheres measured: the selected one, or all of a scene of up to kMaxMeasuredSpheres.
std::vector<std::uint32_t> measuredSpheres(const physics::World& world, int selected);

// Whether the meter follows floor bounces here: contacts recorded, a floor under gravity,
// spheres to measure (with `selected`, or -1 for the scene's own).
bool followsBounces(const physics::World& world, const physics::Params& params, int selected);

class RestitutionMeter {
public:
    void reset();
    // Forgets the flights and contacts being followed (the world was edited by hand),
    // keeps the measurements.
    void forgetFlights() { tracks_.clear(); }
    // The timeline shows the state at `time` (s): the measurements are shown as they were
    // then (the flights are the caller's: forgetFlights). Those after it are kept for a later
    // frame of the timeline until forgetAfter(time): running on from there measures them again.
    void showAt(double time);
    void forgetAfter(double time);
    // After every step, with world.contacts of that step.
    void afterStep(const physics::World& world, const physics::Params& params, int selected);

    const std::deque<BounceMeasurement>& last() const { return last_; }  // oldest first
    // The newest clean floor bounce at least kMinLabelledImpactSpeedInGH g h fast, slow ones
    // (under kMinImpactSpeedInGH) too: the apex ratio a view's label shows, where comparing
    // the methods at one coarse h is the lesson (slide 7's three answers).
    const std::optional<BounceMeasurement>& latest() const { return latest_; }
    // Which of the labelled bounces since the restart latest() is: 1 the first ("0.47 at the
    // fifth", 14's text says of view A's); 0 none.
    std::uint64_t latestNumber() const { return labelled_; }
    std::uint64_t measuredCount() const { return measured_; }
    // Clean floor bounces left unmeasured because they were slower than
    // kMinImpactSpeedInGH g h (a large h makes every bounce so).
    std::uint64_t tooSlowCount() const { return tooSlow_; }

private:
    struct Track {
        bool inContact = false;
        bool flightKnown = false;  // energyInFlight holds a free-flight value
        double energyInFlight = 0.0;
        double energyBefore = 0.0;
        bool beforeKnown = false;
        bool floorBounce = false;  // a bounce on the floor during this contact
        bool otherContact = false;  // anything else touched it: not a clean floor bounce
    };
    // Every bounce judged since reset, oldest first: what a rewind takes back.
    struct Judged {
        BounceMeasurement bounce;
        bool labelled = false;  // at least kMinLabelledImpactSpeedInGH g h fast
        bool tooSlow = false;   // under kMinImpactSpeedInGH g h: counted, not measured
    };
    static constexpr std::size_t kMostJudgedKept = std::size_t(1) << 16;  // past the timeline's 19 200 steps
    void judge(const Judged& judged);
    void show(const Judged& judged);  // as the newest: last_, latest_ and the counts

    std::uint64_t droppedMeasured_ = 0, droppedTooSlow_ = 0, droppedLabelled_ = 0;  // of the judged_ the cap dropped
    std::uint64_t labelled_ = 0;  // labelled bounces shown
    std::vector<Track> tracks_;  // by sphere index
    std::vector<Judged> judged_;
    std::deque<BounceMeasurement> last_;
    std::optional<BounceMeasurement> latest_;
    std::uint64_t measured_ = 0;
    std::uint64_t tooSlow_ = 0;
    int floor_ = -2;  // the floor plane of the last step; -2: not known yet
};

}  // namespace app
