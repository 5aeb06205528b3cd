// What the overlays cost a frame on a machine without a GPU: the pile preset after
// it has come to rest (10 s simulated), drawn headless (OSMesa's llvmpipe, or EGL)
// into the window's scene view (855x720 px beside the panel at 1280x800, 4x MSAA as
// the window), with no overlay, each overlay alone, and all of them. A frame is what
// the window does: one step of h (its substeps, recording contacts when an overlay
// needs them), the snapshot with its overlay lines, the draw and glFinish; each part
// is timed and the table gives medians.
//   usage: spheres_bench_overlays [--frames F] [--scene NAME]
#include <glad/gl.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "app/views/frame_builder.h"
#include "app/run/simulation.h"
#include "bench/bench_common.h"
#include "platform/headless_context.h"
#include "render/camera.h"
#include "render/offscreen_target.h"
#include "render/renderer.h"

namespace {

constexpr int kWidth = 855, kHeight = 720, kSamples = 4;  // px: the window's scene view at 1280x800
constexpr double kRestSeconds = 10.0;                     // s simulated before timing

struct Row {
    const char* name;
    ui::PanelState view;
    bool everyMark = false;  // the hidden marks sent to the GL too (Renderer::cullHiddenMarks off)
};

std::vector<Row> rows() {
    std::vector<Row> list;
    ui::PanelState none;
    list.push_back({"none", none, false});
    const auto with = [&](const char* name, bool ui::PanelState::*flag) {
        ui::PanelState view;
        view.*flag = true;
        list.push_back({name, view, false});
    };
    with("velocity", &ui::PanelState::showVelocity);
    with("contacts", &ui::PanelState::showContacts);
    with("impulses", &ui::PanelState::showImpulses);
    with("penetration", &ui::PanelState::showPenetration);
    with("trails", &ui::PanelState::showTrails);
    ui::PanelState all;
    all.showVelocity = all.showContacts = all.showImpulses = all.showPenetration = all.showTrails = true;
    list.push_back({"all", all, false});
    list.push_back({"contacts, hidden marks too", list[2].view, true});
    list.push_back({"all, hidden marks too", all, true});
    return list;
}

}  // namespace

int main(int argc, char** argv) {
    int frames = 15;
    std::string scene = "pile";
    for (int k = 1; k < argc; k += 2) {
        const std::string option = argv[k];
        if (option == "--help" || option == "-h") {
            std::printf("usage: spheres_bench_overlays [--frames F] [--scene NAME]\n");
            return 0;
        }
        if (k + 1 < argc && option == "--frames") frames = std::atoi(argv[k + 1]);
        else if (k + 1 < argc && option == "--scene") scene = argv[k + 1];
        else {  // an unknown option, or one without its value
            std::fprintf(stderr, "spheres_bench_overlays: %s: usage: spheres_bench_overlays [--frames F] [--scene NAME]\n",
                         option.c_str());
            return 2;
        }
    }
    if (frames < 1 || frames > 1000) {
        std::fprintf(stderr, "spheres_bench_overlays: --frames: from 1 to 1000\n");
        return 2;
    }
    std::string error;
    const auto context = platform::createHeadless(platform::HeadlessBackend::Auto, &error);
    if (!context) {
        std::fprintf(stderr, "spheres_bench_overlays: no headless GL context: %s\n", error.c_str());
        return 2;
    }
    render::Renderer renderer;
    render::OffscreenTarget target;
    if (std::string why = renderer.init(); !why.empty() || !(why = target.resize(kWidth, kHeight, kSamples)).empty()) {
        std::fprintf(stderr, "spheres_bench_overlays: %s\n", why.c_str());
        return 2;
    }
    const std::string preset = bench::presetContaining(scene);
    std::printf("%s after %.0f s, %dx%d px, %dx MSAA, %s backend, %s; load average %s\n\n", preset.c_str(),
                kRestSeconds, kWidth, kHeight, kSamples, context->name(), bench::cpuModel().c_str(),
                bench::loadAverage().c_str());
    std::printf("| overlays | lines + dots | drawn | step ms (%s) | snapshot ms | draw ms | frame ms |\n", "h, recorded");
    std::printf("|---|---:|---:|---:|---:|---:|---:|\n");
    app::Simulation rested(bench::loadPreset(preset));
    rested.singleStep();
    while (rested.world().time < kRestSeconds) rested.singleStep();
    render::Camera camera;
    glm::vec3 lo, hi;
    app::sceneBounds(rested, lo, hi);
    camera.reset(lo, hi, float(kWidth) / float(kHeight));
    for (const Row& row : rows()) {
        app::Simulation simulation = rested;
        renderer.cullHiddenMarks = !row.everyMark;
        renderer.style.overlayOnTop = app::overlaysOnTop(row.view, simulation.world().size());
        render::FrameSnapshot snapshot;
        std::vector<double> step, build, draw;
        for (int frame = 0; frame < frames + 20; ++frame) {  // 20 frames for the trails and impulses to fill in
            auto start = std::chrono::steady_clock::now();
            simulation.singleStep();
            const double stepSeconds = bench::secondsSince(start);
            start = std::chrono::steady_clock::now();
            app::buildSnapshot(simulation, row.view, snapshot);
            const double buildSeconds = bench::secondsSince(start);
            target.bind();
            start = std::chrono::steady_clock::now();
            renderer.draw(snapshot, camera, 0, 0, kWidth, kHeight);
            glFinish();
            if (frame < 20) continue;
            step.push_back(stepSeconds);
            build.push_back(buildSeconds);
            draw.push_back(bench::secondsSince(start));
        }
        const double s = bench::median(step), b = bench::median(build), d = bench::median(draw);
        std::printf("| %s | %zu | %zu | %.2f | %.2f | %.1f | %.1f |\n", row.name,
                    snapshot.lines.size() + snapshot.points.size(), renderer.drawnMarks(), 1e3 * s, 1e3 * b, 1e3 * d,
                    1e3 * (s + b + d));
        std::fflush(stdout);
    }
    return 0;
}
