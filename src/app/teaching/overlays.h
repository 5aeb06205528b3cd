#pragma once
// The overlays drawn over the scene (velocity arrows, contact points and normals,
// impulse arrows, penetration depth, trails of the centres), as render::FrameSnapshot
// lines and dots, so that the window and `spheres capture` draw the same thing.
//
// OverlayState keeps what spans frames: the impulses of recent impacts (they fade
// over kImpulseFadeSeconds of simulated time) and the trails. Simulation updates it
// after every step from world.contacts and clears it on restart. Everything costs
// nothing while its overlay is off: no contacts are recorded, no trail is kept.
#include <cstddef>
#include <cstdint>
#include <deque>
#include <string>
#include <vector>

#include <glm/gtc/type_precision.hpp>
#include <glm/vec3.hpp>

#include "physics/world.h"
#include "render/frame_snapshot.h"

namespace app {

// Which overlays are shown (ui::PanelState's checkboxes, `capture --overlay`).
struct OverlayFlags {
    bool velocity = false;     // velocity arrows
    bool contacts = false;     // contact points and normals of the last step
    bool impulses = false;     // impulse arrows at impact, fading
    bool penetration = false;  // overlap depth, exaggerated
    bool trails = false;       // fading trails of the centres
    bool graph = false;        // slide 14's contact graph, coloured by level
    bool any() const { return velocity || contacts || impulses || penetration || trails || graph; }
    // Whether world.contacts must be recorded for them.
    bool needsContacts() const { return contacts || impulses; }
    bool operator==(const OverlayFlags& o) const {
        return velocity == o.velocity && contacts == o.contacts && impulses == o.impulses &&
               penetration == o.penetration && trails == o.trails && graph == o.graph;
    }
};

// The overlay names of `capture --overlay`, in this order.
constexpr const char* kOverlayNames[] = {"velocity", "contacts", "impulses", "penetration", "trails", "graph"};
// Sets the flag called `name`; false when there is none of that name.
bool setOverlayByName(OverlayFlags& flags, const std::string& name);
// The names of the overlays that are on, in kOverlayNames order.
std::vector<std::string> overlayNames(const OverlayFlags& flags);

// ---- scales and looks (the legend states them) ----
constexpr double kVelocityArrowSeconds = 0.1;   // s: an arrow is the path of the centre in this time
constexpr double kImpulseMetresPerUnit = 0.05;  // m of arrow per kg m/s of impulse
constexpr double kPenetrationExaggeration = 10.0;  // the red segment is this many times the depth
constexpr double kImpulseFadeSeconds = 0.5;     // s of simulated time
constexpr double kTrailSeconds = 1.5;           // s of simulated time kept
constexpr double kTrailSampleSeconds = 1.0 / 60.0;  // s between trail points (at most one per step)
constexpr double kShortestTrailSegment = 2e-3;  // m: shorter steps of a trail are joined (a pixel or so)
constexpr std::size_t kMaxTrailSpheres = 200;   // the first ones (or the selected sphere only)
constexpr std::size_t kMaxArrowSpheres = 2000;  // velocity arrows: the first ones
constexpr std::size_t kMaxRecordSpheres = 5000;  // above: contacts are not recorded (too many)
constexpr std::size_t kMaxImpulseMarks = 4000;  // the newest are kept
constexpr std::size_t kMaxDrawnContacts = 20000;

constexpr glm::u8vec4 kVelocityColor{225, 40, 190, 255};    // magenta
constexpr glm::u8vec4 kNormalColor{0, 200, 225, 255};       // cyan
constexpr glm::u8vec4 kContactPointColor{255, 225, 0, 255};  // yellow
constexpr glm::u8vec4 kImpulseColor{255, 255, 255, 255};    // white
constexpr glm::u8vec4 kPenetrationColor{235, 20, 20, 255};  // red
constexpr glm::u8vec4 kOutlineColor{20, 22, 30, 255};       // under every arrow, for contrast
// The contact graph's levels from the floor up (level k: kLevelColors[k % 6], darker for
// 6-11, paler for 12-17, palest for 18-23: levelColor), and the spheres that reach no plane.
constexpr glm::u8vec4 kLevelColors[] = {{230, 40, 40, 255},  {255, 140, 0, 255},  {240, 220, 0, 255},
                                        {40, 200, 60, 255},  {0, 200, 225, 255},  {70, 90, 255, 255}};
constexpr glm::u8vec4 kNoLevelColor{150, 150, 160, 255};
glm::u8vec4 levelColor(int level);

// One impulse at an impact: drawn where it happened, fading with age.
struct ImpulseMark {
    std::uint32_t sphere = 0;  // the sphere it acted on
    glm::dvec3 point{0.0};     // m, the contact point at impact
    glm::dvec3 impulse{0.0};   // kg m/s, on `sphere`, summed over the step's passes
    double time = 0.0;         // s, simulated time of the step that made it
};

// The recent positions of one sphere's centre, oldest first.
struct Trail {
    std::uint32_t sphere = 0;
    std::deque<glm::dvec3> points;  // m
    std::deque<double> times;       // s, simulated
};

class OverlayState {
public:
    void reset();
    // After every step: the impulses of the step's bounces (flags.impulses, from
    // world.contacts) and the trail points (flags.trails). `selected` >= 0 keeps the
    // trail of that sphere only.
    void afterStep(const physics::World& world, const OverlayFlags& flags, int selected);

