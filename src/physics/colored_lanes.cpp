// The colored order's position based pair stage, several pairs of one colour side by
// side (SIMD): a colour's pairs share no sphere, so W of them can be loaded, answered and
// stored together. GCC and Clang vector extensions of W doubles, compiled for the vector
// unit the CPU has: 2 lanes (SSE2, every x86-64, and other CPUs), 4 (AVX2) or 8
// (AVX-512), chosen when the program starts.
//
// Each lane does one pair's numbers exactly as the one-pair code (position_based.cpp,
// collision_response.cpp) does them: the same operations in the same order, none fused
// (CMake builds the physics with -ffp-contract=off), both branches of each choice worked
// out and the slide's one kept. So every width gives the one-pair result, bit for bit.
#include <cmath>
#include <cstdint>

#include "physics/solver_stages.h"

#define LANES_INLINE inline __attribute__((always_inline))
// Every function that takes or returns lanes is inlined into the one compiled for its
// width: GCC's note that a non-inlined one would pass them differently does not apply.
#pragma GCC diagnostic ignored "-Wpsabi"

namespace physics {
namespace {

template <int W>
struct Lanes {
    typedef double Value __attribute__((vector_size(W * sizeof(double))));
    typedef std::int64_t Mask __attribute__((vector_size(W * sizeof(double))));  // -1: true, 0: false
    struct Vec {
        Value x, y, z;
    };
};

template <class Vec>
LANES_INLINE Vec add(const Vec& a, const Vec& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
template <class Vec>
LANES_INLINE Vec sub(const Vec& a, const Vec& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
template <class Vec, class Value>
LANES_INLINE Vec scale(const Value& s, const Vec& a) { return {s * a.x, s * a.y, s * a.z}; }
template <class Vec>
LANES_INLINE auto dot(const Vec& a, const Vec& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }  // as glm::dot
template <class Vec, class Mask>
LANES_INLINE Vec choose(const Mask& m, const Vec& a, const Vec& b) {
    return {m ? a.x : b.x, m ? a.y : b.y, m ? a.z : b.z};
}
template <class Value>
LANES_INLINE Value splat(double s) { return Value{} + s; }

template <int W>
LANES_INLINE typename Lanes<W>::Vec gather(const glm::dvec3* v, const std::uint32_t (&index)[W]) {
    typename Lanes<W>::Vec out;
    for (int l = 0; l < W; ++l) {
        out.x[l] = v[index[l]].x;
        out.y[l] = v[index[l]].y;
        out.z[l] = v[index[l]].z;
    }
    return out;
}
template <int W>
LANES_INLINE typename Lanes<W>::Value gather(const double* v, const std::uint32_t (&index)[W]) {
    typename Lanes<W>::Value out;
    for (int l = 0; l < W; ++l) out[l] = v[index[l]];
    return out;
}
template <int W>
LANES_INLINE void scatter(glm::dvec3* v, const std::uint32_t (&index)[W], const typename Lanes<W>::Vec& value) {
    for (int l = 0; l < W; ++l) v[index[l]] = {value.x[l], value.y[l], value.z[l]};
}
template <int W>
LANES_INLINE std::uint64_t countLanes(const typename Lanes<W>::Mask& m) {
    std::uint64_t count = 0;
    for (int l = 0; l < W; ++l) count += std::uint64_t(m[l] & 1);
    return count;
}

// The contact state of a sphere after a response (step.cpp's record), without a branch:
// whether a lane bounced is a coin toss in a jittering pile.
LANES_INLINE ContactState recorded(ContactState state, bool bounce, bool isStatic) {
    const bool becomesStatic = isStatic & (state == ContactState::Free);
    return bounce ? ContactState::Colliding : becomesStatic ? ContactState::Static : state;
}

// collision_response.cpp's respondWithShares for W pairs: the new velocities, and which
// lanes bounced and which were static contacts (the others keep theirs).
template <int W>
struct LaneResponse {
    typename Lanes<W>::Vec v1, v2;
    typename Lanes<W>::Mask bounce, isStatic;
};
template <int W>
LANES_INLINE LaneResponse<W> respondInLanes(const typename Lanes<W>::Vec& v1, const typename Lanes<W>::Vec& v2,
                                            const typename Lanes<W>::Value& first,
                                            const typename Lanes<W>::Value& second,
                                            const typename Lanes<W>::Vec& u, const Params& params) {
    using Value = typename Lanes<W>::Value;
    using Vec = typename Lanes<W>::Vec;
    const Value approach = dot(sub(v2, v1), u);  // m/s, positive while approaching
    const Value magnitude = approach < 0.0 ? -approach : approach;
    LaneResponse<W> r;
    r.isStatic = magnitude <= params.epsilon;
    r.bounce = ~r.isStatic & ~(approach < 0.0);  // as respondWithShares, NaN too
    // Static contact (slide 13): the approach removed, then friction.
    const auto closing = approach > 0.0;
    Vec s1 = choose(closing, add(v1, scale(approach * first, u)), v1);
    Vec s2 = choose(closing, sub(v2, scale(approach * second, u)), v2);
    if (!frictionOnRelativeVelocity(params)) {
        s1 = scale(splat<Value>(params.mu), s1);
        s2 = scale(splat<Value>(params.mu), s2);
    } else {
        const Vec relative = sub(s2, s1);
        const Vec change = scale(splat<Value>(1.0 - params.mu), sub(relative, scale(dot(relative, u), u)));
        s1 = add(s1, scale(first, change));
        s2 = sub(s2, scale(second, change));
    }
    // Bounce: slide 12, or equal and opposite impulses.
    Vec b1, b2;
    if (params.response == ResponseModel::LectureAttenuation) {
        const Value elastic = 2.0 * approach;
        const Vec v1Perp = scale(dot(v1, u), u), v2Perp = scale(dot(v2, u), u);
        const Value alpha = splat<Value>(params.alpha), beta = splat<Value>(params.beta);
        b1 = add(scale(alpha, sub(v1, v1Perp)), scale(beta, add(v1Perp, scale(elastic * first, u))));
        b2 = add(scale(alpha, sub(v2, v2Perp)), scale(beta, sub(v2Perp, scale(elastic * second, u))));
    } else {
        const Vec tangential = sub(sub(v2, v1), scale(approach, u));
        const Vec change =
            add(scale((1.0 + params.beta) * approach, u), scale(splat<Value>(1.0 - params.alpha), tangential));
        b1 = add(v1, scale(first, change));
        b2 = sub(v2, scale(second, change));
    }
    r.v1 = choose(r.isStatic, s1, choose(r.bounce, b1, v1));
    r.v2 = choose(r.isStatic, s2, choose(r.bounce, b2, v2));
    return r;
}

// Pairs [first, last) of one colour, W at a time; returns where it stopped.
template <int W>
LANES_INLINE std::uint32_t separateInLanes(World& world, const Params& params, const SpherePair* pairs,
                                           std::uint32_t first, std::uint32_t last, StepStats& stats, int pass,
                                           double positionFactor, bool respond, bool staticOnly) {
    using Value = typename Lanes<W>::Value;
    using Mask = typename Lanes<W>::Mask;
    using Vec = typename Lanes<W>::Vec;
    glm::dvec3* position = world.position.data();
    glm::dvec3* velocity = world.velocity.data();
    ContactState* state = world.contactState.data();
    double* clearance = world.workspace.wallClearance.data();
    const bool halfHalf = params.split == PositionSplit::HalfHalf;
    std::uint32_t k = first;
    for (; k + W <= last; k += W) {
        std::uint32_t i[W], j[W];
        for (int l = 0; l < W; ++l) {
            i[l] = pairs[k + std::uint32_t(l)].i;
            j[l] = pairs[k + std::uint32_t(l)].j;
        }
        // Narrow phase (slide 9), as touching(): a NaN centre counts as touching there too.
        const Vec p1 = gather<W>(position, i), p2 = gather<W>(position, j);
        const Vec delta = sub(p1, p2);
        const Value reach = gather<W>(world.radius.data(), i) + gather<W>(world.radius.data(), j);  // m
        const Value distanceSquared = dot(delta, delta);
        const Mask touch = ~(distanceSquared > reach * reach);
        Value distance;  // m
        for (int l = 0; l < W; ++l) distance[l] = std::sqrt(distanceSquared[l]);  // one instruction: -fno-math-errno
        const Value inverse = 1.0 / distance;
        const Mask apart = distance > 0.0;
        const Value zero = splat<Value>(0.0);
        const Vec u{apart ? delta.x * inverse : zero, apart ? delta.y * inverse : zero,
                    apart ? delta.z * inverse : splat<Value>(1.0)};
        const Value depth = reach - distance;  // m
        const Value m1 = gather<W>(world.mass.data(), i), m2 = gather<W>(world.mass.data(), j);  // kg
        if (respond) {
            const Value perTotalMass = 1.0 / (m1 + m2);
            const Vec v1 = gather<W>(velocity, i), v2 = gather<W>(velocity, j);
            const LaneResponse<W> r = respondInLanes<W>(v1, v2, m2 * perTotalMass, m1 * perTotalMass, u, params);
            const Mask isStatic = touch & r.isStatic;
            const Mask bounce = staticOnly ? isStatic & ~isStatic : touch & r.bounce;  // staticOnly: none
            const Mask answered = staticOnly ? isStatic : touch;
            scatter<W>(velocity, i, choose(answered, r.v1, v1));
            scatter<W>(velocity, j, choose(answered, r.v2, v2));
            for (int l = 0; l < W; ++l) {
                const ContactState si = recorded(state[i[l]], bounce[l] != 0, isStatic[l] != 0);
                const ContactState sj = recorded(state[j[l]], bounce[l] != 0, isStatic[l] != 0);
                if (si != state[i[l]]) state[i[l]] = si;
                if (sj != state[j[l]]) state[j[l]] = sj;
            }
            stats.collisions += countLanes<W>(bounce);
            stats.staticContacts += countLanes<W>(isStatic);
            if (pass == 0) stats.sphereContacts += countLanes<W>(touch);
        }
        // Slide 13, step 3 (separateSpheres): apart by d, or reflecting by (1 + beta) d.
        const Value d = positionFactor == 1.0 ? depth : positionFactor * depth;  // m
        Value share1 = splat<Value>(0.5), share2 = splat<Value>(0.5);
        if (!halfHalf) {
            const Value perTotalMass = 1.0 / (m1 + m2);
            share1 = m2 * perTotalMass;
            share2 = m1 * perTotalMass;
        }
        const Value moved1 = touch ? share1 * d : zero, moved2 = touch ? share2 * d : zero;  // m
        scatter<W>(position, i, choose(touch, add(p1, scale(moved1, u)), p1));
        scatter<W>(position, j, choose(touch, sub(p2, scale(moved2, u)), p2));
        for (int l = 0; l < W; ++l) {  // x - 0 is x, bit for bit: no branch for the lanes apart
            clearance[i[l]] -= moved1[l];
            clearance[j[l]] -= moved2[l];
        }
    }
    return k;
}

// The shock sweep's push of a sphere off the frozen spheres below it (shock_propagation.cpp,
// its run of graph.neighbour one level down), one after another, positions only, for W
// spheres side by side: along the line of centres by the overlap, as touching() and
// moveOffFrozenSphere find and move them, with the same operations in the same order (W =
// 1 is the one-sphere code). A lane whose sphere has no frozen sphere left at a turn is
// masked (pushed by 0). With `params` (the sweep's first round), each touching contact that
// is static (|c| <= epsilon) is answered first, as respondToFrozenContact answers it (the
// frozen sphere's mass infinite), and counted in `stats`.
template <int W>
LANES_INLINE void pushOffFrozenInLanes(World& world, const ContactGraph& graph, const std::uint32_t* spheres,
                                       bool lowerClearance, std::uint8_t* again, double settled,
                                       const Params* params, StepStats* stats) {
    using Value = typename Lanes<W>::Value;
    using Mask = typename Lanes<W>::Mask;
    using Vec = typename Lanes<W>::Vec;
    std::uint32_t i[W], first[W], count[W], most = 0;
    for (int l = 0; l < W; ++l) {
        i[l] = spheres[l];
        first[l] = graph.edgeStart[i[l]];  // its run of neighbours one level down
        count[l] = graph.belowCount[i[l]];
        most = count[l] > most ? count[l] : most;
    }
    glm::dvec3* position = world.position.data();
    glm::dvec3* velocity = world.velocity.data();
    const double* radius = world.radius.data();
    double* clearance = world.workspace.wallClearance.data();
    const Value zero = splat<Value>(0.0);
    Vec p = gather<W>(position, i);
    Vec v = params ? gather<W>(velocity, i) : Vec{zero, zero, zero};  // m/s
    Mask answered = Mask{} == 1;  // lanes with a static contact answered
    const Value r = gather<W>(radius, i);  // m
    Value lowered = lowerClearance ? gather<W>(clearance, i) : zero;  // m
    Value deepest = zero;  // m
    Value pushed = zero;   // frozen spheres it was pushed off
    for (std::uint32_t b = 0; b < most; ++b) {
        std::uint32_t frozen[W];
        Mask active;
        for (int l = 0; l < W; ++l) {
            active[l] = b < count[l] ? -1 : 0;
            frozen[l] = b < count[l] ? graph.neighbour[first[l] + b] : i[l];
        }
        const Vec delta = sub(p, gather<W>(position, frozen));
        const Value reach = r + gather<W>(radius, frozen);  // m
        const Value distanceSquared = dot(delta, delta);   // m^2
        Value distance;                                    // m
        for (int l = 0; l < W; ++l) distance[l] = std::sqrt(distanceSquared[l]);
        const Value inverse = 1.0 / distance;
        const Mask apart = distance > 0.0;
        const Vec u{apart ? delta.x * inverse : zero, apart ? delta.y * inverse : zero,
                    apart ? delta.z * inverse : splat<Value>(1.0)};
        const Mask touches = active & (distanceSquared <= reach * reach);
        if (params) {
            const LaneResponse<W> response =
                respondInLanes<W>(v, gather<W>(velocity, frozen), splat<Value>(1.0), zero, u, *params);
            const Mask isStatic = touches & response.isStatic;
            v = choose(isStatic, response.v1, v);
            answered |= isStatic;
            stats->staticContacts += countLanes<W>(isStatic);
        }
        const Value depth = touches ? reach - distance : zero;  // m
        p = choose(touches, add(p, scale(depth, u)), p);
        lowered = lowered - depth;
        deepest = deepest < depth ? depth : deepest;  // as std::max
        pushed = depth > 0.0 ? pushed + 1.0 : pushed;
    }
    scatter<W>(position, i, p);
    if (params) {
        scatter<W>(velocity, i, v);
        ContactState* state = world.contactState.data();
        for (int l = 0; l < W; ++l) state[i[l]] = recorded(state[i[l]], false, answered[l] != 0);
    }
    if (lowerClearance) {
        for (int l = 0; l < W; ++l) clearance[i[l]] = lowered[l];
    }
    if (again) {
        for (int l = 0; l < W; ++l) again[l] = pushed[l] > 1.0 && deepest[l] > settled * r[l];
    }
}

template <int W>
LANES_INLINE void pushOffFrozenSideBySide(World& world, const ContactGraph& graph, const std::uint32_t* spheres,
                                          std::size_t count, bool lowerClearance, std::uint8_t* again,
                                          double settled, const Params* params, StepStats* stats) {
    std::size_t k = 0;
    for (; k + W <= count; k += W) {
        pushOffFrozenInLanes<W>(world, graph, spheres + k, lowerClearance, again ? again + k : nullptr, settled,
                                params, stats);
    }
    for (; k < count; ++k) {
        pushOffFrozenInLanes<1>(world, graph, spheres + k, lowerClearance, again ? again + k : nullptr, settled,
                                params, stats);
    }
}

// One function per width, each compiled for the instructions it needs.
std::uint32_t separateIn2Lanes(World& world, const Params& params, const SpherePair* pairs, std::uint32_t first,
                               std::uint32_t last, StepStats& stats, int pass, double factor, bool respond,
                               bool staticOnly) {
    return separateInLanes<2>(world, params, pairs, first, last, stats, pass, factor, respond, staticOnly);
}
void pushOffFrozenIn2Lanes(World& world, const ContactGraph& graph, const std::uint32_t* spheres, std::size_t count,
                           bool lowerClearance, std::uint8_t* again, double settled, const Params* params,
                           StepStats* stats) {
    pushOffFrozenSideBySide<2>(world, graph, spheres, count, lowerClearance, again, settled, params, stats);
}
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__EMSCRIPTEN__)
#define SPHERES_WIDE_LANES 1
__attribute__((target("avx2"))) std::uint32_t separateIn4Lanes(World& world, const Params& params,
                                                               const SpherePair* pairs, std::uint32_t first,
                                                               std::uint32_t last, StepStats& stats, int pass,
                                                               double factor, bool respond, bool staticOnly) {
    return separateInLanes<4>(world, params, pairs, first, last, stats, pass, factor, respond, staticOnly);
}
__attribute__((target("avx512f"))) std::uint32_t separateIn8Lanes(World& world, const Params& params,
                                                                  const SpherePair* pairs, std::uint32_t first,
                                                                  std::uint32_t last, StepStats& stats, int pass,
                                                                  double factor, bool respond, bool staticOnly) {
    return separateInLanes<8>(world, params, pairs, first, last, stats, pass, factor, respond, staticOnly);
}
__attribute__((target("avx2"))) void pushOffFrozenIn4Lanes(World& world, const ContactGraph& graph,
                                                           const std::uint32_t* spheres, std::size_t count,
                                                           bool lowerClearance, std::uint8_t* again,
                                                           double settled, const Params* params, StepStats* stats) {
    pushOffFrozenSideBySide<4>(world, graph, spheres, count, lowerClearance, again, settled, params, stats);
}
__attribute__((target("avx512f"))) void pushOffFrozenIn8Lanes(World& world, const ContactGraph& graph,
                                                              const std::uint32_t* spheres, std::size_t count,
                                                              bool lowerClearance, std::uint8_t* again,
                                                              double settled, const Params* params, StepStats* stats) {
    pushOffFrozenSideBySide<8>(world, graph, spheres, count, lowerClearance, again, settled, params, stats);
}
#endif

}  // namespace

std::vector<int> laneWidths() {
    std::vector<int> widths{2};
#ifdef SPHERES_WIDE_LANES
    if (__builtin_cpu_supports("avx2")) widths.push_back(4);
    if (__builtin_cpu_supports("avx512f")) widths.push_back(8);
#endif
    return widths;
}

std::uint32_t separateColorInLanes(World& world, const Params& params, const SpherePair* pairs, std::uint32_t first,
                                   std::uint32_t last, StepStats& stats, int pass, double positionFactor,
                                   bool respond, int width) {
    // The overflow colour's pairs may share a sphere: one at a time, by the caller.
    if (first >= overflowRange(world.workspace).begin) return first;
    return separateSideBySide(world, params, pairs, first, last, stats, pass, positionFactor, respond, false, width);
}

std::uint32_t separateSideBySide(World& world, const Params& params, const SpherePair* pairs, std::uint32_t first,
                                 std::uint32_t last, StepStats& stats, int pass, double positionFactor, bool respond,
                                 bool staticOnly, int width) {
    static const int widest = laneWidths().back();
    switch (width == 0 ? widest : width) {
#ifdef SPHERES_WIDE_LANES
        case 8:
            return separateIn8Lanes(world, params, pairs, first, last, stats, pass, positionFactor, respond, staticOnly);
        case 4:
            return separateIn4Lanes(world, params, pairs, first, last, stats, pass, positionFactor, respond, staticOnly);
#endif
        default:
            return separateIn2Lanes(world, params, pairs, first, last, stats, pass, positionFactor, respond, staticOnly);
    }
}

void pushOffFrozenSideBySide(World& world, const ContactGraph& graph, const std::uint32_t* spheres,
                             std::size_t count, bool lowerClearance, std::uint8_t* again, double settled,
                             int width, const Params* params, StepStats* stats) {
    static const int widest = laneWidths().back();
    switch (width == 0 ? widest : width) {
#ifdef SPHERES_WIDE_LANES
        case 8: return pushOffFrozenIn8Lanes(world, graph, spheres, count, lowerClearance, again, settled, params, stats);
        case 4: return pushOffFrozenIn4Lanes(world, graph, spheres, count, lowerClearance, again, settled, params, stats);
#endif
        case 1:
            return pushOffFrozenSideBySide<1>(world, graph, spheres, count, lowerClearance, again, settled, params, stats);
        default: return pushOffFrozenIn2Lanes(world, graph, spheres, count, lowerClearance, again, settled, params, stats);
    }
}

}  // namespace physics
