// chooseView (view_choice.h): the camera policy of every command, the viewer and Python.

#include "vissort/view_choice.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <sstream>
#include <vector>

namespace vissort {
namespace {

// A field as the caller names it: "--ortho-dir" on the command line, "ortho_dir" in Python
// (whose field of view is "fov_deg", as vissort.Camera's).
std::string nameOf(OptionNames names, std::string_view option) {
    if (names == OptionNames::command_line)
        return "--" + std::string(option);
    if (option == "fov")
        return "fov_deg";
    std::string name(option);
    for (char& c : name)
        if (c == '-')
            c = '_';
    return name;
}

// The message with each {option} named as the caller names it.
std::string named(OptionNames names, std::string_view message) {
    std::string out;
    for (std::size_t i = 0; i < message.size();) {
        const std::size_t close = message[i] == '{' ? message.find('}', i) : std::string::npos;
        if (close == std::string::npos) {
            out += message[i++];
            continue;
        }
        out += nameOf(names, message.substr(i + 1, close - i - 1));
        i = close + 1;
    }
    return out;
}

// A failure: `message` with its fields named, then `detail` as it is (a camera's name or a
// loader's message may hold braces of its own).
Result<ChosenView> failure(const ViewDef& def, std::string_view message,
                           const std::string& detail = {}) {
    return Result<ChosenView>::failure(named(def.names, message) + detail);
}

// The scene's camera path must give a usable camera on every frame that will run: between two
// valid key frames the mix can still be unusable (eye on target, up along the view).
Status checkScenePath(const ViewDef& def, const Scene& scene) {
    for (int frame = 0; frame < def.frames; ++frame) {
        const double time = frame * kFrameInterval;
        if (auto e = validateCamera(cameraAtTime(scene.camera_path, time)).error; !e.empty()) {
            std::ostringstream seconds;
            seconds << time;
            return Status::failure(named(def.names, "{path} scene: frame ") +
                                   std::to_string(frame) + " (" + seconds.str() +
                                   " s into the scene's camera path): " + e);
        }
    }
    return Status::ok();
}

std::string fileCamera(const Scene& scene, std::size_t index) {
    return "the file's camera " + std::to_string(index) + " '" + scene.cameras[index].name + "'";
}

} // namespace

Result<ChosenView> chooseView(const ViewDef& def, const Scene& scene) {
    ChosenView view;
    view.width = def.width;
    view.height = def.height;
    if (def.frames < 1 || def.frames > kMaxFrames)
        return failure(def, "{frames} must be between 1 and ", std::to_string(kMaxFrames));
    view.frames = def.frames;
    view.path = def.path;

    const bool perspective_given = def.eye || def.target || def.up || def.fov_degrees;
    const bool orbit_given = def.azimuth_degrees || def.elevation_degrees || def.distance;
    // "framed" names no stored camera: it goes with the options that place a framed view.
    const bool framed_asked = def.stored_camera == "framed";
    const bool stored_asked = !def.stored_camera.empty() && !framed_asked;
    if (orbit_given) {
        if (def.eye || def.target || def.up || def.ortho_direction || stored_asked)
            return failure(def, "{azimuth}, {elevation} and {distance} place the eye around the "
                                "scene's centre: they cannot be combined with {eye}, {target}, "
                                "{up}, {ortho-dir} or {camera}");
        if (def.azimuth_degrees && !std::isfinite(*def.azimuth_degrees))
            return failure(def, "{azimuth} must be a finite number of degrees");
        if (def.elevation_degrees && !(std::abs(*def.elevation_degrees) <= 90))
            return failure(def, "{elevation} must be between -90 and 90 degrees");
        if (def.distance && !(*def.distance > 0 && *def.distance < 1e30))
            return failure(def, "{distance} must be positive and below 1e30");
    }
    if (def.path == CameraPath::scene) {
        if (scene.camera_path.empty())
            return failure(def, "{path} scene: the scene has no camera path (a JSON scene's "
                                "\"camera_path\": docs/scene-format.md)");
        if (perspective_given || orbit_given || def.ortho_direction || !def.stored_camera.empty())
            return failure(def, "{path} scene takes every frame's camera from the scene: it "
                                "cannot be combined with the camera options ({eye}, {azimuth}, "
                                "{ortho-dir}, {camera}, ...)");
        if (Status usable = checkScenePath(def, scene); !usable)
            return Result<ChosenView>::failure(usable.error);
    }
    // The scene's own camera: the one def.stored_camera picks, else its default one (a file's
    // first).
    std::optional<CameraSpec> scene_camera = scene.camera;
    std::string scene_camera_source = "the scene's camera";
    std::optional<std::size_t> scene_camera_index = defaultStoredCamera(scene);
    if (scene_camera_index)
        scene_camera_source = fileCamera(scene, *scene_camera_index);
    if (framed_asked)
        scene_camera.reset();
    if (stored_asked) {
        if (def.ortho_direction)
            return failure(def, "{camera} cannot be combined with {ortho-dir}");
        Result<std::size_t> picked = findStoredCamera(scene, def.stored_camera);
        if (!picked)
            return failure(def, "{camera}: ", picked.error);
        scene_camera = scene.cameras[*picked.value].camera;
        scene_camera_index = *picked.value;
        scene_camera_source = fileCamera(scene, *picked.value);
        if (perspective_given && scene_camera->projection == Projection::orthographic)
            return failure(def, "{camera} ",
                           def.stored_camera + named(def.names,
                                                     " is orthographic: {eye}, {target}, {up} and "
                                                     "{fov} do not apply to it"));
    }
    if (def.path == CameraPath::scene)
        view.source = "the scene's camera path";
    else if (def.ortho_direction)
        view.source = nameOf(def.names, "ortho-dir");
    if (def.ortho_direction) {
        if (perspective_given)
            return failure(def, "{ortho-dir} cannot be combined with {eye}, {target}, {up} or "
                                "{fov}");
        view.camera.projection = Projection::orthographic;
        view.camera.ortho_direction = *def.ortho_direction;
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
                def.azimuth_degrees.value_or(std::atan2(d.x, d.z) * 180 / std::numbers::pi),
                def.elevation_degrees.value_or(std::asin(d.y) * 180 / std::numbers::pi));
        }
        // A field of view for a framed view is framed with, so the framing stays tight.
        if (def.fov_degrees && !def.eye && !def.target)
            orientation.fov_degrees = *def.fov_degrees;
        view.camera =
            framed ? framingCameraOf(scene, aspect, view.frames, orientation) : *scene_camera;
        if (def.path != CameraPath::scene)
            view.source = orbit_given
                              ? named(def.names, def.distance ? "{azimuth}/{elevation}/{distance}"
                                                              : "{azimuth}/{elevation}, framed")
                          : framed ? "framed to the geometry"
                                   : scene_camera_source;
        if (perspective_given && !orbit_given)
            view.source += named(def.names, ", changed by the options");
        if (!framed && !perspective_given && def.path != CameraPath::scene)
            view.stored_camera = scene_camera_index;
        if (framed && def.eye)
            view.camera.target = bounds.centre();
        if (def.distance) {
            view.camera.target = bounds.centre();
            view.camera.eye = bounds.centre() + normalized(orientation.eye) * *def.distance;
        }
        view.camera.eye = def.eye.value_or(view.camera.eye);
        view.camera.target = def.target.value_or(view.camera.target);
        view.camera.up = def.up.value_or(view.camera.up);
        view.camera.fov_degrees = def.fov_degrees.value_or(view.camera.fov_degrees);
    }
    if (auto e = validateCamera(view.camera).error; !e.empty()) {
        // Name where the bad camera came from: the request, or the scene file.
        if (def.ortho_direction)
            return failure(def, "{ortho-dir}: ", e);
        if (orbit_given)
            return failure(def, "{azimuth}/{elevation}/{distance}/{fov}: ", e);
        if (perspective_given)
            return failure(def, "{eye}/{target}/{up}/{fov}: ", e);
        if (!def.stored_camera.empty())
            return failure(def, "{camera} ", def.stored_camera + ": " + e);
        return Result<ChosenView>::failure("the scene's camera: " + e);
    }
    return Result<ChosenView>{std::move(view), {}};
}

