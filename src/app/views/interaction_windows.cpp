#include "app/views/interaction_windows.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include <imgui.h>
#include <imgui_stdlib.h>

#include "app/teaching/contact_explanation.h"
#include "app/run/session.h"
#include "app/views/view_labels.h"
#include "ui/tooltip_timing.h"
#include "ui/wrapped_text.h"

namespace app {
namespace {

constexpr ImGuiWindowFlags kFixed = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                    ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing;
constexpr float kBackgroundAlpha = 0.86f;
const ImVec4 kHeadingColor{1.0f, 0.85f, 0.45f, 1.0f};  // the slide a line comes from
const ImVec4 kResultColor{0.55f, 0.90f, 0.55f, 1.0f};
const ImVec4 kNoteColor{1.0f, 0.62f, 0.30f, 1.0f};
const ImVec4 kRingNoteColor{1.0f, 0.55f, 0.95f, 1.0f};  // the rings' legend, magenta like the partner's

void tooltip(const char* text) {
    if (!ImGui::IsItemHovered()) return;
    ui::showTooltip(text);
}

void place(const Placement& placement) {
    ImGui::SetNextWindowPos(ImVec2(placement.position.x, placement.position.y), ImGuiCond_Always,
                            ImVec2(placement.pivot.x, placement.pivot.y));
    ImGui::SetNextWindowSize(ImVec2(placement.width, placement.height), ImGuiCond_Always);
    if (placement.maxHeight > 0.0f) {
        ImGui::SetNextWindowSizeConstraints(ImVec2(placement.width, 0.0f), ImVec2(placement.width, placement.maxHeight));
    }
    ImGui::SetNextWindowBgAlpha(kBackgroundAlpha);
}

// One vector field: three numbers; true when edited (the new value is in `v`). An edit counts
// when Enter is pressed (applied keystroke by keystroke, "150" passed through 15 on its way,
// and a refused value left its first digits behind), and only in the numbers whose text was
// changed (valueAfterEnter): the others keep every digit.
bool vectorField(const char* label, glm::dvec3& v, bool editable) {
    constexpr const char* kFormat = "%.3f";
    constexpr double kShownAsZero = 0.0005;  // under half the last of three decimals: 0.000, not -0.000
    double values[3];
    for (int k = 0; k < 3; ++k) values[k] = v[k] < 0.0 && v[k] > -kShownAsZero ? 0.0 : v[k];
    const ImGuiInputTextFlags flags = editable ? ImGuiInputTextFlags_EnterReturnsTrue : ImGuiInputTextFlags_ReadOnly;
    if (!ImGui::InputScalarN(label, ImGuiDataType_Double, values, 3, nullptr, nullptr, kFormat, flags)) return false;
    bool changed = false;
    for (int k = 0; k < 3; ++k) {
        const double after = valueAfterEnter(values[k], v[k], kFormat);
        changed |= after != v[k];
        v[k] = after;
    }
    return changed;
}

bool scalarField(const char* label, double& value, bool editable) {
    constexpr const char* kFormat = "%.4g";
    double typed = value;
    const ImGuiInputTextFlags flags = editable ? ImGuiInputTextFlags_EnterReturnsTrue : ImGuiInputTextFlags_ReadOnly;
    if (!ImGui::InputScalar(label, ImGuiDataType_Double, &typed, nullptr, nullptr, kFormat, flags)) return false;
    const double after = valueAfterEnter(typed, value, kFormat);
    const bool changed = after != value;
    value = after;
    return changed;
}

}  // namespace

double valueAfterEnter(double typed, double value, const char* format) {
    char shown[64];
    std::snprintf(shown, sizeof shown, format, value);
    return typed == std::strtod(shown, nullptr) ? value : typed;  // -0.000 reads as 0: equal
}

float timelineBarHeight() {
    const ImGuiStyle& style = ImGui::GetStyle();
    return 2.0f * ImGui::GetFrameHeight() + style.ItemSpacing.y + 2.0f * style.WindowPadding.y;
}

void drawTimelineBar(const glm::vec4& scene, const TimelineInfo& timeline, bool compareOn, ToolWindowsState& state,
                     ToolActions& actions) {
    ImGui::SetNextWindowPos(ImVec2(scene.x, scene.y + scene.w), ImGuiCond_Always, ImVec2(0.0f, 1.0f));
    ImGui::SetNextWindowSize(ImVec2(scene.z, timelineBarHeight()), ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(kBackgroundAlpha);
    ImGui::Begin("##timeline bar", nullptr,
                 kFixed | ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse);

    char info[96];
    std::snprintf(info, sizeof info, "t %.3f s  solver step %llu  (%.1f s kept)", timeline.cursorTime,
                  static_cast<unsigned long long>(timeline.cursorSteps), timeline.keptSeconds);
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted("Timeline");
    ImGui::SameLine();
    const float infoWidth = ImGui::CalcTextSize(info).x + ImGui::GetStyle().ItemSpacing.x;
    ImGui::SetNextItemWidth(std::max(ImGui::GetContentRegionAvail().x - infoWidth, ImGui::GetFontSize() * 4.0f));
    int cursor = static_cast<int>(timeline.cursor);
    const int last = std::max(static_cast<int>(timeline.size) - 1, 0);
    ImGui::BeginDisabled(timeline.size < 2);
    if (ImGui::SliderInt("##timeline", &cursor, 0, last, "") && timeline.size > 0) {
        actions.scrub = true;
        actions.scrubTo = static_cast<std::size_t>(cursor);
    }
    ImGui::EndDisabled();
    char help[256];
    std::snprintf(help, sizeof help,
                  "Step back: the last frames are kept (%zu, %.1f MB). Drag to scrub back (it pauses); Left and "
                  "Right arrows step through them. Run (P) or Step (O) goes on from the state shown: the future is "
                  "recomputed, and is the same as before unless something was changed.",
                  timeline.size, double(timeline.bytes) / (1024.0 * 1024.0));
    tooltip(help);
    ImGui::SameLine();
    ImGui::TextUnformatted(info);

    if (ImGui::Button("Shoot (F)")) actions.shoot = true;
    tooltip("A new sphere from the camera along the view direction (F: through the mouse pointer). Outside the box "
            "it starts where the ray enters the box. Refused where it would overlap a sphere.");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 7.0f);
    ImGui::SliderFloat("##shot speed", &state.shootSpeed, 1.0f, 50.0f, "%.0f m/s");
    tooltip("Speed of the shot sphere, m/s.");
    ImGui::SameLine();
    bool compare = compareOn;
    if (ImGui::Checkbox("Side by side (V)", &compare)) actions.toggleCompare = true;
    tooltip("Views of the same initial state, stepping together (each shows the same instant; a costlier view "
            "slows them all): A the panel's parameters, the others the same with the name=value overrides given "
            "here (e.g. method=velocity; method=reflection,continuous makes a view per value; four views at most). "
            "Turning it on restarts them all.");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(std::max(ImGui::GetContentRegionAvail().x, ImGui::GetFontSize() * 6.0f));
    if (ImGui::InputTextWithHint("##compare", "name=value,...", &state.compareText,
                                 ImGuiInputTextFlags_EnterReturnsTrue)) {
        actions.applyCompare = true;  // Enter: side by side (again) with these overrides
    }
    tooltip("name=value overrides for the right view; Enter applies them (and turns side by side on).");
    ImGui::End();
}

void drawMessage(const glm::vec4& scene, const ToolWindowsState& state) {
    if (state.message.empty()) return;
    const float gap = ImGui::GetFontSize() * 0.5f;
    ImGui::SetNextWindowPos(ImVec2(scene.x + 0.5f * scene.z, scene.y + scene.w - gap),
                            ImGuiCond_Always, ImVec2(0.5f, 1.0f));
    ImGui::SetNextWindowSize(ImVec2(0.0f, 0.0f), ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(kBackgroundAlpha);
    ImGui::Begin("##message", nullptr,
                 kFixed | ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoInputs | ImGuiWindowFlags_AlwaysAutoResize);
    const bool refused = state.message.find("cannot") != std::string::npos;  // "cannot ...", "A: cannot ..."
    ImGui::PushStyleColor(ImGuiCol_Text, refused ? kNoteColor : kResultColor);
    ImGui::PushTextWrapPos(std::min(0.9f * scene.z, ImGui::GetFontSize() * 40.0f));  // long ones wrap, never cut
    ImGui::TextUnformatted(state.message.c_str());
    ImGui::PopTextWrapPos();
    ImGui::PopStyleColor();
    ImGui::End();
}

float drawInspector(const Placement& placement, const physics::World& world, int selected, char view, bool paused,
                    int graphLevel, ToolWindowsState& state, ToolActions& actions) {
    if (selected < 0 || static_cast<std::size_t>(selected) >= world.size()) return 0.0f;
    const auto i = static_cast<std::size_t>(selected);
    place(placement);
    char title[64];
    if (view != '\0') {  // side by side: which view's sphere the numbers are
        std::snprintf(title, sizeof title, "Sphere #%d in view %c###inspector", selected, view);
    } else {
        std::snprintf(title, sizeof title, "Sphere #%d###inspector", selected);
    }
    ImGui::Begin(title, nullptr, kFixed | ImGuiWindowFlags_NoCollapse);
    ImGui::PushItemWidth(-ImGui::GetFontSize() * 3.5f);  // the fields take the width the labels leave
    SphereFields fields{world.position[i], world.velocity[i], world.radius[i], world.mass[i]};
    bool changed = vectorField("p (m)", fields.p, paused);
    changed |= vectorField("v (m/s)", fields.v, paused);
    changed |= scalarField("r (m)", fields.r, paused);
    changed |= scalarField("m (kg)", fields.m, paused);
    ImGui::PopItemWidth();
    if (changed) {
        actions.edited = true;
        actions.fields = fields;
    }
    if (!state.inspectorRefusal.empty() && state.refusedSphere == selected) {  // beside the fields; they kept their values
        ImGui::PushStyleColor(ImGuiCol_Text, kNoteColor);
        ui::textWrappedAtSpaces(state.inspectorRefusal);
        ImGui::PopStyleColor();
    }
    const physics::ContactState contact =
        i < world.contactState.size() ? world.contactState[i] : physics::ContactState::Free;
    const glm::dvec3& v = world.velocity[i];
    ImGui::Text("|v| = %s, %s", speedText(glm::length(v)).c_str(), contactStateName(contact));
    if (graphLevel >= 0) {
        ImGui::Text("contact graph level %d%s", graphLevel, graphLevel == 0 ? " (touches a plane)" : "");
        tooltip("Slide 14: level 0 touches a plane, level k + 1 touches level k and none lower. Shock "
                "propagation answers the levels from the floor up, each frozen once answered.");
    } else if (graphLevel == -1) {
        ImGui::TextUnformatted("contact graph: no level (reaches no plane)");
    }
    if (!paused) {  // wrapped: the dock may be narrow
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
        ui::textWrappedAtSpaces("pause (P) to edit; Ctrl + drag to throw");
        ImGui::PopStyleColor();
    }
    if (ImGui::Button(state.explainer ? "Hide explanation (E)" : "Explain contacts (E)")) actions.toggleExplainer = true;
    tooltip("The slides' formulas with the numbers of this sphere's latest contacts.");
    const ImGuiStyle& style = ImGui::GetStyle();
    if (ImGui::CalcTextSize("Deselect").x + 2.0f * style.FramePadding.x + style.ItemSpacing.x <
        ImGui::GetContentRegionAvail().x - ImGui::GetItemRectSize().x) {
        ImGui::SameLine();  // beside it where it fits (a narrow dock: under it)
    }
    if (ImGui::Button("Deselect")) actions.deselect = true;
    // Its content's height, whatever room it had: the layout keeps that much from the next frame on.
    const float height = ImGui::GetCursorPosY() - ImGui::GetStyle().ItemSpacing.y + ImGui::GetStyle().WindowPadding.y;
    ImGui::End();
    return height;
}

int explainedPartner(const Session& session, const ToolWindowsState& state) {
    const std::vector<physics::ContactEvent>& events = session.latestContacts().events;
    const int selected = session.selected();
    if (!state.explainer || selected < 0 || events.empty()) return -1;
    const physics::ContactEvent& event = events[std::size_t(std::clamp(state.explainIndex, 0, int(events.size()) - 1))];
    return contactPartner(event, selected);
}

void drawExplainer(const Placement& placement, const ExplainerInput& input, ToolWindowsState& state,
                   ToolActions& actions) {
    if (!state.explainer || input.selected < 0 || !input.events || !input.params) return;
    place(placement);
    char title[80];
    if (input.view != '\0') {  // side by side: which view's contact it is (a presented dock has no inspector)
        std::snprintf(title, sizeof title, "Explain this contact: sphere #%d in view %c###explainer", input.selected,
                      input.view);
    } else {
        std::snprintf(title, sizeof title, "Explain this contact: sphere #%d###explainer", input.selected);
    }
    bool open = true;
    ImGui::Begin(title, &open, kFixed | ImGuiWindowFlags_NoCollapse);
    if (!open) actions.toggleExplainer = true;
    const std::vector<physics::ContactEvent>& events = *input.events;
    if (events.empty() && !input.recording) {
        ImGui::TextWrapped("Contacts are not recorded in this scene (too many spheres): nothing to explain.");
    } else if (events.empty()) {
        ImGui::TextWrapped(input.frameRecalled ? "Sphere #%d touched nothing in the frame shown, nor since. %s"
                                               : "No contact of sphere #%d recorded since it was selected. %s",
                           input.selected,
                           input.paused ? "Step with O until it touches something, or back with \u2190 to a contact it had."
                                        : "It is explained here after its next contact.");
    }
    if (events.empty()) {
        ImGui::End();
        return;
    }
    const int count = static_cast<int>(events.size());
    state.explainIndex = std::clamp(state.explainIndex, 0, count - 1);
    if (ImGui::ArrowButton("##previous", ImGuiDir_Left)) state.explainIndex = (state.explainIndex + count - 1) % count;
    ImGui::SameLine();
    if (ImGui::ArrowButton("##next", ImGuiDir_Right)) state.explainIndex = (state.explainIndex + 1) % count;
    ImGui::SameLine();
    const physics::ContactEvent& event = events[static_cast<std::size_t>(state.explainIndex)];
    // Wrapped: "100 of 100: vs #834, after the last pass, velocities only, static" is
    // wider than the window at 1280 px.
    ui::textWrappedAtSpaces(std::to_string(state.explainIndex + 1) + " of " + std::to_string(count) + ": " +
                            contactTitle(event, input.selected, input.boxPlaneCount, input.params->passes));
    if (!event.isPlane()) {  // which ring is which sphere
        ImGui::TextColored(kRingNoteColor, "ringed: #%d yellow, #%d magenta", input.selected,
                           contactPartner(event, input.selected));
    }
    const double age = input.now - input.eventTime;  // s
    // The log holds a whole time step h: its `substeps` solver steps end at eventSteps.
    const unsigned long long last = input.eventSteps;
    const unsigned long long first = last + 1 - std::min<unsigned long long>(last, std::max(1, input.params->substeps));
    char steps[64], when[192];
    if (first == last) {  // one substep a step
        std::snprintf(steps, sizeof steps, "solver step %llu", last);
    } else {
        std::snprintf(steps, sizeof steps, "solver steps %llu-%llu", first, last);
    }
    if (age > 0.0) {
        std::snprintf(when, sizeof when, "in the time step to t = %.4f s (%s), %.3g s ago", input.eventTime, steps, age);
    } else {
        std::snprintf(when, sizeof when, "in the last time step, to t = %.4f s (%s)", input.eventTime, steps);
    }
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ui::textWrappedAtSpaces(when);
    ImGui::PopStyleColor();
    ImGui::Separator();
    const ContactExplanation explanation = explainContact(event, *input.params);
    std::vector<ExplanationLine> lines = explanationLines(explanation, *input.params, input.boxPlaneCount);
    if (input.solvedTogether) {
        for (ExplanationLine& line : solvedWithLines(event, *input.solvedTogether, input.boxPlaneCount)) {
            lines.push_back(std::move(line));
        }
    }
    for (const ExplanationLine& line : lines) {
        const ImVec4 color = line.kind == ExplanationLine::Kind::Heading  ? kHeadingColor
                             : line.kind == ExplanationLine::Kind::Result ? kResultColor
                             : line.kind == ExplanationLine::Kind::Note   ? kNoteColor
                                                                          : ImGui::GetStyleColorVec4(ImGuiCol_Text);
        ImGui::PushStyleColor(ImGuiCol_Text, color);
        ui::textWrappedAtSpaces(line.text);
        ImGui::PopStyleColor();
    }
    ImGui::End();
}

glm::vec2 viewLabelSize(const ViewLabel& label) {
    const ImGuiStyle& style = ImGui::GetStyle();
    float width = 0.0f;
    for (const std::string& line : label.lines) width = std::max(width, ImGui::CalcTextSize(line.c_str()).x);
    const float lines = float(label.lines.size());
    return {width + 2.0f * style.WindowPadding.x,
            lines * ImGui::GetTextLineHeightWithSpacing() - style.ItemSpacing.y + 2.0f * style.WindowPadding.y};
}

float labelsWidth(const std::vector<ViewLabel>& labels) {
    float width = 0.0f;
    for (const ViewLabel& label : labels) width = std::max(width, viewLabelSize(label).x);
    const float font = ImGui::GetFontSize();
    return std::ceil(width / font + 1.0f) * font;  // a font to spare: a mark's dash becomes a wider check
}

namespace {

constexpr float kSmallestType = 0.6f;  // of the panel's type

// The widest word of a label's lines no wider than `upTo` (units, in the type of the window
// drawing at the time).
float widestWord(const ViewLabel& label, float upTo = 1e30f) {
    float widest = 0.0f;
    for (const std::string& line : label.lines) widest = std::max(widest, ui::widestWord(line, upTo));
    return widest;
}

// A label's type, as a share of the panel's: where a word is wider than its lines
// `lineWidth` (units), smaller, down to kSmallestType, so that the word stays whole (a
// quarter of a 1024 px projector broke "penetrati" / "on" and "✗ momentu" / "m"). A word
// wider still (a hash in a very narrow label) is cut where the line is full, and does not
// keep the others from being whole.
float wholeWordsScale(const ViewLabel& label, float lineWidth) {
    const float widest = widestWord(label, lineWidth / kSmallestType);
    if (widest <= std::max(lineWidth, 0.0f)) return 1.0f;  // (no room at all: a minimised window)
    return std::max(0.99f * kSmallestType, 0.99f * lineWidth / widest);  // a hair to spare for the widths' rounding
}

// `labels` with each title's letter held to the word after it ("A   sequential" had wrapped
// as "A" / "sequential" in a label a quarter of a projector wide): the spaces after the
// letter made non-breaking, where the two fit the label's line (`lineWidth(label)`, units)
// in type no smaller than kLetterHeldType; else the letter may stand alone ("B   simultaneous"
// held together at 1024x768 would have been cut).
constexpr float kLetterHeldType = 0.8f;  // of the panel's

template <class LineWidth>
std::vector<ViewLabel> lettersKeptWithTitles(std::vector<ViewLabel> labels, LineWidth lineWidth) {
    for (ViewLabel& label : labels) {
        if (label.lines.empty()) continue;
        std::string& title = label.lines.front();
        std::size_t spaces = 1;
        while (spaces < title.size() && title[spaces] == ' ') ++spaces;
        if (spaces < 2) continue;
        // The word up to where a line may break in it: a space, or after a hyphen or a '/'
        // ("generalized-" of "generalized-reflections").
        const std::size_t mark = title.find_first_of(" -/", spaces);
        const std::size_t wordEnd = mark == std::string::npos ? title.size() : title[mark] == ' ' ? mark : mark + 1;
        if (ImGui::CalcTextSize(title.substr(0, wordEnd).c_str()).x * kLetterHeldType > lineWidth(label)) continue;
        std::string held = title.substr(0, 1);
        for (std::size_t k = 1; k < spaces; ++k) held += "\u00a0";
        title = held + title.substr(spaces);
    }
    return labels;
}

// A line's height (units) wrapped at `wrapWidth` (units, unscaled) in `type`.
float lineHeight(const std::string& line, float wrapWidth, float type) {
    return type * ImGui::CalcTextSize(ui::wrapAtSpaces(line, wrapWidth).c_str()).y;
}

// The tallest title of `labels` (units), each wrapped at wrapWidth(label): every title takes
// as many rows, so that the lines under them stand side by side ("A / sequential" over two
// rows had put A's E~ a row below C's "C   lcp").
template <class WrapWidth>
float titleRows(const std::vector<ViewLabel>& labels, WrapWidth wrapWidth, float type) {
    float tallest = 0.0f;
    for (const ViewLabel& label : labels) {
        if (!label.lines.empty()) tallest = std::max(tallest, lineHeight(label.lines.front(), wrapWidth(label), type));
    }
    return tallest;
}

// A label's height (units) with its lines wrapped at `wrapWidth` (units, unscaled) in `type`
// and its title `title` high, as ImGui lays it: the cursor goes to a whole unit after each line.
float wrappedHeight(const ViewLabel& label, float wrapWidth, float type, float title) {
    const ImGuiStyle& style = ImGui::GetStyle();
    float cursor = style.WindowPadding.y, bottom = cursor;
    for (std::size_t n = 0; n < label.lines.size(); ++n) {
        const float height = lineHeight(label.lines[n], wrapWidth, type);
        bottom = cursor + (n == 0 ? std::max(height, title) : height);
        cursor = std::floor(bottom + style.ItemSpacing.y);
    }
    return bottom + style.WindowPadding.y;
}

}  // namespace

float labelsHeight(const std::vector<ViewLabel>& shown, float width) {
    const ImGuiStyle& style = ImGui::GetStyle();
    const float text = std::max(width - 2.0f * style.WindowPadding.x, ImGui::GetFontSize() * 4.0f);  // units
    const std::vector<ViewLabel> labels = lettersKeptWithTitles(shown, [&](const ViewLabel&) { return text; });
    float type = 1.0f;  // as drawViewLabels sets it at this width: every label alike
    for (const ViewLabel& label : labels) type = std::min(type, wholeWordsScale(label, text));
    // Lines wrapped a font narrower than drawn: changing digits and marks (- to a check) may
    // widen a line by that much, and the room then holds the line it wraps into. (A whole
    // line to spare left a blank band under every presented label: 48 px at 1920 x 1080.)
    const float wrapWidth = std::max(text / type - ImGui::GetFontSize(), ImGui::GetFontSize());
    const float title = titleRows(labels, [&](const ViewLabel&) { return wrapWidth; }, type);
    float tallest = 0.0f;
    for (const ViewLabel& label : labels) tallest = std::max(tallest, wrappedHeight(label, wrapWidth, type, title));
    return std::ceil(tallest);
}

LabelsDrawn drawViewLabels(const std::vector<ViewLabel>& shown) {
    LabelsDrawn drawn;
    // Measured before any label's window sets its type (the window drawing now has the panel's).
    const auto lineWidth = [](const ViewLabel& label) {  // units
        return std::min(viewLabelSize(label).x, label.room.x) - 2.0f * ImGui::GetStyle().WindowPadding.x;
    };
    const std::vector<ViewLabel> labels = lettersKeptWithTitles(shown, lineWidth);
    float type = 1.0f;
    for (const ViewLabel& label : labels) type = std::min(type, wholeWordsScale(label, lineWidth(label)));  // all alike
    for (const ViewLabel& label : labels) drawn.wordsBroken += type * widestWord(label) > lineWidth(label);
    // Every label as tall as the tallest drawn (side by side, one whose title wraps had stood
    // lower than the others).
    const auto wrapWidth = [&](const ViewLabel& label) { return lineWidth(label) / type; };  // units, unscaled
    const float title = titleRows(labels, wrapWidth, type);
    float tallest = 0.0f;
    for (const ViewLabel& label : labels) tallest = std::max(tallest, wrappedHeight(label, wrapWidth(label), type, title));
    for (std::size_t k = 0; k < labels.size(); ++k) {
        const ViewLabel& label = labels[k];
        ImGui::SetNextWindowPos(ImVec2(label.topLeft.x, label.topLeft.y), ImGuiCond_Always);
        // As wide as the place the layout keeps for it (labels as wide as their text stood
        // ragged over views of one width), as high as this frame's text (an auto-sized window
        // lags a frame behind changing numbers): a longer line wraps.
        const bool placed = label.room.x < 1e5f;
        const glm::vec2 size = glm::min(glm::vec2(placed ? label.room.x : viewLabelSize(label).x, tallest), label.room);
        ImGui::SetNextWindowSize(ImVec2(size.x, size.y), ImGuiCond_Always);
        ImGui::SetNextWindowBgAlpha(0.75f);
        const std::string name = "##view label " + std::to_string(k);
        ImGui::Begin(name.c_str(), nullptr,
                     kFixed | ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_AlwaysAutoResize |
                         ImGuiWindowFlags_NoInputs | ImGuiWindowFlags_NoBringToFrontOnFocus);
        ImGui::SetWindowFontScale(type);
        const ImGuiStyle& style = ImGui::GetStyle();
        for (std::size_t n = 0; n < label.lines.size(); ++n) {
            const ImVec4 color = n == 0 ? ImVec4(label.color.x / 255.0f, label.color.y / 255.0f, label.color.z / 255.0f, 1.0f)
                                        : ImGui::GetStyleColorVec4(ImGuiCol_Text);
            const float top = ImGui::GetCursorPosY();
            ImGui::PushStyleColor(ImGuiCol_Text, color);
            ui::textWrappedAtSpaces(label.lines[n]);
            ImGui::PopStyleColor();
            if (n == 0) ImGui::SetCursorPosY(std::max(ImGui::GetCursorPosY(), std::floor(top + title + style.ItemSpacing.y)));
        }
        // The lines' bottom and the padding under them, against the room the window got.
        const float needed = ImGui::GetCursorPosY() - style.ItemSpacing.y + style.WindowPadding.y;  // units
        drawn.cut += needed > ImGui::GetWindowHeight() + 0.5f;
        // The label takes no input (a drag across it turns the camera), but the pointer
        // resting on it explains its marks (ui::tooltipDue: not while a button is down, nor for
        // ever).
        const ImVec2 corner = ImGui::GetWindowPos(), extent = ImGui::GetWindowSize();
        if (!label.tooltip.empty() && !ImGui::IsAnyItemHovered() &&
            ImGui::IsMouseHoveringRect(corner, ImVec2(corner.x + extent.x, corner.y + extent.y), false) &&
            ui::tooltipDue(corner)) {
            ui::showTooltip(label.tooltip);
        }
        ImGui::End();
    }
    return drawn;
}

namespace {

glm::vec4 asVec4(const Rect& r) { return {r.min.x, r.min.y, r.size.x, r.size.y}; }

// A docked window: `rect` exactly, or its width and at most its height when `fitHeight`.
Placement docked(const Rect& rect, bool fitHeight) {
    return {rect.min, {0.0f, 0.0f}, rect.size.x, fitHeight ? rect.size.y : 0.0f, fitHeight ? 0.0f : rect.size.y};
}

}  // namespace

ToolActions drawInteractionWindows(const Session& session, const WindowLayout& layout, std::vector<ViewLabel> labels,
                                   ToolWindowsState& state) {
    ToolActions actions;
    // The sphere as seen in the view it was clicked in (side by side, each run has its own).
    const Simulation& simulation = session.run(session.selectedView());
    const physics::World& world = simulation.world();
    const RewindBuffer& timeline = session.timeline();
    TimelineInfo info;
    info.size = timeline.size();
    info.cursor = timeline.cursor();
    if (!timeline.empty()) {
        info.cursorTime = timeline.at(timeline.cursor()).time;
        info.cursorSteps = timeline.at(timeline.cursor()).stepCount;
        info.keptSeconds = timeline.at(timeline.size() - 1).time - timeline.at(0).time;
    }
    info.bytes = timeline.bytes();
    const Comparison* comparison = session.comparison();
    if (!layout.timeline.empty()) drawTimelineBar(asVec4(layout.timeline), info, comparison != nullptr, state, actions);

    const int selected = session.selected();
    const bool showsLevel = (simulation.params().shock == physics::ShockPropagation::On || simulation.overlayFlags().graph) &&
                            selected >= 0 && static_cast<std::size_t>(selected) < world.size();
    const int level = showsLevel ? simulation.contactGraph().level[std::size_t(selected)] : kLevelNotShown;
    state.inspectorHeight = 0.0f;
    const char view = comparison ? char('A' + session.selectedView()) : '\0';
    if (!layout.inspector.empty()) {
        state.inspectorHeight = drawInspector(docked(layout.inspector, true), world, selected, view,
                                              session.run(0).paused, level, state, actions);
    } else if (selected >= 0) {
        state.inspectorHeight = 10.0f * ImGui::GetFontSize();  // room for it from the next frame on
    }
    if (!layout.explainer.empty()) {
        const Session::Contacts& contacts = session.latestContacts();
        drawExplainer(docked(layout.explainer, false),
                      {selected, &contacts.events, contacts.time, contacts.steps, world.time, world.boxPlaneCount,
                       &simulation.params(), session.run(0).paused, world.recordContacts, contacts.frameRecalled,
                       &contacts.solvedTogether, view},
                      state, actions);
    }
    for (std::size_t k = 0; k < labels.size() && k < std::size_t(kMostViews); ++k) {
        labels[k].topLeft = layout.labels[k].min;
        labels[k].room = layout.labels[k].size;
    }
    drawViewLabels(labels);
    drawMessage(asVec4(Rect{layout.scene.min, layout.scene.size}), state);
    return actions;
}

}  // namespace app
