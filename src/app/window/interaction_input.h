#pragma once
// The window's interaction controls, between ImGui's input and the Session: a left
// click selects the sphere under the mouse, Ctrl + left drag grabs one and throws it
// on release, F shoots, V toggles side by side, E the explainer; the tool windows'
// actions; the last message. The camera's own mouse controls stay in the window.
#include <string>

#include "app/views/interaction_windows.h"
#include "app/run/session.h"
#include "app/views/window_layout.h"
#include "render/camera.h"

namespace app {

class InteractionInput {
public:
    static constexpr double kMessageSeconds = 8.0;  // s a result or refusal stays on screen
    static constexpr double kBriefMessageSeconds = 2.0;  // s a confirmation stays (F12's)
    static constexpr float kClickPixels = 5.0f;     // a press that moves less is a click (select)

    explicit InteractionInput(Session& session) : session_(session), suggested_(tools_.compareText) {
        suggestOverrides();
    }

    ToolWindowsState& tools() { return tools_; }
    const ToolWindowsState& tools() const { return tools_; }

    // ImGui's mouse this frame (window time `now`, s). True when it was used here (a
    // grab, its drag, its release): the camera must then not move.
    bool handleMouse(const ViewLayout& views, const render::Camera& camera, double now);

    // F: through the mouse pointer when it is over a view; the button: along the view direction.
    void shoot(const ViewLayout& views, const render::Camera& camera, bool throughMouse, double now);
    // V: side by side on or off (both restart); true when the views changed shape.
    bool toggleCompare(double now);
    // Side by side with the overrides' field, on or again; says what the views differ
    // in, or that they do not. False when refused (the runs stay as they were).
    bool applyCompare(double now);
    // E: the explainer, for the selected sphere; with none selected, says to click one.
    void toggleExplainer(double now = 0.0);
    // Esc (after the presentation layout): closes the explainer, else deselects the
    // sphere. False when nothing was open: Esc never ends the session.
    bool backOut();
    // The tool windows' actions; true when the views changed shape.
    bool apply(const ToolActions& actions, const ViewLayout& views, const render::Camera& camera, double now);

    // Once per frame: forgets an old message; true once after side by side started
    // (the views' labels carry the readouts: the app folds its readouts window).
    void expireMessage(double now);
    bool takeFoldReadouts();

    // "name=value,..." given on the command line: side by side from the start.
    std::string startComparison(const std::vector<std::string>& lists);
    // The first scene opened: side by side with `asked` (--compare; "" or why it is refused),
    // or else with the scene's own "compare", as a preset opened later does (so that the next
    // preset stops it: 14's three views had stayed on 13, started from the command line).
    std::string openFirstScene(const std::vector<std::string>& asked);
    // After the primary's scene changed: Session::sceneChanged, and the bar shows the
    // overrides of the side by side the new scene opens with, if any (suggestOverrides).
    void sceneChanged();
    // The bar's overrides, while the user has written none: suggestedOverrides(scene).
    void suggestOverrides();

    // The message centred above the timeline bar, for a few seconds from `now`.
    void say(double now, const char* format, ...) __attribute__((format(printf, 3, 4)));
    // A confirmation, over the views for kBriefMessageSeconds only: it lies over the lower
    // views' spheres (F12's, in front of a class, stayed 8 s, in the next screenshot too).
    void sayBriefly(double now, const std::string& text);

private:

    Session& session_;
    ToolWindowsState tools_;
    std::string suggested_;       // the bar's last offer: while it shows it, the next scene's replaces it
    bool comparingSuggestion_ = false;  // side by side with the bar's offer: the next scene's replaces it
    double messageTime_ = 0.0;    // s, window time of tools_.message
    double messageSeconds_ = kMessageSeconds;  // s it stays
    bool pressInScene_ = false;   // the left button went down over the scene, not over a window
    int dragView_ = 0;
    bool foldReadouts_ = false;
};

}  // namespace app
