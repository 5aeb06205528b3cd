#pragma once
// Turns the simulation into what the renderer and the panel read: the plain
// snapshot of spheres and planes, and the readouts. Shared by the window and the
// capture mode so both show the same thing.
#include "app/run/comparison.h"
#include "app/run/session.h"
#include "app/run/simulation.h"
#include "render/camera.h"
#include "render/frame_snapshot.h"
#include "ui/control_panel.h"

namespace app {

// The overlays the panel's view state asks for.
OverlayFlags overlayFlags(const ui::PanelState& view);
// The window's default view options with these overlays on: overlayFlags' inverse.
ui::PanelState viewShowing(const OverlayFlags& flags);

// Whether the overlays are drawn over everything (render::RenderStyle::overlayOnTop):
// in scenes of up to kOverlaysOnTopMaxSpheres spheres, where a contact point or an
// impulse would otherwise hide inside a sphere; in denser ones they are depth-tested,
// so that only the front layer shows. The contact graph's lines run between centres, inside
// the spheres: with it shown, up to kGraphOnTopMaxSpheres (a pyramid, a few stacks).
constexpr std::size_t kOverlaysOnTopMaxSpheres = 50;
constexpr std::size_t kGraphOnTopMaxSpheres = 200;
bool overlaysOnTop(const ui::PanelState& view, std::size_t sphereCount);

// Whether a view of this many spheres gets anti-aliased outlines (render::RenderStyle::
// antialiasEdges): the window and the page draw without samples, and blending the outlines
// over what is behind costs a software GL more than the spheres above kMostSpheresAntialiased
// (llvmpipe, 1280 x 720, 10k spheres: 9 ms a frame hard, 14 blended), where the window is to
// keep 30 frames per second. Above, the outlines are hard (the readouts say so).
constexpr std::size_t kMostSpheresAntialiased = 5000;
inline bool outlinesAntialiased(std::size_t sphereCount) { return sphereCount <= kMostSpheresAntialiased; }

// What the view options of the panel (colouring, overlays) ask to draw. It also
// tells the simulation which overlays are shown and which sphere is selected, so
// that it records contacts and trails from the next step on, and only then.
void buildSnapshot(Simulation& simulation, const ui::PanelState& view, render::FrameSnapshot& snapshot);

// The readouts of `simulation` (view A side by side); with `comparison`, the claims of the
// text that the other views measure are listed too, each with its view's letter.
ui::Readouts makeReadouts(const Simulation& simulation, const ui::FrameTimes& timing,
                          const Comparison* comparison = nullptr);
// "sphere #12: |v| 0.59 cm/s" for the session's selected sphere, as the view it was clicked
// in runs it (side by side: "sphere #12 in view B: ..."); "" when none is selected
// (ui::Readouts::selected).
std::string selectedSpeedLine(const Session& session);
// Only the claims' part of them: r.claims and claimsWatched (every view's), and
// claimsForOtherSettings and claimsInterrupted (view A's: the views are edited together).
void addMeasuredClaims(const Simulation& simulation, const Comparison* comparison, ui::Readouts& r);

// What the camera fits, axis-aligned, m: the scene's camera "fits", else the box, else the
// spheres (and at least [-1, 1] m on every axis).
void sceneBounds(const Simulation& simulation, glm::vec3& lo, glm::vec3& hi);
// The scene's camera angles (the three-quarter view's where it gives none), not yet fitted.
render::Camera sceneCameraAngles(const scenes::Scene& scene);
// The camera a scene opens with, and C puts back: its angles, sceneBounds fitted in a view
// of `aspect` (width / height).
render::Camera openingCamera(const Simulation& simulation, float aspect);

}  // namespace app
