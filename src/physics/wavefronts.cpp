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

void sortIntoWavefronts(const std::vector<SpherePair>& pairs, std::vector<std::uint32_t>& next,
                        std::vector<std::uint32_t>& ofPair, std::vector<std::uint32_t>& start,
                        std::vector<SpherePair>& order) {
    ofPair.resize(pairs.size());
    std::uint32_t wavefronts = 0;
    for (std::size_t k = 0; k < pairs.size(); ++k) {
        const std::uint32_t w = std::max(next[pairs[k].i], next[pairs[k].j]);
        ofPair[k] = w;
        next[pairs[k].i] = next[pairs[k].j] = w + 1;
        wavefronts = std::max(wavefronts, w + 1);
    }
    for (const SpherePair& pair : pairs) next[pair.i] = next[pair.j] = 0;
    // Placed by wavefront, each in pass order (a counting sort).
    start.assign(std::size_t(wavefronts) + 1, 0);
    for (const std::uint32_t w : ofPair) ++start[w + 1];
    for (std::uint32_t w = 0; w < wavefronts; ++w) start[w + 1] += start[w];
    order.resize(pairs.size());
    for (std::size_t k = 0; k < pairs.size(); ++k) order[start[ofPair[k]]++] = pairs[k];
    for (std::uint32_t w = wavefronts; w > 0; --w) start[w] = start[w - 1];  // back to where each starts
    start[0] = 0;
}

void findWavefronts(World& world) {
    Workspace& ws = world.workspace;
    ws.wavefrontNext.resize(world.size(), 0);
    sortIntoWavefronts(ws.visitOrder, ws.wavefrontNext, ws.wavefrontOfPair, ws.wavefrontStart, ws.wavefrontOrder);
}

}  // namespace physics
