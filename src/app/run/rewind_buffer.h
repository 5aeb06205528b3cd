#pragma once
// Step back: the last few seconds of states, one per frame that changed the world,
// in a ring whose memory is capped. Restoring an entry puts back everything the
// next step depends on (positions, velocities, radii, masses, time, step count)
// plus what the views show (contact states, and the recorded contacts of one
// sphere for the explainer); the solver's next state is a function of these, so
// running on from a restored state recomputes the same future, hash for hash.
#include <cstddef>
#include <cstdint>
#include <deque>
#include <vector>

#include "physics/world.h"

namespace app {

// One stored state of a world.
struct WorldState {
    std::vector<glm::dvec3> position;  // m
    std::vector<glm::dvec3> velocity;  // m/s
    std::vector<double> radius;        // m
    std::vector<double> mass;          // kg
    std::vector<physics::ContactState> contactState;
    std::vector<physics::ContactEvent> contacts;  // of the kept sphere only (see push)
    std::vector<int> emitted;          // per emitter of the scene
    double time = 0.0;                 // s
    std::uint64_t stepCount = 0;

    std::size_t bytes() const;  // memory held, approximately
};

// Copies the world into `state`, reusing its memory; keeps the contact events that
// involve sphere `keepContactsOf` (none when -1).
void saveState(const physics::World& world, int keepContactsOf, WorldState& state);
// Puts the state back; the planes and the seed stay the world's own.
void restoreState(const WorldState& state, physics::World& world);

class RewindBuffer {
public:
    static constexpr std::size_t kDefaultFrames = 600;                      // 10 s at 60 frames/s
    static constexpr std::size_t kDefaultBytes = std::size_t(200) << 20;  // 200 MiB

    explicit RewindBuffer(std::size_t maxFrames = kDefaultFrames, std::size_t maxBytes = kDefaultBytes);

    // Appends the world's state after the cursor, dropping whatever came after the
    // cursor (a future that is about to be recomputed) and the oldest entries beyond
    // the caps; the cursor moves to it. One entry is always kept, however large.
    void push(const physics::World& world, int keepContactsOf = -1);
    void clear();

    std::size_t size() const { return states_.size(); }
    bool empty() const { return states_.empty(); }
    const WorldState& at(std::size_t index) const { return states_[index]; }

    // The entry shown: size() - 1 unless the user scrubbed back.
    std::size_t cursor() const { return cursor_; }
    bool atNewest() const { return states_.empty() || cursor_ + 1 == states_.size(); }
    // Moves the cursor (clamped) and restores that entry into `world`; false when empty.
    bool restore(std::size_t index, physics::World& world);
    // Drops the entries after the cursor: the run goes on from the cursor's state.
    void truncateAfterCursor();

    std::size_t bytes() const { return bytes_; }
    std::size_t maxFrames() const { return maxFrames_; }
    std::size_t maxBytes() const { return maxBytes_; }
    void setCaps(std::size_t maxFrames, std::size_t maxBytes);

private:
    void evict();

    std::deque<WorldState> states_;
    std::size_t cursor_ = 0;
    std::size_t bytes_ = 0;
    std::size_t maxFrames_;
    std::size_t maxBytes_;
    WorldState spare_;  // the memory of the last evicted entry, reused by the next push
};

}  // namespace app
