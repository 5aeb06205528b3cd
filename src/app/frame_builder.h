#pragma once
// Turns the simulation into what the renderer and the panel read: the plain
// snapshot of spheres and planes, and the readouts. Shared by the window and the
// capture mode so both show the same thing.
#include "app/simulation.h"
#include "render/frame_snapshot.h"
#include "ui/control_panel.h"

namespace app {

// What the view options of the panel (colouring, overlays) ask to draw.
void buildSnapshot(const Simulation& simulation, const ui::PanelState& view, render::FrameSnapshot& snapshot);

ui::Readouts makeReadouts(const Simulation& simulation, double fps, double renderMs);

// Axis-aligned bounds of the box (or of the spheres when there is none), m, for the camera.
void sceneBounds(const Simulation& simulation, glm::vec3& lo, glm::vec3& hi);

// The scene's viewport (x, y, width, height; GL's lower-left origin) in a framebuffer
// of `size` pixels whose left `panelPixels` belong to the panel.
glm::ivec4 viewportRightOf(glm::ivec2 size, float panelPixels);

}  // namespace app
