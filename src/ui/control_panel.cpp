#include "ui/control_panel.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <string_view>

#include <glm/geometric.hpp>
#include <imgui.h>
#include <imgui_internal.h>  // TempInputIsActive: a number typed into a slider
#include <imgui_stdlib.h>

#include "scenes/overrides.h"
#include "scenes/parameters.h"
#include "ui/tooltip_timing.h"
#include "ui/wrapped_text.h"

namespace ui {
namespace {

// What the colours mean (scenes::kColorByLegends), under the readouts; presented, under the
// sliders for the penetration colouring alone (the texts say what green and orange mean
// where it matters, and the projector's panel has no line to spare).
std::string colourLegend(const PanelState& state, bool presented) {
    if (state.colorBy < 0 || state.colorBy >= int(std::size(scenes::kColorByNames))) return "";
    const bool penetration = std::string_view(scenes::kColorByNames[state.colorBy]) == "penetration";
    const std::string legend = scenes::kColorByLegends[state.colorBy];
    return legend.empty() || (presented && !penetration) ? "" : "colours: " + legend;
}

// Under a slider side by side: the other views keep the value their overrides give them.
constexpr const char* kOnlyViewA = "view A only: the other views set their own";
// Presented, where no sphere is selected and the text asks for a click (in grey).
constexpr const char* kClickASphere = "click a sphere: its |v| shows here";
bool asksToClickASphere(const scenes::Scene& scene) { return scene.description.find("click") != std::string::npos; }

const ImVec4 kAlarmLit{1.0f, 0.30f, 0.25f, 1.0f};     // red, readable on the dark panel
const ImVec4 kNoteOrange{1.0f, 0.55f, 0.2f, 1.0f};    // paused, behind real time: the run's state
const ImVec4 kAlarmDimmed{0.72f, 0.42f, 0.40f, 1.0f};  // fired earlier
const ImVec4 kHintColor{0.85f, 0.78f, 0.70f, 1.0f};
const ImVec4 kMeasuredColor{0.55f, 0.85f, 1.0f, 1.0f};
const ImVec4 kRefusalColor{1.0f, 0.62f, 0.30f, 1.0f};  // orange: refused, nothing changed

// The item's tooltip, when tooltipDue says.
void tooltip(std::string_view text) {
    if (!ImGui::IsItemHovered() || text.empty() || !tooltipDue(ImGui::GetItemRectMin())) return;
    showTooltip(text);
}

std::string labelOf(const scenes::Parameter& p) {
    std::string label(p.label);
    if (!p.unit.empty()) label += " (" + std::string(p.unit) + ")";
    if (p.applies == scenes::Applies::Restart) label += " (restart)";
    return label + "##" + std::string(p.name);
}

void wrappedColored(const ImVec4& color, const std::string& text);

// A list's width that shows its choice whole (presented at 1024 px, "response-only" read
// "response-o"), at most the panel's.
float choiceWidth(const std::string& shown) {
    const ImGuiStyle& style = ImGui::GetStyle();
    const float width = ImGui::CalcTextSize(shown.c_str()).x + ImGui::GetFrameHeight() + 2.0f * style.FramePadding.x;
    return std::min(width, ImGui::GetContentRegionAvail().x);
}

// The text typed into a slider (Ctrl+click), read as --set and links read it when Enter
// is pressed (or the field is left): ImGui's own reading keeps the leading number, so the
// texts' "1/240" for h was read as 1 and refused, and "1/2" for beta set 1 without a word.
// A text that is not a number is refused under the slider; Esc keeps the value. Returns
// whether the field was left this frame (its edit, if any, is then in `actions`).
bool typedTextEntered(const scenes::Parameter& p, bool typing, PanelState& state, PanelActions& actions) {
    if (typing) {
        if (const ImGuiInputTextState* field = ImGui::GetInputTextState(ImGui::GetItemID())) {
            char text[64];
            ImTextStrToUtf8(text, sizeof text, field->TextW.Data, field->TextW.Data + field->CurLenW);
            state.typedName = std::string(p.name);
            state.typedText = text;
            state.typedFrame = ImGui::GetFrameCount();
            state.typedChanged = std::string(text) != field->InitialTextA.Data;  // not the value as shown
        }
        return false;
    }
    // Left in this frame, typed into until the last (not a field left long ago, its slider
    // hidden while typing, and a later drag of the same slider).
    const bool justLeft = state.typedName == p.name && state.typedFrame == ImGui::GetFrameCount() - 1;
    if (!justLeft || !ImGui::IsItemDeactivated()) return false;
    state.typedName.clear();
    if (state.pendingName == p.name) state.pendingName.clear();  // ImGui's reading of the text, not used
    // Esc, or the value as it was shown (0.01667 for h = 1/60, rounded): nothing to set.
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape)) || !state.typedChanged) return true;
    double value = 0.0;
    const std::string error = scenes::parseValue(p, state.typedText, value);
    if (error.empty()) {
        actions.edits.push_back({&p, value});
    } else {
        state.refusedName = std::string(p.name);
        state.refusal = error;
    }
    return true;
}

// The slider (or list) of one table entry. Its edit goes into `actions`: a Live one
// while it is dragged, a Restart one when it is let go (meanwhile `state` holds the
// value shown). Under it, why its last edit was refused. `labelAbove`: its label on a line
// of its own and the widget the panel's width (large type in a narrow panel).
// `noteViewA`: say "view A only" under it when side by side sets it in the other views
// (the presented panel says it once, under all its sliders).
void parameterWidget(const scenes::Parameter& p, const scenes::Scene& scene, PanelState& state,
                     PanelActions& actions, bool labelAbove = false, bool noteViewA = true) {
    const bool pending = state.pendingName == p.name;
    double value = pending ? state.pendingValue : p.get(scene);
    bool changed = false;
    std::string label = labelOf(p);
    if (labelAbove) {
        ImGui::TextUnformatted(label.c_str(), label.c_str() + label.find("##"));
        label = label.substr(label.find("##"));
        ImGui::PushItemWidth(-FLT_MIN);
    }
    if (p.kind == scenes::ParameterKind::Choice) {
        int index = static_cast<int>(value);
        const std::string current = p.choiceShown(static_cast<std::size_t>(index));
        if (state.present && !labelAbove) ImGui::SetNextItemWidth(std::max(ImGui::CalcItemWidth(), choiceWidth(current)));
        if (ImGui::BeginCombo(label.c_str(), current.c_str())) {
            for (std::size_t k = 0; k < p.choices.size(); ++k) {
                const std::string name = p.choiceShown(k);
                if (ImGui::Selectable(name.c_str(), static_cast<int>(k) == index)) {
                    value = static_cast<double>(k);
                    changed = true;
                }
            }
            ImGui::EndCombo();
        }
    } else if (p.kind == scenes::ParameterKind::Integer) {
        int integer = static_cast<int>(std::clamp(value, -2e9, 2e9));  // a seed typed past an int
        const int lo = static_cast<int>(p.min), hi = static_cast<int>(std::min(p.max, 1e9));
        const std::string format = integer == 0 && !p.zeroMeans.empty() ? std::string(p.zeroMeans) : "%d";
        changed = ImGui::SliderInt(label.c_str(), &integer, lo, std::min(hi, lo + 100000), format.c_str());
        value = integer;
    } else {
        const bool logarithmic = p.min > 0.0 && p.max / p.min > 100.0;
        // h as the texts write it, "1/60"; a format without a number (Ctrl+click opens empty).
        const std::string fraction = scenes::fractionShown(p, value);
        changed = ImGui::SliderScalar(label.c_str(), ImGuiDataType_Double, &value, &p.min, &p.max,
                                      fraction.empty() ? "%.4g" : fraction.c_str(),
                                      logarithmic ? ImGuiSliderFlags_Logarithmic : 0);
    }
    // A number typed into the slider (Ctrl+click) counts once Enter is pressed, not key by
    // key: typing 1.5 for beta would apply 1 on the way (and a refusal of 1.5 leave it).
    const bool typing = ImGui::TempInputIsActive(ImGui::GetItemID());
    // The label is the lecture's word; --set, links and scene files take the table's name.
    if (ImGui::IsItemHovered()) {
        tooltip(std::string(p.tooltip) + "\n\nNamed " + std::string(p.name) + " in --set, links and scene files.");
    }
    if (typedTextEntered(p, typing, state, actions)) {
        // read as --set reads it (done: ImGui's own reading is not used)
    } else if ((p.applies == scenes::Applies::Live || p.kind == scenes::ParameterKind::Choice) && !typing && !pending) {
        if (changed) actions.edits.push_back({&p, value});
    } else {
        // A restart rebuilds the world: only when the slider is let go, not on every drag frame.
        if (changed) {
            state.pendingName = std::string(p.name);
            state.pendingValue = value;
        }
        if (ImGui::IsItemDeactivated() && state.pendingName == p.name) {
            if (ImGui::IsItemDeactivatedAfterEdit()) actions.edits.push_back({&p, state.pendingValue});
            state.pendingName.clear();
        }
    }
    if (labelAbove) ImGui::PopItemWidth();
    if (state.refusedName == p.name && !state.refusal.empty()) wrappedColored(kRefusalColor, state.refusal);
    if (noteViewA && std::find(state.onlyViewA.begin(), state.onlyViewA.end(), p.name) != state.onlyViewA.end()) {
        wrappedColored(ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled), kOnlyViewA);
    }
}

