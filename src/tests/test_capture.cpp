// `spheres capture`: refused input (exit code 2 through the command line, nothing
// written), then properties of captured frames that need no stored image, run
// once per headless backend (OSMesa, EGL), and the manifest against a world
// stepped the same way here.
#include <gtest/gtest.h>

#include "image_compare.h"
#include "shaded_colour.h"
#include <imgui.h>
#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <glm/geometric.hpp>
#include <string>
#include <vector>

#include "app/commands/progress_line.h"
#include "app/run/scene_source.h"
#include "scenes/presets.h"
#include "physics/diagnostics.h"
#include "render/palette.h"
#include "test_capture_support.h"

namespace {

using app::CaptureOptions;
using app::UsageError;
using capture_test::fs::exists;
using platform::HeadlessBackend;

// ---------------------------------------------------------------- refusals

// A capture that would succeed, to be broken one option at a time.
CaptureOptions validOptions(const std::string& out) {
    CaptureOptions options =
        capture_test::smallCapture("02_bounce_projection", out, HeadlessBackend::Auto);
    options.frames = 2;
    return options;
}

// Runs the capture, expects a one-line UsageError containing `expected` and no
// output folder; returns the message.
std::string expectRefused(const CaptureOptions& options, const std::string& expected) {
    std::string message;
    try {
        app::runCapture(options);
        ADD_FAILURE() << "not refused; expected: " << expected;
    } catch (const UsageError& e) {
        message = e.what();
    }
    EXPECT_NE(message.find(expected), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << "one line: " << message;
    EXPECT_FALSE(exists(options.out)) << "nothing may be written: " << options.out;
    return message;
}

TEST(CaptureRefusals, SizesOutsideSixteenTo8192PixelsOrMalformed) {
    const std::string out = capture_test::freshFolder("refused_size");
    for (const char* size : {"0x200", "320x0", "9000x200", "320x8193", "320", "axb", "320x200x3",
                             "-320x200", "320x", ""}) {
        CaptureOptions options = validOptions(out);
        options.size = size;
        expectRefused(options, "--size");
    }
}

TEST(CaptureRefusals, MalformedCamera) {
    const std::string out = capture_test::freshFolder("refused_camera");
    for (const char* camera : {"10", "1,2,3,4", "a,b,c", "10,,3", "nan,10,3", "10,95", "10,-89,3",
                               "10,20,0", "10,20,-1"}) {
        CaptureOptions options = validOptions(out);
        options.camera = camera;
        expectRefused(options, "--camera");
    }
}

TEST(CaptureRefusals, FramesMustBeEitherFramesWithEveryOrAnIncreasingAtList) {
    const std::string out = capture_test::freshFolder("refused_frames");
    CaptureOptions neither = validOptions(out);
    neither.frames.reset();
    expectRefused(neither, "--frames N");
    CaptureOptions both = validOptions(out);
    both.at = "0,10";
    expectRefused(both, "not both");
    CaptureOptions everyAlone = validOptions(out);
    everyAlone.frames.reset();
    everyAlone.every = 5;
    expectRefused(everyAlone, "--every needs --frames");
    CaptureOptions noFrames = validOptions(out);
    noFrames.frames = 0;
    expectRefused(noFrames, "--frames");
    CaptureOptions everyZero = validOptions(out);
    everyZero.every = 0;
    expectRefused(everyZero, "--every");
    for (const char* list : {"", "5,3", "3,3", "1,,2", "-1", "1000000", "4,x"}) {
        CaptureOptions at = validOptions(out);
        at.frames.reset();
        at.at = list;
        expectRefused(at, "--at");
    }
}

TEST(CaptureRefusals, UnknownColouringGlBackendAndSamples) {
    const std::string out = capture_test::freshFolder("refused_names");
    CaptureOptions colour = validOptions(out);
    colour.colorBy = "mass";
    expectRefused(colour, "--color-by mass: expected id, speed, contact or penetration");
    CaptureOptions gl = validOptions(out);
    gl.gl = "glx";
    expectRefused(gl, "--gl glx: expected osmesa, egl or auto");
    CaptureOptions samples = validOptions(out);
    samples.samples = 64;
    expectRefused(samples, "--samples");
}

TEST(CaptureRefusals, OutThatIsAFileCannotBeCreatedOrTakesNoFiles) {
    const std::string folder = capture_test::freshFolder("refused_out");
    capture_test::fs::create_directories(folder);
    const std::string file = folder + "/not_a_folder";
    std::ofstream(file) << "keep me";
    CaptureOptions onFile = validOptions(file);
    try {
        app::runCapture(onFile);
        ADD_FAILURE() << "a file as --out was not refused";
    } catch (const UsageError& e) {
        EXPECT_NE(std::string(e.what()).find("is not a folder"), std::string::npos) << e.what();
    }
    EXPECT_EQ(capture_test::fs::file_size(file), 7u) << "the file is left alone";
    expectRefused(validOptions(file + "/frames"), "cannot create the folder");
    expectRefused(validOptions("/proc/spheres_capture_test/frames"), "cannot create the folder");
    EXPECT_EQ(std::vector<capture_test::fs::path>(capture_test::fs::directory_iterator(folder), {})
                  .size(),
              1u);
    // A folder that exists but takes no files (even for root): refused, and left in place.
    try {
        app::runCapture(validOptions("/proc"));
        ADD_FAILURE() << "/proc as --out was not refused";
    } catch (const UsageError& e) {
        EXPECT_NE(std::string(e.what()).find("cannot write files"), std::string::npos) << e.what();
    }
    EXPECT_TRUE(capture_test::fs::is_directory("/proc"));
}

TEST(CaptureRefusals, BrokenSceneOrSettingIsRefusedBeforeWriting) {
    const std::string out = capture_test::freshFolder("refused_scene");
    CaptureOptions scene = validOptions(out);
    scene.scene = "no_such_scene_anywhere";
    EXPECT_ANY_THROW(app::runCapture(scene));
    CaptureOptions setting = validOptions(out);
    setting.settings = {"beta=7"};
    EXPECT_THROW(app::runCapture(setting), UsageError);
    EXPECT_FALSE(exists(out));
    // A count the pile's region cannot hold is the setting's doing, said as its own, before
    // any GL or folder (the folder had been left, the GL line said first).
    CaptureOptions count = validOptions(out);
    count.scene = "11_pile";
    count.settings = {"count=1000000"};
    expectRefused(count, "--set count=1000000: the scene cannot be built: the region holds only");
}

// Side by side at a size that leaves the views a sliver (16's four views and labels at
// 320x200 had views 1 px high, written as blank frames with exit 0): refused, nothing written.
TEST(CaptureRefusals, ASizeTooSmallForTheViewsIsRefused) {
    CaptureOptions four = validOptions(capture_test::freshFolder("refused_small_views"));
    four.scene = "16_bernoulli";
    four.size = "320x200";
    expectRefused(four, "--size 320x200: too small for 4 views side by side with their labels");
    four.size = "640x400";  // large enough
    EXPECT_EQ(app::runCapture(four), 0);
}

// The README's example captures `--scene cradle` into `--out cradle/`: once that folder
// exists (a second run, or made before the scene is read again), the name still means the
// preset; a folder that names no preset is refused as no scene file.
TEST(SceneSource, AFolderNamedAfterAPresetDoesNotHideIt) {
    const std::string folder = capture_test::freshFolder("cradle");
    std::filesystem::create_directories(folder);
    const std::filesystem::path before = std::filesystem::current_path();
    std::filesystem::current_path(std::filesystem::path(folder).parent_path());
    const std::string cradle = app::resolveScenePath("cradle");
    std::filesystem::create_directories("not_a_preset_here");
    std::string refusal;
    try {
        app::resolveScenePath("not_a_preset_here");
    } catch (const UsageError& e) {
        refusal = e.what();
    }
    std::filesystem::current_path(before);
    EXPECT_EQ(cradle, scenes::presetPath("08_newtons_cradle"));
    EXPECT_NE(refusal.find("is a folder, not a scene file"), std::string::npos) << refusal;
}

// A teacher opens the preset of a slide by its number: "01", or "8" for 08; a number no
// preset has is no preset.
TEST(SceneSource, APresetIsNamedByItsNumberToo) {
    EXPECT_EQ(app::resolveScenePath("01"), scenes::presetPath("01_bounce_response_only"));
    EXPECT_EQ(app::resolveScenePath("8"), scenes::presetPath("08_newtons_cradle"));
    EXPECT_EQ(app::resolveScenePath("22"), scenes::presetPath("22_shock_pyramid"));
    EXPECT_EQ(app::resolveScenePath("99"), "");
    EXPECT_EQ(app::resolveScenePath("0"), "");
}

class CaptureBackendRefusal : public ::testing::TestWithParam<HeadlessBackend> {};

TEST_P(CaptureBackendRefusal, UnavailableBackendSaysWhatWasTriedAndWhatToDo) {
    if (capture_test::unavailableReason(GetParam()).empty()) {
        GTEST_SKIP() << platform::toString(GetParam()) << " works here: nothing to refuse";
    }
    CaptureOptions options = validOptions(capture_test::freshFolder("refused_backend"));
    options.gl = platform::toString(GetParam());
    const std::string message = expectRefused(options, "tried " + options.gl);
    EXPECT_NE(message.find("libosmesa6"), std::string::npos) << message;
}

INSTANTIATE_TEST_SUITE_P(Backends, CaptureBackendRefusal,
                         ::testing::Values(HeadlessBackend::OSMesa, HeadlessBackend::EGL),
                         capture_test::backendName);

// The real executable: exit code 2, one line "spheres: ..." on stderr, nothing written.
TEST(CaptureCommandLine, RefusedInputExitsWithCodeTwoAndOneLine) {
    const std::string out = capture_test::freshFolder("cli_refused");
    const std::string command = std::string("'") + SPHERES_EXECUTABLE +
                                "' capture --scene pile --frames 3 --size 0x0 --out '" + out +
                                "' 2>&1";
    FILE* pipe = popen(command.c_str(), "r");
    ASSERT_NE(pipe, nullptr);
    std::string output;
    char buffer[256];
    while (std::fgets(buffer, sizeof buffer, pipe)) output += buffer;
    const int status = pclose(pipe);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 2);
    EXPECT_EQ(output.rfind("spheres: --size 0x0:", 0), 0u) << output;
    EXPECT_EQ(std::count(output.begin(), output.end(), '\n'), 1) << output;
    EXPECT_FALSE(exists(out));
}


namespace {

struct Outcome {
    int code = -1;
    std::string output;  // stdout and stderr
};

// The real executable's exit code and output for `arguments` (a shell line), with
// `environment` ("NAME=value ...") set for it.
Outcome runSpheres(const std::string& arguments, const std::string& environment = "") {
    const std::string command = environment + (environment.empty() ? "" : " ") + "'" + SPHERES_EXECUTABLE + "' " +
                                arguments + " 2>&1";
    Outcome outcome;
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) return outcome;
    char buffer[256];
    while (std::fgets(buffer, sizeof buffer, pipe)) outcome.output += buffer;
    const int status = pclose(pipe);
    outcome.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return outcome;
}

// What the real executable prints (stdout and stderr) for `arguments`.
std::string outputOf(const std::string& arguments) { return runSpheres(arguments).output; }

}  // namespace

