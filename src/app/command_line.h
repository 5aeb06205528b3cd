#pragma once
// The one executable's command line: `spheres [window options]`, `spheres simulate`,
// `spheres capture`, `spheres presets`.
namespace app {

// Parses argv and runs the chosen command; returns the process exit code:
// 0 success, 1 runtime failure, 2 bad input (with a one-line message on stderr).
int runCommandLine(int argc, char** argv);

}  // namespace app
