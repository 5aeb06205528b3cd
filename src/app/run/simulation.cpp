#include "app/run/simulation.h"

#include <algorithm>
#include <chrono>
#include <exception>
#include <functional>
#include <utility>

#include "scenes/parameters.h"

namespace app {

Simulation::Simulation(scenes::Scene scene) : scene_(std::move(scene)) { restart(); }

void Simulation::setScene(scenes::Scene scene) {
    physics::World world = scenes::buildWorld(scene);  // throws with everything unchanged
    scene_ = std::move(scene);
    startFrom(std::move(world));
}

void Simulation::openScene(scenes::Scene scene) {
    const bool chosen = timeScale != scene_.timeScale;
    setScene(std::move(scene));
    if (!chosen) timeScale = scene_.timeScale;
    paused = scene_.opensPaused;
}

void Simulation::restart() { startFrom(scenes::buildWorld(scene_)); }

void Simulation::startFrom(physics::World world) {
    world_ = std::move(world);
    accumulator_ = 0.0;
    lastStats_ = {};
    mostWork_ = {};
    impacts_ = {};
    impactsBefore_.clear();
    behindFor_ = 0.0;
    history_.clear();
    mostInContact_ = 0;
    deepestInFrame_ = 0.0;
    overlays_.reset();
    ghosts_.reset();
    alarms_.clear();
    restitution_.reset();
    bounces_ = 0;
    skipEnergyCheck_ = false;
    lastStepTime_ = world_.time;
    claims_ = scenes::LiveClaims(scene_);
    claimsInterrupted_ = false;
    claimsParameters_ = scenes::tableValues(scene_);
    settingsAtLastStep_.clear();
    settingsChange_ = {};
    claims_.observe(world_);
    claimsStates_.assign(1, SeenState{world_.stepCount, physics::stateHash(world_)});
    claimsStartSteps_ = world_.stepCount;
    updateRecording();
    measureNow();
}

bool Simulation::claimsForOtherSettings() const {
    const bool claimed = std::any_of(scene_.claims.begin(), scene_.claims.end(), [](const scenes::Claim& c) {
        return c.in == scenes::ClaimSource::Description && !c.ratioTo;
    });
    return claimed && claims_.empty() && !claimsInterrupted_;
}

std::optional<std::uint64_t> Simulation::claimsStateAt(std::uint64_t solverSteps) const {
    const auto at = std::lower_bound(claimsStates_.begin(), claimsStates_.end(), solverSteps,
                                     [](const SeenState& seen, std::uint64_t s) { return seen.solverSteps < s; });
    if (at == claimsStates_.end() || at->solverSteps != solverSteps) return std::nullopt;
    return at->hash;
}

bool Simulation::claimsSawThisState(std::uint64_t state, const std::vector<double>& parameters) const {
    return !claims_.empty() && parameters == claimsParameters_ && claimsStateAt(world_.stepCount) == state;
}

// The states are kept as far back as the timeline can go and further (kClaimsStatesKept
// steps); past that, every other of the older half goes (a rewind to a step no longer kept
// stops the claims), the first always kept.
void Simulation::keepClaimsState(std::uint64_t hash) {
    if (claimsStates_.size() >= kClaimsStatesKept) {
        const std::size_t half = claimsStates_.size() / 2;
        std::size_t kept = 1;
        for (std::size_t k = 1; k < half; k += 2) claimsStates_[kept++] = claimsStates_[k];
        claimsStates_.erase(claimsStates_.begin() + std::ptrdiff_t(kept), claimsStates_.begin() + std::ptrdiff_t(half));
    }
    claimsStates_.push_back({world_.stepCount, hash});
}

void Simulation::stopClaims() {
    claims_ = {};
    claimsStates_.resize(1);  // the start: a change of settings there watches them again
    claimsInterrupted_ = true;
}

void Simulation::watchClaims() {
    const bool atStart = world_.stepCount == claimsStartSteps_;
    if (claims_.empty() && !atStart) return;  // nothing to stop, nothing to start: no hash of every sphere
    const std::uint64_t state = physics::stateHash(world_);
    std::vector<double> parameters = scenes::tableValues(scene_);
    if (claimsSawThisState(state, parameters)) return;  // the newest step, or one the timeline went back to
    // Settings changed before the first step (a text's "switch response to lecture", done
    // at t = 0): that variant's claims are watched from the start, not stopped.
    if (atStart && !claimsStates_.empty() && state == claimsStates_[0].hash) {
        claims_ = scenes::LiveClaims(scene_);
        claimsInterrupted_ = false;
        claimsParameters_ = std::move(parameters);
        claims_.observe(world_);
        claimsStates_.assign(1, SeenState{world_.stepCount, state});
        return;
    }
    if (!claims_.empty()) stopClaims();
}

const physics::ContactGraph& Simulation::contactGraph() const {
    std::uint64_t state = physics::stateHash(world_) ^ world_.stepCount;  // radii too: the inspector edits them
    for (const double r : world_.radius) state = state * 1099511628211ull ^ std::hash<double>{}(r);
    if (!graphFound_ || state != graphOf_) {
        physics::findContactGraph(world_, scene_.params.order, graph_);
        graphOf_ = state;
        graphFound_ = true;
    }
    return graph_;
}

void Simulation::restoredFromTimeline() {
    // A frame before the newest step: the trails and the bounce in flight were the later state's.
    if (world_.time < lastStepTime_) resetOverlays();
    restitution_.showAt(world_.time);
    impacts_ = impactsAt(world_.time);
}

ImpactRecord Simulation::impactsAt(double time) const {
    const auto after = std::upper_bound(impactsBefore_.begin(), impactsBefore_.end(), time,
                                        [](double t, const std::pair<double, ImpactRecord>& kept) { return t < kept.first; });
    return after == impactsBefore_.begin() ? ImpactRecord{} : std::prev(after)->second;
}

void Simulation::resetOverlays() {
    overlays_.reset();
    ghosts_.reset();
    restitution_.forgetFlights();
    skipEnergyCheck_ = true;
}

void Simulation::setOverlayFlags(const OverlayFlags& flags) {
    overlayFlags_ = flags;
    updateRecording();
}

void Simulation::setSelectedSphere(int index) {
    selected_ = index;
    updateRecording();
}

void Simulation::updateRecording() {
    const bool measuring = !measuredSpheres(world_, selected_).empty();
    world_.recordContacts =
        (overlayFlags_.needsContacts() || measuring) && world_.size() <= kMaxRecordSpheres;
    if (!world_.recordContacts) world_.contacts.clear();
    // The properties' marks up to kMostMirroredSpheres; beyond, only for a claim of the text.
    world_.measureImpacts = world_.size() <= physics::kMostMirroredSpheres || claims_.needsImpacts();
}

int Simulation::advance(double realSeconds) {
    if (paused) {
        behindFor_ = 0.0;  // nothing is behind while paused
        return 0;
    }
    // A step is due when the accumulator holds h up to rounding: without the slack,
    // frames of exactly h would now and then run no step and then two.
    const double h = scene_.params.timeStep;
    const double due = h * (1.0 - 1e-9);
    accumulator_ += realSeconds * timeScale;
    const auto start = std::chrono::steady_clock::now();
    int steps = 0;
    double lastStep = 0.0;  // s of wall time the last step took: what the next may take
    while (accumulator_ >= due && steps < kMaxStepsPerFrame) {
        const auto stepStart = std::chrono::steady_clock::now();
        if (!beforeStep() || !guardedStep()) break;
        afterStep();
        accumulator_ -= h;
        ++steps;
        if (paused) break;  // an alarm stopped it
        const auto now = std::chrono::steady_clock::now();
        lastStep = std::chrono::duration<double>(now - stepStart).count();
        if (std::chrono::duration<double>(now - start).count() + lastStep > wallBudget) break;
    }
    const bool behind = !paused && accumulator_ >= due;
    behindFor_ = behind ? kBehindHoldSeconds : paused ? 0.0 : std::max(0.0, behindFor_ - realSeconds);
    if (behind || paused) accumulator_ = 0.0;
    if (steps > 0) measureNow();
    return steps;
}

int Simulation::catchUpTo(double time) {
    const double h = scene_.params.timeStep;
    int steps = 0;
    while (world_.time + 0.5 * h <= time && steps < kMostCatchUpSteps) {
        if (!beforeStep() || !guardedStep()) break;
        afterStep();
        ++steps;
    }
    accumulator_ = 0.0;
    behindFor_ = 0.0;
    if (steps > 0) measureNow();
    return steps;
}

void Simulation::singleStep() {
    if (beforeStep() && guardedStep()) afterStep();
    measureNow();
}

bool Simulation::guardedStep() {
    try {
        stepOnce();
        return true;
    } catch (const std::exception&) {
        // A value that turned NaN within the step's first substeps makes the broad
        // phase of the next one fail (it cannot size a grid around it): say which.
        if (alarms_.checkFinite(world_)) throw;
        paused = true;
        return false;
    }
}

bool Simulation::beforeStep() {
    updateRecording();  // the sphere count may have changed
    if (!alarms_.checkFinite(world_)) {
        paused = true;
        return false;
    }
    // The clock went back (a rewind restored an earlier state): trails and impulses
    // drawn from the later state would no longer match it.
    if (world_.time < lastStepTime_) {
        overlays_.reset();
        ghosts_.reset();
        restitution_.forgetFlights();
        restitution_.forgetAfter(world_.time);
        impacts_ = impactsAt(world_.time);
        while (!impactsBefore_.empty() && impactsBefore_.back().first > world_.time) impactsBefore_.pop_back();
    }
    energyBefore_ = physics::modifiedEnergy(world_, scene_.params);
    sizeBefore_ = world_.size();
    watchClaims();
    noteSettingsChange();
    return true;
}

void Simulation::noteSettingsChange() {
    std::vector<double> now = scenes::tableValues(scene_);
    if (!settingsAtLastStep_.empty() && now != settingsAtLastStep_) {
        settingsChange_ = {world_.time, ""};
        const std::vector<scenes::Parameter>& table = scenes::parameterTable();
        for (std::size_t k = 0; k < table.size() && k < now.size(); ++k) {
            if (now[k] == settingsAtLastStep_[k]) continue;
            if (!settingsChange_.what.empty()) settingsChange_.what += ", ";
            settingsChange_.what += std::string(table[k].name) + " = " + scenes::formatValue(table[k], scene_);
        }
    }
    settingsAtLastStep_ = std::move(now);
}

void Simulation::afterStep() {
    if (!claims_.empty()) {
        // A new step is measured; a step the claims saw before the timeline went back must
        // come out as it did then, else the run is not the one they measured.
        const std::uint64_t state = physics::stateHash(world_);
        if (world_.stepCount > claimsStates_.back().solverSteps) {
            claims_.observe(world_, &lastStats_);
            keepClaimsState(state);
        } else if (claimsStateAt(world_.stepCount) != state) {
            stopClaims();
        }
    }
    bounces_ += lastStats_.collisions;
    mostInContact_ = std::max(mostInContact_, lastStats_.mostSpheresInContact);
    if (world_.size() <= kPenetrationEachStepUpTo) {
        deepestInFrame_ = std::max(deepestInFrame_, physics::measure(world_, scene_.params).maxPenetration);
    }
    if (lastStats_.impacts.contacts > 0) {
        impacts_.add(lastStats_.impacts);
        if (impactsBefore_.size() == kMostImpactRecordsKept) {
            constexpr std::size_t kQuarter = kMostImpactRecordsKept / 4;
            for (std::size_t k = 0; k < kQuarter; ++k) impactsBefore_[k] = impactsBefore_[2 * k];
            impactsBefore_.erase(impactsBefore_.begin() + kQuarter, impactsBefore_.begin() + 2 * kQuarter);
        }
        impactsBefore_.emplace_back(world_.time, impacts_);
    }
    keepMostWork();
    const double energyAfter = physics::modifiedEnergy(world_, scene_.params);
    // A sphere added or removed, or energy the app put in, is not the solver's doing.
    const bool checkEnergy = !skipEnergyCheck_ && world_.size() == sizeBefore_;
    skipEnergyCheck_ = false;
    alarms_.checkEvents(lastStats_, scene_.params, world_.time);
    if (!alarms_.checkStep(world_, scene_.params, checkEnergy ? energyBefore_ : energyAfter, energyAfter, settingsChange_)) {
        paused = true;
        return;
    }
    overlays_.afterStep(world_, overlayFlags_, selected_);
    restitution_.afterStep(world_, scene_.params, selected_);
    ghosts_.afterStep(world_, scene_.params, selected_);
    lastStepTime_ = world_.time;
}

void Simulation::keepMostWork() {
    const physics::StepStats& s = lastStats_;
    physics::StepStats& most = mostWork_;
    most.lcpSweeps = std::max(most.lcpSweeps, s.lcpSweeps);
    most.reflectionRounds = std::max(most.reflectionRounds, s.reflectionRounds);
    most.passesUsed = std::max(most.passesUsed, s.passesUsed);
    most.events = std::max(most.events, s.events);
    most.shockLevels = std::max(most.shockLevels, s.shockLevels);
    most.shockRounds = std::max(most.shockRounds, s.shockRounds);
}

void Simulation::stepOnce() {
    lastStats_ = physics::step(world_, scene_.params);
    scenes::emitDue(scene_, world_);  // the course's emitter, after the step as in simulate
}

void Simulation::measureNow() {
    // The broad phase cannot place a position that is not finite: measure nothing then.
    if (!alarms_.checkFinite(world_)) {
        paused = true;
        return;
    }
    diagnostics_ = physics::measure(world_, scene_.params);
    alarms_.checkMeasurement(diagnostics_, scene_.params, world_.time);
    alarms_.checkRest(world_, scene_.params);
    physics::Diagnostics sampled = diagnostics_;
    sampled.maxPenetration = std::max(sampled.maxPenetration, deepestInFrame_);
    history_.add(world_.time, sampled, mostInContact_, bounces_);
    mostInContact_ = 0;
    deepestInFrame_ = 0.0;
}

}  // namespace app
