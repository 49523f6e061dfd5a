#include <charconv>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <numbers>
#include <sstream>

#include "cli/cli_common.h"
#include "cli/command_files.h"
#include "cli/text_output.h"
#include "scenes/scene_library.h"
#include "vissort/tet_grid.h"

namespace vissort::cli {
namespace {

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
                       "'vissort info SCENE' lists them); framed: none of them, the geometry "
                       "framed");
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

std::string resolveView(const ViewOptions& options, const Scene& scene, ChosenView& view) {
    ViewDef def;
    if (auto error = parseSize(options.size, def.width, def.height); !error.empty())
        return error;
    const Result<CameraPath> path = parseCameraPath(options.path);
    if (!path)
        return "--path: " + path.error;
    def.path = *path.value;
    def.frames = options.frames;
    // The vectors as numbers; which of them may be combined is chooseView's policy.
    const std::pair<const std::string*, std::optional<Vec3>*> vectors[] = {
        {&options.eye, &def.eye},
        {&options.target, &def.target},
        {&options.up, &def.up},
        {&options.ortho_dir, &def.ortho_direction}};
    const char* names[] = {"--eye", "--target", "--up", "--ortho-dir"};
    for (std::size_t i = 0; i < std::size(vectors); ++i) {
        if (vectors[i].first->empty())
            continue;
        Vec3 value;
        if (auto e = parseVec3(names[i], *vectors[i].first, value); !e.empty())
            return e;
        *vectors[i].second = value;
    }
    def.fov_degrees = options.fov;
    def.stored_camera = options.camera;
    def.azimuth_degrees = options.azimuth;
    def.elevation_degrees = options.elevation;
    def.distance = options.distance;
    Result<ChosenView> chosen = chooseView(def, scene);
    if (!chosen)
        return chosen.error;
    view = std::move(*chosen.value);
    return {};
}

std::string cameraLine(const ChosenView& view) {
    std::string line = "camera: " + describeCamera(view.camera) + " (" + view.source + ")";
    if (view.frames > 1 && view.path != CameraPath::fixed)
        line += std::string("; --path ") + cameraPathName(view.path) + " moves it every frame";
    return line;
}

void addObjectsOption(CLI::App& command, std::string& objects) {
    command.add_option("--objects", objects,
                       "How a mesh file's meshes become objects: mesh (one object each, the "
                       "default), node (one per node of the file, its meshes parts of it) or "
                       "file (the file one object); a JSON scene says it per entry");
}

int loadSceneOrReport(const std::string& specification, const std::string& objects,
                      std::optional<Scene>& scene) {
    if (isGridSpec(specification))
        return fail(kExitInput,
                    specification +
                        " is a tetrahedral grid, not a scene: 'vissort volume' renders it and "
                        "'vissort info' describes it (docs/volume.md)");
    std::optional<ObjectGrouping> grouping;
    if (!objects.empty()) {
        const Result<ObjectGrouping> named =
            parseEnum<ObjectGrouping>(kObjectGroupingNames, objects, "grouping");
        if (!named)
            return fail(kExitUsage, "--objects: " + named.error);
        grouping = *named.value;
    }
    Result<Scene> loaded = samples::loadScene(specification, grouping);
    if (!loaded)
        return fail(kExitInput, loaded.error);
    // The files known only now (a JSON scene's meshes, an OBJ's .mtl), against every output
    // before any work.
    std::vector<FileUse> read;
    for (const std::string& file : loaded.value->source_files)
        read.push_back({file == specification ? "the scene file" : "a file the scene reads", file});
    if (const std::string clash = checkInputs(read); !clash.empty())
        return fail(kExitFailure, clash);
    scene = std::move(*loaded.value);
    return kExitOk;
}

int loadSceneAndView(const std::string& specification, const std::string& objects,
                     const ViewOptions& options, std::optional<Scene>& scene, ChosenView& view) {
    if (const int code = loadSceneOrReport(specification, objects, scene); code != kExitOk)
        return code;
    if (auto error = resolveView(options, *scene, view); !error.empty())
        return fail(kExitUsage, error);
    // A camera a mesh file stores that sees little of the scene (inside a mesh scaled 100x, or
    // cropping it): say so, and how to see the whole. (A JSON or built-in scene's camera was
    // placed for vissort: the power plant's walkthrough starts inside the plant on purpose.)
    if (!view.stored_camera)
        return kExitOk;
    const double seen = shareOfSurfaceInView(*scene, view.camera, view.width, view.height);
    std::ostringstream share;
    share << std::setprecision(2) << 100 * seen << '%';
    if (seen < kFewInView)
        warn(view.source + " sees " + share.str() +
             " of the scene's surface: --camera framed frames the whole scene");
    else if (seen < kMostInView)
        std::cout << "note: " << view.source << " sees " << share.str()
                  << " of the scene's surface, the rest is outside the picture; --camera framed "
                     "shows all of it\n";
    return kExitOk;
}

} // namespace vissort::cli
