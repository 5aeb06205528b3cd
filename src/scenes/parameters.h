#pragma once
// The one table of the lecture's parameters. The UI draws its sliders from it,
// the command line's --set name=value and the JSON loader's "parameters" read
// it, so every parameter has one name, one range and one explanation.
#include <string>
#include <string_view>
#include <vector>

#include "scenes/scene.h"

namespace scenes {

// When a change takes effect.
enum class Applies {
    Live,     // at the next step
    Restart,  // when the world is rebuilt from the scene (R)
};

enum class ParameterKind {
    Real,     // any number in [min, max]
    Integer,  // a whole number in [min, max]
    Choice,   // one of `choices`; the value is its index
};

struct Parameter {
    std::string_view name;   // JSON key and --set name
    std::string_view label;  // for the UI, with the lecture's symbol
    std::string_view unit;   // "m/s", "s", "" ...
    double min = 0.0;        // inclusive, in `unit`
    double max = 1.0;        // inclusive, in `unit`
    double defaultValue =
        0.0;                   // in `unit`: a default Scene's value (Live); a typical one (Restart)
    std::string_view tooltip;  // in the lecture's words
    Applies applies = Applies::Live;
    ParameterKind kind = ParameterKind::Real;
    std::vector<std::string_view> choices;  // Choice: the names, value = index
    double (*get)(const Scene&) = nullptr;
    // Stores a value already checked by checkValue; returns "" or why it cannot.
    std::string (*set)(Scene&, double) = nullptr;
    // Whether the scene has what the parameter acts on (an emitter, a generator, the
    // method it belongs to); nullptr: always. The UI hides the others, and a setting of
    // it refused where it acts on nothing (settingsThatActOnNothing) says `availableWhen`:
    // "acts only with the continuous method".
    bool (*available)(const Scene&) = nullptr;
    std::string_view availableWhen = {};
    // Integer: what the slider shows for 0 when 0 means something else than none
    // (threads = 0: one per core); "": the number. A literal, shown as an ImGui format.
    std::string_view zeroMeans = {};
    // Real: shown as 1/N where it is one, as the texts write h ("1/240", not "0.004167").
    bool shownAsFraction = false;
    // Choice: what the UI shows beside each name ("" nothing; empty: none at all), such as
    // an order that is not the lecture's.
    std::vector<std::string_view> choiceNotes;

    bool availableIn(const Scene& scene) const { return !available || available(scene); }
    // Choice k's name with its note: "colored (not the lecture's)".
    std::string choiceShown(std::size_t k) const;
};

// Every parameter, in the order the UI shows them: the Live ones, then the Restart ones.
const std::vector<Parameter>& parameterTable();

// The entry called `name`, or nullptr.
const Parameter* findParameter(std::string_view name);

// Once every setting of a run is applied (so that their order does not matter): "" when
// each acts on something in `scene`, else one line naming the first that does not
// ("toi=bisection: toi acts only with the continuous method, and this run's is velocity").
std::string settingsThatActOnNothing(const Scene& scene, const std::vector<std::string>& settings);

// "name=value": checks the value against the table and stores it in the scene.
// Returns "" on success, else one line naming the problem (unknown name with
// close and valid names, a value that is not a number, out of range with the
// range, an unknown choice with the choices). The scene is unchanged on error.
std::string applySetting(Scene& scene, std::string_view assignment);

// The number `text` stands for, as --set, links and a slider's Ctrl+click take it: a
// choice's name (its index), a decimal, or a fraction as the texts write h ("1/240").
// "" when it reads, else one line saying why not; the range is checkValue's.
std::string parseValue(const Parameter& parameter, std::string_view text, double& value);

// Checks a number (a Choice's index) and stores it: "" or one line saying why not.
std::string setValue(const Parameter& parameter, Scene& scene, double value);

// "" when the value is in range (and whole for Integer), else one line saying why not.
std::string checkValue(const Parameter& parameter, double value);

// The index of a Choice parameter's `name`, or -1.
int choiceIndex(const Parameter& parameter, std::string_view name);

// The current value as applySetting reads it back: a choice name, a whole
// number, or the shortest decimal that round-trips the double. No unit.
std::string formatValue(const Parameter& parameter, const Scene& scene);

// "1/N" when `parameter` is shown as a fraction and `value` is 1/N to the last bit or
// two (N from 2 to 100 000), else "".
std::string fractionShown(const Parameter& parameter, double value);

// The shortest decimal text that reads back as the same double.
std::string formatNumber(double value);

}  // namespace scenes
