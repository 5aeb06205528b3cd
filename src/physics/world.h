#pragma once
// The state the solver advances: spheres stored as arrays (one entry per
// sphere, index = id) and the planes that bound them.
#include <cstdint>
#include <vector>

#include <glm/common.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "physics/automatic_threads.h"
#include "physics/impact_properties.h"

namespace physics {

// A plane is a point and a unit normal pointing into the free side (slide 3). With a
// thickness it is a thin wall instead, free on both sides: a sphere meets the face on
// its centre's side, so a centre that jumps past the middle in one step has tunnelled.
struct Plane {
    glm::dvec3 point{0.0};   // m
    glm::dvec3 normal{0.0, 0.0, 1.0};  // unit
    double thickness = 0.0;  // m; 0: a half-space (everything behind it is solid)
};

// The face of `plane` that a sphere centred at p meets: the plane itself, or for a
// thin wall the face on p's side, its normal pointing towards p. (Inline: it runs
// for every sphere and plane in every pass.)
inline Plane faceFor(const Plane& plane, const glm::dvec3& p) {
    if (plane.thickness <= 0.0) return plane;
    const glm::dvec3 d = p - plane.point;
    const double side = d.x * plane.normal.x + d.y * plane.normal.y + d.z * plane.normal.z >= 0.0 ? 1.0 : -1.0;
    return {plane.point + (0.5 * plane.thickness * side) * plane.normal, side * plane.normal, 0.0};
}

// What happened to a sphere in the last solver step, for colouring and teaching.
enum class ContactState : std::uint8_t {
    Free,       // touched nothing
    Colliding,  // bounced: relative normal speed above epsilon
    Static,     // static contact: relative normal speed at or below epsilon (slide 13)
};

// One velocity response, as the slides compute it, for overlays and "explain this
// contact". Recorded only while World::recordContacts is on.
struct ContactEvent {
    std::uint32_t i = 0;         // the sphere
    std::int32_t other = -1;     // the other sphere's index, or -1 - (plane index) for a plane
    int pass = 0;                // which of the K passes; K: shock propagation's sweep, after them
    bool bounce = false;         // true: relative normal speed above epsilon; false: static contact
    glm::dvec3 normal{0.0};      // unit: u (from the other sphere to i) or the plane's n
    glm::dvec3 point{0.0};       // m, on i's surface towards the other
    double depth = 0.0;          // m, penetration when detected
    glm::dvec3 velocityBefore[2]{};  // m/s, of i and of the other sphere (zero for a plane)
    glm::dvec3 velocityAfter[2]{};   // m/s
    double massOf[2]{0.0, 0.0};      // kg (0 for a plane; infinite for a frozen sphere of the shock sweep)
    // s: the continuous method's instant of contact within its solver step (the
    // velocities are those at that instant); -1 for the other methods.
    double timeOfImpact = -1.0;
    // kg m/s: the normal impulse lambda a global solve gave this contact (slide 14's lcp and
    // generalized reflections, summed over the rounds); -1 for the pairwise responses.
    double solvedImpulse = -1.0;
    // The solver step it was answered in (World::stepCount then): a time step's log holds
    // `substeps` of them, and a global solve's contacts are those of one step and pass.
    std::uint64_t solverStep = 0;
    bool isPlane() const { return other < 0; }
    glm::dvec3 impulse() const { return massOf[0] * (velocityAfter[0] - velocityBefore[0]); }  // kg m/s on i
};

struct SpherePair {
    std::uint32_t i, j;  // i < j
};

// Index order: by first sphere, then by second.
inline bool inIndexOrder(const SpherePair& a, const SpherePair& b) { return a.i != b.i ? a.i < b.i : a.j < b.j; }

// Narrow phase, slide 9: where a touching pair touches.
struct SphereContact {
    glm::dvec3 u{0.0, 0.0, 1.0};  // (p1 - p2) / |p1 - p2|, from 2 to 1
    double depth = 0.0;           // m, d = r1 + r2 - |p1 - p2| (>= 0 when touching)
};

// A sphere touching plane `plane` through `face` (faceFor(plane, its centre)).
struct WallContact {
    std::uint32_t plane = 0;
    Plane face;
};

// What one parallel task of the broad phase writes. A cache line of its own, so that
// two threads appending to their vectors never write to the same line.
struct alignas(64) TaskScratch {
    std::vector<SpherePair> pairs;        // the pairs this task found
    std::vector<SpherePair> kept;         // the cached pairs it kept, at the front; only grows
    std::vector<std::uint32_t> partners;  // candidates of one sphere, only grows
};

// One predicted impact of the continuous method (continuous.cpp): sphere i meets sphere
// `other`, or plane -1 - other, at `time` (s within the solver step), if neither sphere's
// path has changed since (the versions).
struct PredictedImpact {
    double time = 0.0;  // s
    std::uint32_t i = 0;
    std::int32_t other = -1;
    std::uint32_t versionOfI = 0, versionOfOther = 0;
};

// The continuous method's scratch. Within a solver step each sphere follows a path
// p(t) = p0 + w (t - t0) + 1/2 g (t - t0)^2 from its last impact at t0; World::position
// and World::velocity hold p0 and w (the path's velocity at t0) until the step ends.
struct ContinuousWorkspace {
    std::vector<double> pathStart;          // s: t0 of each sphere's path
    std::vector<std::uint32_t> version;     // grows with each change of a sphere's path
    std::vector<glm::dvec3> anchor;         // m: the path starts the candidate pairs were found from
    double reach = 0.0;                     // m: no sphere moves farther than this from its anchor
    std::vector<std::uint32_t> pairStart;   // sphere i's candidate pairs: pairOf[pairStart[i], pairStart[i + 1])
    std::vector<std::uint32_t> pairOf;      // indices into Workspace::pairs
    std::vector<std::uint32_t> nextSlot;    // scratch of that index: per sphere, its next slot
    std::vector<std::uint8_t> pairResting;  // per candidate pair: in static contact this step
    std::vector<std::uint8_t> planeResting;  // per sphere and plane (i * planes + k): the same
    std::vector<PredictedImpact> queue;     // a heap, earliest first
    std::vector<PredictedImpact> sameInstant;  // impacts taken together (slide 14's global solvers)
    std::vector<SpherePair> previousPairs;  // scratch of a rebuild: the pairs before it
    std::vector<std::uint8_t> previousResting;
};

// One contact of slide 14's global solve (lcp.cpp).
struct LcpContact {
    std::uint32_t i = 0;
    std::int64_t j = -1;        // the other sphere, or -1: a plane
    std::int32_t other = -1;    // as ContactEvent::other: j, or -1 - (plane index)
    glm::dvec3 u{0.0};          // unit, from j to i
    double depth = 0.0;         // m, the overlap when found
    double target = 0.0;        // m/s: the least relative normal velocity after
    double lambda = 0.0;        // kg m/s: its impulse, >= 0
    bool isStatic = false;      // |relative normal speed| <= epsilon before (slide 13)
};

// The contacts [first, first + count) of one cluster of the global solvers.
struct ContactCluster {
    std::uint32_t first = 0;
    std::uint32_t count = 0;
    // What solving it took: sweeps, rounds (generalized reflections), the residual left
    // (m/s), and whether a cap stopped it.
    std::uint32_t sweeps = 0;
    std::uint32_t rounds = 0;
    double residual = 0.0;
    bool capped = false;
};

// Slide 14's contact graph (contact_graph.cpp): spheres are its nodes, touching pairs its
// edges (within Workspace::margin), each sphere's level its distance in contacts from a
// plane. Kept from step to step by the shock sweep (shock_propagation.cpp).
struct ContactGraph {
    std::vector<std::uint32_t> edgeStart;  // sphere i's neighbours: neighbour[edgeStart[i], edgeStart[i + 1])
    // Each sphere's neighbours in three runs, each by number: belowCount[i] one level down,
    // then besideCount[i] in its own level (the first besideBefore[i] of them numbered
    // below i), then the rest.
    std::vector<std::uint32_t> neighbour;
    std::vector<std::uint32_t> belowCount, besideCount, besideBefore;
    std::vector<std::int32_t> level;       // per sphere: 0 touches a plane; -1 reaches none
    std::vector<std::uint32_t> byLevel;    // the spheres with a level, by level, then number
    std::vector<std::uint32_t> levelStart;  // level k: byLevel[levelStart[k], levelStart[k + 1])
    std::vector<SpherePair> builtFrom;     // the candidate pairs it was found from (in index order if builtInIndexOrder)
    bool builtInIndexOrder = false;        // whether the next step's pairs may update it
    std::vector<std::uint8_t> zero;        // per sphere: near a plane (level 0), as it was found
    std::vector<glm::dvec3> positionsBeforePasses;  // m, the position stages' (shock on)
    std::vector<SpherePair> pairsAfterPasses;  // their pairs within reach after the passes, in index order
    // Scratch of the sweep: a level's contacts answered again; per sphere, moved in this
    // round (all 0 between uses; the graph's update marks the spheres it relevels in it
    // too); per byLevel slot, the spheres whose frozen rounds go on.
    std::vector<SpherePair> pressed;
    std::vector<std::uint8_t> moved;
    std::vector<std::uint32_t> again;
    std::vector<std::uint8_t> goesOn;
    // Spheres to push off the frozen level, by how many frozen spheres each has below, so
    // that the spheres side by side in the lanes have as many (per byLevel slot; then the
    // moved spheres of a round).
    std::vector<std::uint32_t> byBelow, movedByBelow;
    // Scratch of the sweep's first round inside a level, by wavefronts: the pairs, each one's
    // wavefront, where each wavefront starts, and per sphere the wavefront of its next pair
    // (all 0 between uses).
    std::vector<SpherePair> insidePairs, byWavefront;
    std::vector<std::uint32_t> wavefrontOfPair, wavefrontStart, wavefrontNext;
    // Scratch of the graph's update (contact_graph.cpp).
    struct Change {
        std::uint32_t sphere, other;
        bool added;
    };
    struct Relevelled {
        std::uint32_t sphere;
        std::int32_t was;
    };
    std::vector<SpherePair> added, removed;
    std::vector<Change> changes;
    std::vector<std::uint32_t> touched, zeroChanged, unset, runs;
    std::vector<Relevelled> relevelled;
    std::vector<std::vector<std::uint32_t>> rounds;
    std::vector<std::uint32_t> queue;  // the breadth-first search's; the sweep's moved spheres
    std::vector<std::uint32_t> next;   // the counting sorts': where the next entry goes
};

// The broad phase's uniform grid (broad_phase.cpp): cubic cells from `origin`, `dims`
// of them along x, y, z; a centre outside belongs to the nearest cell.
struct GridShape {
    glm::dvec3 origin{0.0};  // m, corner of cell (0, 0, 0)
    double cellSize = 1.0;   // m
    glm::ivec3 dims{1};

