#pragma once
// Overrides of a scene's parameters, "name=value[,name=value]", as side by side takes
// them (the window's bar, --compare, a scene's "compare" key): split, checked,
// labelled, and spread over views when names take several values.
#include <string>
#include <string_view>
#include <vector>

#include "scenes/scene.h"

namespace scenes {

// The most views side by side: the scene as given (A) and up to three others.
constexpr int kMostViews = 4;

// "name=value[,name=value]" lists (each string may hold several, separated by
// commas) as single "name=value" settings, trimmed, empty ones dropped.
std::vector<std::string> splitOverrides(const std::vector<std::string>& lists);

// The overrides of each view but A. A value after a comma without a name is another
// value of the name before it (as is a name written again: "beta=0.5,beta=0.2" is
// "beta=0.5,0.2"), and each of that name's values is a view of its own:
// "method=reflection,continuous,passes=1" gives {method=reflection, passes=1} and
// {method=continuous, passes=1}. Several names with several values make a view per
// combination: "shock=off,on,passes=1,4" gives four (the names with several values first,
// then the others, each group in the order written). A view whose
// overrides change nothing in `scene` is left out when another view does change
// something (A shows it already). Returns "" or why not; `variants` is then filled.
using Variants = std::vector<std::vector<std::string>>;
std::string overrideVariants(const Scene& scene, const std::vector<std::string>& lists, Variants& variants);
// Whether no view's overrides change anything in `scene` (every view shows what A shows).
bool changesNothing(const Scene& scene, const Variants& variants);
// "" when overrideVariants takes the lists, else why not.
inline std::string checkCompare(const Scene& scene, const std::vector<std::string>& lists) {
    Variants variants;
    return overrideVariants(scene, lists, variants);
}

// "" when every override applies to a copy of `scene`, else one line naming the bad one.
std::string checkOverrides(const Scene& scene, const std::vector<std::string>& overrides);

// A parameter as a view's label shows it: {"method", "velocity"}.
struct ShownSetting {
    std::string name, value;
};
// What a view shows about its parameters: each overridden name once, in the order written,
// with its value in `scene`; `exact` numbers to the last digit (for comparing two scenes),
// else to 6 significant digits (h = 0.0166667, not 0.016666666666666666).
std::vector<ShownSetting> shownSettings(const Scene& scene, const std::vector<std::string>& overrides, bool exact = false);
// The same as one line: "method = velocity, order = reversed".
std::string overrideLabel(const std::vector<ShownSetting>& settings);
inline std::string overrideLabel(const Scene& scene, const std::vector<std::string>& overrides, bool exact = false) {
    return overrideLabel(shownSettings(scene, overrides, exact));
}

// The name of a "name=value" setting, trimmed.
std::string settingName(std::string_view setting);

// The parameters a scene's text tells the class to move: those its "compare" views differ
// in, then those its description's claims set, each in the parameter table's order. The
// presentation layout shows their sliders only, the first where not all fit (at 1024x768,
// 21 had kept μ, which a claim sets, and scrolled away the K and shock its views differ in).
std::vector<std::string> slidersToMove(const Scene& scene);

}  // namespace scenes
