#pragma once
// Camera paths for multi-frame runs, shared by every command.

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
};

inline constexpr EnumName<CameraPath> kCameraPathNames[] = {
    {CameraPath::fixed, "static"},
    {CameraPath::orbit, "orbit"},
    {CameraPath::flythrough, "flythrough"},
};
/// "static", "orbit" or "flythrough", or "unknown camera path 'NAME' (expected ...)".
inline Result<CameraPath> parseCameraPath(std::string_view name) {
    return parseEnum<CameraPath>(kCameraPathNames, name, "camera path");
}
inline const char* cameraPathName(CameraPath path) {
    return enumName<CameraPath>(kCameraPathNames, path);
}

/// The camera of frame `frame` (0 = the base camera itself, except for flythrough, which starts
/// on its circle) for a scene whose first frame has the given bounds.
CameraSpec cameraOnPath(const CameraSpec& base, CameraPath path, int frame, const Bounds& bounds);

/// Seconds between frames of a dynamic scene.
inline constexpr double kFrameInterval = 1.0 / 30.0;

} // namespace vissort
