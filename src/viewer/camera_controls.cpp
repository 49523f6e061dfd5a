// The viewer's camera controls (camera_controls.h).

#include "viewer/camera_controls.h"

#include <algorithm>
#include <cmath>

namespace vissort::viewer {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kPoleMargin = 0.01; // radians kept between the view and the up axis

// v turned by angle about the unit axis (Rodrigues).
Vec3 rotate(const Vec3& v, const Vec3& axis, double angle) {
    const double c = std::cos(angle), s = std::sin(angle);
    return v * c + cross(axis, v) * s + axis * (dot(axis, v) * (1 - c));
}

// The image's right and up directions for a view direction and an up vector.
void imageAxes(const Vec3& forward, const Vec3& up, Vec3& right, Vec3& image_up) {
    right = normalized(cross(forward, up));
    image_up = cross(right, forward);
}

// offset turned about the up axis by yaw, then towards up by pitch, kept off the pole.
Vec3 turn(const Vec3& offset, const Vec3& up_vector, double yaw, double pitch) {
    const Vec3 up = normalized(up_vector);
    Vec3 turned = rotate(offset, up, yaw);
    const double angle = std::acos(std::clamp(dot(normalized(turned), up), -1.0, 1.0));
    const double next = std::clamp(angle - pitch, kPoleMargin, kPi - kPoleMargin);
    const Vec3 right = normalized(cross(up, turned));
    if (length(right) == 0) // on the pole already: only the yaw applies
        return turned;
    return rotate(turned, right, -(angle - next));
}

} // namespace

CameraSpec orbit(const CameraSpec& camera, double dx, double dy) {
    CameraSpec out = camera;
    const double yaw = -dx * kOrbitRadiansPerPixel, pitch = dy * kOrbitRadiansPerPixel;
    if (camera.projection == Projection::orthographic) {
        // The direction points at the scene: the eye's offset is its opposite.
        out.ortho_direction = -turn(-camera.ortho_direction, camera.up, yaw, pitch);
        return out;
    }
    out.eye = camera.target + turn(camera.eye - camera.target, camera.up, yaw, pitch);
    return out;
}

CameraSpec pan(const CameraSpec& camera, double dx, double dy, double height) {
    if (camera.projection == Projection::orthographic || height <= 0)
        return camera;
    const Vec3 offset = camera.target - camera.eye;
    const double distance = length(offset);
    Vec3 right, image_up;
    imageAxes(normalized(offset), camera.up, right, image_up);
    const double per_pixel = 2 * distance * std::tan(camera.fov_degrees * kPi / 360) / height;
    const Vec3 move = (right * -dx + image_up * dy) * per_pixel;
    CameraSpec out = camera;
    out.eye = camera.eye + move;
    out.target = camera.target + move;
    return out;
}

CameraSpec zoom(const CameraSpec& camera, double steps, double min_distance) {
    if (camera.projection == Projection::orthographic)
        return camera;
    const Vec3 offset = camera.eye - camera.target;
    const double distance = std::max(length(offset) * std::pow(kZoomPerStep, steps), min_distance);
    CameraSpec out = camera;
    out.eye = camera.target + normalized(offset) * distance;
    return out;
}

CameraSpec fly(const CameraSpec& camera, double forward, double right, double up, double step) {
    if (camera.projection == Projection::orthographic)
        return camera;
    Vec3 right_axis, image_up;
    const Vec3 view = normalized(camera.target - camera.eye);
    imageAxes(view, camera.up, right_axis, image_up);
    const Vec3 move = (view * forward + right_axis * right + normalized(camera.up) * up) * step;
    CameraSpec out = camera;
    out.eye = camera.eye + move;
    out.target = camera.target + move;
    return out;
}

CameraSpec frameBounds(const CameraSpec& camera, const Bounds& bounds) {
    if (bounds.isEmpty())
        return camera;
    CameraSpec out = camera;
    out.target = bounds.centre();
    if (camera.projection == Projection::orthographic)
        return out;
    Vec3 direction = normalized(camera.eye - camera.target);
    if (length(direction) == 0)
        direction = {0, 0, 1};
    const double half_fov = camera.fov_degrees * kPi / 360;
    out.eye = out.target + direction * (std::max(bounds.radius(), 1e-9) / std::sin(half_fov));
    return out;
}

} // namespace vissort::viewer
