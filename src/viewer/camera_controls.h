#pragma once
// How the viewer's mouse and keys move a camera, as pure functions of a CameraSpec: the same
// conventions as mesh viewers (MeshLab, Polyscope, Blender's orbit), testable without a window.
// Perspective cameras take every control; an orthographic camera (which frames the whole scene
// along its direction, camera.h) only turns: orbit rotates its direction, the rest leave it.

#include "vissort/camera.h"
#include "vissort/geometry.h"

namespace vissort::viewer {

/// Orbit: radians the camera turns per pixel dragged.
inline constexpr double kOrbitRadiansPerPixel = 0.01;
/// Zoom: the distance to the target is multiplied by this per wheel step towards the scene.
inline constexpr double kZoomPerStep = 0.9;
/// Fly: one key press moves the eye and target by this fraction of the scene's radius.
inline constexpr double kFlyStepOfRadius = 0.05;

/// Turns the eye about the target: dx pixels to the right turn it by -dx * kOrbitRadiansPerPixel
/// about the up axis (the scene turns right), dy pixels down raise it by dy * that angle towards
/// up (never over the pole: within 0.01 rad of it).
CameraSpec orbit(const CameraSpec& camera, double dx, double dy);

/// Moves eye and target together so that the point under the cursor follows it: dx pixels right
/// move the scene right, dy down move it down (at the target's distance, for an image height
/// pixels high).
CameraSpec pan(const CameraSpec& camera, double dx, double dy, double height);

/// Moves the eye towards the target by kZoomPerStep per step (negative steps move away), never
/// nearer than min_distance.
CameraSpec zoom(const CameraSpec& camera, double steps, double min_distance);

/// Moves eye and target along the view direction (forward), the image's right and the up
/// vector, by these multiples of step.
CameraSpec fly(const CameraSpec& camera, double forward, double right, double up, double step);

/// The whole of bounds in view from the current direction: the target at its centre, the eye
/// far enough back that its bounding sphere fits the vertical field of view.
CameraSpec frameBounds(const CameraSpec& camera, const Bounds& bounds);

} // namespace vissort::viewer
