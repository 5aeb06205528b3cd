// The lecture's pair orders (index, reversed, shuffled) run wavefront by wavefront, so
// that the position based pair stage answers several pairs side by side and on several
// threads, with the pass order's result bit for bit (solver_stages.h's forEachWavefront).
// A pair's wavefront is the number of pairs before it, in pass order, in the longest run
// of pairs that each share a sphere with the next: one more than the latest wavefront of
// its two spheres' earlier pairs.
#include <algorithm>

#include "physics/solver_stages.h"

namespace physics {

bool passesByWavefronts(const World& world, const Params& params) {
    static const bool wideLanes = laneWidths().back() >= 4;
    const bool positionStage = params.method == Method::PositionBased || params.method == Method::Reflection;
    return wideLanes && positionStage && params.order != PairOrder::Colored && !solvesTogether(params.solver) &&
           !world.recordContacts;
}

void findWavefronts(World& world) {
    Workspace& ws = world.workspace;
    const std::vector<SpherePair>& pairs = ws.visitOrder;  // in pass order
    std::vector<std::uint32_t>& next = ws.wavefrontNext;   // per sphere: the wavefront of its next pair
    std::vector<std::uint32_t>& ofPair = ws.wavefrontOfPair;
    next.assign(world.size(), 0);
    ofPair.resize(pairs.size());
    std::uint32_t wavefronts = 0;
    for (std::size_t k = 0; k < pairs.size(); ++k) {
        const std::uint32_t w = std::max(next[pairs[k].i], next[pairs[k].j]);
        ofPair[k] = w;
        next[pairs[k].i] = next[pairs[k].j] = w + 1;
        wavefronts = std::max(wavefronts, w + 1);
    }
    // Placed by wavefront, each in pass order (a counting sort).
    ws.wavefrontStart.assign(std::size_t(wavefronts) + 1, 0);
    for (const std::uint32_t w : ofPair) ++ws.wavefrontStart[w + 1];
    for (std::uint32_t w = 0; w < wavefronts; ++w) ws.wavefrontStart[w + 1] += ws.wavefrontStart[w];
    next.assign(ws.wavefrontStart.begin(), ws.wavefrontStart.end() - 1);
    ws.wavefrontOrder.resize(pairs.size());
    for (std::size_t k = 0; k < pairs.size(); ++k) ws.wavefrontOrder[next[ofPair[k]]++] = pairs[k];
}

}  // namespace physics