// Under a button that reads or writes a file: what it did, or why not.
void fileNotice(const PanelState& state, PanelState::FileButton button) {
    if (state.noticeAt != button || state.notice.empty()) return;
    wrappedColored(state.noticeIsError ? kRefusalColor : kMeasuredColor, state.notice);
}

void wrappedColored(const ImVec4& color, const std::string& text) {
    ImGui::PushStyleColor(ImGuiCol_Text, color);
    textWrappedAtSpaces(text);
    ImGui::PopStyleColor();
}

// Slide 14's five properties, a check mark (green), a cross (red) or a dash (untested)
// before each, its number after.
void propertiesSection(const Readouts& r) {
    if (r.properties.empty()) return;
    ImGui::TextDisabled("five properties (Smith et al.)");
    tooltip("What a simultaneous-impact answer may keep (slide 14's global approach), measured on the contacts of "
            "every step since the last restart (symmetry: on the state now). Compare solvers side by side on one "
            "of slide 14's presets.");
    for (const Readouts::Property& p : r.properties) {
        static const ImVec4 kColours[] = {{0.45f, 0.9f, 0.45f, 1.0f}, {1.0f, 0.4f, 0.35f, 1.0f}, {0.6f, 0.6f, 0.6f, 1.0f}};
        static const char* kMarks[] = {"\u2713", "\u2717", "-"};
        const int v = std::clamp(p.verdict, 0, 2);
        ImGui::TextColored(kColours[v], "%s %s", kMarks[v], p.name.c_str());
        tooltip(p.meaning.c_str());
        ImGui::SameLine();
        textWrappedAtSpaces(p.value);  // never "1." / "0000"
    }
}

// Invariant alarms, red while recent, dimmed once older; the hint under each.
void alarmsSection(const std::vector<Readouts::Alarm>& alarms) {
    if (alarms.empty()) return;
    ImGui::Separator();
    for (const Readouts::Alarm& alarm : alarms) {
        wrappedColored(alarm.lit ? kAlarmLit : kAlarmDimmed, alarm.text);
        if (!alarm.hint.empty()) {
            tooltip(alarm.hint);
            ImGui::Indent();
            wrappedColored(alarm.lit ? kHintColor : ImGui::GetStyle().Colors[ImGuiCol_TextDisabled], alarm.hint);
            ImGui::Unindent();
        }
    }
    ImGui::Separator();
}

// Under the beta slider: its square and the apex ratios measured at floor bounces.
void measuredRestitution(const Readouts& r) {
    std::string text = "β² = ";
    char number[32];
    std::snprintf(number, sizeof number, "%.3f", r.betaSquared);
    text += number;
    if (r.measuredBetaSquared.empty()) {
        ImGui::TextUnformatted(text.c_str());
        if (!r.restitutionNote.empty()) {  // beside the value when it fits, else wrapped under it
            ImGui::SameLine();
            if (ImGui::CalcTextSize(r.restitutionNote.c_str()).x > ImGui::GetContentRegionAvail().x) ImGui::NewLine();
            wrappedColored(ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled), r.restitutionNote);
        }
    } else {
        text += "   measured ≈";
        for (auto it = r.measuredBetaSquared.rbegin(); it != r.measuredBetaSquared.rend(); ++it) {
            std::snprintf(number, sizeof number, " %.3f", *it);
            text += number;
        }
        ImGui::TextColored(kMeasuredColor, "%s", text.c_str());
    }
    tooltip("Measured \u03b2\u00b2: the apex height after a floor bounce over the apex height before it, newest first, "
            "read from the modified energy of the motion along the normal (exact in free flight). Slide 4: it "
            "should be \u03b2\u00b2. Position based loses up to \u03c4 s / H of it; velocity based gains about 2 g \u03c4 / s "
            "(\u03c4 = h / substeps, the solver step; s the impact speed, H the fall above the contact). "
            "Measured for scenes of up to 10 spheres, or the selected sphere.");
}

// Whether the steps, not the rest of the frame, took most of the last frame.
bool stepsTookTheFrame(const FrameTimes& timing) {
    const double frameMs = 1000.0 / timing.fps;
    return timing.steppingMs >= frameMs - timing.steppingMs;
}

void runSection(double& timeScale, const Readouts& r, PanelActions& actions) {
    if (ImGui::Button(r.paused ? "Run (P)" : "Pause (P)")) actions.togglePause = true;
    ImGui::SameLine();
    if (ImGui::Button("Step (O)")) actions.step = true;
    ImGui::SameLine();
    if (ImGui::Button("Restart (R)")) actions.restart = true;
    ImGui::SliderScalar("time scale", ImGuiDataType_Double, &timeScale,
                        &kTimeScaleRange[0], &kTimeScaleRange[1], "%.3g x", ImGuiSliderFlags_Logarithmic);
    tooltip("Simulated seconds per real second: below 1 is slow motion. The step h does not change.");
    ImGui::Text("t = %.3f s   %llu solver steps   %zu %s", r.time, static_cast<unsigned long long>(r.steps), r.sphereCount,
                r.sphereCount == 1 ? "sphere" : "spheres");
    // A line of its own whatever it says: a warning that came and went moved every slider
    // under it by a line, under the pointer.
    if (r.behindRealTime) {
        ImGui::TextColored(kNoteOrange, "%s", behindRealTimeLine(r.timing).c_str());
        tooltip(behindRealTimeRemedy(r.timing));
    } else if (r.paused) {
        ImGui::TextDisabled("paused");
    } else if (r.timing.fps > 0.0) {
        ImGui::TextDisabled("keeping up with real time");
    } else {
        ImGui::NewLine();  // a capture has no real time to keep up with
    }
}

