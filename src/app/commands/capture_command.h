#pragma once
// `spheres capture`: renders chosen frames of a scene without a display (OSMesa
// or EGL) into PNG files plus a manifest.json. It steps one app::Simulation by
// advance(1/60 s) per frame, exactly as the window does, and draws with the
// window's renderer and layout, so a frame here is a frame there.
#include <optional>
#include <string>
#include <vector>

namespace app {

// The most frames a capture writes, and the largest --every: frame_NNNNNN.png has six digits.
constexpr int kMostCapturedFrames = 1000000;

struct CaptureOptions {
    std::string scene;                  // file or preset name
    std::vector<std::string> settings;  // "name=value", applied in order
    std::optional<int> frames;          // run frames 0 .. N-1 and write every `every`-th
    std::optional<int> every;           // with frames only; default 1
    std::optional<std::string> at;      // instead of frames: "f1,f2,..." strictly increasing
    std::string out;                    // folder, created when missing
    std::string size = "1280x800";      // "WxH", px
    std::string camera;  // "azimuth,elevation[,distance]": deg, deg, m; "": fit the box
    std::string colorBy;  // id | speed | contact | penetration; "": the scene's "color_by", else contact
    bool withUi = false;              // draw the panel and readouts as the window does
    // With withUi or side by side: the panel's and the labels' UI scale (default 1; 2 draws
    // as a HiDPI screen at 2x does).
    std::optional<float> uiScale;
    bool present = false;             // with withUi: the presentation layout
    std::vector<std::string> compare;  // "name=value[,name=value]": a second view side by side with these
    std::string overlay;  // "velocity,contacts,impulses,penetration,trails" (any of them, or all); "": none
    std::string gl = "auto";          // osmesa | egl | auto
    int samples = 0;                  // MSAA samples per pixel; 0: none
};

// One real second of the window is 60 frames (at time scale 1).
constexpr double kCaptureFrameSeconds = 1.0 / 60.0;  // s

// Writes OUT/frame_NNNNNN.png (six digits, the frame index) for every chosen
// frame and OUT/manifest.json; prints the GL backend it uses (one line).
// Returns 0, or 1 when a file cannot be written midway. Throws UsageError
// (command_line.cpp: exit code 2) for refused input, and scenes::SceneError for
// a broken scene, both before anything is written.
int runCapture(const CaptureOptions& options);

}  // namespace app
