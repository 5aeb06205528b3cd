#pragma once
// The state the app owns: the scene (its parameters are what the UI edits), the
// world built from it, and the fixed-step clock. The window and the capture mode
// both advance it through advance(), so they step exactly alike.
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "app/teaching/alarms.h"
#include "app/teaching/contact_ghost.h"
#include "app/teaching/impact_report.h"
#include "app/run/history.h"
#include "app/teaching/overlays.h"
#include "app/teaching/restitution.h"
#include "physics/diagnostics.h"
#include "physics/step.h"
#include "scenes/claims.h"
#include "scenes/scene.h"

namespace app {

class Simulation {
public:
    explicit Simulation(scenes::Scene scene);

    // Rebuilds the world from the scene (same seed, same initial state).
    void restart();
    // Builds the world from `scene`, then takes both; throws (scenes::SceneError) when
    // the scene cannot be built, with the scene and the world unchanged.
    void setScene(scenes::Scene scene);
    // Another scene in its place (a file or a preset loaded), as setScene. The time scale a
    // user chose is kept; one left where the last scene opened it follows the new scene's own
    // (16-19 open in slow motion, the pile after them at 1x). It opens paused if the scene
    // says so (13, 16-20), else running: the last scene's pause is not carried over (after
    // 20, paused at its start, 21 ran frozen at t = 0, and 12's rain as an empty box).
    void openScene(scenes::Scene scene);

    // Real seconds since the last frame: scaled by timeScale, accumulated, and spent
    // in whole steps of h. At most kMaxStepsPerFrame run per call, and after the first
    // none that would end past wallBudget (as long as the last took); time beyond that is
    // dropped (the "spiral of death" guard) and behindRealTime() says so.
    // Returns the number of steps run. Does nothing while paused.
    int advance(double realSeconds);
    // Steps of h, with no wall budget, while a step ends no later than `time` (s) plus half
    // of one: a side-by-side view keeps up with the first, however much more its steps
    // cost; paused or not (the first view decides). At most kMostCatchUpSteps per call, and
    // none once a value is not finite (its alarm). Returns the steps run.
    int catchUpTo(double time);
    static constexpr int kMostCatchUpSteps = 4096;
    void singleStep();  // one step of h, paused or not

    const scenes::Scene& scene() const { return scene_; }
    scenes::Scene& editableScene() { return scene_; }  // live parameters apply at the next step
    const physics::World& world() const { return world_; }
    physics::World& editableWorld() { return world_; }
    const physics::Params& params() const { return scene_.params; }

    bool paused = false;
    double timeScale = 1.0;  // simulated seconds per real second
    // s of wall time one advance() may spend stepping, after its first step; the
    // window sets it so a slow scene runs in slow motion instead of freezing the frame.
    // Unlimited by default: capture and tests step exactly as many steps as time asks.
    double wallBudget = std::numeric_limits<double>::infinity();

    const physics::StepStats& lastStepStats() const { return lastStats_; }
    // The most work any one time step took since the restart: the global solvers' sweeps
    // and rounds, the passes until converged, the impacts, the shock sweep's levels and
    // rounds (only those fields are kept).
    const physics::StepStats& mostWorkAStep() const { return mostWork_; }
    // Whether time was dropped within the last kBehindHoldSeconds of real time: a window
    // that falls behind every other frame (the 1k pile at 1920x1080 on a software GL)
    // keeps its note shown, instead of a line that comes and goes at every frame.
    bool behindRealTime() const { return behindFor_ > 0.0; }
    const History& history() const { return history_; }
    const physics::Diagnostics& diagnostics() const { return diagnostics_; }

    // What the view shows (buildSnapshot sets it every frame): contacts are recorded
    // (world.recordContacts) only while an overlay or the restitution meter needs
    // them, trails only while shown.
    void setOverlayFlags(const OverlayFlags& flags);
    const OverlayFlags& overlayFlags() const { return overlayFlags_; }
    // The sphere the overlays and the restitution meter focus on; -1: none.
    void setSelectedSphere(int index);
    int selectedSphere() const { return selected_; }
    const OverlayState& overlays() const { return overlays_; }
    // Slide 14's contact graph of the world as it is now (its levels, as shock propagation
    // sweeps them), from the last step's candidate pairs (none after a rewind, until the
    // next step), found when first asked after the state changed: the graph overlay and
    // the inspector's level.
    const physics::ContactGraph& contactGraph() const;

    // The claims of the scene's text this run has measured so far (scenes::LiveClaims):
    // judged once their stretch of time has passed. None once the run was changed by
    // hand (a parameter, a sphere): claimsInterrupted() says so. Stepping back on the
    // timeline changes nothing the claims saw: the steps replayed come out the same.
    std::vector<scenes::ClaimCheck> measuredClaims() const { return claims_.judged(world_.time); }
    std::size_t claimsWatched() const { return claims_.size(); }  // judged or not yet
    double claimsLastMoment() const { return claims_.lastMoment(); }  // s: all judged from then on
    bool claimsInterrupted() const { return claimsInterrupted_; }
    // The text claims something, but at other settings than this run's (a restart with a
    // slider moved): none of its claims is measured.
    bool claimsForOtherSettings() const;