// A full disk: each file the commands write is checked once closed, and a file that could
// not be written whole is said and not left behind (a 16 KB disk left a tenth of a state,
// of a log and of a screenshot, each called written). /dev/full fails every write.
TEST(CaptureCommandLine, AFileThatCannotBeWrittenWholeIsSaidAndNotLeft) {
    if (!std::filesystem::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
    const std::filesystem::path folder = std::filesystem::path(SPHERES_TEST_OUTPUT_DIR) / "full_disk";
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    // The files are written beside their name first (a killed run leaves the .part): that is /dev/full.
    for (const char* name : {"state.csv.part", "log.csv.part", "log.jsonl.part"}) std::filesystem::create_symlink("/dev/full", folder / name);
    const Outcome state = runSpheres("simulate --scene 11_pile --steps 1 --state '" + (folder / "state.csv").string() + "'");
    EXPECT_EQ(state.code, 2) << state.output;
    EXPECT_NE(state.output.find("state.csv: cannot be written whole (is the disk full?)"), std::string::npos) << state.output;
    // A log stops the run at the first write that fails (it stepped on to the end, 600 steps,
    // then said so): a long run on a full disk was hours of nothing.
    for (const char* log : {"log.csv", "log.jsonl"}) {
        const Outcome out = runSpheres("simulate --scene 11_pile --steps 600 --every 1 --out '" + (folder / log).string() + "'");
        EXPECT_EQ(out.code, 2) << out.output;
        const std::string said = std::string(log) + ": cannot be written whole (is the disk full?); the run stopped at step ";
        const std::size_t at = out.output.find(said);
        ASSERT_NE(at, std::string::npos) << out.output;
        EXPECT_LT(std::stoi(out.output.substr(at + said.size())), 100) << "its buffer's first flush failed" << out.output;
        EXPECT_FALSE(std::filesystem::exists(std::filesystem::symlink_status(folder / (std::string(log) + ".part"))));
    }
    EXPECT_FALSE(std::filesystem::exists(std::filesystem::symlink_status(folder / "state.csv"))) << "a truncated state is there";
    EXPECT_FALSE(std::filesystem::exists(std::filesystem::symlink_status(folder / "state.csv.part"))) << "the part is left";
    // A capture stops at the first frame it cannot write, in one line, and leaves no manifest
    // (it went on rendering, with a line for each frame left, and exited 1). Frame 1 is
    // written beside its name first: that file is /dev/full.
    const std::filesystem::path frames = folder / "frames";
    std::filesystem::create_directories(frames);
    std::filesystem::create_symlink("/dev/full", frames / "frame_000001.png.part");
    const Outcome capture = runSpheres("capture --scene 03_head_on --frames 40 --out '" + frames.string() + "'");
    EXPECT_EQ(capture.code, 2) << capture.output;
    EXPECT_NE(capture.output.find("frame_000001.png: cannot be written whole (is the disk full?); the capture stopped\n"),
              std::string::npos)
        << capture.output;
    std::size_t said = 0;  // lines of ours (a sanitized build adds its own report)
    for (std::size_t at = capture.output.find("spheres: "); at != std::string::npos; at = capture.output.find("spheres: ", at + 1)) ++said;
    EXPECT_EQ(said, 1u) << "one line, not one for each frame left: " << capture.output;
    EXPECT_FALSE(std::filesystem::exists(frames / "manifest.json"));
    EXPECT_FALSE(std::filesystem::exists(frames / "frame_000039.png")) << "it went on";
    // A report on a full disk fails the run (`spheres claims > report.txt` exited 0, the report
    // empty). Its line goes to the same /dev/full here: the code says it.
    for (const char* command : {"presets", "claims --scene 03_head_on", "simulate --scene 03_head_on --steps 1"}) {
        EXPECT_EQ(runSpheres(std::string(command) + " >/dev/full").code, 2) << command;
    }
}

// A GL driver that crashes while it starts (Debian 12's OSMesa, given a GALLIUM_DRIVER it
// does not have, dereferences a null screen) ends the capture with one line naming the
// setting, exit code 2, instead of "Segmentation fault". A Mesa that refuses the name
// instead of crashing says so through the usual refusal, which names it too.
TEST(CaptureCommandLine, AGlDriverThatCrashesWhileStartingIsOneLineNamingIt) {
    if (!platform::headlessBackendCompiled(platform::HeadlessBackend::OSMesa)) GTEST_SKIP() << "OSMesa not built";
    const std::string out = capture_test::freshFolder("cli_bogus_driver");
    const Outcome outcome =
        runSpheres("capture --scene 03_head_on --at 0 --gl osmesa --out '" + out + "'", "GALLIUM_DRIVER=bogus");
    EXPECT_EQ(outcome.code, 2) << outcome.output;
    EXPECT_EQ(outcome.output.rfind("spheres: ", 0), 0u) << outcome.output;
    EXPECT_NE(outcome.output.find("GALLIUM_DRIVER=bogus"), std::string::npos) << outcome.output;
    EXPECT_EQ(std::count(outcome.output.begin(), outcome.output.end(), '\n'), 1) << outcome.output;
    // virpipe, finding no render server, aborts (SIGABRT) inside EGL's start: named too,
    // after the one line Mesa writes itself.
    if (!platform::headlessBackendCompiled(platform::HeadlessBackend::EGL)) return;
    const Outcome aborted =
        runSpheres("capture --scene 03_head_on --at 0 --gl egl --out '" + out + "'", "GALLIUM_DRIVER=virpipe");
    EXPECT_EQ(aborted.code, 2) << aborted.output;
    EXPECT_NE(aborted.output.find("spheres: the GL driver crashed while EGL created its context, with GALLIUM_DRIVER=virpipe"),
              std::string::npos)
        << aborted.output;
}

// Input the command line cannot take is one line naming it, exit code 2, and nothing
// written: a window option before a subcommand (it would be dropped, the subcommand
// running without it), a scene path that names no readable file, an output path whose
// folder is missing, a screenshot of a window that cannot open, a UI scale for a capture
// that draws no panel and no labels (the scene's own side by side would have labels), an
// empty file name (it was taken as none asked for).
TEST(CommandLine, RefusedInputIsOneLineNamingItAndLeavesNothing) {
    const std::string folder = capture_test::freshFolder("cli_refusals");
    std::filesystem::create_directories(folder);
    std::filesystem::create_symlink("loop.json", folder + "/loop.json");
    const std::string logFolder = folder + "_log.csv";  // a folder named as a log
    std::filesystem::create_directories(logFolder);
    const struct {
        std::string arguments, starts;
    } cases[] = {
        {"--set beta=5 simulate --scene cradle --steps 1",
         "spheres: --set before `simulate` is the window's option: write it after the command"},
        {"--set beta=0.1 simulate --scene cradle --steps 1", "spheres: --set before `simulate`"},
        {"--scene pile simulate --steps 1", "spheres: --scene before `simulate`"},
        {"--frames 3 simulate --scene cradle --steps 1", "spheres: --frames is the window's option; `spheres simulate` takes none"},
        {"--set beta=5 presets", "spheres: --set is the window's option; `spheres presets` takes none"},
        {"simulate --scene /dev/null --steps 1", "spheres: --scene /dev/null: is not a regular file"},
        {"simulate --scene '" + folder + "/loop.json' --steps 1", "spheres: --scene " + folder + "/loop.json: "},
        {"claims --scene '" + folder + "/loop.json'", "spheres: --scene " + folder + "/loop.json: "},
        {"simulate --scene cradle --steps 1 --state '" + folder + "/none/state.csv'",
         "spheres: --state " + folder + "/none/state.csv: its folder " + folder + "/none does not exist"},
        {"--frames 99999999999", "spheres: --frames: must be a whole number, 1 to 2147483647 (got 99999999999)"},
        {"capture --scene cradle --frames 99999999999 --out '" + folder + "/frames'",
         "spheres: --frames: must be a whole number, 1 to 1000000 (got 99999999999)"},
        {"simulate --scene cradle --steps 1 --state '" SPHERES_EXECUTABLE "/state.csv'",
         "spheres: --state " SPHERES_EXECUTABLE "/state.csv: its folder " SPHERES_EXECUTABLE " is a file, not a folder"},
        {"simulate --scene cradle --steps 1 --save '" + folder + "/cradle.json' --state '" + folder + "/none/s.csv'",
         "spheres: --state "},
        {"--scene cradle --select 99 --screenshot '" + folder + "/shot.png'", "spheres: "},
        {"simulate --scene cradle --steps 1 --out ''", "spheres: --out: needs a file name (got \"\")"},
        {"--scene cradle --frames 1 --screenshot ''", "spheres: --screenshot: needs a file name (got \"\")"},
        {"capture --scene cradle --at 0 --overlay '' --out '" + folder + "/frames'",
         "spheres: --overlay: needs a list of overlays (got \"\")"},
        {"capture --scene cradle --at 0 --camera 30,10,1e-9 --out '" + folder + "/frames'",
         "spheres: --camera 30,10,1e-9: the distance must be 0.1 to 1000 m"},
        // One grammar for whole numbers: hex and exponents were taken by some options, and
        // 1e3 was called out of range.
        {"--width 0x400", "spheres: --width: must be a whole number, 320 to 8192 (got 0x400)"},
        {"--width 1e3", "spheres: --width: must be a whole number, 320 to 8192 (got 1e3)"},
        {"capture --scene cradle --at 0 --samples 2.5 --out '" + folder + "/frames'",
         "spheres: --samples: must be a whole number, 0 to 16 (got 2.5)"},
        {"capture --scene cradle --at 0 --ui-scale 2 --out '" + folder + "/frames'",
         "spheres: --ui-scale sizes the panel and the views' labels, and this capture draws neither: give --with-ui"},
        // A folder where the log goes is said as one (it had been "is the disk full?" at the end);
        // empty and repeated values, a --select past the last sphere, in the project's words.
        {"simulate --scene cradle --steps 1 --out '" + logFolder + "'", "spheres: --out " + logFolder + ": is a folder, not a file"},
        {"capture --scene cradle --at 0 --color-by '' --out '" + folder + "/frames'",
         "spheres: --color-by: needs id, speed, contact or penetration (got \"\")"},
        {"capture --scene cradle --at 0 --camera '' --out '" + folder + "/frames'", "spheres: --camera: needs azimuth,elevation"},
        {"capture --scene cradle --scene pile --at 0 --out '" + folder + "/frames'", "spheres: --scene: given 2 times; give it once"},
        {"capture --scene cradle --out '" + folder + "/frames' --frames", "spheres: --frames: needs a value"},
        {"--version", "spheres: The following argument was not expected: --version (see spheres --help)"},
        {"simulate --scene cradle --steps 1 --verbose",
         "spheres: The following argument was not expected: --verbose (see spheres simulate --help)"},
        // A slip in an option's name is named, before the option it missed.
        {"capture --scen cradle --at 0 --out '" + folder + "/frames'",
         "spheres: The following arguments were not expected: --scen cradle (see spheres capture --help)"},
    };
    const std::string display = std::getenv("DISPLAY") ? std::getenv("DISPLAY") : "";
    unsetenv("DISPLAY");  // the screenshot's window cannot open
    for (const auto& c : cases) {
        const Outcome outcome = runSpheres(c.arguments);
        EXPECT_EQ(outcome.code, 2) << c.arguments << ": " << outcome.output;
        EXPECT_EQ(outcome.output.rfind(c.starts, 0), 0u) << c.arguments << ": " << outcome.output;
        EXPECT_EQ(std::count(outcome.output.begin(), outcome.output.end(), '\n'), 1) << c.arguments << ": " << outcome.output;
    }
    // What was refused wrote nothing (the checks of the output paths included).
    std::vector<std::string> left;
    for (const auto& entry : std::filesystem::directory_iterator(folder)) left.push_back(entry.path().filename().string());
    EXPECT_EQ(left, std::vector<std::string>{"loop.json"});
    if (!display.empty()) setenv("DISPLAY", display.c_str(), 1);
    const Outcome after = runSpheres("simulate --scene cradle --steps 1 --set beta=0.1");  // where it belongs
    EXPECT_EQ(after.code, 0) << after.output;
}

// A sample count the GL does not give (3: llvmpipe gives 4; 16: more than its most) is
// said in a line, and the manifest records what the images have. Skipped only where no
// headless GL can be made; a capture that fails where one can is a failure.
TEST(CaptureCommandLine, SamplesTheGlGivesAreSaidAndRecorded) {
    const std::string noOSMesa = capture_test::unavailableReason(HeadlessBackend::OSMesa);
    const std::string noEgl = capture_test::unavailableReason(HeadlessBackend::EGL);
    if (!noOSMesa.empty() && !noEgl.empty()) GTEST_SKIP() << "no headless GL here: " << noOSMesa << "; " << noEgl;
    for (const int asked : {3, 16}) {
        const std::string out = capture_test::freshFolder("cli_samples_" + std::to_string(asked));
        const Outcome outcome = runSpheres("capture --scene cradle --at 0 --size 64x48 --samples " + std::to_string(asked) +
                                           " --out '" + out + "'");
        ASSERT_EQ(outcome.code, 0) << outcome.output;
        const int given = capture_test::readManifest(out).at("samples").get<int>();
        EXPECT_GT(given, 0);
        const std::string said = "samples: " + std::to_string(given) + " per pixel (asked " + std::to_string(asked);
        EXPECT_EQ(outcome.output.find(said) != std::string::npos, given != asked) << outcome.output;
    }
}

// Slide 14: `simulate` ends with the five properties when the scene had contacts; none
// before the first contact.
TEST(SimulateCommandLine, PrintsTheFivePropertiesOnceThereWereContacts) {
    const std::string sequential = outputOf("simulate --scene 16_bernoulli --steps 6");
    EXPECT_NE(sequential.find("properties: momentum \u2713"), std::string::npos) << sequential;
    EXPECT_NE(sequential.find("symmetry \u2717 off by 0.43 m/s"), std::string::npos) << sequential;
    // It runs view A only, and says so (a teacher took it for the whole comparison).
    EXPECT_NE(sequential.find("(the scene as given, view A: its side-by-side views, "
                              "solver=simultaneous,lcp,generalized-reflections, run with --set)"),
              std::string::npos)
        << sequential;
    const std::string reflections = outputOf("simulate --scene 16_bernoulli --steps 6 --set solver=generalized-reflections");
    EXPECT_NE(reflections.find("energy \u2713 after/before 1.000000"), std::string::npos) << reflections;
    EXPECT_NE(reflections.find("symmetry \u2713"), std::string::npos) << reflections;
    EXPECT_NE(reflections.find("break-away \u2713 1 of 1 resting pairs parted"), std::string::npos) << reflections;
    EXPECT_NE(reflections.find("positivity \u2713"), std::string::npos) << reflections;
    const std::string none = outputOf("simulate --scene 03_head_on --steps 1");
    EXPECT_EQ(none.find("properties:"), std::string::npos) << none;
    EXPECT_NE(none.find("03_head_on"), std::string::npos) << none;
}

// The diagnostics log holds step 0, every K steps and the last (--steps 7 --every 3 left
// the final state out), and is there only once whole: no .part beside it.
TEST(SimulateCommandLine, TheLogEndsWithTheLastStep) {
    const std::string folder = capture_test::freshFolder("simulate_log");
    std::filesystem::create_directories(folder);
    const std::string log = folder + "/log.csv";
    ASSERT_EQ(runSpheres("simulate --scene 03_head_on --steps 7 --every 3 --out '" + log + "'").code, 0);
    std::ifstream file(log);
    std::string line, steps;
    std::getline(file, line);  // the header
    while (std::getline(file, line)) steps += line.substr(0, line.find(',')) + " ";
    EXPECT_EQ(steps, "0 3 6 7 ");
    EXPECT_FALSE(std::filesystem::exists(log + ".part"));
}

// ---------------------------------------------------------------- frames, per backend

class CaptureImages : public ::testing::TestWithParam<HeadlessBackend> {
  protected:
    void SetUp() override {
        if (const std::string why = capture_test::unavailableReason(GetParam()); !why.empty()) {
            GTEST_SKIP() << platform::toString(GetParam()) << " is not available here: " << why;
        }
    }

    // Captures `scene` into a fresh folder named after the test and the backend.
    std::string capture(CaptureOptions options, const std::string& name) {
        options.out = capture_test::freshFolder(name + "_" + platform::toString(GetParam()));
        options.gl = platform::toString(GetParam());
        EXPECT_EQ(app::runCapture(options), 0);
        return options.out;
    }

    CaptureOptions small(const std::string& scene) const {
        return capture_test::smallCapture(scene, "", GetParam());
    }
};

glm::u8vec4 pixelAt(const render::Image& image, const glm::vec3& projected) {
    return image.pixel(static_cast<int>(projected.x), static_cast<int>(projected.y));
}

glm::vec2 sizeOf(const render::Image& image) { return {float(image.width), float(image.height)}; }

// Without --color-by, a capture colours as the window opens the scene: 22 by penetration.
TEST(CaptureColouring, TheScenesOwnColouringUnlessOneIsAsked) {
    const auto colouring = [](const char* asked) {
        CaptureOptions options;
        options.scene = "22_shock_pyramid";
        options.at = "0";
        options.size = "480x320";  // its four views and their labels
        options.colorBy = asked;
        options.out = capture_test::freshFolder(std::string("colouring_") + (*asked ? asked : "scene"));
        EXPECT_EQ(app::runCapture(options), 0);
        return capture_test::readManifest(options.out).at("color_by").get<std::string>();
    };
    EXPECT_EQ(colouring(""), "penetration");
    EXPECT_EQ(colouring("speed"), "speed");
}

TEST_P(CaptureImages, FallingSphereCentreLandsOnAPixelOfItsColour) {
    CaptureOptions options = small("02_bounce_projection");
    options.at = "0,20,40";
    options.colorBy = "id";
    const std::string out = capture(options, "sphere_centre");
    const nlohmann::json manifest = capture_test::readManifest(out);
    const render::Camera camera = capture_test::cameraOf(manifest);
    const scenes::Scene scene = capture_test::presetScene("02_bounce_projection");
    for (int frame : {0, 20, 40}) {
        const physics::World world = capture_test::worldAtFrame(scene, frame);
        const render::Image image = capture_test::readFrame(out, frame);
        const glm::vec3 centre = camera.project(glm::vec3(world.position[0]), sizeOf(image));
        expectShadedVersionOf(pixelAt(image, centre), render::idColor(0));
        // Two radii above the centre is no longer the sphere.
        const glm::vec3 above = camera.project(
            glm::vec3(world.position[0]) + glm::vec3(0, 0, 2 * world.radius[0]), sizeOf(image));
        EXPECT_GT(capture_test::channelSpread(pixelAt(image, above), pixelAt(image, centre)), 30)
            << frame;
    }
}

TEST_P(CaptureImages, CameraOptionSetsTheAnglesAndTheDistance) {
    CaptureOptions options = small("02_bounce_projection");
    options.at = "0";
    options.colorBy = "id";
    options.camera = "-90,0,4";
    const std::string out = capture(options, "camera_option");
    const nlohmann::json camera = capture_test::readManifest(out).at("camera");
    EXPECT_NEAR(camera.at("azimuth_deg").get<double>(), -90.0, 1e-4);
    EXPECT_NEAR(camera.at("elevation_deg").get<double>(), 0.0, 1e-4);
    EXPECT_NEAR(camera.at("distance_m").get<double>(), 4.0, 1e-6);
    // Looking along +y from the front at the box's mid-height: the sphere at
    // (0, 0, 1.5) is on the vertical centre line, above the middle.
    const render::Image image = capture_test::readFrame(out, 0);
    const glm::vec3 centre = capture_test::cameraOf(capture_test::readManifest(out))
                                 .project({0.0f, 0.0f, 1.5f}, sizeOf(image));
    EXPECT_NEAR(centre.x, 160.0f, 0.5f);
    EXPECT_LT(centre.y, 100.0f);
    expectShadedVersionOf(pixelAt(image, centre), render::idColor(0));
}

TEST_P(CaptureImages, FloorIsDrawnBelowTheSpheresAndHiddenByThem) {
    CaptureOptions options = small("09_column");
    options.at = "0";
    options.colorBy = "id";
    const std::string out = capture(options, "floor");
    const render::Camera camera = capture_test::cameraOf(capture_test::readManifest(out));
    const render::Image image = capture_test::readFrame(out, 0);
    const glm::vec2 size = sizeOf(image);
    // The bottom sphere (r = 0.0625 m on the floor) shows its own colour through the floor.
    const glm::vec3 bottom = camera.project({0.0f, 0.0f, 0.0625f}, size);
    expectShadedVersionOf(pixelAt(image, bottom), render::idColor(0));
    // A floor point in front of the column, between grid lines: below the sphere
    // on screen, light and grey (the floor), not the background's blue-grey.
    const glm::vec3 floor = camera.project({0.15f, -0.25f, 0.0f}, size);
    EXPECT_GT(floor.y, bottom.y + 5.0f);
    const glm::u8vec4 floorPixel = pixelAt(image, floor);
    EXPECT_GT(capture_test::luminance(floorPixel), 200.0f);
    EXPECT_LT(capture_test::channelSpread(floorPixel, glm::u8vec4(floorPixel.x)), 20);
    // Outside the box, at the same height on screen, the background is darker.
    const glm::u8vec4 background = image.pixel(2, static_cast<int>(floor.y));
    EXPECT_GT(capture_test::luminance(floorPixel), capture_test::luminance(background) + 40.0f);
}

TEST_P(CaptureImages, FramesChangeWhileTheBallFallsAndNotWhenNothingMoves) {
    CaptureOptions falling = small("02_bounce_projection");
    falling.frames = 21;
    falling.every = 10;
    const std::string out = capture(falling, "moving");
    const render::Image f0 = capture_test::readFrame(out, 0);
    const render::Image f10 = capture_test::readFrame(out, 10);
    const render::Image f20 = capture_test::readFrame(out, 20);
    EXPECT_GT(differingPixels(f0, f10), 50);
    EXPECT_GT(differingPixels(f10, f20), 50);
    EXPECT_FALSE(
        capture_test::fs::exists(capture_test::fs::path(out) / capture_test::frameName(5)));

    // No gravity, nothing moving: the solver steps, the picture stays.
    CaptureOptions still = small("02_bounce_projection");
    still.settings = {"gravity=0"};
    still.at = "0,30";
    const std::string stillOut = capture(still, "still");
    EXPECT_EQ(capture_test::readFrame(stillOut, 0).rgba,
              capture_test::readFrame(stillOut, 30).rgba);
    const nlohmann::json frames = capture_test::readManifest(stillOut).at("frames");
    EXPECT_GT(frames[1].at("steps").get<int>(), 0) << "the simulation did advance";
}

TEST_P(CaptureImages, WithUiThePanelFillsTheLeftOfTheFrame) {
    CaptureOptions options = small("02_bounce_projection");
    options.size = "640x400";
    options.at = "0";
    options.withUi = true;
    const std::string out = capture(options, "with_ui");
    const nlohmann::json manifest = capture_test::readManifest(out);
    const int panel = manifest.at("viewport")[0].get<int>();
    EXPECT_GT(panel, 200);  // min(25 font sizes, 45 %) of 640 px at 17 px
    EXPECT_LE(panel, 288);
    // The panel's background: ImGui's dark WindowBg over the window's clear colour.
    ImGuiStyle style;
    ImGui::StyleColorsDark(&style);
    const ImVec4 bg = style.Colors[ImGuiCol_WindowBg];
    const glm::vec3 clear(0.09f, 0.10f, 0.12f);
    const glm::vec3 expected = glm::vec3(bg.x, bg.y, bg.z) * bg.w + clear * (1.0f - bg.w);
    const glm::u8vec4 panelColour(glm::vec4(expected * 255.0f + 0.5f, 255.0f));
    const render::Image image = capture_test::readFrame(out, 0);
    int inPanel = 0, inScene = 0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const bool match = capture_test::channelSpread(image.pixel(x, y), panelColour) <= 3;
            (x < panel ? inPanel : inScene) += match ? 1 : 0;
            ASSERT_EQ(image.pixel(x, y).w, 255) << "opaque at " << x << ", " << y;
        }
    }
    EXPECT_GT(inPanel, panel * image.height / 3) << "a third of the panel is its plain background";
    EXPECT_LT(inScene, (image.width - panel) * image.height / 100);
}