// The alarms the panel shows. While the pointer is over the panel they stay as they were
// when it came (a new one, several lines high, would push every control below it down
// under the pointer: a click meant for h landed on substeps); the title counts the new ones.
const std::vector<Readouts::Alarm>& alarmsToShow(const Readouts& r, PanelState& state, std::size_t& unseen) {
    unseen = 0;
    if (!state.pointerOverPanel) {
        state.alarmsShown = r.alarms;
        return state.alarmsShown;
    }
    for (const Readouts::Alarm& alarm : r.alarms) {
        const auto same = [&](const Readouts::Alarm& shown) { return shown.text == alarm.text; };
        unseen += std::none_of(state.alarmsShown.begin(), state.alarmsShown.end(), same);
    }
    return state.alarmsShown;
}

std::string panelTitle(std::size_t unseenAlarms) {
    if (unseenAlarms == 0) return "Rigid spheres###Panel";
    return std::to_string(unseenAlarms) + (unseenAlarms == 1 ? " new alarm" : " new alarms") +
           " (shown when the pointer leaves)###Panel";
}

void sceneSection(const scenes::Scene& scene, PanelState& state, const std::vector<std::string>& presets,
                  PanelActions& actions) {
    const char* current = state.presetIndex >= 0 ? presets[static_cast<std::size_t>(state.presetIndex)].c_str() : "(file)";
    if (ImGui::BeginCombo("preset ([ ])", current)) {
        for (std::size_t k = 0; k < presets.size(); ++k) {
            if (ImGui::Selectable(presets[k].c_str(), static_cast<int>(k) == state.presetIndex)) {
                actions.preset = static_cast<int>(k);
            }
        }
        ImGui::EndCombo();
    }
    for (const scenes::Parameter& p : scenes::parameterTable()) {
        if (p.applies == scenes::Applies::Restart && p.availableIn(scene)) parameterWidget(p, scene, state, actions);
    }
    ImGui::TextUnformatted("scene file");
    ImGui::SetNextItemWidth(-FLT_MIN);  // the whole width: a path is long
    ImGui::InputText("##file", &state.scenePath);
    tooltip(state.scenePath);
    if (ImGui::Button("Load")) actions.loadPath = state.scenePath;
    tooltip("Loads the scene file named above (a path, or a preset's name).");
    ImGui::SameLine();
    if (ImGui::Button("Save state")) actions.saveState = true;
    tooltip("Saves the current positions, velocities and parameters as a new scene file in the output folder "
            "(never over an existing file) and puts its path in the field above: Load reads it back. Its text "
            "says when it was saved.");
    fileNotice(state, PanelState::FileButton::Scene);
    if (!state.outputFolder.empty()) {
        wrappedColored(ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled), "files go to " + state.outputFolder);
        tooltip("Saved states, exported plots and screenshots are written here, each under a new name.");
    }
}

// Where the last frame's time went, and the last step's profile (window only).
void frameTimings(const Readouts& r) {
    ImGui::Text("%.0f FPS   draw %.1f ms", r.timing.fps, r.timing.drawMs);
    if (r.timing.antialiasedUpTo > 0) {
        ImGui::TextDisabled("no anti-aliasing above %zu spheres", r.timing.antialiasedUpTo);
        tooltip("A software GL (no graphics card) pays for each of the 4 samples per pixel: at 10 000 spheres they "
                "doubled the time to draw. Above this many the view is drawn with one sample, and the spheres' edges "
                "show their pixels.");
    }
    ImGui::Text("stepping %.1f ms (%llu step%s)", r.timing.steppingMs,
                static_cast<unsigned long long>(r.timing.stepsThisFrame), r.timing.stepsThisFrame == 1 ? "" : "s");
    tooltip("Wall time of the last frame: drawing the scene until the GL has finished it, and "
            "stepping: the solver's steps (h / substeps each), a side-by-side run's too, and "
            "the measurements after them.");
    const physics::StepStats& s = r.stats;
    ImGui::Text("broad phase %.2f ms  passes %.2f ms", 1e3 * s.broadPhaseSeconds, 1e3 * s.passesSeconds);
    if (s.broadPhaseBuilds > 0) {
        ImGui::Text("  %llu pair tests, %llu candidates", static_cast<unsigned long long>(s.pairTests),
                    static_cast<unsigned long long>(s.candidatePairs));
    } else {
        ImGui::Text("  pairs kept, no tests: %llu candidates", static_cast<unsigned long long>(s.candidatePairs));
    }
    tooltip("Where the last step went (its substeps together): finding the candidate pairs "
            "(the broad phase: a grid, or all N(N-1)/2 pairs; the pair tests are its distance tests, none when no sphere "
            "moved far enough to need new pairs), then the K collision passes over the "
            "candidates. Switch the broad phase to compare.");
    if (s.slowerThreads > 0) {
        ImGui::Text("solver threads %d (%d were slower)", s.threads, s.slowerThreads);
    } else {
        ImGui::Text("solver threads %d", s.threads);
    }
    tooltip("The threads of the last solver step. With 'solver threads' on auto the solver "
            "tries one thread now and then, and keeps it while more were slower (other "
            "programs busy on the same cores). Any count gives the same result.");
}

// A scrolling plot of `samples` against `times` (s), oldest first, its latest value
// printed on it; hovering shows the time and the value there (ImGui's PlotLines would
// show the sample's index).
void plotAgainstTime(const char* name, const std::vector<float>& samples, const std::vector<double>& times) {
    const ImVec2 size(ImGui::GetContentRegionAvail().x, ImGui::GetFontSize() * 2.5f);
    ImGui::InvisibleButton((std::string("##") + name).c_str(), size);
    const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
    ImDrawList& draw = *ImGui::GetWindowDrawList();
    draw.AddRectFilled(lo, hi, ImGui::GetColorU32(ImGuiCol_FrameBg), ImGui::GetStyle().FrameRounding);
    const auto [least, most] = std::minmax_element(samples.begin(), samples.end());
    const float range = *most > *least ? *most - *least : 1.0f;
    const float pad = ImGui::GetStyle().FramePadding.y;
    std::vector<ImVec2> points(samples.size());
    const float dx = samples.size() > 1 ? (hi.x - lo.x) / float(samples.size() - 1) : 0.0f;
    for (std::size_t k = 0; k < samples.size(); ++k) {
        points[k] = {lo.x + dx * float(k), hi.y - pad - (samples[k] - *least) / range * (hi.y - lo.y - 2.0f * pad)};
    }
    draw.AddPolyline(points.data(), int(points.size()), ImGui::GetColorU32(ImGuiCol_PlotLines), 0, 1.0f);
    char text[64];
    std::snprintf(text, sizeof text, "%.4g", samples.back());
    draw.AddText({0.5f * (lo.x + hi.x - ImGui::CalcTextSize(text).x), lo.y + pad}, ImGui::GetColorU32(ImGuiCol_Text),
                 text);
    if (!ImGui::IsItemHovered() || samples.size() < 2) return;
    const auto k = std::size_t(std::clamp((ImGui::GetIO().MousePos.x - lo.x) / dx + 0.5f, 0.0f, float(samples.size() - 1)));
    draw.AddLine({points[k].x, lo.y}, {points[k].x, hi.y}, ImGui::GetColorU32(ImGuiCol_PlotLinesHovered));
    ImGui::SetTooltip("t = %.3f s: %.6g", times[k], double(samples[k]));
}

