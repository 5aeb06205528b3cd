#include "app/teaching/overlays.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <unordered_map>
#include <unordered_set>

#include <glm/geometric.hpp>

#include "physics/broad_phase.h"

namespace app {
namespace {

constexpr float kArrowWidth = 4.0f;     // px
constexpr float kOutlineExtra = 3.0f;   // px wider than the line it outlines
constexpr float kTrailWidth = 3.0f;     // px
constexpr float kPointSize = 11.0f;     // px
constexpr double kTimeSlack = 1e-9;     // s, for sums of steps that should be equal
constexpr std::size_t kCrowdedMarks = 50;  // more contact or penetration marks: thinner, no outline

std::uint64_t pairKey(std::uint32_t sphere, std::int32_t other) {
    return (std::uint64_t(sphere) << 32) | std::uint32_t(other);
}

glm::u8vec4 withOpacity(glm::u8vec4 color, double opacity) {
    color.w = static_cast<std::uint8_t>(std::clamp(opacity, 0.0, 1.0) * color.w + 0.5);
    return color;
}

// Two unit vectors perpendicular to `d` and to each other.
void perpendiculars(const glm::dvec3& d, glm::dvec3& a, glm::dvec3& b) {
    const glm::dvec3 helper = std::abs(d.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
    a = glm::normalize(glm::cross(d, helper));
    b = glm::cross(d, a);
}

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// A dot with its dark outline, or without (`outlined` false: a crowded scene).
void appendDot(render::FrameSnapshot& snapshot, const glm::dvec3& p, glm::u8vec4 color, float size,
               bool outlined = true) {
    if (outlined) snapshot.addPoint(glm::vec3(p), withOpacity(kOutlineColor, color.w / 255.0), size + kOutlineExtra);
    snapshot.addPoint(glm::vec3(p), color, size);
}

}  // namespace

bool setOverlayByName(OverlayFlags& flags, const std::string& name) {
    if (name == "velocity") flags.velocity = true;
    else if (name == "contacts") flags.contacts = true;
    else if (name == "impulses") flags.impulses = true;
    else if (name == "penetration") flags.penetration = true;
    else if (name == "trails") flags.trails = true;
    else if (name == "graph") flags.graph = true;
    else return false;
    return true;
}

std::vector<std::string> overlayNames(const OverlayFlags& flags) {
    const bool on[] = {flags.velocity, flags.contacts, flags.impulses, flags.penetration, flags.trails, flags.graph};
    static_assert(sizeof on == sizeof kOverlayNames / sizeof kOverlayNames[0]);
    std::vector<std::string> names;
    for (std::size_t k = 0; k < sizeof on; ++k) {
        if (on[k]) names.emplace_back(kOverlayNames[k]);
    }
    return names;
}

// ---------------------------------------------------------------- state across steps

void OverlayState::reset() {
    impulses_.clear();
    trails_.clear();
    lastTrailTime_ = -1.0;
}

double OverlayState::impulseOpacity(const ImpulseMark& mark, double now) {
    return std::clamp(1.0 - (now - mark.time) / kImpulseFadeSeconds, 0.0, 1.0);
}

void OverlayState::afterStep(const physics::World& world, const OverlayFlags& flags, int selected) {
    // Old impulses go whether or not the overlay is on, so that none reappears later.
    while (!impulses_.empty() &&
           (world.time - impulses_.front().time >= kImpulseFadeSeconds - kTimeSlack)) {
        impulses_.pop_front();
    }
    if (flags.impulses && world.recordContacts) addImpulses(world);
    if (flags.trails) {
        addTrailPoints(world, selected);
    } else if (!trails_.empty()) {
        trails_.clear();
        lastTrailTime_ = -1.0;
    }
}

void OverlayState::addImpulses(const physics::World& world) {
    // The passes of one step may answer one contact several times: one arrow per
    // (sphere, other) and step, the impulses summed.
    std::unordered_map<std::uint64_t, std::size_t> index;
    const std::size_t first = impulses_.size();
    const auto add = [&](std::uint32_t sphere, std::int32_t other, const glm::dvec3& point,
                         const glm::dvec3& impulse) {
        const auto [it, inserted] = index.emplace(pairKey(sphere, other), impulses_.size());
        if (inserted) {
            impulses_.push_back({sphere, point, impulse, world.time});
        } else {
            impulses_[it->second].impulse += impulse;
        }
    };
    for (const physics::ContactEvent& e : world.contacts) {
        if (!e.bounce) continue;
        add(e.i, e.other, e.point, e.impulse());
        if (!e.isPlane() && std::isfinite(e.massOf[1])) {  // a frozen sphere takes nothing
            const glm::dvec3 onOther = e.massOf[1] * (e.velocityAfter[1] - e.velocityBefore[1]);
            add(static_cast<std::uint32_t>(e.other), static_cast<std::int32_t>(e.i), e.point, onOther);
        }
    }
    // Drop what is too small to see and anything not finite, then cap the count.
    const auto end = std::remove_if(impulses_.begin() + static_cast<std::ptrdiff_t>(first), impulses_.end(),
                                    [](const ImpulseMark& m) {
                                        return !finite(m.impulse) || !finite(m.point) ||
                                               glm::length(m.impulse) * kImpulseMetresPerUnit < 1e-4;
                                    });
    impulses_.erase(end, impulses_.end());
    while (impulses_.size() > kMaxImpulseMarks) impulses_.pop_front();
}

void OverlayState::addTrailPoints(const physics::World& world, int selected) {
    const std::vector<std::uint32_t> spheres = overlaySpheres(world, selected, kMaxTrailSpheres);
    bool same = spheres.size() == trails_.size();
    for (std::size_t k = 0; same && k < spheres.size(); ++k) same = trails_[k].sphere == spheres[k];
    if (!same) {
        trails_.assign(spheres.size(), Trail{});
        for (std::size_t k = 0; k < spheres.size(); ++k) trails_[k].sphere = spheres[k];
        lastTrailTime_ = -1.0;
    }
    const double now = world.time;
    if (lastTrailTime_ >= 0.0 && now - lastTrailTime_ < kTrailSampleSeconds - kTimeSlack) return;
    lastTrailTime_ = now;
    for (Trail& trail : trails_) {
        trail.points.push_back(world.position[trail.sphere]);
        trail.times.push_back(now);
        while (!trail.times.empty() && now - trail.times.front() > kTrailSeconds + kTimeSlack) {
            trail.points.pop_front();
            trail.times.pop_front();
        }
    }
}

std::vector<std::uint32_t> overlaySpheres(const physics::World& world, int selected, std::size_t limit) {
    std::vector<std::uint32_t> spheres;
    if (selected >= 0 && static_cast<std::size_t>(selected) < world.size()) {
        spheres.push_back(static_cast<std::uint32_t>(selected));
        return spheres;
    }
    const std::size_t n = std::min(world.size(), limit);
    spheres.reserve(n);
    for (std::size_t i = 0; i < n; ++i) spheres.push_back(static_cast<std::uint32_t>(i));
    return spheres;
}

// ---------------------------------------------------------------- drawing

void appendArrow(render::FrameSnapshot& snapshot, const glm::dvec3& from, const glm::dvec3& to,
                 glm::u8vec4 color, float width) {
    const glm::dvec3 shaft = to - from;
    const double length = glm::length(shaft);
    if (!(length > 0.0) || !finite(from) || !finite(to)) return;
    const glm::dvec3 d = shaft / length;
    glm::dvec3 a, b;
    perpendiculars(d, a, b);
    const double head = std::min(0.3 * length, 0.08);  // m
    const glm::dvec3 back = to - head * d;
    const glm::dvec3 barbs[4] = {back + 0.5 * head * a, back - 0.5 * head * a, back + 0.5 * head * b,
                                 back - 0.5 * head * b};
    const glm::u8vec4 outline = withOpacity(kOutlineColor, color.w / 255.0);
    // Outlines first, then the colour over them.
    snapshot.addLine(glm::vec3(from), glm::vec3(to), outline, width + kOutlineExtra);
    for (const glm::dvec3& barb : barbs) snapshot.addLine(glm::vec3(to), glm::vec3(barb), outline, width + kOutlineExtra);
    snapshot.addLine(glm::vec3(from), glm::vec3(to), color, width);
    for (const glm::dvec3& barb : barbs) snapshot.addLine(glm::vec3(to), glm::vec3(barb), color, width);
}

void appendVelocityArrows(const physics::World& world, int selected, render::FrameSnapshot& snapshot) {
    for (std::uint32_t i : overlaySpheres(world, selected, kMaxArrowSpheres)) {
        const glm::dvec3& v = world.velocity[i];
        const double speed = glm::length(v);
        const double length = speed * kVelocityArrowSeconds;  // m
        if (!(length > 1e-3)) continue;                        // at rest (or not finite)
        const glm::dvec3 d = v / speed;
        // From the surface, so that a slow sphere's arrow is not hidden inside it.
        const glm::dvec3 from = world.position[i] + world.radius[i] * d;
        appendArrow(snapshot, from, from + length * d, kVelocityColor, kArrowWidth);
    }
}

void appendContacts(const physics::World& world, int selected, render::FrameSnapshot& snapshot) {
    // The last response of each (sphere, other) in the step: the passes repeat contacts.
    std::unordered_set<std::uint64_t> seen;
    seen.reserve(std::min(world.contacts.size(), kMaxDrawnContacts));
    std::vector<const physics::ContactEvent*> latest;
    for (auto it = world.contacts.rbegin(); it != world.contacts.rend() && latest.size() < kMaxDrawnContacts; ++it) {
        const physics::ContactEvent& e = *it;
        if (!seen.insert(pairKey(e.i, e.other)).second) continue;
        if (!finite(e.point) || !finite(e.normal) || e.i >= world.size()) continue;
        latest.push_back(&e);
    }
    // Many contacts (a pile): smaller dots without their dark outline, so that the
    // spheres still show between them, and the normals of the selected sphere only:
    // a pile's normals are a few pixels each, mostly hidden in the gaps, and were half
    // of what the overlay cost a software GL.
    const bool crowded = latest.size() > kCrowdedMarks;
    const float scale = crowded ? 0.5f : 1.0f;
    for (const physics::ContactEvent* e : latest) {
        const bool ofSelected = selected >= 0 && (e->i == std::uint32_t(selected) || e->other == selected);
        if (!crowded || ofSelected) {
            const double length = 0.9 * world.radius[e->i];  // m, into the sphere the normal points to
            const glm::dvec3 tip = e->point + length * e->normal;
            if (!crowded) {
                snapshot.addLine(glm::vec3(e->point), glm::vec3(tip), kOutlineColor, kArrowWidth + kOutlineExtra);
            }
            snapshot.addLine(glm::vec3(e->point), glm::vec3(tip), kNormalColor, scale * kArrowWidth);
        }
        appendDot(snapshot, e->point, kContactPointColor, scale * (e->bounce ? kPointSize : 0.7f * kPointSize), !crowded);
    }
}

void appendImpulses(const OverlayState& state, const physics::World& world, render::FrameSnapshot& snapshot) {
    for (const ImpulseMark& mark : state.impulses()) {
        const double opacity = OverlayState::impulseOpacity(mark, world.time);
        if (opacity <= 0.0) continue;
        const glm::u8vec4 color = withOpacity(kImpulseColor, opacity);
        appendArrow(snapshot, mark.point, mark.point + kImpulseMetresPerUnit * mark.impulse, color, kArrowWidth + 1.0f);
        appendDot(snapshot, mark.point, color, 0.8f * kPointSize);
    }
}

void appendTrails(const OverlayState& state, const physics::World& world, render::FrameSnapshot& snapshot) {
    const double now = world.time;
    // Two passes: every dark rim first (it keeps light sphere colours readable on the
    // light floor), then the colours over them, so the rims do not cut the lines.
    for (const bool rim : {true, false}) {
        for (const Trail& trail : state.trails()) {
            if (trail.sphere >= snapshot.colors.size() || trail.points.size() < 2) continue;
            const glm::u8vec4 base = snapshot.colors[trail.sphere];
            std::size_t from = 0;  // the segment runs from the last point drawn to
            for (std::size_t k = 1; k < trail.points.size(); ++k) {
                const double opacity = 0.9 * (1.0 - (now - trail.times[k]) / kTrailSeconds);
                const glm::dvec3& a = trail.points[from];
                const glm::dvec3& b = trail.points[k];
                if (!finite(a) || !finite(b)) {
                    from = k;
                    continue;
                }
                // A sphere at rest, or jittering in place, moves less than a pixel: its
                // points are joined into one segment, drawn once it is long enough.
                if (opacity <= 0.0 || glm::distance(a, b) < kShortestTrailSegment) continue;
                from = k;
                if (rim) {
                    snapshot.addLine(glm::vec3(a), glm::vec3(b), withOpacity(kOutlineColor, 0.6 * opacity),
                                     kTrailWidth + 2.0f);
                } else {
                    snapshot.addLine(glm::vec3(a), glm::vec3(b), glm::u8vec4(glm::u8vec3(base), 255 * opacity),
                                     kTrailWidth);
                }
            }
        }
    }
}

std::vector<Overlap> currentOverlaps(const physics::World& world, physics::Workspace& scratch) {
    std::vector<Overlap> overlaps;
    physics::findPairsGrid(world, 0.0, scratch);
    for (const physics::SpherePair& pair : scratch.pairs) {
        const glm::dvec3 delta = world.position[pair.i] - world.position[pair.j];
        const double distance = glm::length(delta);
        const double depth = world.radius[pair.i] + world.radius[pair.j] - distance;
        if (!(depth > 0.0) || !(distance > 0.0)) continue;
        const glm::dvec3 u = delta / distance;
        overlaps.push_back({world.position[pair.j] + (world.radius[pair.j] - 0.5 * depth) * u, u, depth});
    }
    for (std::size_t i = 0; i < world.size(); ++i) {
        for (const physics::Plane& plane : world.planes) {
            const physics::Plane face = physics::faceFor(plane, world.position[i]);
            const double distance = glm::dot(world.position[i] - face.point, face.normal);
            const double depth = world.radius[i] - distance;
            if (!(depth > 0.0)) continue;
            overlaps.push_back({world.position[i] - (world.radius[i] - 0.5 * depth) * face.normal, face.normal, depth});
        }
    }
    return overlaps;
}

void appendPenetration(const std::vector<Overlap>& overlaps, render::FrameSnapshot& snapshot) {
    // m: an overlap whose exaggerated segment would be shorter, about a pixel, is not drawn.
    constexpr double kShortestSegment = 1e-3;
    std::vector<const Overlap*> shown;
    for (const Overlap& o : overlaps) {
        if (shown.size() >= kMaxDrawnContacts) break;
        if (kPenetrationExaggeration * o.depth >= kShortestSegment) shown.push_back(&o);
    }
    const bool crowded = shown.size() > kCrowdedMarks;  // without outlines, as the contacts
    for (const Overlap* o : shown) {
        const glm::dvec3 half = (0.5 * kPenetrationExaggeration * o->depth) * o->normal;
        const glm::vec3 a(o->point - half), b(o->point + half);
        if (!crowded) snapshot.addLine(a, b, kOutlineColor, 6.0f + kOutlineExtra);
        snapshot.addLine(a, b, kPenetrationColor, 6.0f);
    }
}

// Levels 0-5 in their hues, 6-11 the same darker, 12-17 paler, 18-23 palest, then the four
// again: in the column of twenty every level has its own colour, and level 6 is no longer
// level 0's red ("touches a plane").
glm::u8vec4 levelColor(int level) {
    constexpr int kColors = sizeof kLevelColors / sizeof kLevelColors[0];
    if (level < 0) return kNoLevelColor;
    const glm::vec3 hue(kLevelColors[level % kColors]), white(255.0f);
    glm::vec3 shaded = hue;
    switch (level / kColors % 4) {
        case 1: shaded = 0.55f * hue; break;                   // darker
        case 2: shaded = hue + 0.5f * (white - hue); break;    // paler
        case 3: shaded = hue + 0.75f * (white - hue); break;   // palest
        default: break;
    }
    return {glm::u8vec3(glm::round(shaded)), 255};
}

void appendContactGraph(const physics::World& world, const physics::ContactGraph& graph,
                        render::FrameSnapshot& snapshot) {
    if (graph.level.size() != world.size() || graph.edgeStart.size() != world.size() + 1) return;
    if (snapshot.colors.size() == world.size()) {  // in a pile the lines hide in the spheres
        for (std::size_t i = 0; i < world.size(); ++i) snapshot.colors[i] = levelColor(graph.level[i]);
    }
    std::size_t drawn = 0;
    for (std::uint32_t i = 0; i < world.size() && drawn < kMaxDrawnContacts; ++i) {
        const int level = graph.level[i];
        for (std::uint32_t e = graph.edgeStart[i]; e < graph.edgeStart[i + 1]; ++e) {
            const std::uint32_t j = graph.neighbour[e];
            if (j < i) continue;
            snapshot.addLine(glm::vec3(world.position[i]), glm::vec3(world.position[j]),
                             levelColor(std::max(level, graph.level[j])), kTrailWidth);
            ++drawn;
        }
        if (level != 0) continue;
        for (const physics::Plane& plane : world.planes) {  // the contacts that make it level 0
            const physics::Plane face = physics::faceFor(plane, world.position[i]);
            const double distance = glm::dot(world.position[i] - face.point, face.normal);  // m
            if (distance > world.radius[i] + world.workspace.margin) continue;
            snapshot.addLine(glm::vec3(world.position[i]), glm::vec3(world.position[i] - distance * face.normal),
                             levelColor(0), kTrailWidth);
            ++drawn;
        }
    }
}

std::vector<LegendLine> overlayLegend(const OverlayFlags& flags, std::size_t sphereCount, int selected) {
    std::vector<LegendLine> lines;
    char text[200];
    const bool one = selected >= 0 && static_cast<std::size_t>(selected) < sphereCount;
    const auto which = [&](std::size_t limit) -> std::string {
        if (one) return ", sphere " + std::to_string(selected) + " only";
        if (sphereCount > limit) return ", first " + std::to_string(limit) + " spheres";
        return "";
    };
    if (flags.velocity) {
        std::snprintf(text, sizeof text, "velocity: 1 m/s = %.0f cm, from the surface (path in %.1f s)%s",
                      100.0 * kVelocityArrowSeconds, kVelocityArrowSeconds, which(kMaxArrowSpheres).c_str());
        lines.push_back({text, kVelocityColor});
    }
    const std::string notRecorded =
        sphereCount > kMaxRecordSpheres ? " (off above " + std::to_string(kMaxRecordSpheres) + " spheres)" : "";
    if (flags.contacts) {
        lines.push_back({"contacts: point (yellow), normal (cyan; over " + std::to_string(kCrowdedMarks) +
                             " contacts, the selected sphere's only), last step" + notRecorded,
                         kNormalColor});
    }
    if (flags.impulses) {
        std::snprintf(text, sizeof text, "impulse at impact: 1 kg m/s = %.0f cm, fades in %.1f s%s",
                      100.0 * kImpulseMetresPerUnit, kImpulseFadeSeconds, notRecorded.c_str());
        lines.push_back({text, kImpulseColor});
    }
    if (flags.penetration) {
        std::snprintf(text, sizeof text, "penetration: depth × %.0f along the normal", kPenetrationExaggeration);
        lines.push_back({text, kPenetrationColor});
    }
    if (flags.trails) {
        std::snprintf(text, sizeof text, "trails: the last %.1f s of the centres%s", kTrailSeconds,
                      which(kMaxTrailSpheres).c_str());
        lines.push_back({text, glm::u8vec4(200, 200, 210, 255)});
    }
    if (flags.graph) {
        lines.push_back({"contact graph: spheres and links by level from the floor, 0 red, 1 orange, 2 yellow, "
                         "3 green, 4 cyan, 5 blue, then darker from 6, paler from 12, palest from 18; grey reaches no plane",
                         levelColor(1)});  // not red: the penetration line above is
    }
    return lines;
}

}  // namespace app
