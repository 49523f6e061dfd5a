// Scene specifications: `builtin:NAME?k=v&...`, a JSON scene, or a mesh file.

#include <algorithm>
#include <cctype>
#include <exception>

#include "scene/json_scene.h"
#include "scene/mesh_loader.h"
#include "vissort/scene.h"
#include "vissort/specification.h"

namespace vissort {
namespace {

constexpr std::string_view kBuiltinPrefix = "builtin:";

bool endsWithJson(const std::string& path) {
    if (path.size() < 5)
        return false;
    std::string extension = path.substr(path.size() - 5);
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension == ".json";
}

Result<Scene> loadBuiltin(const std::string& specification, const BuiltinSceneMaker& builtins) {
    const std::string rest = specification.substr(kBuiltinPrefix.size());
    const std::size_t question = rest.find('?');
    const std::string name = rest.substr(0, question);
    if (name.empty())
        return Result<Scene>::failure(specification + ": missing the built-in scene name");
    Result<SceneParameters> parameters = parseSpecificationQuery(
        question == std::string::npos ? std::string() : rest.substr(question + 1), specification);
    if (!parameters)
        return Result<Scene>::failure(parameters.error);
    if (!builtins)
        return Result<Scene>::failure(
            specification + ": no built-in scenes here: the library loads files; the vissort "
                            "command and the Python module have the samples' scenes");
    // Its messages name the scene and the parameter.
    return builtins(name, *parameters.value);
}

Result<Scene> loadSpecification(const std::string& specification, const BuiltinSceneMaker& builtins,
                                std::optional<ObjectGrouping> mesh_file_objects) {
    if (specification.empty())
        return Result<Scene>::failure("empty scene specification");
    const bool builtin = specification.starts_with(kBuiltinPrefix),
               json = !builtin && endsWithJson(specification);
    if (mesh_file_objects && (builtin || json))
        return Result<Scene>::failure(
            specification + ": how a file's meshes become objects applies to a mesh file; " +
            (json ? "a JSON scene says it per entry (\"objects\": \"mesh\", \"node\" or \"file\")"
                  : "a built-in scene makes its own objects"));
    try {
        Result<Scene> scene =
            builtin ? loadBuiltin(specification, builtins)
            : json  ? detail::loadJsonScene(specification)
                    : detail::loadMeshFile(specification,
                                           mesh_file_objects.value_or(ObjectGrouping::mesh));
        if (!scene)
            return scene;
        if (Status valid = validateScene(*scene.value); !valid)
            return Result<Scene>::failure(specification + ": " + valid.error);
        return scene;
    } catch (const std::exception& e) {
        // The loaders return errors as values; this only catches what they cannot (out of memory).
        return Result<Scene>::failure(specification + ": " + e.what());
    }
}

} // namespace

Result<Scene> loadScene(const std::string& specification, const BuiltinSceneMaker& builtins,
                        std::optional<ObjectGrouping> mesh_file_objects) {
    Result<Scene> scene = loadSpecification(specification, builtins, mesh_file_objects);
    if (!scene)
        scene.error = oneLine(scene.error);
    return scene;
}

Result<Scene> loadMeshFromMemory(const void* data, std::size_t size, const std::string& format_hint,
                                 const std::string& label, ObjectGrouping objects) {
    try {
        Result<Scene> scene = detail::loadMeshMemory(data, size, format_hint, label, objects);
        if (scene)
            if (Status valid = validateScene(*scene.value); !valid)
                scene = Result<Scene>::failure(label + ": " + valid.error);
        if (!scene)
            scene.error = oneLine(scene.error);
        return scene;
    } catch (const std::exception& e) {
        return Result<Scene>::failure(oneLine(label + ": " + e.what()));
    }
}

} // namespace vissort