void readoutsBody(const Readouts& r, const PanelState& state, PanelActions& actions) {
    const physics::Diagnostics& d = r.diagnostics;
    if (r.timing.fps > 0.0) {
        frameTimings(r);
    } else {
        ImGui::TextDisabled("FPS and timings: not measured here");  // capture: equal runs, equal images
    }
    // The overlays' scales and the colours first: they explain what is drawn.
    const std::string colours = colourLegend(state, false);
    if (!r.legend.empty() || !colours.empty()) {
        for (const Readouts::LegendLine& line : r.legend) {
            wrappedColored(ImVec4(line.color[0], line.color[1], line.color[2], line.color[3]), line.text);
        }
        if (!colours.empty()) ImGui::TextWrapped("%s", colours.c_str());
        ImGui::Separator();
    }
    // Answers, not contacts: 07's 4 resting wall contacts read "76 static" under "0 sphere + 4 wall".
    // Wrapped: the dock beside the view is narrow.
    char line[128];
    std::snprintf(line, sizeof line, "touching now: %llu sphere + %llu wall contacts",
                  static_cast<unsigned long long>(d.sphereContacts), static_cast<unsigned long long>(d.wallContacts));
    textWrappedAtSpaces(line);
    std::snprintf(line, sizeof line, "last step answered %llu bounces, %llu static",
                  static_cast<unsigned long long>(r.stats.collisions), static_cast<unsigned long long>(r.stats.staticContacts));
    textWrappedAtSpaces(line);
    tooltip("Contact answers in the last step, counted in every pass and substep (a contact answered in each of "
            "4 substeps and 2 passes counts 8). A bounce is a contact whose relative normal speed is above "
            "\u03b5; a static contact is at or below it (slide 13).");
    ImGui::Text("bounces since restart %llu", static_cast<unsigned long long>(r.bouncesSinceRestart));
    tooltip("Contacts answered as a bounce since the last restart, counted in every pass and substep.");
    if (r.untilConverged) {
        ImGui::Text("passes last step %llu (at most K = %d a solver step)", static_cast<unsigned long long>(r.stats.passesUsed),
                    r.passCap);
        ImGui::Text("solver steps that reached K: %llu", static_cast<unsigned long long>(r.stats.passCapHits));
        tooltip("Until converged: the passes run in the last time step, summed over its substeps (each solver step "
                "runs at most K), and how many solver steps reached K with a contact still approaching (raise K to "
                "let them converge).");
    }
    if (r.globalSolve) {
        ImGui::Text("LCP sweeps last step %llu", static_cast<unsigned long long>(r.stats.lcpSweeps));
        ImGui::Text("LCP residual %.2g m/s", r.stats.lcpResidual);
        tooltip("The global solve, each cluster of touching spheres on its own (and on several threads): projected "
                "Gauss-Seidel sweeps of the cluster that took most, summed over the last time step's passes, and the "
                "most any contact ended off its target speed (the tolerance is 1e-12 m/s, or 1e-14 of the fastest "
                "approach for a cluster of at most 64 contacts with an impact; a pile needs hundreds of sweeps; lcp "
                "makes at most 1000 a solve, one solve a pass; generalized reflections up to 1000 a round, many "
                "rounds a pass).");
    }
    if (r.reflections) {
        ImGui::TextWrapped("reflection rounds last step %llu, capped %llu",
                    static_cast<unsigned long long>(r.stats.reflectionRounds),
                    static_cast<unsigned long long>(r.stats.reflectionCapHits));
        tooltip("Generalized reflections: rounds of { the contacts that approach, solved together } of the cluster "
                "that took most, summed over the last time step's passes, and the clusters that stopped at a cap "
                "(10 000 rounds, or 10^7 contact visits, 500 sweeps of the contacts above 20 000) with a contact "
                "still approaching, the step's last positivity solve included.");
    }
    if (r.shock) {
        ImGui::Text("shock: %llu levels, %llu rounds last step", static_cast<unsigned long long>(r.stats.shockLevels),
                    static_cast<unsigned long long>(r.stats.shockRounds));
        tooltip("Shock propagation, slide 14's contact graph: the most levels a solver step swept from the floor up (level 0 touches a "
                "plane), and the rounds over them in the last time step, all substeps: one a level, more where the "
                "pushes off a frozen level pressed spheres of the next one together (at most four a level).");
    }
    if (r.continuous) {
        ImGui::Text("impacts last step %llu, TOI iterations %llu", static_cast<unsigned long long>(r.stats.events),
                    static_cast<unsigned long long>(r.stats.toiIterations));
        tooltip("Continuous method: impacts answered at their instant in the last time step (bounces and static "
                "contacts, all substeps), and the bisection's halvings spent finding those instants (0 with the "
                "closed form): slide 7's \"computationally heavy\", counted.");
        ImGui::Text("steps at the impact cap since restart %llu", static_cast<unsigned long long>(r.cappedSinceRestart));
        tooltip("Solver steps that reached the most impacts per step and were projected from there.");
    }
    propertiesSection(r);
    ImGui::Text("kinetic %.5g J", d.kinetic);
    ImGui::Text("potential %.5g J", d.potential);
    ImGui::Text("total %.6g J", d.total);
    ImGui::Text("E~ %.6g J", d.modified);
    tooltip("E~ = \u03a3 m (\u2212g\u00b7p + |v + \u03c4 g/2|\u00b2 / 2), \u03c4 = h / substeps the solver step: the energy the time "
            "integration keeps exactly in free flight. "
            "Use it for bounce heights: the naive total wobbles by O(g v h).");
    const glm::dvec3 p = physics::momentumShown(d);  // kg m/s
    ImGui::Text("p (%.2g, %.2g, %.2g) kg m/s", p.x, p.y, p.z);
    tooltip("Total momentum, \u03a3 m v. Gravity changes it; the walls too. Between spheres alone it is kept by the "
            "momentum-conserving response for every \u03b1, \u03b2, \u03bc, and by the lecture's only when \u03b1 = \u03b2 = 1 "
            "and no static contact damps it (slide 13's v \u2190 \u03bc v scales each sphere's own velocity). A component "
            "within 10\u207b\u00b9\u00b2 of \u03a3 m |v| of zero is rounding and reads 0.");
    ImGui::Text("deepest penetration %.2f %% of r", 100.0 * d.maxPenetration);
    ImGui::Text("state hash %016llx", static_cast<unsigned long long>(d.hash));
    tooltip("Same scene, same seed, same parameters: same hash. Compare runs with it.");
    for (const auto& [name, samples] : r.plots) {
        if (samples->empty() || !r.plotTimes || r.plotTimes->size() != samples->size()) continue;
        ImGui::TextUnformatted(name);
        plotAgainstTime(name, *samples, *r.plotTimes);
    }
    if (ImGui::Button("Export plots as CSV")) actions.exportCsv = true;
    tooltip("Writes the plots' samples with their times as a new CSV file in the output folder.");
    fileNotice(state, PanelState::FileButton::Plots);
}

