#include "vissort/camera_path.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>

namespace vissort {
namespace {

// Rotation about the vertical axis through `centre`.
Vec3 turnAboutVertical(const Vec3& p, const Vec3& centre, double radians) {
    const double c = std::cos(radians), s = std::sin(radians);
    const double dx = p.x - centre.x, dz = p.z - centre.z;
    return {centre.x + c * dx + s * dz, p.y, centre.z - s * dx + c * dz};
}

double degrees(double d) {
    return d * std::numbers::pi / 180.0;
}

} // namespace

CameraSpec cameraAtTime(std::span<const CameraKey> keys, double time) {
    assert(!keys.empty());
    if (time <= keys.front().time)
        return keys.front().camera;
    if (time >= keys.back().time)
        return keys.back().camera;
    // The first key after time; the one before it is at or before time.
    const auto after =
        std::upper_bound(keys.begin(), keys.end(), time,
                         [](double t, const CameraKey& key) { return t < key.time; });
    const CameraKey& a = *(after - 1);
    const CameraKey& b = *after;
    const double s = (time - a.time) / (b.time - a.time);
    const auto mix = [s](const Vec3& p, const Vec3& q) {
        return Vec3{p.x + s * (q.x - p.x), p.y + s * (q.y - p.y), p.z + s * (q.z - p.z)};
    };
    CameraSpec camera = a.camera;
    camera.eye = mix(a.camera.eye, b.camera.eye);
    camera.target = mix(a.camera.target, b.camera.target);
    camera.up = mix(a.camera.up, b.camera.up);
    camera.fov_degrees = a.camera.fov_degrees + s * (b.camera.fov_degrees - a.camera.fov_degrees);
    return camera;
}

CameraSpec cameraOnPath(const CameraSpec& base, CameraPath path, int frame, const Bounds& bounds,
                        std::span<const CameraKey> scene_keys) {
    if (path == CameraPath::fixed)
        return base;
    if (path == CameraPath::scene)
        return scene_keys.empty() ? base : cameraAtTime(scene_keys, frame * kFrameInterval);
    CameraSpec camera = base;
    const Vec3 centre = bounds.centre();
    if (path == CameraPath::orbit || camera.projection == Projection::orthographic) {
        const double angle = degrees(3.0 * frame);
        if (camera.projection == Projection::orthographic) {
            camera.ortho_direction = turnAboutVertical(base.ortho_direction, {}, angle);
        } else {
            camera.eye = turnAboutVertical(base.eye, centre, angle);
            camera.target = turnAboutVertical(base.target, centre, angle);
            // up turns with the eye: a tilted up stays valid and the image does not roll.
            camera.up = turnAboutVertical(base.up, {}, angle);
        }
        return camera;
    }
    const double r = bounds.radius() > 0 ? bounds.radius() : 1.0;
    const double angle = degrees(2.0 * frame), ahead = angle + degrees(10.0);
    camera.eye = {centre.x + 0.6 * r * std::cos(angle), centre.y,
                  centre.z + 0.6 * r * std::sin(angle)};
    camera.target = {centre.x + 0.6 * r * std::cos(ahead), centre.y,
                     centre.z + 0.6 * r * std::sin(ahead)};
    camera.up = {0, 1, 0};
    return camera;
}

} // namespace vissort
