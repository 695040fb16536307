#pragma once
// Viewport navigation as pure functions of a Camera, so the editor's mouse and keyboard
// handling is testable without a window. Units: pixel deltas of the viewport of height
// `viewportHeight`; the look-at point is the orbit centre, as in Blender and most DCC tools.
#include "render/scene/scene.h"

namespace pt::editor {

// Turntable orbit around the look-at point: horizontal drag turns about world +Y, vertical
// drag tilts, stopping short of the poles so the view never flips.
Camera orbitCamera(const Camera& camera, float dxPixels, float dyPixels, float viewportHeight);
// Moves eye and look-at together so the point under the cursor follows it.
Camera panCamera(const Camera& camera, float dxPixels, float dyPixels, float viewportHeight);
// Wheel: each step moves the eye 15% of the way to the look-at point (or back out).
Camera dollyCamera(const Camera& camera, float wheelSteps);
// WASD fly: forward/right/up in [-1, 1] for `seconds`, at `speed` world units per second.
Camera flyCamera(const Camera& camera, float forward, float right, float up, float seconds, float speed);
// A fly speed that crosses the scene's bounds in about four seconds.
float flySpeedFor(const Scene& scene);

}  // namespace pt::editor
