// Golden images: a few scenes and frames captured small (320 x 200 px, no MSAA)
// and compared with assets/golden/*.png, once per headless backend. Mesa versions
// rasterize slightly differently, so a pixel counts as different only when no
// golden pixel within one pixel of it is within a per-channel threshold (edges
// may move by a pixel), and a small budget of such pixels is allowed. A sphere
// that moved or vanished is far beyond the budget.
//
// To regenerate the goldens on purpose (after a deliberate change of the look):
//   SPHERES_UPDATE_GOLDENS=1 build/spheres_tests --gtest_filter='Goldens/CaptureGolden.*'
// or `cmake --build build --target update-goldens`; then look at the images and commit them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <string>
#include <tuple>

#include "test_capture_support.h"

namespace {

using platform::HeadlessBackend;

constexpr int kChannelThreshold =
    24;  // 0-255: a pixel differs when a channel is further off than this
constexpr double kPixelBudget = 0.001;  // fraction of the pixels that may differ (64 of 320 x 200)

struct GoldenCase {
    const char* name;   // file name in assets/golden/, without .png
    const char* scene;  // preset
    int frame;          // index, 1/60 s each
};

// One telling moment of each kind of scene: a bounce, a collision, a chain, a
// stack, a gas, the pile, the incline.
const GoldenCase kCases[] = {
    {"single_bounce_f045", "02_bounce_projection", 45},
    {"head_on_unequal_f050", "04_head_on_unequal", 50},
    {"newtons_cradle_f012", "08_newtons_cradle", 12},
    {"column_f060", "09_column", 60},
    {"gas_f030", "06_gas", 30},
    {"pile_f090", "11_pile", 90},
    {"inclined_plane_f060", "07_inclined_plane", 60},
};

void PrintTo(const GoldenCase& golden, std::ostream* out) { *out << golden.name; }

using GoldenParam = std::tuple<GoldenCase, HeadlessBackend>;

std::string caseName(const ::testing::TestParamInfo<GoldenParam>& info) {
    return std::string(std::get<0>(info.param).name) + "_" +
           platform::toString(std::get<1>(info.param));
}

bool updateRequested() {
    const char* value = std::getenv("SPHERES_UPDATE_GOLDENS");
    return value && std::string(value) == "1";
}

// The backend `--gl auto` picks here: the one whose image becomes the golden.
std::string preferredBackend() {
    const auto context = platform::createHeadless(HeadlessBackend::Auto, nullptr);
    return context ? context->name() : "";
}

struct Comparison {
    int differing = 0;   // pixels beyond the threshold
    render::Image diff;  // the golden faded, differing pixels in red
};

// Whether some golden pixel in the 3 x 3 block around (x, y) matches the actual one.
bool matchesNearby(const render::Image& golden, const render::Image& actual, int x, int y) {
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            const int gx = std::clamp(x + dx, 0, golden.width - 1);
            const int gy = std::clamp(y + dy, 0, golden.height - 1);
            if (capture_test::channelSpread(golden.pixel(gx, gy), actual.pixel(x, y)) <=
                kChannelThreshold)
                return true;
        }
    }
    return false;
}

Comparison compare(const render::Image& golden, const render::Image& actual) {
    Comparison result;
    result.diff = golden;
    for (int y = 0; y < golden.height; ++y) {
        for (int x = 0; x < golden.width; ++x) {
            const std::size_t at = 4 * (static_cast<std::size_t>(y) * golden.width + x);
            const auto faded =
                static_cast<std::uint8_t>(capture_test::luminance(golden.pixel(x, y)) * 0.3f);
            const bool differs = !matchesNearby(golden, actual, x, y);
            result.differing += differs ? 1 : 0;
            result.diff.rgba[at] = differs ? 255 : faded;
            result.diff.rgba[at + 1] = differs ? 0 : faded;
            result.diff.rgba[at + 2] = differs ? 0 : faded;
            result.diff.rgba[at + 3] = 255;
        }
    }
    return result;
}

// Writes the actual image and the diff into the build tree; returns their paths.
std::string keepEvidence(const std::string& name, const render::Image& actual,
                         const render::Image& diff) {
    const capture_test::fs::path folder =
        capture_test::fs::path(SPHERES_TEST_OUTPUT_DIR) / "golden";
    capture_test::fs::create_directories(folder);
    const std::string actualPath = (folder / (name + "_actual.png")).string();
    const std::string diffPath = (folder / (name + "_diff.png")).string();
    render::writePng(actualPath, actual.width, actual.height, actual.rgba);
    render::writePng(diffPath, diff.width, diff.height, diff.rgba);
    return "actual: " + actualPath + "\n  diff:   " + diffPath;
}

class CaptureGolden : public ::testing::TestWithParam<GoldenParam> {};

TEST_P(CaptureGolden, MatchesTheStoredImage) {
    const auto [golden, backend] = GetParam();
    if (const std::string why = capture_test::unavailableReason(backend); !why.empty()) {
        GTEST_SKIP() << platform::toString(backend) << " is not available here: " << why;
    }
    const std::string name = std::string(golden.name) + "_" + platform::toString(backend);
    app::CaptureOptions options = capture_test::smallCapture(
        golden.scene, capture_test::freshFolder("golden_" + name), backend);
    options.at = std::to_string(golden.frame);
    ASSERT_EQ(app::runCapture(options), 0);
    const render::Image actual = capture_test::readFrame(options.out, golden.frame);
    const std::string goldenPath = scenes::assetDirectory() + "/golden/" + golden.name + ".png";

    if (updateRequested() && preferredBackend() == platform::toString(backend)) {
        ASSERT_TRUE(render::writePng(goldenPath, actual.width, actual.height, actual.rgba))
            << goldenPath;
        std::cout << "[ golden   ] wrote " << goldenPath << "\n";
        return;
    }
    render::Image expected;
    ASSERT_TRUE(render::readPng(goldenPath, &expected))
        << "no golden image " << goldenPath
        << "; make it with SPHERES_UPDATE_GOLDENS=1 (see this file's top)";
    ASSERT_EQ(expected.width, actual.width);
    ASSERT_EQ(expected.height, actual.height);
    const Comparison result = compare(expected, actual);
    const int budget = static_cast<int>(kPixelBudget * actual.width * actual.height);
    RecordProperty("differing_pixels", result.differing);
    if (result.differing > budget) {
        ADD_FAILURE() << result.differing << " pixels differ by more than " << kChannelThreshold
                      << " from every golden pixel next to them (budget " << budget << ") from "
                      << goldenPath << "\n  " << keepEvidence(name, actual, result.diff);
    }
}

INSTANTIATE_TEST_SUITE_P(Goldens, CaptureGolden,
                         ::testing::Combine(::testing::ValuesIn(kCases),
                                            ::testing::Values(HeadlessBackend::OSMesa,
                                                              HeadlessBackend::EGL)),
                         caseName);

}  // namespace
