#pragma once
// Where the window writes its files (saved states, exported plots, screenshots): one
// folder, shown in the panel with its full path, and a new name for every file, so
// that nothing a student wrote before is overwritten.
#include <string>

namespace app {

// The folder, absolute: <working directory>/spheres_output.
std::string outputFolder();

// folder/stem_0001.extension with the first number whose file does not exist yet;
// creates the folder. "" when it cannot (and `error` says why).
std::string freshPath(const std::string& folder, const std::string& stem, const std::string& extension,
                      std::string& error);

}  // namespace app
