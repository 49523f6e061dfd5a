#pragma once
// Cameras shared by every command: perspective (glm::lookAt / glm::perspective conventions) and
// orthographic along a direction, framing a scene's bounding sphere.
//
// Depth representation, used by every oracle and by the ground truth alike: d in [0, 1), smaller
// is nearer, computed from the distance z along the view direction:
//   perspective:  d = 1 - near / z       (infinite far plane; affine in screen space)
//   orthographic: d = (z - near) / (far - near)
// Pixel (px, py) has its centre at (px + 0.5, py + 0.5); row 0 is the top of the image.

#include <array>
#include <cstdint>
#include <string>

#include "vissort/geometry.h"
#include "vissort/result.h"

namespace vissort {

enum class Projection { perspective, orthographic };

/// What the user asks for. Fields left unset are derived from the scene by `frameCamera`.
struct CameraSpec {
    Projection projection = Projection::perspective;
    Vec3 eye{0, 0, 5};
    Vec3 target{0, 0, 0};
    Vec3 up{0, 1, 0};
    double fov_degrees = 45.0; // vertical field of view
    Vec3 ortho_direction{0, 0, -1};
};

/// A camera ready to project: column-major 4x4 matrices (OpenGL layout) and the image size.
struct ViewProjection {
    Projection projection = Projection::perspective;
    uint32_t width = 1024, height = 1024;
    std::array<double, 16> view{};              // world -> eye space (camera looks along -z)
    std::array<double, 16> projection_matrix{}; // eye -> clip space, z_clip / w_clip = d
    double near = 0.1, far = 1.0;               // far is unused (infinite) for perspective
    Vec3 eye_position; // perspective eye; orthographic: the eye plane's centre,
                       // 2r before the sphere's centre (behind the near plane)
    Vec3 forward;      // unit view direction

    /// Depth d of a world point (see the header comment); may be outside [0,1) when clipped.
    double depthOf(const Vec3& world) const;
    /// Clip-space position (x, y, z, w) of a world point.
    std::array<double, 4> toClip(const Vec3& world) const;
    /// The ray through screen point (px, py), in pixels from the top-left corner of the image:
    /// pixel (i, j) is sampled at (i + 0.5, j + 0.5). Origin and unit direction, world space.
    void pixelRay(double px, double py, Vec3& origin, Vec3& direction) const;
};

/// The default view of a scene: perspective, 45 degrees vertically, looking at the bounding
/// sphere's centre from the direction (0.6, 0.5, 1), far enough that the whole sphere fits in an
/// image of the given aspect ratio (width / height) with a 5% margin.
CameraSpec defaultCamera(const Bounds& scene_bounds, double aspect = 1.0);

/// Builds the view and projection for a camera over a scene.
/// Perspective: near = max(distance to the sphere - r, r * 1e-3) * 0.99; far = infinity.
/// Orthographic: frames the sphere (half-height r, half-width r * aspect); near/far enclose it.
/// width and height must be at least 1; the camera must not be degenerate (eye == target,
/// up parallel to the view direction, zero direction, fov outside (0, 180)): see validateCamera.
ViewProjection frameCamera(const CameraSpec& camera, const Bounds& scene_bounds, uint32_t width,
                           uint32_t height);

/// Whether the camera is usable; the error says in one line what is wrong.
Status validateCamera(const CameraSpec& camera);

} // namespace vissort
