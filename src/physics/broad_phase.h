#pragma once
// Candidate pairs for the collision passes. Both broad phases return the same
// set in the same order: pairs (i, j), i < j, sorted by i then j, whose spheres
// are within `margin` (m) of touching.
#include <cstdint>
#include <utility>
#include <vector>

#include "physics/params.h"
#include "physics/world.h"

namespace physics {

// Fills workspace.pairs; returns the number of distance tests made. The grid
// spreads its work over `threads` threads; the result does not depend on them.
std::uint64_t findPairs(BroadPhase kind, const World& world, double margin, Workspace& workspace,
                        int threads = 1);

// The lecture's loop over every pair: the reference, O(N^2).
std::uint64_t findPairsAllPairs(const World& world, double margin, std::vector<SpherePair>& pairs);

// A uniform grid of cells at least one largest diameter (+ margin) wide, rebuilt
// by a counting sort of sphere indices by cell: O(N) for bounded density. Each
// sphere is tested against the later spheres of its cell and the 13 neighbour cells
// after its own (half of the 26), so each pair once; a counting sort then puts the
// pairs in index order.
std::uint64_t findPairsGrid(const World& world, double margin, Workspace& workspace, int threads = 1);

// ws.moverPairs <- the pairs that the movers (ws.movers, flagged in ws.isMover) make with
// any sphere, within `margin` of touching now, each once, sorted by i then j; returns the
// distance tests made. The other spheres are looked up in the last grid build's cells
// around each mover: each must be within (the build's reach - margin) of where the build
// saw it, so that one cell around is far enough. Movers are tested with each other. The
// same pairs on any number of threads.
std::uint64_t findMoverPairs(const World& world, double margin, Workspace& ws, int threads = 1);

double maxRadius(const World& world);  // m, 0 for an empty world

// The box around the finite centres (m: its lowest and highest corners), found on
// `threads` threads; a point at 0 if none is finite.
std::pair<glm::dvec3, glm::dvec3> boundsOfCentres(const World& world, int threads = 1);

// Whether the pair's spheres are within `margin` (m) of touching.
bool withinReach(const World& world, const SpherePair& pair, double margin);

}  // namespace physics