TEST_P(CaptureImages, ManifestHashesEqualAWorldSteppedTheSameWay) {
    const std::vector<std::string> settings = {"beta=0.5", "substeps=3"};
    CaptureOptions options = small("04_head_on_unequal");
    options.settings = settings;
    options.frames = 61;
    options.every = 20;
    const std::string out = capture(options, "manifest");
    const nlohmann::json manifest = capture_test::readManifest(out);
    const scenes::Scene scene = capture_test::presetScene("04_head_on_unequal", settings);
    EXPECT_EQ(manifest.at("title"), scene.title);
    EXPECT_EQ(manifest.at("gl").at("backend"), platform::toString(GetParam()));
    EXPECT_EQ(manifest.at("size"), nlohmann::json({320, 200}));
    // Every parameter the scene has; none it lacks (04 has no emitter and no generated
    // spheres: the manifest listed an emitter period of 0.5 s and a count of 0).
    for (const scenes::Parameter& p : scenes::parameterTable()) {
        EXPECT_EQ(manifest.at("parameters").contains(std::string(p.name)), p.availableIn(scene)) << p.name;
    }
    EXPECT_FALSE(manifest.at("parameters").contains("emit_period"));
    EXPECT_EQ(manifest.at("parameters").at("beta").get<double>(), 0.5);
    const nlohmann::json& frames = manifest.at("frames");
    ASSERT_EQ(frames.size(), 4u);
    for (std::size_t k = 0; k < frames.size(); ++k) {
        const int index = static_cast<int>(20 * k);
        const physics::World world = capture_test::worldAtFrame(scene, index);
        char hash[17];
        std::snprintf(hash, sizeof hash, "%016llx",
                      static_cast<unsigned long long>(physics::stateHash(world)));
        EXPECT_EQ(frames[k].at("index").get<int>(), index);
        EXPECT_EQ(frames[k].at("hash").get<std::string>(), hash) << "frame " << index;
        EXPECT_EQ(frames[k].at("steps").get<std::uint64_t>(), world.stepCount);
        EXPECT_DOUBLE_EQ(frames[k].at("time_s").get<double>(), world.time);
        EXPECT_EQ(frames[k].at("file").get<std::string>(), capture_test::frameName(index));
        EXPECT_TRUE(
            capture_test::fs::exists(capture_test::fs::path(out) / capture_test::frameName(index)));
    }
    EXPECT_NE(frames[0].at("hash"), frames[3].at("hash"));
}

