#pragma once
// `spheres [--scene FILE] [--set name=value]... [--frames N] [--screenshot FILE.png]
//  [--compare name=value[,name=value]] [--select INDEX [--explain]] [--present]`: the interactive window.
#include <string>
#include <vector>

namespace app {

struct WindowAppOptions {
    std::string scene = "11_pile";      // file or preset name
    std::vector<std::string> settings;  // "name=value"
    int frames = 0;                     // > 0: run this many frames, then exit
    std::string screenshot;             // write the last frame here (PNG)
    bool paused = false;                // start paused
    int width = 1280, height = 800;     // screen coordinates
    bool sizeGiven = false;             // --width or --height: else a larger screen's window opens larger
    std::vector<std::string> compare;   // "name=value[,name=value]": start side by side
    int select = -1;                    // >= 0: start with this sphere selected (inspector open)
    bool explain = false;               // with select: open "explain this contact"
    bool present = false;               // start in the presentation layout (F5)
    std::string program = "spheres";    // as it was started (argv[0]): the hints' commands name it so
};

// Returns the exit code; 2 when no window can be opened (no display).
int runWindowApp(const WindowAppOptions& options);

}  // namespace app
