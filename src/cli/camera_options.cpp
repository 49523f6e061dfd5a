#include <charconv>
#include <cmath>
#include <iostream>

#include "cli/cli_common.h"
#include "cli/text_output.h"

namespace vissort::cli {
namespace {

// Largest image side and pixel count accepted: beyond them a depth buffer stops being a
// sensible request on one machine (16384^2 floats = 1 GiB).
constexpr uint32_t kMaxSide = 16384;
constexpr uint64_t kMaxPixels = uint64_t(kMaxSide) * kMaxSide / 4;
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
    if (w == 0 || h == 0 || w > kMaxSide || h > kMaxSide || uint64_t(w) * h > kMaxPixels)
        return "--size " + text + " is out of range: each side 1.." + std::to_string(kMaxSide) +
               ", at most " + std::to_string(kMaxPixels) + " pixels";
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
    if (view.path == CameraPath::scene) {
        if (scene.camera_path.empty())
            return "--path scene: the scene has no camera path (a JSON scene's \"camera_path\": "
                   "docs/scene-format.md)";
        if (perspective_given || !options.ortho_dir.empty())
            return "--path scene takes every frame's camera from the scene: it cannot be combined "
                   "with --eye, --target, --up, --fov or --ortho-dir";
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
        view.camera = scene.camera.value_or(defaultCamera(bounds, aspect));
        if (perspective_given && view.camera.projection == Projection::orthographic)
            view.camera = defaultCamera(bounds, aspect);
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
        if (perspective_given)
            return "--eye/--target/--up/--fov: " + e;
        return "the scene's camera: " + e;
    }
    return {};
}

std::optional<Scene> loadSceneOrReport(const std::string& specification) {
    Result<Scene> loaded = loadScene(specification);
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
