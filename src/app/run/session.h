#pragma once
// What the window steps and edits: the primary Simulation, optionally up to three more
// side by side (Comparison), a rewind buffer for each, and the selected sphere.
// Every edit (drag, throw, shot, inspector) goes to every run, so that the views
// stay comparable; every frame that changes a world is kept for stepping back.
// No window, no ImGui: the tests drive it as the window does.
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "app/run/comparison.h"
#include "app/run/interaction.h"
#include "app/run/rewind_buffer.h"
#include "app/run/simulation.h"
#include "render/frame_snapshot.h"
#include "scenes/parameters.h"

namespace app {

class Session {
public:
    // `timelineBytes`: the memory the step-back timeline may keep (the browser, which
    // has no timeline yet, keeps little).
    explicit Session(Simulation& primary, std::size_t timelineBytes = RewindBuffer::kDefaultBytes);

    // ---- the runs: 1, or 2 to kMostViews side by side ----
    int runCount() const { return comparison_ ? 1 + comparison_->count() : 1; }
    Simulation& run(int k) { return k > 0 && comparison_ ? comparison_->simulation(k - 1) : primary_; }
    const Simulation& run(int k) const { return k > 0 && comparison_ ? comparison_->simulation(k - 1) : primary_; }
    const Comparison* comparison() const { return comparison_.get(); }
    // Side by side with the overrides ("name=value[,name=value]" each; a name with
    // several values, a view each: overrideVariants): every run restarts from the
    // scene's initial state. Returns "" or why not (the runs are then unchanged).
    std::string startComparison(const std::vector<std::string>& lists);
    void stopComparison();
    // R: every run from its start again, paused where the scene opens paused (13, 16-20: a
    // replay would show the impact before the class looks).
    void restartAsOpened();

    // ---- stepping: both runs, the same real seconds; frames that stepped are kept ----
    int advance(double realSeconds);
    void singleStep();
    // Both runs from the scene; the timeline starts again. Side by side stops when its
    // overrides no longer apply to the scene (takeNote() says so).
    void restart();
    // After the primary's setScene (which restarted it): the same, no selection. A scene
    // with a "compare" key opens side by side with it; side by side that the previous
    // scene asked for ends with it.
    void sceneChanged();
    // What happened that the user did not ask for (side by side stopped), once; or "".
    std::string takeNote() { return std::move(note_); }

    // ---- the panel's edits ----
    // Sets parameter `p` of the primary's scene to `value` as the panel does: a Live
    // one at the next step, a Restart one by restarting. A value the table refuses, or
    // one whose scene cannot be built (a count the region cannot hold, a radius too
    // large for it), is refused: the scene, the worlds and the timeline stay as they
    // were. Returns "" or the one-line reason.
    std::string setParameter(const scenes::Parameter& p, double value);

    // ---- the selected sphere (-1: none) ----
    int selected() const { return selected_; }
    // Selects sphere `index` as seen in run `view` (the view clicked): the inspector and the
    // explanation show that run's sphere and contacts (run 0 once that run is gone).
    void select(int index, int view = 0);
    int selectedView() const { return selectedView_ < runCount() ? selectedView_ : 0; }
    // Puts the fields into every run (sphere `selected()`), and keeps the new state.
    // Refused, with every run unchanged, when checkSphereFields refuses them: "" or
    // the one-line reason.
    std::string editSelected(const SphereFields& fields);

    // ---- mouse: grab `index` of run `view` where `ray` meets the plane through its
    // centre facing the camera; drag it (every run); throw it on release ----
    bool beginDrag(int view, std::size_t index, const render::Ray& ray, const glm::vec3& facing, double time);
    void dragTo(const render::Ray& ray, double time);
    glm::dvec3 endDrag();  // m/s, the velocity it was thrown with
    bool dragging() const { return drag_.active(); }
    int dragView() const { return dragView_; }  // the run whose view the drag began in
    int draggedSphere() const { return drag_.active() ? static_cast<int>(drag_.index()) : -1; }

    // A new sphere along `aim` at `speed` (m/s) in every run, selected; "" or why not.
    std::string shoot(const render::Ray& aim, double speed);

    // ---- stepping back ----
    const RewindBuffer& timeline() const { return rewind_[0]; }
    void scrubTo(std::size_t index);  // pauses, restores that frame in every run
    void stepBack() { scrubTo(timeline().cursor() > 0 ? timeline().cursor() - 1 : 0); }
    void stepForward() { scrubTo(timeline().cursor() + 1); }

    // ---- for the views ----
    // The selected sphere's contact responses of the latest step that had any (in run selectedView()):
    // a bounce lasts one step, so the explainer keeps showing it after it. Empty when it
    // had none in the frame shown when it was selected (that frame run again from the
    // timeline, contacts recorded) nor since (Simulation records contacts while a sphere
    // is selected).
    struct Contacts {
        std::vector<physics::ContactEvent> events;
        // Slide 14's global solvers: every contact of that step they solved (its impulse
        // in solvedImpulse), for "solved together with" (at most kMostSolvedTogether).
        std::vector<physics::ContactEvent> solvedTogether;
        double time = 0.0;  // s, the world's time after that step
        std::uint64_t steps = 0;
        // The frame shown when the sphere was selected was run again (recallContacts): an
        // empty list then means it touched nothing in that frame.
        bool frameRecalled = false;
    };
    const Contacts& latestContacts() const { return latest_; }
    // While on (the explainer is open), advance() runs the frame's steps one call at a
    // time, so that a contact in any step of a frame is caught, not only in its last.
    void setCatchEveryStep(bool on) { catchEveryStep_ = on; }
    // The readouts of run k, measured again when the world was edited since its last step.
    physics::Diagnostics diagnostics(int k) const;
    // A ring around the selected sphere facing the camera (yellow), one around
    // `partner` (magenta: the other sphere of the contact explained; -1 none) and,
    // while dragging, a line down to the floor, appended to `snapshot` of run k.
    void appendSelection(int k, const render::Camera& camera, render::FrameSnapshot& snapshot,
                         int partner = -1) const;

private:
    void startAgain();  // the comparison from the primary's scene, an empty timeline
    void noteContacts();  // latest_ from run selectedView()'s world, after a step
    void recallContacts();  // latest_ for a sphere just selected: the frame shown, run again
    void keep();  // pushes every run's state into its rewind buffer
    void prepareToStep();
    void edited();   // touched(), then kept for stepping back
    void touched();  // the worlds changed outside a step
    template <class Edit>
    void forEachWorld(Edit edit);

    Simulation& primary_;
    std::unique_ptr<Comparison> comparison_;
    bool comparisonFromScene_ = false;  // started by the scene's "compare" key
    std::vector<RewindBuffer> rewind_;  // one per run
    std::size_t timelineBytes_;         // for one or two runs; more share twice as much
    int selected_ = -1;
    int selectedView_ = 0;
    SphereDrag drag_;
    Contacts latest_;
    bool catchEveryStep_ = false;
    std::string note_;
    int dragView_ = 0;
    std::vector<char> stale_;  // per run: edited since the last step, Simulation::diagnostics() is old
    void resizeRuns();         // one rewind buffer and stale flag per run
};

}  // namespace app
