#pragma once
// Cameras shared by every command: perspective (glm::lookAt / glm::perspective conventions) and
// orthographic along a direction, framing a scene's bounding sphere.
//
// Depth representation, used by every oracle and by the ground truth alike: d in [0, 1), smaller
// is nearer, computed from the distance z along the view direction:
//   perspective:  d = 1 - near / z       (infinite far plane; affine in screen space)
//   orthographic: d = (z - near) / (far - near)
// Pixel (px, py) has its centre at (px + 0.5, py + 0.5); row 0 is the top of the image.
//
// Layer: vissort::geometry (the package's `order` component; docs/architecture.md).

#include <array>
#include <cstdint>
#include <span>
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

/// The screen rectangle that points project into, in pixels from the top-left corner (as the
/// rasterizers place a corner: ((x/w + 1) / 2 * width, (1 - y/w) / 2 * height)), grown one point
/// at a time; `wraps` once a point lies at or behind the eye plane, where corners bound nothing.
struct ScreenExtent {
    double low_x = 1e300, low_y = 1e300, high_x = -1e300, high_y = -1e300;
    bool wraps = false;

    void add(const ViewProjection& view, const Vec3& point) {
        const std::array<double, 4> clip = view.toClip(point);
        if (!(clip[3] > 0)) {
            wraps = true;
            return;
        }
        const double x = (clip[0] / clip[3] + 1) * 0.5 * view.width;
        const double y = (1 - clip[1] / clip[3]) * 0.5 * view.height;
        low_x = x < low_x ? x : low_x;
        high_x = x > high_x ? x : high_x;
        low_y = y < low_y ? y : low_y;
        high_y = y > high_y ? y : high_y;
    }
    bool isEmpty() const { return !(low_x <= high_x && low_y <= high_y); }
};

/// Whether no point of box can be seen in view: every corner is outside one plane of the clip
/// volume, the same plane (left, right, bottom, top: |x|, |y| <= w; or near: z >= 0), so their
/// hull is too. Conservative: a box within a rounding error of a plane (1e-5 of the corner's
/// clip coordinates, the GPU's float transform) counts as seen; the far plane is not tested
/// (perspective views have none). An empty box is outside.
bool boxOutsideView(const Bounds& box, const ViewProjection& view);

/// The default view of a scene: perspective, 45 degrees vertically, looking at the bounding
/// sphere's centre from the direction (0.6, 0.5, 1), far enough that the whole sphere fits in an
/// image of the given aspect ratio (width / height) with a 5% margin.
CameraSpec defaultCamera(const Bounds& scene_bounds, double aspect = 1.0);

/// The orientation of every default view: perspective, 45 degrees, up 0,1,0, eye in the
/// direction (0.6, 0.5, 1) from the target at the origin.
CameraSpec defaultOrientation();

/// The default view of the geometry itself, framed as mesh viewers frame it: `orientation`'s
/// view direction (target - eye), up and field of view (by default perspective, 45 degrees
/// vertically, up 0,1,0, looking from the direction (0.6, 0.5, 1)), and as close as the points
/// allow: every point inside an image of the given aspect ratio with a 5% margin on each side,
/// the extent that binds touching the margin on both sides, the other centred. The eye stays at
/// least 1.1 radii of the bounding sphere from its centre, so an object seen end-on keeps a
/// usable near plane. Deterministic. No points: the default camera of a unit sphere at the
/// origin. An unusable orientation (validateCamera) is replaced by the default one.
CameraSpec framingCamera(std::span<const Vec3> points, double aspect = 1.0,
                         const CameraSpec& orientation = defaultOrientation());
CameraSpec framingCamera(PositionsView positions, double aspect = 1.0,
                         const CameraSpec& orientation = defaultOrientation());

/// The orientation of a view from azimuth and elevation in degrees about the y axis: eye
/// direction (sin az cos el, sin el, cos az cos el) from the target (azimuth 0 looks along -z,
/// 90 along -x; elevation 90 looks straight down), up the direction of rising elevation (0,1,0
/// at elevation 0: never parallel to the view), 45 degrees field of view. Eye at that direction,
/// target at the origin: move both, or frame it with framingCamera.
CameraSpec orbitOrientation(double azimuth_degrees, double elevation_degrees);

/// Builds the view and projection for a camera over a scene.
/// Perspective: near = max(distance to the sphere - r, r * 1e-3) * 0.99; far = infinity.
/// Orthographic: frames the sphere (half-height r, half-width r * aspect); near/far enclose it.
/// width and height must be at least 1; the camera must not be degenerate (eye == target,
/// up parallel to the view direction, zero direction, fov outside (0, 180)): see validateCamera.
ViewProjection frameCamera(const CameraSpec& camera, const Bounds& scene_bounds, uint32_t width,
                           uint32_t height);

/// The largest image side and pixel count a view may ask for: beyond them a depth buffer stops
/// being a sensible request on one machine (16384^2 floats = 1 GiB).
inline constexpr uint32_t kMaxImageSide = 16384;
inline constexpr uint64_t kMaxImagePixels = uint64_t(kMaxImageSide) * kMaxImageSide / 4;
/// Whether width x height is within those limits, each side at least 1; the error reads
/// "WxH is out of range: each side 1..16384, at most 67108864 pixels".
Status validateImageSize(uint64_t width, uint64_t height);
/// A camera in one line: "perspective from 1.2,3,4 towards 0,0,0, up 0,1,0, fov 45 degrees" or
/// "orthographic along 0,0,-1"; numbers with 4 significant digits.
std::string describeCamera(const CameraSpec& camera);
/// Whether the camera is usable; the error says in one line what is wrong.
Status validateCamera(const CameraSpec& camera);

} // namespace vissort
