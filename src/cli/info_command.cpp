#include <algorithm>
#include <cmath>
#include <iostream>

#include "cli/commands.h"
#include "cli/json_output.h"
#include "cli/text_output.h"
#include "vissort/depth_complexity.h"
#include "vissort/tet_grid.h"
#if VISSORT_WITH_GL
#include "vissort/gl_context.h"
#endif

namespace vissort::cli {
CLI::App* addInfoCommand(CLI::App& app, InfoOptions& options) {
    CLI::App* command =
        app.add_subcommand("info", "Describe a scene (objects, triangles, bounds, depth "
                                   "complexity from a view) or a grid (cells, scalars, boundary)");
    command->add_option(
        "scene", options.scene,
        "Mesh file, JSON scene, grid file, or builtin:NAME?key=value&... (optional with --gl)");
    command->add_flag("--gl", options.gl,
                      "Print the OpenGL context's EGL platform, vendor, renderer and version "
                      "(VISSORT_GL_PLATFORM=auto|device|surfaceless picks the platform)");
    command->add_flag("--all-objects", options.all_objects,
                      "List every object (default: the first 10; --json always has them all)");
    addObjectsOption(*command, options.objects);
    addViewOptions(*command, options.view, false);
    addJsonOptions(*command, options.json,
                   "Write the facts as JSON: objects, transparent_objects, triangles, "
                   "transparent_triangles, bounds, object_list, cameras, camera, "
                   "depth_complexity (docs/cli.md)");
    return command;
}

namespace {

int printGlInfo() {
#if !VISSORT_WITH_GL
    return failWithoutGl("info --gl");
#else
    Result<std::shared_ptr<GlContext>> context = GlContext::shared();
    if (!context)
        return fail(kExitFailure, context.error);
    const GlContextInfo& info = (*context.value)->info();
    std::cout << "OpenGL: " << info.version << '\n'
              << "  renderer: " << info.renderer << '\n'
              << "  vendor: " << info.vendor << '\n'
              << "  EGL platform: " << info.platform
              << (info.device.empty() ? "" : " (" + info.device + ")") << '\n';
    return kExitOk;
#endif
}

nlohmann::json objectList(const Scene& scene) {
    nlohmann::json list = nlohmann::json::array();
    for (const SceneObject& o : scene.objects) {
        nlohmann::json record = {{"name", o.name},
                                 {"first_triangle", o.first_triangle},
                                 {"triangles", o.triangle_count},
                                 {"transparent", o.transparent},
                                 {"colour", {o.colour.r, o.colour.g, o.colour.b, o.colour.a}}};
        if (!o.parts.empty()) {
            nlohmann::json parts = nlohmann::json::array();
            for (const ObjectPart& p : o.parts)
                parts.push_back({{"name", p.name},
                                 {"first_triangle", p.first_triangle},
                                 {"triangles", p.triangle_count},
                                 {"colour", {p.colour.r, p.colour.g, p.colour.b, p.colour.a}}});
            record["parts"] = std::move(parts);
        }
        list.push_back(std::move(record));
    }
    return list;
}

nlohmann::json storedCameras(const Scene& scene) {
    nlohmann::json list = nlohmann::json::array();
    for (const StoredCamera& c : scene.cameras) {
        nlohmann::json record = cameraJson(c.camera);
        record["name"] = c.name;
        if (!c.problem.empty())
            record["problem"] = c.problem;
        list.push_back(std::move(record));
    }
    return list;
}

} // namespace

int runInfo(const InfoOptions& options) {
    if (options.gl) {
        if (const int code = printGlInfo(); code != kExitOk)
            return code;
        if (options.scene.empty())
            return kExitOk;
    } else if (options.scene.empty()) {
        return fail(kExitUsage, "info needs a scene, or --gl (run 'vissort info --help')");
    }
    if (isGridSpec(options.scene))
        return runGridInfo(options);
    std::optional<Scene> scene;
    ChosenView view;
    if (const int code =
            loadSceneAndView(options.scene, options.objects, options.view, scene, view);
        code != kExitOk)
        return code;

    const Bounds bounds = scene->positions.bounds();
    std::size_t transparent = 0;
    for (const SceneObject& o : scene->objects)
        transparent += o.transparent ? 1 : 0;
    std::cout << "scene: " << (scene->name.empty() ? options.scene : scene->name) << '\n'
              << "objects: " << scene->objects.size() << " (" << transparent << " transparent)\n"
              << "triangles: " << scene->triangleCount() << '\n'
              << "dynamic: " << (scene->isDynamic() ? "yes" : "no") << '\n'
              << "bounds: [" << bounds.min.x << ", " << bounds.min.y << ", " << bounds.min.z
              << "] to [" << bounds.max.x << ", " << bounds.max.y << ", " << bounds.max.z
              << "], radius " << bounds.radius() << '\n';
    constexpr std::size_t kListedObjects = 10;
    const std::size_t listed = options.all_objects
                                   ? scene->objects.size()
                                   : std::min(scene->objects.size(), kListedObjects);
    for (std::size_t i = 0; i < listed; ++i) {
        const SceneObject& o = scene->objects[i];
        std::cout << "  object " << i << " '" << o.name
                  << "': " << counted(o.triangle_count, "triangle")
                  << (o.parts.empty() ? "" : " in " + counted(o.parts.size(), "part"))
                  << (o.transparent ? ", transparent" : "") << '\n';
    }
    if (listed < scene->objects.size())
        std::cout << "  ... and " << scene->objects.size() - listed
                  << " more (--all-objects lists every one; --json has them all)\n";
    if (!scene->cameras.empty()) {
        std::cout << counted(scene->cameras.size(), "camera")
                  << " in the file (--camera NAME|INDEX picks one; the first usable is the "
                     "default):\n";
        for (std::size_t i = 0; i < scene->cameras.size(); ++i) {
            const StoredCamera& c = scene->cameras[i];
            std::cout << "  camera " << i << " '" << c.name << "': "
                      << (c.problem.empty() ? describeCamera(c.camera)
                                            : "cannot be used: " + c.problem)
                      << '\n';
        }
    }
    std::cout << cameraLine(view) << '\n';

    const DepthComplexity depth =
        estimateDepthComplexity(scene->positions, view.camera, bounds, view.width, view.height);
    std::cout << "depth complexity (" << depth.width << 'x' << depth.height << " rays, "
              << (view.camera.projection == Projection::perspective ? "perspective"
                                                                    : "orthographic")
              << "): max " << depth.max << ", mean " << depth.mean << " over "
              << depth.covered_pixels << " covered pixels\n";
    if (options.json.path.empty())
        return kExitOk;
    uint64_t transparent_triangles = 0;
    for (const SceneObject& o : scene->objects)
        transparent_triangles += o.transparent ? o.triangle_count : 0;
    const nlohmann::json document = {
        {"scene", scene->name.empty() ? options.scene : scene->name},
        {"objects", scene->objects.size()},
        {"transparent_objects", transparent},
        {"triangles", scene->triangleCount()},
        {"transparent_triangles", transparent_triangles},
        {"dynamic", scene->isDynamic()},
        {"bounds",
         {{"min", vec3Json(bounds.min)},
          {"max", vec3Json(bounds.max)},
          {"radius", bounds.radius()}}},
        {"object_list", objectList(*scene)},
        {"cameras", storedCameras(*scene)},
        {"camera", cameraJson(view.camera)},
        {"depth_complexity",
         {{"max", depth.max},
          {"mean", depth.mean},
          {"covered_pixels", depth.covered_pixels},
          {"rays", {depth.width, depth.height}},
          {"projection",
           view.camera.projection == Projection::perspective ? "perspective" : "orthographic"},
          {"histogram", depth.histogram}}}};
    return writeJsonFile(options.json, document);
}

} // namespace vissort::cli