void viewSection(PanelState& state, PanelActions& actions) {
    // The list's names, in scenes::kColorByNames' order; the legends are the readouts'
    // (scenes::kColorByLegends), said once.
    static const char* const colourings[] = {"sphere id", "speed", "contact state", "penetration"};
    static_assert(std::size(colourings) == std::size(scenes::kColorByNames));
    ImGui::Combo("colour by", &state.colorBy, colourings, int(std::size(colourings)));
    static const std::string colours = [] {
        std::string text;
        for (std::size_t k = 1; k < std::size(scenes::kColorByLegends); ++k) {
            text += std::string(colourings[k]) + ": " + scenes::kColorByLegends[k] + ".\n";
        }
        return text + "Penetration shows how far a stack has sunk into itself, where the views look alike. "
                      "The readouts say what the colours mean.";
    }();
    tooltip(colours.c_str());
    ImGui::Checkbox("box", &state.showBox);
    ImGui::SameLine();
    ImGui::Checkbox("floor grid", &state.showGrid);
    ImGui::TextDisabled("overlays (scales in the readouts)");
    ImGui::Checkbox("velocity", &state.showVelocity);
    tooltip("An arrow from each sphere's surface along v: the path of the centre in 0.1 s (1 m/s = 10 cm).");
    ImGui::SameLine();
    ImGui::Checkbox("trails", &state.showTrails);
    tooltip("The last 1.5 s of each centre, fading (the first 200 spheres, or the selected one).");
    ImGui::Checkbox("contacts", &state.showContacts);
    tooltip("Every contact of the last step: the point (yellow) and the normal (cyan), u from the other sphere "
            "or the plane's n (slides 3 and 9).");
    ImGui::SameLine();
    ImGui::Checkbox("impulses", &state.showImpulses);
    tooltip("At each bounce, the impulse m (v after - v before) on each sphere, from the contact point "
            "(1 kg m/s = 5 cm); it fades over 0.5 s of simulated time.");
    ImGui::Checkbox("penetration", &state.showPenetration);
    tooltip("Each overlap now: a red segment along the normal, 10 times the depth d (slide 7: p <- p + d n).");
    ImGui::SameLine();
    ImGui::Checkbox("contact graph", &state.showGraph);
    tooltip("Slide 14's contact graph: each sphere, and a line between the centres of spheres that touch, "
            "coloured by level "
            "(0 red: touches a plane, 1 orange: touches level 0, 2 yellow, 3 green, 4 cyan, 5 blue; 6 to 11 "
            "the same darker, 12 to 17 paler, 18 to 23 palest; grey: reaches no plane). Shock propagation "
            "sweeps the levels from the floor up.");
    if (ImGui::SliderFloat("UI scale", &state.uiScale, kUiScaleRange[0], kUiScaleRange[1], "%.2f")) actions.fontChanged = true;
    if (ImGui::Button("Reset view (C)")) actions.resetCamera = true;
    ImGui::SameLine();
    if (ImGui::Button("Screenshot (F12)")) actions.screenshot = true;
    fileNotice(state, PanelState::FileButton::Screenshot);
}

// The scene's title, its slide and its text: what the class reads first.
void sceneText(const scenes::Scene& scene) {
    textWrappedAtSpaces(scenes::withCount(scene.title, scene));
    if (!scene.slide.empty()) {  // wrapped: a long slide line must not be cut off
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
        textWrappedAtSpaces(scene.slide);
        ImGui::PopStyleColor();
    }
    if (!scene.description.empty()) textWrappedAtSpaces(scenes::describedText(scene));
}

// The claims whose moment the run has not reached yet, and when the last is.
std::string claimsPendingLine(const Readouts& r) {
    char line[160];
    std::snprintf(line, sizeof line, "%zu more are measured as the run reaches their moment (the last at t = %.3g s).",
                  r.claimsWatched - r.claims.size(), r.claimsLastMoment);
    return line;
}

// What the list leaves out, and where it is measured.
std::string claimsElsewhereLine(const Readouts& r) {
    return std::to_string(r.claimsElsewhere) + " more of the text's claims name other settings or compare two "
           "runs: the command spheres claims measures every one.";
}

// Under the text: its claims as this run measured them (scenes/claims.h), folded under a
// line that counts them, so that the sliders stay where they are.
void measuredClaims(const Readouts& r, PanelState& state) {
    const bool wereOpen = state.claimsWereOpen;
    state.claimsWereOpen = false;
    if (r.claimsWatched == 0 && !r.claimsInterrupted) {
        if (!r.claimsForOtherSettings) return;
        ImGui::TextDisabled("The text, measured: not at these settings");
        tooltip("Each claim of the text is measured at the settings it names, and this run's differ from all of "
                "them (a slider moved before the restart). The preset list or [ ] opens the text's settings again.");
        return;
    }
    int held = 0;
    for (const Readouts::ClaimLine& c : r.claims) held += c.holds;
    // While the pointer is over the panel the lines stay as they were when it came, but for a
    // list just unfolded (by a click, so under the pointer), and a run restarted or another
    // scene's (fewer measured, or another count to watch).
    const bool sameRun = r.claims.size() >= state.claimsMeasuredShown && r.claimsWatched == state.claimsWatchedShown;
    const bool keepLines = state.pointerOverPanel && wereOpen && sameRun;
    char header[160];
    // Its shorter words where the whole line would not fit beside the arrow (presented at
    // 1024 px the count ran under the scroll bar: "5 ✓ 0 ✗ of").
    const float room = ImGui::GetContentRegionAvail().x - ImGui::GetFontSize() - 2.0f * ImGui::GetStyle().FramePadding.x;
    for (const char* words : {"The text, measured: ", "Measured: ", ""}) {
        if (r.claimsInterrupted) {
            std::snprintf(header, sizeof header, "%sstopped; R measures again###claims", words);
        } else if (r.claimsWatched > r.claims.size()) {  // "7 ✓ 0 ✗ of 17" read as ten claims missing
            std::snprintf(header, sizeof header, "%s%d \u2713 %d \u2717, %zu to come###claims", words, held,
                          int(r.claims.size()) - held, r.claimsWatched - r.claims.size());
        } else {
            std::snprintf(header, sizeof header, "%s%d \u2713 %d \u2717 of %zu###claims", words, held,
                          int(r.claims.size()) - held, r.claimsWatched);
        }
        if (ImGui::CalcTextSize(header, nullptr, true).x <= room) break;
    }
    const bool open = ImGui::CollapsingHeader(header);
    tooltip("What the text above says, measured in this run since its start: each claim once its moment has "
            "passed (the lab sheet checks the same claims). Side by side, each view measures what the text says "
            "of it (its letter first). A change by hand once the run has started (a slider, a sphere) "
            "stops the measurement until the next restart (R); the timeline does not (the steps replayed come out "
            "as they did, and are checked to); a setting changed before the first step "
            "measures the text's claims for that setting. While the pointer is over the panel the list holds "
            "still (a new line would push the sliders under it), and says how many it will add.");
    if (!open) return;
    state.claimsWereOpen = true;
    if (!keepLines) {
        state.claimsMeasuredShown = r.claims.size();
        state.claimsWatchedShown = r.claimsWatched;
        std::vector<std::pair<std::string, int>>& lines = state.claimLinesShown;
        lines.clear();
        for (const Readouts::ClaimLine& c : r.claims) {
            const std::string view = c.view ? std::string(1, c.view) + "  " : "";
            lines.emplace_back(view + (c.holds ? "\u2713 " : "\u2717 ") + "\u201c" + c.says + "\u201d: " + c.measured, int(c.holds));
        }
        state.claimsPendingShown = std::size_t(-1);
        if (r.claimsWatched > r.claims.size() && !r.claimsInterrupted) {
            state.claimsPendingShown = lines.size();
            lines.emplace_back(claimsPendingLine(r), 2);
        }
        if (r.claimsElsewhere > 0) lines.emplace_back(claimsElsewhereLine(r), 2);
    } else if (const std::size_t waiting = r.claims.size() - state.claimsMeasuredShown;
               waiting > 0 && state.claimsPendingShown < state.claimLinesShown.size()) {
        // Held with claims measured since: the pending line says so, in its place, else the
        // header's count and the list disagree.
        state.claimLinesShown[state.claimsPendingShown].first =
            std::to_string(waiting) + " more measured since: the list shows them once the pointer leaves the panel.";
    }
    const ImVec4 colours[] = {kAlarmLit, ImVec4(0.45f, 0.9f, 0.45f, 1.0f), ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled)};
    for (const auto& [text, kind] : state.claimLinesShown) wrappedColored(colours[kind], text);
}

