#pragma once
// Helpers for the capture tests: a folder per test in the build tree, the
// options of a small capture, reading its frames and manifest back, and a
// world stepped the way the window steps it, written out independently.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <glm/trigonometric.hpp>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "app/commands/capture_command.h"
#include "physics/step.h"
#include "platform/headless_context.h"
#include "render/camera.h"
#include "render/image_io.h"
#include "scenes/parameters.h"
#include "scenes/presets.h"
#include "scenes/scene_json.h"

namespace capture_test {

namespace fs = std::filesystem;

// A fresh, empty folder under the build tree's test output for `name`.
inline std::string freshFolder(const std::string& name) {
    const fs::path folder = fs::path(SPHERES_TEST_OUTPUT_DIR) / "capture" / name;
    fs::remove_all(folder);
    fs::create_directories(folder.parent_path());
    return folder.string();
}

// Why the backend cannot make a context here, or "" when it can.
inline std::string unavailableReason(platform::HeadlessBackend backend) {
    std::string error;
    const auto context = platform::createHeadless(backend, &error);
    return context ? std::string() : error;
}

inline std::string backendName(const ::testing::TestParamInfo<platform::HeadlessBackend>& info) {
    return platform::toString(info.param);
}

// A small, fast capture: 320 x 200 px, no MSAA, scene only.
inline app::CaptureOptions smallCapture(const std::string& scene, const std::string& out,
                                        platform::HeadlessBackend backend) {
    app::CaptureOptions options;
    options.scene = scene;
    options.out = out;
    options.size = "320x200";
    options.gl = platform::toString(backend);
    return options;
}

inline std::string frameName(int index) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%06d.png", index);
    return name;
}

inline render::Image readFrame(const std::string& folder, int index) {
    render::Image image;
    EXPECT_TRUE(render::readPng((fs::path(folder) / frameName(index)).string(), &image))
        << folder << " " << index;
    return image;
}

inline nlohmann::json readManifest(const std::string& folder) {
    std::ifstream file(fs::path(folder) / "manifest.json");
    EXPECT_TRUE(file.good()) << folder;
    return file ? nlohmann::json::parse(file) : nlohmann::json();
}

// The camera the manifest says the frames were drawn with.
inline render::Camera cameraOf(const nlohmann::json& manifest) {
    const nlohmann::json& c = manifest.at("camera");
    render::Camera camera;
    camera.azimuth = static_cast<float>(glm::radians(c.at("azimuth_deg").get<double>()));
    camera.elevation = static_cast<float>(glm::radians(c.at("elevation_deg").get<double>()));
    camera.distance = c.at("distance_m").get<float>();
    camera.target = {c.at("target_m")[0].get<float>(), c.at("target_m")[1].get<float>(),
                     c.at("target_m")[2].get<float>()};
    return camera;
}

// The preset with --set style overrides applied.
inline scenes::Scene presetScene(const std::string& name,
                                 const std::vector<std::string>& settings = {}) {
    scenes::Scene scene = scenes::loadScene(scenes::presetPath(name));
    for (const std::string& setting : settings)
        EXPECT_EQ(scenes::applySetting(scene, setting), "") << setting;
    return scene;
}

// The window's clock, written out here on purpose (not app::Simulation): each
// frame adds 1/60 s to an accumulator spent in whole steps of h, at most 32 per
// frame, the rest dropped when behind.
inline physics::World worldAtFrame(const scenes::Scene& scene, int frames) {
    physics::World world = scenes::buildWorld(scene);
    const double h = scene.params.timeStep;  // s
    double accumulator = 0.0;                // s
    for (int frame = 0; frame < frames; ++frame) {
        accumulator += 1.0 / 60.0;
        for (int steps = 0; accumulator >= h && steps < 32; ++steps) {
            physics::step(world, scene.params);
            accumulator -= h;
        }
        if (accumulator >= h) accumulator = 0.0;
    }
    return world;
}

inline int channelSpread(glm::u8vec4 a, glm::u8vec4 b) {
    return std::max({std::abs(a.x - b.x), std::abs(a.y - b.y), std::abs(a.z - b.z)});
}

inline float luminance(glm::u8vec4 c) { return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z; }

}  // namespace capture_test
