// What a machine without a GPU can show: the time to draw N spheres headless
// (OSMesa's llvmpipe, or EGL), 1280x720, Renderer::draw + glFinish, median of several
// frames after a warm-up, with hard outlines, blended ones (the window's) and MSAA. The spheres are the pile preset's
// lattice as generated (radius 5 cm x (1000/N)^(1/3), the volume of the pile), seen
// by the default camera fitted to the box, coloured by id. Also prints the time to
// copy the world into a FrameSnapshot (the demo does it every frame) and how much of
// the image the spheres cover.
//   usage: spheres_bench_render --help
#include <glad/gl.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

#include "bench/bench_common.h"
#include "platform/headless_context.h"
#include "render/camera.h"
#include "render/frame_snapshot.h"
#include "render/image_io.h"
#include "render/offscreen_target.h"
#include "render/renderer.h"

namespace {

constexpr int kWidth = 1280;  // px
constexpr int kHeight = 720;  // px

const bench::Usage kUsage{"spheres_bench_render",
    "usage: spheres_bench_render [options]\n"
    "Times drawing N spheres headless at 1280x720 (draw + glFinish); prints a markdown table.\n"
    "  --backend B    auto (OSMesa, else EGL), osmesa or egl (default auto)\n"
    "  --n LIST       sphere counts (default 1k,10k,100k,1M)\n"
    "  --outlines LIST how the spheres' outlines are drawn: hard, blended (one sample: the window's\n"
    "                 up to 5000 spheres) or a number of MSAA samples (alpha to coverage)\n"
    "                 (default hard,blended,4)\n"
    "  --frames F     timed frames per row, after 2 untimed ones (default 7)\n"
    "  --quick        --n 1k,10k,100k --frames 3\n"
    "  --save DIR     also write each drawn frame as DIR/render_<N>_<outlines>.png\n"};

[[noreturn]] void usageError(const std::string& why) { bench::usageError(kUsage, why); }

// One way of drawing the outlines: samples per pixel (0: none), and with none, whether
// they are blended (RenderStyle::antialiasEdges).
struct Outlines {
    int samples = 0;
    bool blended = false;
    // In the table; `x` in file names.
    std::string name(const char* times = "×") const {
        return samples > 0 ? std::to_string(samples) + times : blended ? "blended" : "hard";
    }
};

struct Options {
    platform::HeadlessBackend backend = platform::HeadlessBackend::Auto;
    std::vector<int> counts{1000, 10000, 100000, 1000000};
    std::vector<Outlines> outlines{{0, false}, {0, true}, {4, true}};
    int frames = 7;
    std::string saveDirectory;  // empty: write no images
};

Options parseOptions(int argc, char** argv) {
    Options o;
    for (int k = 1; k < argc; ++k) {
        const std::string option = argv[k];
        bench::helpIfAsked(kUsage, option);
        if (option == "--quick") {
            o.counts = {1000, 10000, 100000};
            o.frames = 3;
            continue;
        }
        if (k + 1 >= argc) usageError(option + ": missing value (or unknown option)");
        const std::string value = argv[++k];
        if (option == "--backend") {
            const auto backend = platform::parseHeadlessBackend(value);
            if (!backend) usageError("--backend " + value + ": expected auto, osmesa or egl");
            o.backend = *backend;
        } else if (option == "--n") {
            if (!bench::parseCounts(value, o.counts)) usageError("--n: expected e.g. 1k,10k");
            for (int count : o.counts) {
                if (count > scenes::kMaxGeneratedCount) usageError("--n: at most 1M spheres");
            }
        } else if (option == "--outlines") {
            o.outlines.clear();
            std::size_t start = 0;
            while (start <= value.size()) {
                const std::size_t comma = std::min(value.find(',', start), value.size());
                const std::string part = value.substr(start, comma - start);
                char* end = nullptr;
                const long n = std::strtol(part.c_str(), &end, 10);
                if (part == "hard" || part == "blended") {
                    o.outlines.push_back({0, part == "blended"});
                } else if (!part.empty() && *end == '\0' && n >= 1 && n <= 16) {
                    o.outlines.push_back({int(n), true});
                } else {
                    usageError("--outlines: expected hard, blended or samples from 1 to 16, e.g. hard,blended,4");
                }
                start = comma + 1;
            }
        } else if (option == "--save") {
            o.saveDirectory = value;
        } else if (option == "--frames") {
            o.frames = std::atoi(value.c_str());
            if (o.frames < 1 || o.frames > 1000) usageError("--frames: from 1 to 1000");
        } else {
            usageError("unknown option " + option);
        }
    }
    return o;
}

const char* glText(GLenum name) {
    const auto* text = reinterpret_cast<const char*>(glGetString(name));
    return text ? text : "?";
}

// The fraction of pixels that differ between two images of the same size: with
// and without the spheres, how much they cover; with and without the hidden ones, 0.
double differingPixels(const render::Image& a, const render::Image& b) {
    long differ = 0;
    for (std::size_t k = 0; k + 3 < a.rgba.size() && k + 3 < b.rgba.size(); k += 4) {
        if (!std::equal(&a.rgba[k], &a.rgba[k] + 3, &b.rgba[k])) ++differ;
    }
    return double(differ) / (double(a.width) * a.height);
}

// Seconds to draw one frame into the target, glFinish included.
double timeDraw(render::Renderer& renderer, render::OffscreenTarget& target,
                const render::FrameSnapshot& snapshot, const render::Camera& camera) {
    target.bind();
    const auto start = std::chrono::steady_clock::now();
    renderer.draw(snapshot, camera, 0, 0, kWidth, kHeight);
    glFinish();
    return bench::secondsSince(start);
}

}  // namespace