// A new scene: its title and text are what the class reads first.
void scrollToTopIfAsked(PanelState& state) {
    if (!state.scrollToTop) return;
    ImGui::SetScrollY(0.0f);
    state.scrollToTop = false;
}

// Page Down / Page Up: the scroll moves by the visible height less a line, in whole lines
// (presenting, the text's lines lie a font size apart from the top and the fold falls
// between two: a page on, the line that was last in sight is the top one), so that the
// class reads on from it. A new scene's scroll to its top comes first.
void scrollByPagesIfAsked(PanelState& state) {
    if (state.pagesToScroll != 0 && !state.scrollToTop) {
        const float line = ImGui::GetFontSize();  // px
        const float visible = ImGui::GetWindowContentRegionMax().y - ImGui::GetWindowContentRegionMin().y;  // px
        const float page = std::max(1.0f, std::floor(visible / line) - 1.0f) * line;
        const float to = std::round((ImGui::GetScrollY() + float(state.pagesToScroll) * page) / line) * line;
        ImGui::SetScrollY(std::clamp(to, 0.0f, ImGui::GetScrollMaxY()));
    }
    state.pagesToScroll = 0;
    state.textScrollY = ImGui::GetScrollY();
}

// Room for the widest label beside each control ("ε static-contact speed (m/s)").
float itemWidth() { return std::min(ImGui::GetFontSize() * 9.5f, 0.4f * ImGui::GetContentRegionAvail().x); }
void pushItemWidth() { ImGui::PushItemWidth(itemWidth()); }

// Presenting, whether a slider's label is too wide beside it (1024 px at 1.5 times the
// type), or a list's choice too wide to leave its label room: then every label goes above
// its slider.
bool labelsAboveSliders(const std::vector<const scenes::Parameter*>& sliders, const scenes::Scene& scene) {
    for (const scenes::Parameter* p : sliders) {
        const std::string label = labelOf(*p);
        const float labelWidth = ImGui::CalcTextSize(label.c_str(), label.c_str() + label.find("##")).x;
        float widget = itemWidth();
        if (p->kind == scenes::ParameterKind::Choice) {
            widget = std::max(widget, choiceWidth(p->choiceShown(static_cast<std::size_t>(p->get(scene)))));
        }
        if (labelWidth + ImGui::GetStyle().ItemInnerSpacing.x > ImGui::GetContentRegionAvail().x - widget) return true;
    }
    return false;
}

// The height the presentation's sliders and `keys` take under the text: each slider, and
// the lines parameterWidget adds under it.
// What stays in sight under the presented text: the lines it takes, each wrapped to the panel.
struct UnderText {
    std::vector<std::string> notes;   // the view-A note (once), the numbers the texts point at
    std::string status;               // "t = 3.450 s, paused (P runs, O steps)"
    std::string statusRoom;           // the status as it reads paused: the room it keeps
    std::vector<std::string> alarms;  // the lit alarms' headlines
    float restitutionHeight = 0.0f;   // under β, its measured apex ratios (measuredRestitution)
    // Each key with what it does, never split between lines ("[ ]:" / "preset" at 1280 px).
    const char* keys = "Esc:\u00a0all\u00a0controls  P:\u00a0pause  R:\u00a0restart  [\u00a0]:\u00a0preset  "
                       "Tab:\u00a0views\u00a0only";
};

float heightUnderText(const std::vector<const scenes::Parameter*>& sliders, const PanelState& state,
                      bool labelsAbove, const UnderText& under, bool withRefusal = true) {
    const ImGuiStyle& style = ImGui::GetStyle();
    const float wrap = ImGui::GetContentRegionAvail().x;
    const auto lines = [&](const std::string& text) {  // as wrappedColored draws it
        return ImGui::CalcTextSize(wrapAtSpaces(text, std::max(wrap, ImGui::GetFontSize() * 4.0f)).c_str()).y + style.ItemSpacing.y;
    };
    float below = 2.0f * style.ItemSpacing.y + lines(under.keys);
    for (const scenes::Parameter* p : sliders) {
        below += ImGui::GetFrameHeightWithSpacing() + (labelsAbove ? ImGui::GetTextLineHeightWithSpacing() : 0.0f);
        if (withRefusal && state.refusedName == p->name && !state.refusal.empty()) below += lines(state.refusal);
    }
    for (const std::string& note : under.notes) below += lines(note);
    below += std::max(lines(under.status), lines(under.statusRoom)) + under.restitutionHeight;
    for (const std::string& alarm : under.alarms) below += lines(alarm);
    return below;
}

bool showsBeta(const std::vector<const scenes::Parameter*>& sliders) {
    return std::any_of(sliders.begin(), sliders.end(), [](const scenes::Parameter* p) { return p->name == "beta"; });
}

// Presented, the measured apex ratios go under β, or under the sliders where the text names
// no β but quotes bounce heights the meter follows (01's "peaks 6 to 13 % lower each bounce").
bool showsRestitution(const std::vector<const scenes::Parameter*>& sliders, const scenes::Scene& scene, const Readouts& r) {
    const auto aboutBounces = [](const scenes::Claim& c) { return c.measure == "bounce_ratio" || c.measure == "apex"; };
    return showsBeta(sliders) || (r.bouncesMeasured && std::any_of(scene.claims.begin(), scene.claims.end(), aboutBounces));
}

