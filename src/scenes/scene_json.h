#pragma once
// Scene files (assets/scenes/*.json, and states saved by the program).
//
// Every key is optional unless marked "required"; an omitted key takes the
// default of scenes::Scene. Units: m, s, kg, degrees.
//
// {
//   "title": "Single bounce",
//   "slide": "Rigid spheres 4/14",                 which lecture slide it shows
//   "description": "Watch ... Move beta ...",      1-2 sentences for the UI
//   "box": {"size": [2, 2, 2], "tilt": 0},         m; degrees about +y through the box
//                                                  centre, in [-90, 90]. null or absent:
//                                                  no box. "size" defaults to [2, 2, 2]
//   "planes": [{"point": [0, 0, 0.3],              m, required
//               "normal": [-0.34, 0, 0.94],        required, not zero; normalised on load
//               "thickness": 0.02}],               m, >= 0, default 0: a half-space (solid
//                                                  behind the plane); > 0: a thin wall of
//                                                  that thickness centred on the plane, free
//                                                  on both sides (a sphere meets the face on
//                                                  its centre's side, so one whose centre
//                                                  jumps past the middle in one step tunnels)
//   "parameters": {"alpha": 1, "method": "position", ...},
//                                                  keys, ranges and choice names are those
//                                                  of parameterTable(); count and radius
//                                                  act on the generators below, emit_period
//                                                  on the first emitter
//   "seed": 7,                                     integer in [0, 2^53]
//   "spheres": [{"p": [0, 0, 1.5],                 m, required
//                "v": [0, 0, 0],                   m/s, default 0
//                "r": 0.1,                         m, > 0, default 0.05
//                "m": 1}],                         kg, > 0, default 1
//   "generate": [{"kind": "lattice",               "lattice" or "random" (default)
//                 "count": 1000,                   required, in [0, 1000000]
//                 "region": {"min": [-0.9, -0.9, 0.5], "max": [0.9, 0.9, 1.9]},
//                                                  m; each sphere lies wholly inside; must
//                                                  lie inside the box
//                 "radius": [0.04, 0.06],          m: a number, or [min, max] (uniform)
//                 "density": 1000,                 kg/m^3 (default 1000), or instead
//                 "mass": 0.5,                     kg, the same for every sphere
//                 "velocity": [0, 0, 0],           m/s, mean
//                 "velocitySpread": 0.2,           m/s: each component uniform in mean +- it
//                 "seed": 3}],                     default: derived from the scene seed
//   "emitters": [{"period": 0.1,                   s, required: one sphere every T seconds,
//                                                  the range of the emit_period parameter
//                 "position": [0, 0, 1.8],         m, required; the largest sphere must fit
//                                                  inside the box there
//                 "velocity": [0, 0, -1],          m/s, mean, default 0
//                 "spread": 0.5,                   m/s, >= 0: each component uniform in
//                                                  mean +- spread, drawn from the scene seed
//                 "radius": [0.04, 0.06],          m: a number or [min, max] (default 0.05)
//                 "density": 1000,                 kg/m^3 (default 1000), or instead "mass"
//                 "max": 300,                      spheres at most, default 100
//                 "emitted": 12}],                 already emitted (saved states), <= max
//   "claims": [{"says": "1.41 m", "measure": "apex", "nth": 1, "near": 1.41, "within": 0.005}],
//                                                  what the preset's texts claim, as the lab-sheet
//                                                  test runs it: the keys are in claims.h. Not
//                                                  written to saved states
//   "time": 1.25,                                  s: saved states only (see below)
//   "steps": 300                                   solver steps taken: saved states only
// }
//
// A file with "time" is a saved state: the world resumes at that time, and
// its spheres may overlap or touch a wall a little, as contacts do while the
// solver runs (only a centre past a wall or an overlap deeper than the smaller
// radius is refused). Without "time", spheres must not overlap at all.
//
// Bad input throws SceneError whose what() is one line "file:line:col: what is
// wrong": JSON syntax, unknown or repeated keys (with the closest valid key),
// wrong types, non-finite numbers (1e999), values out of range, unknown choice
// names, zero normals, overlapping spheres or spheres outside the box (by
// index), generator regions outside the box or too small for their count.
#include <string>
#include <string_view>

#include "physics/world.h"
#include "scenes/scene.h"

namespace scenes {

// Reads and checks a scene file (it also builds the world once, to check it).
Scene loadScene(const std::string& path);

// The same for a text; `filename` is the name the error messages show.
Scene parseScene(std::string_view text, const std::string& filename);

// The text saveScene writes: the scene's metadata and parameters, and the
// world's current state as explicit spheres (no generators), with "time" and
// "steps", and the emitters with the count each has emitted so far. Numbers are written as the shortest decimals that read back as the
// same doubles, so loading the file and building it gives a bit-identical state.
// Throws SceneError if the state holds a non-finite number.
std::string sceneText(const Scene& scene, const physics::World& world);

// Writes sceneText to `path`; throws SceneError if the file cannot be written.
void saveScene(const std::string& path, const Scene& scene, const physics::World& world);

}  // namespace scenes