TEST_P(CaptureImages, SameInputsGiveByteIdenticalFiles) {
    CaptureOptions options = small("08_newtons_cradle");
    options.size = "480x300";
    options.withUi = true;
    options.samples = 4;
    options.at = "0,25";
    const std::string first = capture(options, "identical_a");
    const std::string second = capture(options, "identical_b");
    for (const char* name : {"frame_000000.png", "frame_000025.png", "manifest.json"}) {
        std::ifstream a(capture_test::fs::path(first) / name, std::ios::binary);
        std::ifstream b(capture_test::fs::path(second) / name, std::ios::binary);
        const std::string bytesA((std::istreambuf_iterator<char>(a)), {});
        const std::string bytesB((std::istreambuf_iterator<char>(b)), {});
        EXPECT_FALSE(bytesA.empty()) << name;
        EXPECT_TRUE(bytesA == bytesB) << name << " differs between two equal runs";
    }
}

TEST_P(CaptureImages, AFrameDoesNotDependOnWhichOtherFramesAreWritten) {
    CaptureOptions every = small("08_newtons_cradle");
    every.size = "480x300";
    every.withUi = true;
    every.frames = 21;
    CaptureOptions one = every;
    one.frames.reset();
    one.at = "20";
    const std::string all = capture(every, "every_frame");
    const std::string single = capture(one, "single_frame");
    EXPECT_EQ(capture_test::readFrame(all, 20).rgba, capture_test::readFrame(single, 20).rgba);
}

INSTANTIATE_TEST_SUITE_P(Backends, CaptureImages,
                         ::testing::Values(HeadlessBackend::OSMesa, HeadlessBackend::EGL),
                         capture_test::backendName);

}  // namespace

namespace {

// Long headless runs show their progress on a terminal (and nothing elsewhere).
TEST(Progress, TheLineSaysWhatIsDoneTheRateAndTheTimeLeft) {
    EXPECT_EQ(app::progressText("frames", 120, 600, 4.0), "frames 120/600 (20 %), 30.0 frames/s, 16 s left");
    EXPECT_EQ(app::progressText("steps", 600, 600, 2.0), "steps 600/600 (100 %), 300.0 steps/s");
}

}  // namespace