// Under the presented sliders: "view A only" once (under each slider it took two lines a
// slider), "t = 3.450 s, paused" (a paused scene looked frozen), and the lit alarms (a ball
// that fell through the floor was simply gone).
UnderText underPresentedText(const std::vector<const scenes::Parameter*>& sliders, const scenes::Scene& scene,
                             const PanelState& state, const Readouts& r, const std::vector<Readouts::Alarm>& alarms) {
    UnderText under;
    const bool viewA = std::any_of(sliders.begin(), sliders.end(), [&](const scenes::Parameter* p) {
        return std::find(state.onlyViewA.begin(), state.onlyViewA.end(), p->name) != state.onlyViewA.end();
    });
    if (viewA) under.notes.push_back(kOnlyViewA);
    if (const std::string colours = colourLegend(state, true); !colours.empty()) under.notes.push_back(colours);
    if (showsRestitution(sliders, scene, r)) {
        // "β² = 0.640   measured ≈ ..." on a line, or "β² = 0.640" and its note wrapped under it
        const float wrap = ImGui::GetContentRegionAvail().x;
        under.restitutionHeight = ImGui::GetTextLineHeightWithSpacing();
        // The note goes beside "β² = 0.640" where it fits (measuredRestitution), else under it.
        const float beside = wrap - ImGui::CalcTextSize("β² = 0.000").x - ImGui::GetStyle().ItemSpacing.x;
        if (r.measuredBetaSquared.empty() && !r.restitutionNote.empty() &&
            ImGui::CalcTextSize(r.restitutionNote.c_str()).x > beside) {
            under.restitutionHeight += ImGui::CalcTextSize(r.restitutionNote.c_str(), nullptr, false, wrap).y +
                                       ImGui::GetStyle().ItemSpacing.y;
        }
    }
    // The numbers the texts point at ("the momentum readout", "kinetic energy falls to 18 %"),
    // which the full layout's readouts show (view A's, side by side).
    // On two lines whatever their width: one line that wrapped as its digits changed moved the
    // sliders above it up and down.
    char numbers[160];
    // Both to five digits: "kinetic 3610 J   E~ 3609.7 J" read as two values in zero gravity.
    std::snprintf(numbers, sizeof numbers, "kinetic\u00a0%.5g\u00a0J   E~\u00a0%.5g\u00a0J", r.diagnostics.kinetic,
                  r.diagnostics.modified);
    under.notes.push_back(numbers);
    std::snprintf(numbers, sizeof numbers, "|p|\u00a0%.4g\u00a0kg\u00a0m/s", glm::length(physics::momentumShown(r.diagnostics)));
    under.notes.push_back(numbers);
    if (!scene.emitters.empty()) {  // 12's "nearly 200 after 10 s": the count grows, on a line of its own
        std::snprintf(numbers, sizeof numbers, "%zu\u00a0sphere%s", r.sphereCount, r.sphereCount == 1 ? "" : "s");
        under.notes.push_back(numbers);
    }
    // The clicked sphere's |v|. A text that asks the class to click one (07's "click one: the
    // inspector's |v|") keeps its line, saying how, so that the click moves no slider up.
    if (!r.selected.empty()) {
        under.notes.push_back(r.selected);
    } else if (asksToClickASphere(scene)) {
        under.notes.push_back(kClickASphere);
    }
    // The status as it reads now, and paused: its room is the larger, so that P does not
    // move the sliders above it when the line gets shorter (a teacher saw them jump a line).
    const auto statusLine = [&](bool paused) {
        char status[128];
        std::snprintf(status, sizeof status, "t = %.3f s, %s", r.time, paused ? "paused (P runs, O steps)" : "running (P pauses)");
        std::string line = status;
        if (r.timeScale != 1.0) {  // the class should know that what it sees is slowed down (or sped up)
            std::snprintf(status, sizeof status, r.timeScale < 1.0 ? ", slow\u00a0motion\u00a0%.3g\u00d7" : ", %.3g\u00d7\u00a0real\u00a0time",
                          r.timeScale);
            line += status;
        }
        // The full layout says why in orange; the texts quote times, so the class should know
        // that this computer draws them slower than they pass.
        if (r.behindRealTime) line += ", behind real time";
        return line;
    };
    under.status = statusLine(r.paused);
    under.statusRoom = statusLine(true);
    for (const Readouts::Alarm& alarm : alarms) {
        if (alarm.lit) under.alarms.push_back(alarm.text);
    }
    return under;
}

// The presentation layout: the scene's text and its claims scroll; only the sliders the text
// names, the run's state, its alarms and the keys stay in sight under them (a long text
// pushed them off at 720 lines).
// `alarms` as alarmsToShow keeps them: a new one waits for the pointer to leave the panel,
// so that the sliders do not move up under it.
void presentedPanel(const scenes::Scene& scene, const Readouts& readouts, const std::vector<Readouts::Alarm>& alarms,
                    PanelState& state, PanelActions& actions) {
    std::vector<const scenes::Parameter*> sliders;
    for (const std::string& name : scenes::slidersToMove(scene)) {
        const scenes::Parameter* p = scenes::findParameter(name);
        if (p && p->availableIn(scene)) sliders.push_back(p);
    }
    const bool labelsAbove = labelsAboveSliders(sliders, scene);
    UnderText under = underPresentedText(sliders, scene, state, readouts, alarms);
    // The sliders stay in sight under the text while they leave it at least 38 % of the panel
    // (9 lines at 1280x720: it scrolls; at half, 02's text took the whole panel and hid the
    // β it tells the class to move). Where all of them would take more, the first ones the
    // text names that fit stay (02's β and ε at 1024x768), and the rest scroll with the text,
    // under it (five sliders with their labels above at 1024x768 left it two lines).
    // A refusal under a slider is left out of the count: it would push the slider it is
    // about into the scrolled text, just where the teacher was looking.
    const float most = 0.62f * ImGui::GetContentRegionAvail().y;  // px
    const float restitutionHeight = under.restitutionHeight;
    const auto firstOf = [&](std::size_t n) {
        return std::vector<const scenes::Parameter*>(sliders.begin(), sliders.begin() + std::ptrdiff_t(n));
    };
    std::size_t inSight = sliders.size();
    while (inSight > 0 && heightUnderText(firstOf(inSight), state, labelsAbove, under, false) > most) {
        --inSight;
        under.restitutionHeight = showsBeta(firstOf(inSight)) ? restitutionHeight : 0.0f;  // under β, with it
    }
    const std::vector<const scenes::Parameter*> first = firstOf(inSight);
    const float below = heightUnderText(first, state, labelsAbove, under);
    const bool restitutionInSight = inSight == sliders.size() || showsBeta(first);
    const auto drawSliders = [&](std::size_t begin, std::size_t end, bool restitutionAfter) {
        pushItemWidth();
        for (std::size_t k = begin; k < end; ++k) {
            parameterWidget(*sliders[k], scene, state, actions, labelsAbove, false);  // "view A only" once, under them
            if (sliders[k]->name == "beta") measuredRestitution(readouts);  // 02's "comes back to about β²"
        }
        if (restitutionAfter && !showsBeta(sliders) && showsRestitution(sliders, scene, readouts)) measuredRestitution(readouts);
        ImGui::PopItemWidth();
    };
    // The fold between two of the text's lines, never through one (a class saw the last line
    // cut in half): the title, the slide and the text follow each other without item spacing,
    // so that every line lies a whole number of font sizes from the top, scrolled by pages
    // (scrollByPagesIfAsked) or not.
    const float room = ImGui::GetContentRegionAvail().y - below;  // px
    const float font = ImGui::GetFontSize();
    // Where all of it fits (as it did in the last frame) there is no fold: the claims' line
    // under a short text was cut in half by the fold set for the text's lines.
    const bool fits = state.presentedContentHeight <= room;
    const float cut = !fits && room > font ? std::fmod(room, font) : 0.0f;  // px, under the fold
    ImGui::BeginChild("presented", ImVec2(0.0f, room - cut));
    scrollByPagesIfAsked(state);
    scrollToTopIfAsked(state);
    ImGui::PushStyleVar(ImGuiStyleVar_ItemSpacing, ImVec2(ImGui::GetStyle().ItemSpacing.x, 0.0f));
    sceneText(scene);
    // The claims' line on the same grid, one font size high: with its frame's padding it lay
    // across the fold, cut in half under the text (20 at 1920x1080).
    ImGui::PushStyleVar(ImGuiStyleVar_FramePadding, ImVec2(ImGui::GetStyle().FramePadding.x, 0.0f));
    measuredClaims(readouts, state);
    ImGui::PopStyleVar(2);
    if (inSight < sliders.size()) {
        ImGui::Separator();
        drawSliders(inSight, sliders.size(), !restitutionInSight);
    }
    state.presentedContentHeight = ImGui::GetCursorPosY();  // px, the scrolled content's, whatever its scroll
    ImGui::EndChild();
    ImGui::SetCursorPosY(ImGui::GetCursorPosY() + cut);  // the keys stay at the bottom (a Dummy adds a spacing)
    ImGui::Separator();
    state.presentedSlidersTop = ImGui::GetCursorScreenPos().y;
    drawSliders(0, inSight, restitutionInSight);
    // The numbers the texts point at and the run's state in the body's white: grey washes out
    // on a projector (a teacher measured them at 4.8:1 against 21:1 for the text).
    const ImVec4 white = ImGui::GetStyleColorVec4(ImGuiCol_Text), grey = ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled);
    for (const std::string& note : under.notes) wrappedColored(note == kOnlyViewA || note == kClickASphere ? grey : white, note);
    wrappedColored(readouts.paused || readouts.behindRealTime ? kNoteOrange : white, under.status);
    const float wrap = ImGui::GetContentRegionAvail().x;
    const float spare = ImGui::CalcTextSize(under.statusRoom.c_str(), nullptr, false, wrap).y -
                        ImGui::CalcTextSize(under.status.c_str(), nullptr, false, wrap).y;  // px: running, a line shorter
    if (spare > 0.0f) ImGui::SetCursorPosY(ImGui::GetCursorPosY() + spare);
    for (const std::string& alarm : under.alarms) wrappedColored(kAlarmLit, alarm);
    wrappedColored(ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled), under.keys);
}

}  // namespace

