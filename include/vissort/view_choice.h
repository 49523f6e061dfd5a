#pragma once
// Which camera a run of a scene looks through, from what the user asked for: the one policy the
// command line (--eye, --azimuth, --camera, --path, ...), the viewer and the Python module share.
// Nothing asked: the scene's own camera (a mesh file's first usable one), else the geometry
// framed as mesh viewers frame it, over the frames that will run.
//
// Layer: vissort::scene (the package's `scene` component; docs/architecture.md).

#include <cstdint>
#include <optional>
#include <string>

#include "vissort/camera.h"
#include "vissort/camera_path.h"
#include "vissort/result.h"
#include "vissort/scene.h"

namespace vissort {

/// The most frames a run may ask for.
inline constexpr int kMaxFrames = 100000;

/// How chooseView's messages name the request's fields: as the command line's options
/// ("--ortho-dir", "--fov") or as Python's keywords ("ortho_dir", "fov_deg").
enum class OptionNames { command_line, python };

/// What the user asked of the camera; every field unset means "not asked".
struct ViewDef {
    // A perspective camera's parts; the ones not given are the scene camera's, or target the
    // scene's centre, up (0, 1, 0), 45 degrees.
    std::optional<Vec3> eye, target, up;
    std::optional<double> fov_degrees;
    /// An orthographic view along this direction, framing the scene.
    std::optional<Vec3> ortho_direction;
    /// A camera the mesh file stores, by name or index (findStoredCamera); "framed": none of
    /// them, the geometry framed as for a scene without a camera.
    std::string stored_camera;
    /// The eye around the scene's centre: degrees about the vertical axis (0 looks along -z),
    /// degrees above the horizontal, and the distance (default: framed).
    std::optional<double> azimuth_degrees, elevation_degrees, distance;
    uint32_t width = 1024, height = 1024;
    int frames = 1; // 1 to kMaxFrames
    CameraPath path = CameraPath::fixed;
    OptionNames names = OptionNames::command_line;
};

/// The camera chosen, with the image size, path and frames it was chosen for.
struct ChosenView {
    CameraSpec camera;
    uint32_t width = 0, height = 0;
    CameraPath path = CameraPath::fixed;
    int frames = 1;
    /// Where the camera came from, for people: "framed to the geometry", "the scene's camera",
    /// "the file's camera 1 'Camera.002'", "--azimuth/--elevation, framed", ...
    std::string source;
    /// The index in scene.cameras of the camera when it is a mesh file's stored camera used as
    /// stored (no option changed it), else none.
    std::optional<std::size_t> stored_camera;
};

/// The share of the scene's surface at t = 0 that a width x height view through camera shows,
/// 0 to 1: of 4096 points spread over the triangles by area (each at a low-discrepancy spot of
/// its triangle), those in front of the eye and inside the image. A file's camera inside a mesh
/// scaled 100x sees a sliver; one framing a quad that reaches past the image still sees most of
/// it, which its corners alone would not say. One walk over the triangles, no allocation.
double shareOfSurfaceInView(const Scene& scene, const CameraSpec& camera, uint32_t width,
                            uint32_t height);

/// Below this share in view, a mesh file's camera is worth a warning that says how to frame the
/// scene instead (--camera framed); below kMostInView, a note that it crops the scene.
inline constexpr double kFewInView = 0.05, kMostInView = 0.95;

/// The view `def` asks for of `scene`, or a one-line error naming the fields that cannot be
/// combined or the camera that cannot be used (and where it came from: the request, the file,
/// the scene's camera path at a frame). width and height must already be valid image sizes.
Result<ChosenView> chooseView(const ViewDef& def, const Scene& scene);

} // namespace vissort