    glm::ivec3 cellOf(const glm::dvec3& p) const {
        return glm::clamp(glm::ivec3(glm::floor((p - origin) / cellSize)), glm::ivec3(0), dims - 1);
    }
    std::uint32_t linear(const glm::ivec3& c) const {
        return static_cast<std::uint32_t>((c.z * dims.y + c.y) * dims.x + c.x);
    }
    glm::ivec3 cellAt(std::uint32_t linearIndex) const {  // the inverse of linear()
        const int k = static_cast<int>(linearIndex);
        return {k % dims.x, k / dims.x % dims.y, k / dims.x / dims.y};
    }
};

// Scratch memory reused from step to step, so a step allocates nothing once warm.
struct Workspace {
    std::vector<SpherePair> pairs;          // candidate pairs (i, j), in index order
    std::vector<SpherePair> visitOrder;     // the same pairs, in the order the passes visit them
    double margin = 0.0;                    // m: beyond touching, how far visitOrder's pairs reach
    // The candidate pairs are kept while no sphere has moved far enough to meet a
    // sphere outside them (a Verlet list): these say what they were built from.
    std::vector<glm::dvec3> positionsAtBuild;  // m
    double radiusSumAtBuild = -1.0;            // m, changes when spheres or radii change
    double reachAtBuild = 0.0;                 // m, beyond touching
    bool cached = false;                       // false: rebuild at the next solver step
    bool built = false;                        // the grid has built pairs before
    bool reusedSinceBuild = false;             // the pairs served more than one step
    int buildsNotReused = 0;                   // consecutive builds that served one step
    // Spheres that have moved too far since the build for its pairs to hold theirs
    // (step.cpp's movers): their pairs are found anew, the others' filtered.
    std::vector<std::uint32_t> movers;
    std::vector<std::uint8_t> isMover;  // per sphere, 1 for a mover
    std::vector<SpherePair> moverPairs;  // scratch
    struct MoverInCell {
        std::uint32_t cell, sphere;
    };
    std::vector<MoverInCell> moversByCell;  // scratch
    std::vector<std::uint64_t> moverCells;  // scratch: open addressing, (cell + 1) << 32 | its first in moversByCell
    // The grid of the last grid build, and the spheres in it as they were then.
    GridShape gridAtBuild;
    std::vector<std::uint32_t> cellOfSphere;
    std::vector<std::uint32_t> cellStart;   // counting-sort offsets, one per cell + 1
    std::vector<std::uint32_t> cellCounts;  // scratch of that sort: per thread, per cell
    std::vector<std::uint32_t> sphereByCell;  // then a few slots of padding
    std::vector<glm::dvec4> cellOrdered;      // centre (m) and radius (m), in sphereByCell order
    std::vector<std::uint32_t> pairStart;   // counting-sort offsets, one per sphere + 1
    std::vector<std::uint32_t> pairCounts;  // scratch of that sort: per group of tasks, per sphere
    std::vector<TaskScratch> tasks;         // one per parallel task
    // With several threads the pairs are shared out: thread t visits
    // sharedPairs[shareStart[t], shareStart[t + 1]), the pairs whose first sphere lies in
    // its slab (of x or y, step.cpp's shareSlabs), in pass order. Where a pair's sphere
    // met a pair of another thread last, it waits for that pair (PairNeed), so every
    // sphere still meets its pairs in pass order: the result of one thread, bit for bit.
    struct PairNeed {
        std::uint32_t thread = 0;  // the other thread
        std::uint32_t done = 0;    // how many of its pairs must be done; 0: no need
    };
    int shareThreads = 1;
    std::vector<SpherePair> sharedPairs;
    std::vector<std::uint32_t> shareStart;
    std::vector<PairNeed> pairNeeds;         // two per pair of sharedPairs, one per sphere
    std::vector<std::uint32_t> threadOfPair;  // scratch of the share-out
    std::vector<PairNeed> lastPairOf;         // scratch: per sphere, the last pair that met it
    // Position based: per sphere, a lower bound on its gap to the walls (m, see
    // wallClearance()), lowered by each move of the pair stage, found anew by the wall
    // stage for the spheres it visits.
    std::vector<double> wallClearance;
    // Pair order `colored` (colored_order.cpp): visitOrder holds the pairs group by group,
    // colour by colour: group g's colour c at [colorStart[g * 64 + c], colorStart[g * 64 + c + 1]).
    // The groups are the blocks (runs of sphere numbers, or from 40 960 spheres places of
    // the world: the pairs inside each), then the border (the pairs between blocks); after
    // them, at [colorStart[groups * 64], the end), the overflow. No two pairs of a group's
    // colour share a sphere.
    std::vector<std::uint32_t> colorStart;
    std::vector<std::uint32_t> blockOfSphere;  // per sphere, its block
    std::vector<std::uint32_t> tileOfSphere;   // scratch: per sphere, its tile along the Morton curve
    std::vector<std::uint32_t> tileStart;      // scratch: counting-sort offsets, one per tile + 1
    std::vector<std::uint32_t> tileCounts;     // scratch of that sort: per group of tasks, per tile
    // One task's part of the colouring: a run of groups.
    struct alignas(64) ColoringTask {
        std::vector<std::uint64_t> colorsOfSphere;  // per sphere, the colours its pairs took (then the border's)
        struct KeyedPair {
            std::uint32_t pair;  // its place in index order
            std::uint32_t key;   // g * 64 + c
        };
        std::vector<KeyedPair> colored;  // its groups' pairs, in index order, at [0, count)
        std::uint32_t count = 0;
        std::uint32_t overflow = 0;  // how many of them found no free colour
    };
    std::vector<ColoringTask> coloringTasks;
    std::vector<SpherePair> colorSorted;  // the pairs placed colour by colour; once swapped into visitOrder, the same in index order
    std::uint64_t colorSortedStep = ~std::uint64_t(0);  // the solver step (World::stepCount) whose pairs colorSorted holds
    std::vector<std::uint32_t> colorNext;  // scratch: where each colour's next pair goes
    std::vector<double> slabSample;  // m: scratch of the share-out, coordinates that place its slabs
    // The lecture's orders wavefront by wavefront (wavefronts.cpp): wavefront w's pairs at
    // wavefrontOrder[wavefrontStart[w], wavefrontStart[w + 1]), each in pass order.
    std::vector<SpherePair> wavefrontOrder;
    std::vector<std::uint32_t> wavefrontStart;
    std::vector<std::uint32_t> wavefrontOfPair;  // scratch: per pair in pass order
    std::vector<std::uint32_t> wavefrontNext;    // scratch: per sphere, all 0 between uses
    // On several threads, each wavefront's pairs go by strips across the pile, and each
    // thread takes a range of strips through all the wavefronts of a pass (StripPass).
    struct WavefrontStrips {
        std::vector<std::uint8_t> ofSphere;  // per sphere, its strip: below count
        std::uint32_t count = 1;
        int threads = 1;  // the threads they were found for (1: not by strips)
        // Wavefront w's pairs of strip s: wavefrontOrder[start[w * count + s], start[w * count + s + 1]).
        std::vector<std::uint32_t> start;
        std::uint32_t span = 0;  // the most strips between the two spheres of a pair
        std::uint64_t foundAtStep = 0;  // the solver step (World::stepCount) ofSphere was found at
    };
    WavefrontStrips wavefrontStrips;
    // The colored order on several threads: the wavefronts above hold the border group's
    // pairs for this step (findBorderWavefronts), not a lecture's order's.
    bool borderByWavefronts = false;
    // The contacts of a step whose positions stay put while its passes run (velocity
    // based, response only): found once, used by every pass (findContacts).
    std::vector<std::uint8_t> pairTouches;     // per pair, in the order the passes visit them
    std::vector<SphereContact> pairContacts;   // valid where pairTouches
    std::vector<std::uint32_t> wallStart;      // sphere i's wall contacts: [wallStart[i], wallStart[i + 1])
    std::vector<WallContact> wallContacts;     // by sphere, then plane
    // Slide 14's simultaneous solver: the velocities at the start of a pass (m/s), and
    // each sphere's changes summed over the pass's contacts (m/s).
    std::vector<glm::dvec3> passStart;
    std::vector<glm::dvec3> velocityChange;
    std::vector<LcpContact> lcpContacts;  // the global solve's contacts
    // Their clusters (complementarity.h's sortIntoClusters), and its scratch: per sphere
    // its union-find parent and cluster, the contacts in cluster order.
    std::vector<ContactCluster> clusters;
    std::vector<std::uint32_t> clusterParent;
    std::vector<std::uint32_t> clusterOfSphere;
    std::vector<LcpContact> clusterSorted;
    // restorePositivity's own contacts and clusters.
    std::vector<LcpContact> positivityContacts;
    std::vector<ContactCluster> positivityClusters;
    // Params::threads = 0: the count in use, measured against the other (step()).
    AutomaticThreads automaticThreads;
    ContinuousWorkspace continuous;
    ImpactScratch impacts;  // World::measureImpacts
    ContactGraph contactGraph;  // Params::shock
};

struct World {
    std::vector<glm::dvec3> position;  // m, sphere centres
    std::vector<glm::dvec3> velocity;  // m/s
    std::vector<double> radius;        // m, > 0
    std::vector<double> mass;          // kg, > 0
    std::vector<ContactState> contactState;
    std::vector<Plane> planes;         // the box's walls first, then any extra planes
    int boxPlaneCount = 0;             // how many of `planes` form the box
    double time = 0.0;                 // s, simulated
    std::uint64_t stepCount = 0;       // solver steps taken
    std::uint64_t seed = 1;            // drives the shuffled pair order
    // Spheres placed so far by each emitter of the scene (scenes::emitDue). The solver
    // never reads it; it travels with the state (rewind, save) so that spheres added in
    // other ways (shot, thrown) are never mistaken for emissions.
    std::vector<int> emitted;

    bool recordContacts = false;        // fill `contacts` (costs time: off unless shown)
    std::vector<ContactEvent> contacts;  // every response of the last step(), all substeps
    // Measure the velocity stage's impact properties (impact_properties.h) into
    // StepStats::impacts (costs a pass over the candidate pairs: off unless shown).
    bool measureImpacts = false;
    // The contact log and the impact measures follow every response as it is made: the step
    // then answers its contacts on one thread, one at a time (the same state bit for bit).
    bool answersOneAtATime() const { return recordContacts || measureImpacts; }

    Workspace workspace;

    std::size_t size() const { return position.size(); }
    void addSphere(const glm::dvec3& p, const glm::dvec3& v, double r, double m);
    void removeSphere(std::size_t index);
};

}  // namespace physics
