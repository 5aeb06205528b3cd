#pragma once
// Smith et al.'s five properties of a simultaneous-impact answer (slide 14; physics.md),
// judged from what the velocity stages did since the last restart
// (physics::ImpactProperties) and from the scene's mirror planes: a verdict and the
// number behind it, for the readouts and for `spheres simulate`.
#include <string>
#include <vector>

#include "physics/diagnostics.h"
#include "physics/impact_properties.h"
#include "physics/params.h"

namespace app {

// What the steps since restart did, each step's worst kept.
struct ImpactRecord {
    physics::ImpactProperties total;  // counts summed over the steps
    double worstMomentumChange = 0.0;  // |dP| / sum m|v| of a step, the largest
    double worstEnergyRatio = -1.0;    // kinetic energy after / before of a step, the largest; -1 none
    double leastEnergyRatio = -1.0;    // the smallest
    void add(const physics::ImpactProperties& step);
};

enum class Verdict { Kept, Broken, Untested };

struct PropertyVerdict {
    std::string name;   // "momentum", "energy", "symmetry", "break-away", "positivity"
    std::string value;  // the number behind the verdict, with its unit
    Verdict verdict = Verdict::Untested;
    std::string meaning;  // what the property asks, for a tooltip
};

// The five, in Smith et al.'s order. `mirrors`: the asymmetry now in each mirror plane
// the scene declares (none: symmetry untested).
std::vector<PropertyVerdict> judgeProperties(const ImpactRecord& record,
                                             const std::vector<physics::MirrorAsymmetry>& mirrors,
                                             const physics::Params& params);

// One line: "momentum ✓ 0 | energy ✓ 1.000000 after/before | ...".
std::string propertiesLine(const std::vector<PropertyVerdict>& verdicts);
// The marks alone, for a view's label, on two lines: "✓ momentum  ✓ energy  ✗ symmetry",
// then "✓ break-away  ✓ positivity"; under the continuous method a third, kOthersNotMeasured.
inline constexpr const char* kOthersNotMeasured = "others not measured (continuous)";
std::string propertiesMarks(const std::vector<PropertyVerdict>& verdicts);
// What the marks mean, for a tooltip: a paragraph per property, its mark, name and number,
// then what it asks.
std::string propertiesTooltip(const std::vector<PropertyVerdict>& verdicts);

}  // namespace app
