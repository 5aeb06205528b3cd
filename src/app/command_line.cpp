#include "app/command_line.h"

#include <cstdio>
#include <exception>

#include <CLI/CLI.hpp>

#include "app/scene_source.h"
#include "app/simulate_command.h"
#include "app/window_app.h"
#include "scenes/presets.h"
#include "scenes/scene.h"
#include "scenes/scene_json.h"

namespace app {
namespace {

constexpr int kBadInput = 2;

void addSimulate(CLI::App& cli, SimulateOptions& o) {
    CLI::App* sim = cli.add_subcommand("simulate", "Run a scene without any window or GL and print a summary");
    sim->add_option("--scene", o.scene, "Scene file or preset name (see `spheres presets`)")->required();
    sim->add_option("--steps", o.steps, "Time steps of h to run")->check(CLI::NonNegativeNumber);
    sim->add_option("--set", o.settings, "Override a parameter: name=value (repeatable)");
    sim->add_option("--every", o.every, "Write diagnostics every K steps")->check(CLI::PositiveNumber);
    sim->add_option("--out", o.out, "Diagnostics file: .csv or .jsonl");
    sim->add_option("--state", o.state, "Final state of every sphere (id, p, v, r, m): .csv");
    sim->add_option("--save", o.save, "Save the final state and parameters as a scene .json");
}

void addWindowOptions(CLI::App& cli, WindowAppOptions& o) {
    cli.add_option("--scene", o.scene, "Scene file or preset name (see `spheres presets`)");
    cli.add_option("--set", o.settings, "Override a parameter: name=value (repeatable)");
    cli.add_option("--frames", o.frames, "Run this many frames, then exit")->check(CLI::PositiveNumber);
    cli.add_option("--screenshot", o.screenshot, "Write the last frame to this PNG file");
    cli.add_flag("--paused", o.paused, "Start paused");
    cli.add_option("--width", o.width, "Window width (screen coordinates)")->check(CLI::Range(320, 8192));
    cli.add_option("--height", o.height, "Window height (screen coordinates)")->check(CLI::Range(240, 8192));
}

int listPresets() {
    for (const std::string& name : scenes::listPresets()) {
        const scenes::Scene scene = scenes::loadScene(scenes::presetPath(name));
        std::printf("%-22s %s\n", name.c_str(), scene.title.c_str());
    }
    return 0;
}

int fail(const std::string& message, int code) {
    std::fprintf(stderr, "spheres: %s\n", message.c_str());
    return code;
}

}  // namespace

int runCommandLine(int argc, char** argv) {
    CLI::App cli{"Rigid Spheres: the lecture \"Rigid spheres\" as an interactive demo", "spheres"};
    WindowAppOptions window;
    addWindowOptions(cli, window);
    SimulateOptions simulate;
    addSimulate(cli, simulate);
    CLI::App* presets = cli.add_subcommand("presets", "List the shipped scenes");
    try {
        cli.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return cli.exit(e);
    } catch (const CLI::ParseError& e) {
        return fail(e.what(), kBadInput);
    }
    try {
        if (cli.got_subcommand("simulate")) return runSimulate(simulate);
        if (presets->parsed()) return listPresets();
        return runWindowApp(window);
    } catch (const UsageError& e) {
        return fail(e.what(), kBadInput);
    } catch (const scenes::SceneError& e) {
        return fail(e.what(), kBadInput);
    } catch (const std::exception& e) {
        return fail(e.what(), 1);
    }
}

}  // namespace app
