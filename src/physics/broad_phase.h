#pragma once
// Candidate pairs for the collision passes. Both broad phases return the same
// set in the same order: pairs (i, j), i < j, sorted by i then j, whose spheres
// are within `margin` (m) of touching.
#include <cstdint>
#include <vector>

#include "physics/params.h"
#include "physics/world.h"

namespace physics {

// Fills workspace.pairs; returns the number of distance tests made.
std::uint64_t findPairs(BroadPhase kind, const World& world, double margin, Workspace& workspace);

// The lecture's loop over every pair: the reference, O(N^2).
std::uint64_t findPairsAllPairs(const World& world, double margin, std::vector<SpherePair>& pairs);

// A uniform grid of cells at least one largest diameter (+ margin) wide, rebuilt
// by a counting sort of sphere indices by cell: O(N) for bounded density.
std::uint64_t findPairsGrid(const World& world, double margin, Workspace& workspace);

double maxRadius(const World& world);  // m, 0 for an empty world

// Whether the pair's spheres are within `margin` (m) of touching.
bool withinReach(const World& world, const SpherePair& pair, double margin);

}  // namespace physics
