#pragma once
// Slide 7's ghosts, for the selected sphere: where the continuous method met its last
// contact (the instant of collision, t* into the solver step), beside where the
// position method's projection would have put it from there (free flight to the end
// of the step, then out by d along the normal, or d split between two spheres).
// Drawn as wire spheres joined by a line, so that the class sees the two answers of
// slide 7 one beside the other. Only the continuous method records an instant of
// contact, so only it leaves a ghost.
#include <optional>

#include <glm/vec3.hpp>

#include "physics/params.h"
#include "physics/world.h"
#include "render/frame_snapshot.h"

namespace app {

struct ContactGhost {
    glm::dvec3 atContact{0.0};  // m: the centre at the instant of contact
    glm::dvec3 projected{0.0};  // m: the centre projection would have given at the step's end
    double radius = 0.0;        // m
    double instant = 0.0;       // s into the solver step: t*
    double time = 0.0;          // s, simulated: the end of the step that met it
};

// The ghost of sphere `selected`'s last contact of the world's last step that has an
// instant (ContactEvent::timeOfImpact >= 0); none when there is none.
std::optional<ContactGhost> lastContactGhost(const physics::World& world, const physics::Params& params, int selected);

// Keeps the latest ghost of the selected sphere from step to step, until another
// contact replaces it, the selection changes or the run restarts.
class ContactGhosts {
public:
    void reset() { latest_.reset(); }
    void afterStep(const physics::World& world, const physics::Params& params, int selected);
    const std::optional<ContactGhost>& latest() const { return latest_; }

private:
    std::optional<ContactGhost> latest_;
    int selected_ = -1;
};

constexpr glm::u8vec4 kGhostAtContactColor{120, 235, 120, 255};  // green: the instant of contact
constexpr glm::u8vec4 kGhostProjectedColor{255, 170, 60, 255};   // orange: projection's answer

// Two wire spheres (three great circles each) and the line between their centres.
void appendContactGhost(const ContactGhost& ghost, render::FrameSnapshot& snapshot);

}  // namespace app
