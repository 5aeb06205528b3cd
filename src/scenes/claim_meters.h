#pragma once
// The meters a claim can name (claims.h): each watches a run of a preset, step by
// step, and keeps the samples that fall in the claim's stretch of time.
#include <memory>
#include <vector>

#include "physics/world.h"
#include "scenes/claims.h"
#include "scenes/scene.h"

namespace scenes::detail {

class Meter {
  public:
    virtual ~Meter() = default;
    // Called with the world as built (t = 0) and after every time step.
    virtual void observe(const physics::World& world) = 0;
    const std::vector<double>& samples() const { return samples_; }

  protected:
    std::vector<double> samples_;
};

// The meter `claim.measure` names for a run of `variant` (the preset with the claim's
// settings), or nullptr when there is none of that name.
std::unique_ptr<Meter> makeMeter(const Claim& claim, const Scene& variant);

}  // namespace scenes::detail