    const Alarms& alarms() const { return alarms_; }
    const RestitutionMeter& restitution() const { return restitution_; }
    // Slide 7's ghosts of the selected sphere's last continuous contact.
    const ContactGhosts& contactGhosts() const { return ghosts_; }
    // Slide 14: what the contacts of every step did since restart (measured up to
    // physics::kMostMirroredSpheres spheres).
    const ImpactRecord& impacts() const { return impacts_; }
    // Contacts answered as a bounce (speed above epsilon), every pass and substep, since restart.
    std::uint64_t bouncesSinceRestart() const { return bounces_; }
    // The app itself put energy in (a drag, a throw, an emitted sphere): the next
    // step's energy check is skipped instead of raising the alarm.
    void markEnergyInjected() { skipEnergyCheck_ = true; }
    // The app moved spheres by hand (a rewind, a teleport): the trails and impulses
    // start afresh and a bounce in progress is not measured. Measured ratios, the
    // bounce counter and the alarms stay until restart.
    void resetOverlays();
    // The timeline restored one of its states: the overlays start afresh (but at the newest
    // step), and the slide 14
    // marks and the measured bounces are shown as they were then (those measured later were
    // news from a future the student had stepped back from; the next step forgets them, and
    // running on measures them again).
    void restoredFromTimeline();

    static constexpr int kMaxStepsPerFrame = 32;
    static constexpr double kBehindHoldSeconds = 1.0;

private:
    void startFrom(physics::World world);  // the clock, history, alarms... start again
    void stepOnce();
    // Around every stepOnce(): false from beforeStep() when the world holds a value
    // that is not finite (then the step must not run); afterStep() feeds the alarms,
    // the overlays and the restitution meter. Both pause on a non-finite value.
    bool beforeStep();
    bool guardedStep();  // stepOnce(); false (paused) when it failed on a value not finite
    void afterStep();
    void measureNow();
    void updateRecording();
    void noteSettingsChange();

    scenes::Scene scene_;
    physics::World world_;
    double accumulator_ = 0.0;  // s of simulated time not yet stepped
    physics::StepStats lastStats_;
    physics::StepStats mostWork_;
    ImpactRecord impacts_;
    // impacts_ after each step that measured contacts, with its world time (s), oldest first:
    // what restoredFromTimeline() puts back. Past the cap every other of the older half goes.
    std::vector<std::pair<double, ImpactRecord>> impactsBefore_;
    static constexpr std::size_t kMostImpactRecordsKept = std::size_t(1) << 15;  // past the timeline's 19 200 steps
    static constexpr std::size_t kClaimsStatesKept = std::size_t(1) << 16;        // 1 MB, past the timeline's too
    double behindFor_ = 0.0;  // s of real time behindRealTime() still says so
    History history_;
    physics::Diagnostics diagnostics_;
    // The plots' "spheres in contact": the most whose contact a solver step of the frame
    // answered (a bounce's contact lasts a solver step, gone by the frame's end: counted
    // there, 02's plot of the contacts had shown 2 of 16 bounces).
    std::uint64_t mostInContact_ = 0;
    // The plot's "deepest penetration": the deepest at the end of any time step of the frame,
    // in scenes of up to kPenetrationEachStepUpTo spheres (a page drawing 30 frames a second
    // runs two steps of 1/60 s a frame, and 01's plot showed 3 of its 6 bounces' 39 %).
    static constexpr std::size_t kPenetrationEachStepUpTo = 100;
    double deepestInFrame_ = 0.0;  // of r
    OverlayFlags overlayFlags_;
    int selected_ = -1;
    OverlayState overlays_;
    Alarms alarms_;
    RestitutionMeter restitution_;
    ContactGhosts ghosts_;
    std::uint64_t bounces_ = 0;
    double energyBefore_ = 0.0;   // J, E~ before the running step
    std::size_t sizeBefore_ = 0;  // spheres before the running step
    double lastStepTime_ = 0.0;   // s, world time after the last step
    bool skipEnergyCheck_ = false;
    // The claims measured as the run goes, and the states and parameters they saw, so that
    // a change by hand between steps stops them. claimsStates_: the state after each time
    // step h they measured (World::stepCount counts solver steps: substeps a time step), the
    // world as restarted first; a stop keeps that first one, from which a change of settings
    // at t = 0 watches the claims again. A rewind keeps them: the same settings replay the
    // same steps, checked against these hashes, and the claims measure again from the newest
    // step they saw (any other state, or settings, stops them).
    struct SeenState {
        std::uint64_t solverSteps = 0;  // World::stepCount
        std::uint64_t hash = 0;         // physics::stateHash
    };
    scenes::LiveClaims claims_;
    std::vector<SeenState> claimsStates_;
    std::uint64_t claimsStartSteps_ = 0;
    std::vector<double> claimsParameters_;
    bool claimsInterrupted_ = false;
    // Whether the world now is a state the watched claims saw, at the settings they saw.
    bool claimsSawThisState(std::uint64_t state, const std::vector<double>& parameters) const;
    std::optional<std::uint64_t> claimsStateAt(std::uint64_t solverSteps) const;  // the hash seen then
    void keepClaimsState(std::uint64_t hash);  // after a new step they measured
    void stopClaims();
    // The live settings at the last step, and the last change of them since the restart:
    // the energy alarm's why when the new settings lift what the old ones let sink.
    std::vector<double> settingsAtLastStep_;
    SettingsChange settingsChange_;
    void keepMostWork();  // after a step: mostWork_ from lastStats_
    ImpactRecord impactsAt(double time) const;  // s: the last kept at or before it
    void watchClaims();  // before a step: stop the claims if the run was changed by hand
    mutable physics::ContactGraph graph_;  // contactGraph(), for the state whose hash is graphOf_
    mutable std::uint64_t graphOf_ = 0;
    mutable bool graphFound_ = false;
};

}  // namespace app