std::string behindRealTimeLine(const FrameTimes& timing) {
    if (!(timing.fps > 0.0)) return "behind real time";
    const double frameMs = 1000.0 / timing.fps;
    const bool steps = stepsTookTheFrame(timing);
    const double partMs = steps ? timing.steppingMs : std::max(0.0, frameMs - timing.steppingMs);
    char line[96];
    std::snprintf(line, sizeof line, "slow motion: %s %.0f of %.0f ms a frame", steps ? "the steps take" : "drawing takes",
                  partMs, frameMs);
    return line;
}

const char* behindRealTimeRemedy(const FrameTimes& timing) {
    if (timing.fps > 0.0 && !stepsTookTheFrame(timing)) {
        return "The run is behind real time because drawing (the views, the panel, the swap) takes most of "
               "each frame, and the steps get what is left of 1/30 s. Fewer views side by side, a smaller "
               "window or fewer spheres keep up.";
    }
    return "The run is behind real time because its steps take most of each frame (at most 1/30 s a "
           "frame is spent stepping). A lower time scale, fewer spheres, fewer substeps or passes K, or "
           "a larger h keep up.";
}

float panelWidth(const PanelState& state, float displayWidth) {
    if (!state.visible || state.yieldsToExplainer) return 0.0f;
    // Presented with three or four views, the views take more of the width: at 1024x768 the
    // panel's 45 % left 16's four views boxes of 185 px.
    const float share = state.present && state.views >= 3 ? kPresentedPanelShareManyViews : 0.45f;
    return std::min(ImGui::GetFontSize() * 25.0f, displayWidth * share);
}

PanelActions drawControlPanel(const scenes::Scene& scene, double& timeScale, const Readouts& readouts,
                              PanelState& state, const std::vector<std::string>& presetNames) {
    PanelActions actions;
    if (!state.visible || state.yieldsToExplainer) {
        state.pendingName.clear();  // hidden while a restart slider was held: its drag is over
        state.pagesToScroll = 0;    // nothing to page: the text does not jump when it comes back
        return actions;
    }
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    ImGui::SetNextWindowPos(viewport->WorkPos, ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(panelWidth(state, viewport->WorkSize.x), viewport->WorkSize.y), ImGuiCond_Always);
    std::size_t unseenAlarms = 0;
    const std::vector<Readouts::Alarm>& alarms = alarmsToShow(readouts, state, unseenAlarms);
    ImGui::Begin(panelTitle(unseenAlarms).c_str(), nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
    state.pointerOverPanel = ImGui::IsWindowHovered(ImGuiHoveredFlags_ChildWindows | ImGuiHoveredFlags_AllowWhenBlockedByActiveItem);
    if (state.present) {
        presentedPanel(scene, readouts, alarms, state, actions);
        ImGui::End();
        return actions;
    }
    scrollByPagesIfAsked(state);
    scrollToTopIfAsked(state);
    pushItemWidth();
    sceneText(scene);
    measuredClaims(readouts, state);
    ImGui::Separator();
    runSection(timeScale, readouts, actions);
    alarmsSection(alarms);
    if (ImGui::CollapsingHeader("Lecture parameters", ImGuiTreeNodeFlags_DefaultOpen)) {
        for (const scenes::Parameter& p : scenes::parameterTable()) {
            if (p.applies != scenes::Applies::Live || !p.availableIn(scene)) continue;
            parameterWidget(p, scene, state, actions);
            if (p.name == "beta") measuredRestitution(readouts);
        }
    }
    if (ImGui::CollapsingHeader("Scene", ImGuiTreeNodeFlags_DefaultOpen)) sceneSection(scene, state, presetNames, actions);
    if (ImGui::CollapsingHeader("View and overlays")) viewSection(state, actions);
    ImGui::PopItemWidth();
    ImGui::End();
    return actions;
}

// "Readouts   41 FPS   kinetic 0.5 J   potential 0 J   hash 7568873c8f2cd1a0": the folded line.
// Side by side, the readouts are view A's, and say so.
std::string readoutsTitle(const Readouts& r, bool viewA) {
    char text[208];
    const int fps = static_cast<int>(r.timing.fps + 0.5);
    std::snprintf(text, sizeof text, "Readouts%s   %s%skinetic %.5g J   potential %.5g J   hash %016llx###Readouts",
                  viewA ? " of view A" : "", fps > 0 ? std::to_string(fps).c_str() : "", fps > 0 ? " FPS   " : "",
                  r.diagnostics.kinetic,
                  r.diagnostics.potential, static_cast<unsigned long long>(r.diagnostics.hash));
    return text;
}

void drawReadouts(const Readouts& readouts, PanelState& state, PanelActions& actions, const glm::vec4& line,
                  const glm::vec4& open) {
    const glm::vec4& at = state.readoutsOpen ? open : line;
    if (at.z <= 0.0f) return;
    ImGui::SetNextWindowPos(ImVec2(at.x, at.y), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(at.z, std::max(at.w, ImGui::GetFrameHeight())), ImGuiCond_Always);
    ImGui::SetNextWindowCollapsed(!state.readoutsOpen, ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(0.92f);
    const bool viewA = !state.onlyViewA.empty();  // side by side
    ImGui::Begin(state.readoutsOpen ? (viewA ? "Readouts of view A###Readouts" : "Readouts###Readouts")
                                    : readoutsTitle(readouts, viewA).c_str(),
                 nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoSavedSettings);
    const bool unfolded = !ImGui::IsWindowCollapsed();  // the arrow was clicked: laid out so from the next frame
    if (unfolded) readoutsBody(readouts, state, actions);
    // A click on the folded line's words unfolds it too (ImGui unfolds a window by its arrow
    // or a double click: a single click on "Readouts" did nothing).
    const bool lineClicked = !state.readoutsOpen && !unfolded && ImGui::IsWindowHovered() && ImGui::IsMouseClicked(0);
    ImGui::End();
    state.readoutsOpen = unfolded || lineClicked;
}

}  // namespace ui
