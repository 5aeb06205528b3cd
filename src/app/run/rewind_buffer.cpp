#include "app/run/rewind_buffer.h"

#include <algorithm>
#include <utility>

namespace app {

std::size_t WorldState::bytes() const {
    return sizeof(WorldState) + position.capacity() * sizeof(glm::dvec3) + velocity.capacity() * sizeof(glm::dvec3) +
           radius.capacity() * sizeof(double) + mass.capacity() * sizeof(double) +
           contactState.capacity() * sizeof(physics::ContactState) +
           contacts.capacity() * sizeof(physics::ContactEvent);
}

void saveState(const physics::World& world, int keepContactsOf, WorldState& state) {
    state.position.assign(world.position.begin(), world.position.end());
    state.velocity.assign(world.velocity.begin(), world.velocity.end());
    state.radius.assign(world.radius.begin(), world.radius.end());
    state.mass.assign(world.mass.begin(), world.mass.end());
    state.contactState.assign(world.contactState.begin(), world.contactState.end());
    state.contacts.clear();
    if (keepContactsOf >= 0) {
        for (const physics::ContactEvent& event : world.contacts) {
            if (static_cast<int>(event.i) == keepContactsOf || event.other == keepContactsOf) {
                state.contacts.push_back(event);
            }
        }
    }
    state.emitted = world.emitted;
    state.time = world.time;
    state.stepCount = world.stepCount;
}

void restoreState(const WorldState& state, physics::World& world) {
    world.position = state.position;
    world.velocity = state.velocity;
    world.radius = state.radius;
    world.mass = state.mass;
    world.contactState = state.contactState;
    world.contacts = state.contacts;
    world.emitted = state.emitted;
    world.time = state.time;
    world.stepCount = state.stepCount;
    world.workspace.cached = false;  // a fresh build gives the same pairs as the cache would
    world.workspace.visitOrder.clear();  // the last step's pairs: not this state's (the contact graph reads them)
}

RewindBuffer::RewindBuffer(std::size_t maxFrames, std::size_t maxBytes)
    : maxFrames_(std::max<std::size_t>(maxFrames, 1)), maxBytes_(maxBytes) {}

void RewindBuffer::setCaps(std::size_t maxFrames, std::size_t maxBytes) {
    maxFrames_ = std::max<std::size_t>(maxFrames, 1);
    maxBytes_ = maxBytes;
    evict();
}

void RewindBuffer::clear() {
    states_.clear();
    cursor_ = 0;
    bytes_ = 0;
}

void RewindBuffer::truncateAfterCursor() {
    while (!atNewest()) {
        bytes_ -= states_.back().bytes();
        states_.pop_back();
    }
}

void RewindBuffer::push(const physics::World& world, int keepContactsOf) {
    truncateAfterCursor();
    WorldState state = std::move(spare_);
    spare_ = WorldState();
    saveState(world, keepContactsOf, state);
    bytes_ += state.bytes();
    states_.push_back(std::move(state));
    cursor_ = states_.size() - 1;
    evict();
}

void RewindBuffer::evict() {
    while (states_.size() > 1 && (states_.size() > maxFrames_ || bytes_ > maxBytes_)) {
        bytes_ -= states_.front().bytes();
        spare_ = std::move(states_.front());
        states_.pop_front();
        cursor_ = cursor_ > 0 ? cursor_ - 1 : 0;
    }
}

bool RewindBuffer::restore(std::size_t index, physics::World& world) {
    if (states_.empty()) return false;
    cursor_ = std::min(index, states_.size() - 1);
    restoreState(states_[cursor_], world);
    return true;
}

}  // namespace app