int main(int argc, char** argv) {
    const Options o = parseOptions(argc, argv);
    std::string error;
    const auto context = platform::createHeadless(o.backend, &error);
    if (!context) {
        std::fprintf(stderr, "spheres_bench_render: no headless GL context: %s\n", error.c_str());
        return 2;
    }
    render::Renderer renderer;
    if (const std::string why = renderer.init(); !why.empty()) {
        std::fprintf(stderr, "spheres_bench_render: renderer: %s\n", why.c_str());
        return 2;
    }
    const char* threads = std::getenv("LP_NUM_THREADS");
    std::printf("Machine: %s, %u hardware threads; load average (1, 5, 15 min) at start: %s\n",
                bench::cpuModel().c_str(), std::thread::hardware_concurrency(),
                bench::loadAverage().c_str());
    std::printf("GL: %s backend, %s, %s%s%s\n\n", context->name(), glText(GL_RENDERER),
                glText(GL_VERSION), threads ? ", LP_NUM_THREADS=" : "", threads ? threads : "");
    std::printf(
        "| N | outlines | ms per frame, every sphere | ms per frame, hidden ones left out | "
        "frames per second | spheres drawn | same image | snapshot ms | covered |\n"
        "|---:|---:|---:|---:|---:|---:|:---:|---:|---:|\n");
    std::fflush(stdout);

    render::OffscreenTarget target;
    for (int count : o.counts) {
        const auto built = std::chrono::steady_clock::now();
        const scenes::Scene scene = bench::pileOf(count);
        const physics::World world = scenes::buildWorld(scene);
        std::fprintf(stderr, "N=%d: pile built in %.1f s\n", count, bench::secondsSince(built));

        render::FrameSnapshot snapshot;
        std::vector<double> snapshotSeconds;
        for (int k = 0; k < 5; ++k) {
            const auto start = std::chrono::steady_clock::now();
            render::snapshotSpheres(world, render::ColorBy::Id, snapshot);
            snapshotSeconds.push_back(bench::secondsSince(start));
        }
        render::snapshotPlanes(world, snapshot);
        render::FrameSnapshot emptyBox;  // the same box without its spheres
        render::snapshotPlanes(world, emptyBox);
        const glm::vec3 half(0.5f * glm::vec3(scene.box->size));
        render::Camera camera;
        camera.reset(glm::vec3(-half.x, -half.y, 0.0f), glm::vec3(half.x, half.y, 2.0f * half.z),
                     float(kWidth) / float(kHeight));

        for (const Outlines& outlines : o.outlines) {
            if (const std::string why = target.resize(kWidth, kHeight, outlines.samples); !why.empty()) {
                std::fprintf(stderr, "spheres_bench_render: %d samples: %s\n", outlines.samples,
                             why.c_str());
                return 2;
            }
            renderer.style.antialiasEdges = outlines.samples > 0 || outlines.blended;
            // Every sphere sent, and the hidden ones left out, frame after frame.
            std::vector<double> frames[2];
            for (int frame = 0; frame < 2 + o.frames; ++frame) {
                for (bool cull : {false, true}) {
                    renderer.cullHiddenSpheres = cull;
                    const double seconds = timeDraw(renderer, target, snapshot, camera);
                    if (frame >= 2) frames[cull].push_back(seconds);
                }
            }
            if (const GLenum glError = glGetError(); glError != GL_NO_ERROR) {
                std::fprintf(stderr, "spheres_bench_render: GL error 0x%x\n", glError);
                return 2;
            }
            const std::size_t drawn = renderer.drawnSpheres();
            const render::Image culled = target.read();
            renderer.cullHiddenSpheres = false;
            timeDraw(renderer, target, snapshot, camera);
            const render::Image whole = target.read();
            if (!o.saveDirectory.empty()) {
                const std::string path = o.saveDirectory + "/render_" + std::to_string(count) +
                                         "_" + outlines.name("x") + ".png";
                if (!render::writePng(path, culled.width, culled.height, culled.rgba))
                    std::fprintf(stderr, "spheres_bench_render: cannot write %s\n", path.c_str());
            }
            timeDraw(renderer, target, emptyBox, camera);
            const render::Image empty = target.read();
            const double all = bench::median(frames[0]), seen = bench::median(frames[1]);
            std::printf("| %s | %s | %.1f | %.1f | %.1f | %.1f %% | %s | %.2f | %.0f %% |\n",
                        bench::grouped(count).c_str(),
                        outlines.name().c_str(),
                        1e3 * all, 1e3 * seen, 1.0 / seen, 100.0 * double(drawn) / count,
                        differingPixels(culled, whole) == 0 ? "yes" : "**no**",
                        1e3 * bench::median(snapshotSeconds), 100.0 * differingPixels(whole, empty));
            std::fflush(stdout);
        }
    }
    std::printf("\nLoad average (1, 5, 15 min) at the end: %s\n", bench::loadAverage().c_str());
    return 0;
}
