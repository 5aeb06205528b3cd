#include "app/command_line.h"

#include <cstdio>
#include <exception>
#include <limits>
#include <regex>
#include <stdexcept>

#include <CLI/CLI.hpp>

#include "app/commands/capture_command.h"
#include "app/commands/claims_command.h"
#include "app/run/scene_source.h"
#include "app/commands/simulate_command.h"
#include "app/window/window_app.h"
#include "scenes/presets.h"
#include "scenes/scene.h"
#include "scenes/scene_json.h"

namespace app {
namespace {

constexpr int kBadInput = 2;

// A whole number at least `least`, with a message a person can read (CLI11's own
// range check prints the largest double in full).
// A whole number from `least` to `most` (an int option's most: 99999999999 frames gave
// CLI11's bare "Could not convert").
CLI::Validator wholeNumberFrom(long long least, long long most = std::numeric_limits<long long>::max()) {
    const bool bounded = most < std::numeric_limits<long long>::max();
    return CLI::Validator(
        [least, most, bounded](std::string& text) -> std::string {
            try {
                std::size_t used = 0;
                const long long value = std::stoll(text, &used);
                if (used == text.size() && value >= least && value <= most) return {};
            } catch (const std::out_of_range&) {
                if (!bounded) return "is too large a number (got " + text + ")";
            } catch (const std::exception&) {
            }
            return "must be a whole number, " + std::to_string(least) +
                   (bounded ? " to " + std::to_string(most) : std::string(" or more")) + " (got " + text + ")";
        },
        "INT>=" + std::to_string(least));
}

constexpr long long kMostInt = std::numeric_limits<int>::max();  // an int option's

// An empty value (`--out ""`, a shell variable left unset) was taken as "not asked for":
// nothing written, no overlay drawn, with no word.
CLI::Validator notEmpty(const std::string& what) {
    return CLI::Validator(
        [what](std::string& text) -> std::string { return text.empty() ? "needs " + what + " (got \"\")" : ""; }, "TEXT");
}
CLI::Validator aFileName() { return notEmpty("a file name"); }

void addSimulate(CLI::App& cli, SimulateOptions& o) {
    CLI::App* sim = cli.add_subcommand("simulate", "Run a scene without any window or GL and print a summary");
    sim->add_option("--scene", o.scene, "Scene file or preset name (see `spheres presets`)")->required();
    sim->add_option("--steps", o.steps, "Time steps of h to run")->required()->check(wholeNumberFrom(0));
    sim->add_option("--set", o.settings, "Override a parameter: name=value (repeatable)");
    sim->add_option("--every", o.every, "Write diagnostics every K steps")->check(wholeNumberFrom(1));
    sim->add_option("--out", o.out, "Diagnostics file: .csv or .jsonl")->check(aFileName());
    sim->add_option("--state", o.state, "Final state of every sphere (id, p, v, r, m): .csv")->check(aFileName());
    sim->add_option("--save", o.save, "Save the final state and parameters as a scene .json")->check(aFileName());
}

void addCapture(CLI::App& cli, CaptureOptions& o) {
    CLI::App* cap = cli.add_subcommand("capture", "Render frames of a scene to PNG files without a display (OSMesa or EGL)");
    cap->add_option("--scene", o.scene, "Scene file or preset name (see `spheres presets`)")->required();
    cap->add_option("--set", o.settings, "Override a parameter: name=value (repeatable)");
    cap->add_option_function<int>("--frames", [&o](const int& n) { o.frames = n; },
                                  "Run N frames of 1/60 s (frame 0 = the initial state) and write frames 0 .. N-1")
        ->check(wholeNumberFrom(1, kMostCapturedFrames));
    cap->add_option_function<int>("--every", [&o](const int& k) { o.every = k; },
                                  "With --frames: write only frames 0, K, 2K, ... (default 1)")
        ->check(wholeNumberFrom(1, kMostCapturedFrames));
    cap->add_option_function<std::string>("--at", [&o](const std::string& list) { o.at = list; },
                                          "Instead of --frames: write these frames, e.g. 0,30,120 (increasing)");
    cap->add_option("--out", o.out, "Folder for frame_NNNNNN.png and manifest.json (created if missing)")->required();
    cap->add_option("--size", o.size, "Image size WxH in pixels (16 to 8192 each)")->capture_default_str();
    cap->add_option("--camera", o.camera,
                    "azimuth,elevation[,distance] in degrees, degrees, m (default: the scene's opening view, as the window opens it)")
        ->check(notEmpty("azimuth,elevation[,distance]"));
    cap->add_option("--color-by", o.colorBy,
                    "Sphere colours: id, speed, contact or penetration (default: the scene's own colouring, else contact)")
        ->check(notEmpty("id, speed, contact or penetration"));
    cap->add_flag("--with-ui", o.withUi, "Draw the control panel and the readouts as the window does");
    cap->add_option_function<float>("--ui-scale", [&o](const float& scale) { o.uiScale = scale; },
                                    "With --with-ui or --compare: the UI scale, 0.75 to 3 (default 1; 2: as on a HiDPI screen)");
    cap->add_flag("--present", o.present, "With --with-ui: the presentation layout (as F5 in the window)");
    cap->add_option("--compare", o.compare,
                    "Side by side: more views with these overrides, name=value[,name=value] (e.g. method=velocity; several values of one name make a view each, at most 4 views)");
    cap->add_option("--overlay", o.overlay,
                    "Overlays, comma-separated: velocity, contacts, impulses, penetration, trails, graph (or all)")
        ->check(notEmpty("a list of overlays"));
    cap->add_option("--gl", o.gl, "Headless GL: osmesa, egl or auto (OSMesa first, then EGL)")->capture_default_str();
    cap->add_option("--samples", o.samples, "Multisampling: samples per pixel, 0 to 16")
        ->capture_default_str()
        ->check(wholeNumberFrom(0, 16));
}

void addClaims(CLI::App& cli, ClaimsOptions& o) {
    CLI::App* claims = cli.add_subcommand(
        "claims", "Measure what each scene's text claims, as the lab sheet's test does; exit 1 if a claim fails");
    claims->add_option("--scene", o.scenes, "Scene file or preset name (repeatable; default: every preset)");
    claims->add_flag("--measures", o.measures, "List what a claim may measure (name, unit, meaning) instead");
    claims->add_option("--junit", o.junit, "Also write a JUnit XML report (a test case per claim) for a CI pipeline: .xml")
        ->check(aFileName());
}

void addWindowOptions(CLI::App& cli, WindowAppOptions& o) {
    cli.add_option("--scene", o.scene, "Scene file or preset name (see `spheres presets`; default 11_pile)");
    cli.add_option("--set", o.settings, "Override a parameter: name=value (repeatable)");
    cli.add_option("--frames", o.frames, "Run this many frames, then exit")->check(wholeNumberFrom(1, kMostInt));
    cli.add_option("--screenshot", o.screenshot, "Write the last frame to this PNG file")->check(aFileName());
    cli.add_flag("--paused", o.paused, "Start paused");
    cli.add_option("--width", o.width, "Window width (screen coordinates)")->check(wholeNumberFrom(320, 8192));
    cli.add_option("--height", o.height, "Window height (screen coordinates)")->check(wholeNumberFrom(240, 8192));
    cli.add_option("--compare", o.compare,
                   "Side by side: more views with these overrides, name=value[,name=value] (e.g. method=velocity; several values of one name make a view each, at most 4 views)");
    cli.add_option("--select", o.select, "Start with this sphere selected (the inspector open)")
        ->check(wholeNumberFrom(0, kMostInt));
    cli.add_flag("--explain", o.explain, "With --select: open \"explain this contact\"");
    cli.add_flag("--present", o.present,
                 "Start in the presentation layout (F5): large type, the scene's text, the sliders it names and the view");
}

int listPresets() {
    for (const std::string& name : scenes::listPresets()) {
        const scenes::Scene scene = scenes::loadScene(scenes::presetPath(name));
        std::printf("%-22s %s\n", name.c_str(), scenes::withCount(scene.title, scene).c_str());
    }
    return 0;
}

int fail(const std::string& message, int code) {
    std::fprintf(stderr, "spheres: %s\n", message.c_str());
    return code;
}

// A report that could not be written is said, and the run fails: `spheres claims >
// report.txt` on a full disk exited 0 with an empty report.
int reportLost(int code) {
    if (std::fflush(stdout) == 0 && !std::ferror(stdout)) return code;
    return fail("the standard output could not be written (is the disk full?)", code == 0 ? 2 : code);
}

// The window's options are the command line's own, so one written before a subcommand
// (`spheres --set beta=5 simulate ...`) parses as the window's and the subcommand would
// run without it: "" when none was, else why that is refused.
std::string windowOptionBeforeSubcommand(const CLI::App& cli) {
    const std::vector<CLI::App*> chosen = cli.get_subcommands();
    if (chosen.empty()) return "";
    for (const CLI::Option* option : cli.get_options()) {
        if (option->count() == 0 || option->get_name() == "--help") continue;
        const std::string name = option->get_name(), command = chosen.front()->get_name();
        if (chosen.front()->get_option_no_throw(name) == nullptr) {
            return name + " is the window's option; `spheres " + command + "` takes none of that name";
        }
        return name + " before `" + command + "` is the window's option: write it after the command (spheres " +
               command + " " + name + " ...)";
    }
    return "";
}

// CLI11's refusals in the words of the others: "--scene: At Most 1 required but received 2"
// reads "--scene: given 2 times; give it once", "--frames: 1 required INT:INT>=1 missing" reads
// "--frames: needs a value", and an argument not expected points to the help of the command
// it was given to (`spheres capture --help` after `capture`).
std::string inOurWords(const std::string& refusal, const CLI::App& cli) {
    static const std::regex atMost(R"(^(\S+): At Most 1 required but received (\d+)$)");
    static const std::regex missing(R"(^(\S+): \d+ required .+ missing$)");
    std::smatch m;
    if (std::regex_match(refusal, m, atMost)) return m[1].str() + ": given " + m[2].str() + " times; give it once";
    if (std::regex_match(refusal, m, missing)) return m[1].str() + ": needs a value";
    if (refusal.rfind("The following argument", 0) == 0) {
        const std::vector<CLI::App*> chosen = cli.get_subcommands();
        return refusal + " (see spheres " + (chosen.empty() ? "" : chosen.front()->get_name() + " ") + "--help)";
    }
    return refusal;
}

// What CLI11 refused, an argument it did not expect named first: `capture --scen 07` had
// said "--scene is required", the slip itself unnamed.
std::string unexpectedFirst(const CLI::App& cli, const CLI::ParseError& refusal) {
    const std::vector<std::string> unexpected = cli.remaining(true);
    if (unexpected.empty()) return refusal.what();
    return CLI::ExtrasError({unexpected.rbegin(), unexpected.rend()}).what();  // it joins them backwards
}

}  // namespace

int runCommandLine(int argc, char** argv) {
    CLI::App cli{"Rigid Spheres: the lecture \"Rigid spheres\" as an interactive demo", "spheres"};
    WindowAppOptions window;
    addWindowOptions(cli, window);
    SimulateOptions simulate;
    addSimulate(cli, simulate);
    CaptureOptions capture;
    addCapture(cli, capture);
    ClaimsOptions claims;
    addClaims(cli, claims);
    CLI::App* presets = cli.add_subcommand("presets", "List the shipped scenes");
    try {
        cli.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return cli.exit(e);
    } catch (const CLI::ParseError& e) {
        const std::string misplaced = windowOptionBeforeSubcommand(cli);
        return fail(misplaced.empty() ? inOurWords(unexpectedFirst(cli, e), cli) : misplaced, kBadInput);
    }
    if (const std::string misplaced = windowOptionBeforeSubcommand(cli); !misplaced.empty()) {
        return fail(misplaced, kBadInput);
    }
    try {
        const auto run = [&] {
            if (cli.got_subcommand("simulate")) return runSimulate(simulate);
            if (cli.got_subcommand("capture")) return runCapture(capture);
            if (cli.got_subcommand("claims")) return runClaims(claims);
            if (presets->parsed()) return listPresets();
            window.sizeGiven = cli.count("--width") + cli.count("--height") > 0;
            if (argc > 0 && argv[0] && *argv[0]) window.program = argv[0];
            return runWindowApp(window);
        };
        const int code = run();
        return reportLost(code);
    } catch (const UsageError& e) {
        return fail(e.what(), kBadInput);
    } catch (const scenes::SceneError& e) {
        return fail(e.what(), kBadInput);
    } catch (const std::exception& e) {
        return fail(e.what(), 1);
    }
}

}  // namespace app
