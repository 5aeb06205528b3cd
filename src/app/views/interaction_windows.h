#pragma once
// The ImGui windows of the interaction features, drawn over the scene: the
// timeline bar at the bottom (scrub back, shoot, side by side), the inspector of
// the selected sphere, "explain this contact", and the labels of the two views
// side by side. Like ui::drawControlPanel they read plain data and return what the
// app must do; they never change the world themselves. Rectangles are in ImGui
// units (window coordinates, top-left origin): x, y, width, height.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/gtc/type_precision.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "app/run/interaction.h"
#include "app/views/window_layout.h"
#include "physics/params.h"
#include "physics/world.h"

namespace app {

class Session;

// What the windows keep between frames.
struct ToolWindowsState {
    bool explainer = false;             // "Explain this contact" is open
    int explainIndex = 0;               // which of the selected sphere's contacts
    float shootSpeed = 10.0f;           // m/s
    std::string compareText = "method=velocity";  // name=value[,name=value] for the second view
    std::string message;                // the last result or refusal
    std::string inspectorRefusal;       // why the inspector's last edit was refused, shown under its fields
    int refusedSphere = -1;             // the sphere it was about
    float inspectorHeight = 0.0f;       // ImGui units, as last drawn (the layout keeps room for it)
};

struct ToolActions {
    bool deselect = false;
    bool edited = false;       // `fields` were edited: put them into the world
    SphereFields fields;
    bool shoot = false;
    bool toggleCompare = false;
    bool applyCompare = false;  // Enter in the overrides' field
    bool toggleExplainer = false;
    bool scrub = false;        // restore timeline entry `scrubTo`
    std::size_t scrubTo = 0;
};

// The rewind buffer as the timeline shows it.
struct TimelineInfo {
    std::size_t size = 0;     // entries kept
    std::size_t cursor = 0;   // the entry shown
    double cursorTime = 0.0;  // s
    std::uint64_t cursorSteps = 0;
    double keptSeconds = 0.0;  // s of simulated time between the oldest and newest entry
    std::size_t bytes = 0;
};

// Height (ImGui units) of the timeline bar: two rows, whatever it shows.
float timelineBarHeight();

// The bar, filling `bar` (x, y, width, height).
void drawTimelineBar(const glm::vec4& bar, const TimelineInfo& timeline, bool compareOn, ToolWindowsState& state,
                     ToolActions& actions);

// The last result or refusal (state.message), centred at the bottom of `scene`, on
// top of the other windows: the views keep their size when it comes and goes.
void drawMessage(const glm::vec4& scene, const ToolWindowsState& state);

// Where a window goes: `pivot` of it (0..1 each way) at `position` (ImGui units).
struct Placement {
    glm::vec2 position{0.0f};
    glm::vec2 pivot{0.0f};
    float width = 0.0f;      // ImGui units
    float maxHeight = 0.0f;  // ImGui units; 0: no limit (the rest scrolls)
    float height = 0.0f;     // ImGui units; 0: as tall as its content (up to maxHeight)
};

// The selected sphere's p, v, r, m, editable while paused, and its level in slide 14's
// contact graph (`graphLevel`: -1 reaches no plane; kLevelNotShown: not shown); `view`
// names the view side by side whose sphere it is ('\0': one view). Returns the height its
// content needs (ImGui units), 0 when nothing was drawn.
constexpr int kLevelNotShown = -2;
float drawInspector(const Placement& placement, const physics::World& world, int selected, char view, bool paused,
                    int graphLevel, ToolWindowsState& state, ToolActions& actions);

// An inspector field's value after Enter: `typed`, the number its text reads, or `value` where
// that is the number `value` is shown as in `format` (Enter on a field left as shown, or its
// digits typed again), so that such an Enter changes nothing: it had rounded p to the
// millimetre, cut a tiny negative to 0, and stopped the text's claims as an edit.
double valueAfterEnter(double typed, double value, const char* format);

// What the explainer explains: the selected sphere's latest contact responses.
struct ExplainerInput {
    int selected = -1;
    const std::vector<physics::ContactEvent>* events = nullptr;  // of that step
    double eventTime = 0.0;  // s, the world's time after that step
    std::uint64_t eventSteps = 0;
    double now = 0.0;        // s, the world's time now
    int boxPlaneCount = 0;
    const physics::Params* params = nullptr;
    bool paused = false;
    bool recording = true;  // world.recordContacts: Simulation records while a sphere is selected
    bool frameRecalled = false;  // Session::Contacts': the frame shown was run again at the selection
    const std::vector<physics::ContactEvent>* solvedTogether = nullptr;  // Session::Contacts'
    char view = '\0';  // side by side: the view whose sphere it explains ('A'...), else '\0'
};

// The other sphere of the contact the explainer shows (ringed in magenta), or -1:
// the explainer closed, nothing recorded, or a plane.
int explainedPartner(const Session& session, const ToolWindowsState& state);

// "Explain this contact": the slides' formulas with the numbers of one of the events.
void drawExplainer(const Placement& placement, const ExplainerInput& input, ToolWindowsState& state,
                   ToolActions& actions);


// A view's label: its title and readouts, in the place the layout keeps for it.
struct ViewLabel {
    glm::vec2 topLeft{0.0f};  // ImGui units
    glm::vec2 room{1e6f};     // ImGui units: the place kept for it; longer lines wrap
    std::vector<std::string> lines;  // the first is the title
    glm::u8vec4 color{255, 255, 255, 255};  // of the title
    std::string tooltip;  // shown while the pointer rests on it ("": none)
};
// A label's size with the current font (ImGui units).
glm::vec2 viewLabelSize(const ViewLabel& label);
// The widest of `labels` unwrapped, rounded up to whole font sizes so that changing
// digits do not move the views; the tallest when laid `width` wide, its lines wrapped a
// font narrower (so that changing digits do not wrap one more) and every title as many
// rows as the tallest title.
float labelsWidth(const std::vector<ViewLabel>& labels);
float labelsHeight(const std::vector<ViewLabel>& labels, float width);
// What drawing the labels left out: labels cut (their lines taller than their room), and
// labels with a word broken inside (wider than a line even in the smallest type).
struct LabelsDrawn {
    int cut = 0;
    int wordsBroken = 0;
};
// Draws each label at its place, within its room.
LabelsDrawn drawViewLabels(const std::vector<ViewLabel>& labels);

// All of the above for the session's state, where `layout` puts them: the timeline
// bar, the inspector and the explainer of the selected sphere in the dock, the views'
// `labels` side by side (comparisonLabels; empty for one view), and the message.
ToolActions drawInteractionWindows(const Session& session, const WindowLayout& layout, std::vector<ViewLabel> labels,
                                   ToolWindowsState& state);

}  // namespace app
