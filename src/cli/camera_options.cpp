#include <charconv>
#include <cmath>
#include <iostream>
#include <numbers>

#include "cli/cli_common.h"
#include "cli/text_output.h"
#include "scenes/scene_library.h"

namespace vissort::cli {
namespace {

constexpr int kMaxFrames = 100000;

bool parseDouble(std::string_view text, double& value) {
    if (text.empty())
        return false;
    const char* end = text.data() + text.size();
    auto [ptr, ec] = std::from_chars(text.data(), end, value);
    return ec == std::errc() && ptr == end && std::isfinite(value);
}

std::string parseVec3(const std::string& option, const std::string& text, Vec3& out) {
    double v[3];
    std::size_t start = 0;
    for (int i = 0; i < 3; ++i) {
        const std::size_t comma = text.find(',', start);
        const bool last = i == 2;
        if ((comma == std::string::npos) != last)
            return option + " expects X,Y,Z (three finite numbers), got '" + text + "'";
        const std::string_view part(text.data() + start, (last ? text.size() : comma) - start);
        if (!parseDouble(part, v[i]))
            return option + " expects X,Y,Z (three finite numbers), got '" + text + "'";
        start = comma + 1;
    }
    out = {v[0], v[1], v[2]};
    return {};
}

} // namespace

std::string parseSize(const std::string& text, uint32_t& width, uint32_t& height) {
    const std::size_t x = text.find('x');
    unsigned long w = 0, h = 0;
    const char* b = text.data();
    const char* e = b + text.size();
    if (x == std::string::npos || std::from_chars(b, b + x, w).ptr != b + x ||
        std::from_chars(b + x + 1, e, h).ptr != e || x == 0 || x + 1 == text.size())
        return "--size expects WxH (two positive integers), got '" + text + "'";
    if (Status valid = validateImageSize(w, h); !valid)
        return "--size " + valid.error;
    width = uint32_t(w);
    height = uint32_t(h);
    return {};
}

int fail(int code, const std::string& message) {
    if (colourOnStandardError())
        std::cerr << "vissort: \033[31merror:\033[0m " << message << '\n';
    else
        std::cerr << "vissort: error: " << message << '\n';
    return code;
}

int failWithoutGl(const std::string& what) {
    return fail(kExitFailure, "this vissort was built without OpenGL (VISSORT_WITH_GL=OFF): " +
                                  what + " is not available");
}

void addViewOptions(CLI::App& command, ViewOptions& options, bool with_frames) {
    command.add_option("--eye", options.eye,
                       "Perspective eye position X,Y,Z; the settings not given are the scene's "
                       "camera's, or target the scene's centre, up 0,1,0, fov 45");
    command.add_option("--target", options.target,
                       "Point looked at X,Y,Z (default: the scene camera's, or the scene's "
                       "centre)");
    command.add_option("--up", options.up, "Up vector X,Y,Z (default 0,1,0)");
    command.add_option("--fov", options.fov, "Vertical field of view in degrees (default 45)");
    command.add_option("--ortho-dir", options.ortho_dir,
                       "Orthographic view along X,Y,Z framing the scene's bounding sphere");
    command.add_option("--camera", options.camera,
                       "A camera the mesh file stores, by name or index (default: its first; "
                       "'vissort info SCENE' lists them)");
    command.add_option("--azimuth", options.azimuth,
                       "Degrees about the vertical (y) axis the eye sits at around the scene's "
                       "centre: 0 looks along -z, 90 along -x (default 31, the default view's)");
    command.add_option("--elevation", options.elevation,
                       "Degrees above the horizontal plane, -90 to 90 (default 24)");
    command.add_option("--distance", options.distance,
                       "Eye distance from the scene's centre (default: framed, as close as the "
                       "geometry fits)");
    command.add_option("--size", options.size, "Image size WxH")->capture_default_str();
    if (!with_frames)
        return;
    command.add_option("--frames", options.frames, "Number of frames")->capture_default_str();
    command
        .add_option("--path", options.path,
                    "Camera path: static, orbit, flythrough, or scene (the scene's own key "
                    "frames: builtin:powerplant's walkthrough, a JSON scene's camera_path)")
        ->capture_default_str();
}

std::string resolveView(const ViewOptions& options, const Scene& scene, ResolvedView& view) {
    if (auto error = parseSize(options.size, view.width, view.height); !error.empty())
        return error;
    if (options.frames < 1 || options.frames > kMaxFrames)
        return "--frames must be between 1 and " + std::to_string(kMaxFrames);
    view.frames = options.frames;
    const Result<CameraPath> path = parseCameraPath(options.path);
    if (!path)
        return "--path: " + path.error;
    view.path = *path.value;

    const bool perspective_given =
        !options.eye.empty() || !options.target.empty() || !options.up.empty() || options.fov;
    const bool orbit_given = options.azimuth || options.elevation || options.distance;
    if (orbit_given) {
        if (!options.eye.empty() || !options.target.empty() || !options.up.empty() ||
            !options.ortho_dir.empty() || !options.camera.empty())
            return "--azimuth, --elevation and --distance place the eye around the scene's centre: "
                   "they cannot be combined with --eye, --target, --up, --ortho-dir or --camera";
        if (options.azimuth && !std::isfinite(*options.azimuth))
            return "--azimuth must be a finite number of degrees";
        if (options.elevation && !(std::abs(*options.elevation) <= 90))
            return "--elevation must be between -90 and 90 degrees";
        if (options.distance && !(*options.distance > 0 && *options.distance < 1e30))
            return "--distance must be positive and below 1e30";
    }
    if (view.path == CameraPath::scene) {
        if (scene.camera_path.empty())
            return "--path scene: the scene has no camera path (a JSON scene's \"camera_path\": "
                   "docs/scene-format.md)";
        if (perspective_given || orbit_given || !options.ortho_dir.empty() ||
            !options.camera.empty())
            return "--path scene takes every frame's camera from the scene: it cannot be combined "
                   "with the camera options (--eye, --azimuth, --ortho-dir, --camera, ...)";
        // Between two valid key frames the mix can still be unusable (eye on target, up along
        // the view): say which frame.
        for (int frame = 0; frame < view.frames; ++frame) {
            const double time = frame * kFrameInterval;
            if (auto e = validateCamera(cameraAtTime(scene.camera_path, time)).error; !e.empty()) {
                std::ostringstream seconds;
                seconds << time;
                return "--path scene: frame " + std::to_string(frame) + " (" + seconds.str() +
                       " s into the scene's camera path): " + e;
            }
        }
    }
    // The scene's own camera: the one --camera picks, else its default one (a file's first).
    std::optional<CameraSpec> scene_camera = scene.camera;
    std::string scene_camera_source = "the scene's camera";
    const auto fileCamera = [&](std::size_t index) {
        return "the file's camera " + std::to_string(index) + " '" + scene.cameras[index].name +
               "'";
    };
    if (const std::optional<std::size_t> first = defaultStoredCamera(scene))
        scene_camera_source = fileCamera(*first);
    if (!options.camera.empty()) {
        if (!options.ortho_dir.empty())
            return "--camera cannot be combined with --ortho-dir";
        Result<std::size_t> picked = findStoredCamera(scene, options.camera);
        if (!picked)
            return "--camera: " + picked.error;
        scene_camera = scene.cameras[*picked.value].camera;
        scene_camera_source = fileCamera(*picked.value);
        if (perspective_given && scene_camera->projection == Projection::orthographic)
            return "--camera " + options.camera +
                   " is orthographic: --eye, --target, --up and --fov do not apply to it";
    }
    if (view.path == CameraPath::scene)
        view.camera_source = "the scene's camera path";
    else if (!options.ortho_dir.empty())
        view.camera_source = "--ortho-dir";
    if (!options.ortho_dir.empty()) {
        if (perspective_given)
            return "--ortho-dir cannot be combined with --eye, --target, --up or --fov";
        view.camera.projection = Projection::orthographic;
        if (auto e = parseVec3("--ortho-dir", options.ortho_dir, view.camera.ortho_direction);
            !e.empty())
            return e;
    } else {
        const Bounds bounds = scene.positions.bounds();
        const double aspect = double(view.width) / view.height;
        // Without a camera of the scene's own, the geometry framed as mesh viewers frame it; an
        // eye given alone still looks at the scene's centre, as documented.
        const bool framed =
            !scene_camera || orbit_given ||
            (perspective_given && scene_camera->projection == Projection::orthographic);
        CameraSpec orientation = defaultOrientation();
        if (orbit_given) {
            // Unset angles stay the default view's (0.6, 0.5, 1): azimuth 31, elevation 24.
            const Vec3 d = normalized(orientation.eye);
            orientation = orbitOrientation(
                options.azimuth.value_or(std::atan2(d.x, d.z) * 180 / std::numbers::pi),
                options.elevation.value_or(std::asin(d.y) * 180 / std::numbers::pi));
        }
        // A field of view for a framed view is framed with, so the framing stays tight.
        if (options.fov && options.eye.empty() && options.target.empty())
            orientation.fov_degrees = *options.fov;
        view.camera =
            framed ? framingCameraOf(scene, aspect, view.frames, orientation) : *scene_camera;
        if (view.path != CameraPath::scene)
            view.camera_source = orbit_given
                                     ? (options.distance ? "--azimuth/--elevation/--distance"
                                                         : "--azimuth/--elevation, framed")
                                 : framed ? "framed to the geometry"
                                          : scene_camera_source;
        if (perspective_given && !orbit_given)
            view.camera_source += ", changed by the options";
        if (framed && !options.eye.empty())
            view.camera.target = bounds.centre();
        if (options.distance) {
            view.camera.target = bounds.centre();
            view.camera.eye = bounds.centre() + normalized(orientation.eye) * *options.distance;
        }
        if (!options.eye.empty())
            if (auto e = parseVec3("--eye", options.eye, view.camera.eye); !e.empty())
                return e;
        if (!options.target.empty())
            if (auto e = parseVec3("--target", options.target, view.camera.target); !e.empty())
                return e;
        if (!options.up.empty())
            if (auto e = parseVec3("--up", options.up, view.camera.up); !e.empty())
                return e;
        if (options.fov)
            view.camera.fov_degrees = *options.fov;
    }
    if (auto e = validateCamera(view.camera).error; !e.empty()) {
        // Name where the bad camera came from: the user's options, or the scene file.
        if (!options.ortho_dir.empty())
            return "--ortho-dir: " + e;
        if (orbit_given)
            return "--azimuth/--elevation/--distance/--fov: " + e;
        if (perspective_given)
            return "--eye/--target/--up/--fov: " + e;
        if (!options.camera.empty())
            return "--camera " + options.camera + ": " + e;
        return "the scene's camera: " + e;
    }
    return {};
}

std::string cameraLine(const ResolvedView& view) {
    std::string line = "camera: " + describeCamera(view.camera) + " (" + view.camera_source + ")";
    if (view.frames > 1 && view.path != CameraPath::fixed)
        line += std::string("; --path ") + cameraPathName(view.path) + " moves it every frame";
    return line;
}

std::optional<Scene> loadSceneOrReport(const std::string& specification) {
    Result<Scene> loaded = samples::loadScene(specification);
    if (!loaded) {
        fail(kExitInput, loaded.error);
        return std::nullopt;
    }
    return std::move(*loaded.value);
}

int loadSceneAndView(const std::string& specification, const ViewOptions& options,
                     std::optional<Scene>& scene, ResolvedView& view) {
    scene = loadSceneOrReport(specification);
    if (!scene)
        return kExitInput;
    if (auto error = resolveView(options, *scene, view); !error.empty())
        return fail(kExitUsage, error);
    return kExitOk;
}

} // namespace vissort::cli
