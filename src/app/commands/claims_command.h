#pragma once
// `spheres claims [--scene NAME]...`: what each scene's text tells the class, measured as
// the lab sheet's test measures it (scenes::checkClaims), claim by claim. Every preset when
// no scene is named: a course's pipeline checks that its demo still says the truth, and a
// teacher checks the claims of a scene file they wrote.
#include <string>
#include <vector>

namespace app {

struct ClaimsOptions {
    std::vector<std::string> scenes;  // files or preset names; empty: every preset
    bool measures = false;            // instead: list what a claim may measure
    std::string junit;                // also a JUnit XML report here (a test case per claim); "": none
};

// 0 when every claim holds, 1 when one does not. Throws UsageError / scenes::SceneError on
// a scene that cannot be loaded, and UsageError on a report that cannot be written whole.
int runClaims(const ClaimsOptions& options);

}  // namespace app
