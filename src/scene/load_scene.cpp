// Scene specifications: `builtin:NAME?k=v&...`, a JSON scene, or a mesh file.

#include <algorithm>
#include <cctype>
#include <exception>

#include "scene/json_scene.h"
#include "scene/mesh_loader.h"
#include "vissort/scene.h"

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

/// Splits "k=v&k2=v2" into parameters; an empty query gives none.
Result<SceneParameters> parseQuery(const std::string& query, const std::string& specification) {
    SceneParameters parameters;
    std::size_t begin = 0;
    while (begin < query.size()) {
        std::size_t end = query.find('&', begin);
        if (end == std::string::npos)
            end = query.size();
        const std::string item = query.substr(begin, end - begin);
        const std::size_t equals = item.find('=');
        if (item.empty())
            return Result<SceneParameters>::failure(specification +
                                                    ": empty parameter between '&'");
        if (equals == std::string::npos)
            return Result<SceneParameters>::failure(specification + ": parameter '" + item +
                                                    "' needs a value (key=value)");
        const std::string key = item.substr(0, equals);
        if (key.empty())
            return Result<SceneParameters>::failure(specification + ": parameter '" + item +
                                                    "' has no key");
        if (!parameters.emplace(key, item.substr(equals + 1)).second)
            return Result<SceneParameters>::failure(specification + ": parameter '" + key +
                                                    "' given twice");
        begin = end + 1;
        if (end + 1 == query.size())
            return Result<SceneParameters>::failure(specification +
                                                    ": empty parameter after the last '&'");
    }
    return {std::move(parameters), {}};
}

/// Messages quote the specification and parts of the input as they are (a file name, a key, a
/// value); control characters in them are written as \xNN, so that every error stays one line.
/// (The scene_parameters fuzzer found "builtin:x?&" followed by line ends.)
std::string oneLine(const std::string& message) {
    static constexpr char kHex[] = "0123456789abcdef";
    std::string line;
    line.reserve(message.size());
    for (const char c : message) {
        const auto byte = static_cast<unsigned char>(c);
        if (byte < 0x20 || byte == 0x7f) {
            line += "\\x";
            line += kHex[byte >> 4];
            line += kHex[byte & 15];
        } else {
            line += c;
        }
    }
    return line;
}

Result<Scene> loadBuiltin(const std::string& specification, const BuiltinSceneMaker& builtins) {
    const std::string rest = specification.substr(kBuiltinPrefix.size());
    const std::size_t question = rest.find('?');
    const std::string name = rest.substr(0, question);
    if (name.empty())
        return Result<Scene>::failure(specification + ": missing the built-in scene name");
    Result<SceneParameters> parameters = parseQuery(
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
