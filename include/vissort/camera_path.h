#pragma once
// Camera paths for multi-frame runs, shared by every command.
//
// Layer: vissort::geometry (the package's `order` component; docs/architecture.md).

#include <span>
#include <string>

#include "vissort/camera.h"
#include "vissort/enum_names.h"

namespace vissort {

enum class CameraPath {
    fixed,      // "static": the same camera every frame
    orbit,      // the eye, target and up (or the orthographic direction) turn 3 degrees per
                // frame about the vertical axis through the scene's centre
    flythrough, // the eye flies inside the scene on a horizontal circle of radius 0.6 r around
                // the centre, 2 degrees per frame, looking along its direction of travel;
                // an orthographic camera has no inside, so it orbits instead
    scene,      // the scene's own key frames (Scene::camera_path), by time: cameraAtTime
};

/// A key frame of a camera path: a perspective camera at a time (seconds from frame 0).
struct CameraKey {
    double time = 0;
    CameraSpec camera;
};

/// The camera at `time` on a path of key frames (times increasing, cameras perspective): eye,
/// target, up and field of view interpolated linearly between the two keys around it, the first
/// key's before it and the last key's after it. keys must not be empty. Between keys that look
/// opposite ways the mix can be unusable (the eye on the target, up along the view): callers
/// check it with validateCamera (the command line does, for every frame).
CameraSpec cameraAtTime(std::span<const CameraKey> keys, double time);

inline constexpr EnumName<CameraPath> kCameraPathNames[] = {
    {CameraPath::fixed, "static"},
    {CameraPath::orbit, "orbit"},
    {CameraPath::flythrough, "flythrough"},
    {CameraPath::scene, "scene"},
};
/// "static", "orbit", "flythrough" or "scene", or "unknown camera path 'NAME' (expected ...)".
inline Result<CameraPath> parseCameraPath(std::string_view name) {
    return parseEnum<CameraPath>(kCameraPathNames, name, "camera path");
}
inline const char* cameraPathName(CameraPath path) {
    return enumName<CameraPath>(kCameraPathNames, path);
}

/// Seconds between frames (a dynamic scene's time, a scene path's clock).
inline constexpr double kFrameInterval = 1.0 / 30.0;

/// The camera of frame `frame` (0 = the base camera itself, except for flythrough, which starts
/// on its circle) for a scene whose first frame has the given bounds. CameraPath::scene follows
/// scene_keys (cameraAtTime at frame * kFrameInterval), or stays at base where there are none.
CameraSpec cameraOnPath(const CameraSpec& base, CameraPath path, int frame, const Bounds& bounds,
                        std::span<const CameraKey> scene_keys = {});

} // namespace vissort