double shareOfSurfaceInView(const Scene& scene, const CameraSpec& camera, uint32_t width,
                            uint32_t height) {
    constexpr int kSamples = 4096;
    const TrianglePositions& p = scene.positions;
    const std::size_t triangles = p.triangleCount();
    const auto area = [&](std::size_t t) {
        const Vec3 a = p.corner(3 * t), b = p.corner(3 * t + 1), c = p.corner(3 * t + 2);
        return length(cross(b - a, c - a));
    };
    double total = 0;
    for (std::size_t t = 0; t < triangles; ++t)
        total += area(t);
    if (!(total > 0))
        return 1;
    const ViewProjection view = frameCamera(camera, p.bounds(), width, height);
    // Sample s sits where the running area passes (s + 0.5) / kSamples of the total: one walk
    // over the triangles, the samples in order.
    int seen = 0, s = 0;
    double running = 0;
    for (std::size_t t = 0; t < triangles && s < kSamples; ++t) {
        running += area(t);
        const bool last = t + 1 == triangles;
        for (; s < kSamples && ((s + 0.5) / kSamples * total <= running || last); ++s) {
            // The R2 sequence's point s, folded into the triangle.
            double u = std::fmod(0.5 + s * 0.7548776662466927, 1.0);
            double v = std::fmod(0.5 + s * 0.5698402909980532, 1.0);
            if (u + v > 1) {
                u = 1 - u;
                v = 1 - v;
            }
            const Vec3 a = p.corner(3 * t), b = p.corner(3 * t + 1), c = p.corner(3 * t + 2);
            const std::array<double, 4> clip = view.toClip(a + (b - a) * u + (c - a) * v);
            // In front of the eye and inside the image (the depth range is framed to the
            // bounds).
            seen += clip[3] > 0 && std::abs(clip[0]) <= clip[3] && std::abs(clip[1]) <= clip[3];
        }
    }
    return double(seen) / kSamples;
}

} // namespace vissort
