#pragma once
// The meters a claim can name (claims.h): each watches a run of a preset, step by
// step, and keeps the samples that fall in the claim's stretch of time.
#include <algorithm>
#include <memory>
#include <vector>

#include "physics/step.h"
#include "physics/world.h"
#include "scenes/claims.h"
#include "scenes/scene.h"

namespace scenes::detail {

class Meter {
  public:
    virtual ~Meter() = default;
    // Called with the world as built (t = 0) and after every time step.
    void observe(const physics::World& world) {
        mostSpheres_ = std::max(mostSpheres_, world.size());
        measure(world);
    }
    // Called after every time step, before observe(), with what the step did.
    virtual void stepped(const physics::StepStats&) {}
    // Whether the run must measure the contacts' properties for it (World::measureImpacts).
    virtual bool needsImpacts() const { return false; }
    const std::vector<double>& samples() const { return samples_; }
    // The most spheres a world it observed held: a claim's sphere numbered beyond them was
    // never in the run (the claim fails and says so, rather than measuring the others).
    std::size_t mostSpheres() const { return mostSpheres_; }

  protected:
    virtual void measure(const physics::World& world) = 0;
    std::vector<double> samples_;

  private:
    std::size_t mostSpheres_ = 0;
};

// The meter `claim.measure` names for a run of `variant` (the preset with the claim's
// settings), or nullptr when there is none of that name.
std::unique_ptr<Meter> makeMeter(const Claim& claim, const Scene& variant);

}  // namespace scenes::detail