    const std::deque<ImpulseMark>& impulses() const { return impulses_; }
    const std::vector<Trail>& trails() const { return trails_; }
    // 1 at impact, 0 once kImpulseFadeSeconds old.
    static double impulseOpacity(const ImpulseMark& mark, double now);

private:
    void addImpulses(const physics::World& world);
    void addTrailPoints(const physics::World& world, int selected);

    std::deque<ImpulseMark> impulses_;
    std::vector<Trail> trails_;
    double lastTrailTime_ = -1.0;  // s; < 0: none yet
};

// The spheres that per-sphere overlays draw: the selected one, or the first `limit`.
std::vector<std::uint32_t> overlaySpheres(const physics::World& world, int selected, std::size_t limit);

// ---- drawing into the snapshot (after its spheres: trails take their colours) ----
void appendVelocityArrows(const physics::World& world, int selected, render::FrameSnapshot& snapshot);
void appendContacts(const physics::World& world, int selected, render::FrameSnapshot& snapshot);
void appendImpulses(const OverlayState& state, const physics::World& world, render::FrameSnapshot& snapshot);
void appendTrails(const OverlayState& state, const physics::World& world, render::FrameSnapshot& snapshot);
// Slide 14's contact graph: each sphere in the colour of its level, a line between the
// centres of each pair it joins in the colour of the higher level (the sweep answers the
// pair there), and from each level-0 sphere to the planes it touches; grey where no plane
// is reached. Call after the spheres are in the snapshot.
void appendContactGraph(const physics::World& world, const physics::ContactGraph& graph,
                        render::FrameSnapshot& snapshot);

// Overlaps of the current state (sphere pairs and planes), for the penetration overlay.
struct Overlap {
    glm::dvec3 point{0.0};   // m, middle of the overlap
    glm::dvec3 normal{0.0};  // unit
    double depth = 0.0;      // m
};
std::vector<Overlap> currentOverlaps(const physics::World& world, physics::Workspace& scratch);
void appendPenetration(const std::vector<Overlap>& overlaps, render::FrameSnapshot& snapshot);

// An arrow from `from` to `to` (m): a shaft and four barbs, over a dark outline.
void appendArrow(render::FrameSnapshot& snapshot, const glm::dvec3& from, const glm::dvec3& to,
                 glm::u8vec4 color, float width);

// One legend line per shown overlay, with its colour: "velocity: 1 m/s = 10 cm ...".
struct LegendLine {
    std::string text;
    glm::u8vec4 color;
};
std::vector<LegendLine> overlayLegend(const OverlayFlags& flags, std::size_t sphereCount, int selected);

}  // namespace app
