// Mesh files to scenes through assimp. Triangle ids must be predictable from the file (tests and
// ground truth refer to them), so nothing here welds, splits or reorders: every polygon becomes
// the fan (v0, vi, vi+1) in face order, meshes keep their file order, and only the node world
// transform moves vertices (identity for OBJ, PLY and STL).

#include "scene/mesh_loader.h"

#include "scene/declared_sizes.h"
#include "scene/file_cameras.h"
#include "scene/off_faces.h"

#include <assimp/DefaultIOSystem.h>
#include <assimp/Importer.hpp>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <new>
#include <sstream>
#include <system_error>
#include <vector>

namespace vissort::detail {
namespace {

constexpr uint64_t kMaxTriangles = 50'000'000;

struct MeshInstance {
    unsigned mesh_index = 0;
    aiMatrix4x4 world; // node-to-world transform of the node that references the mesh
    std::string node_name;
    std::size_t node = 0; // the node's place in a depth-first walk; meshes of no node get one each
};

// What std::bad_alloc says ("std::bad_alloc") names no problem. Some of assimp's readers
// allocate for counts their file declares, and declaredSizeProblem checks only some formats.
constexpr const char* kOutOfMemory =
    "not enough memory to read the file (a declared size out of proportion to the file?)";

std::string lowerCase(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return text;
}

/// The file's extension without the dot ("" when it has none).
std::string extensionOf(const std::string& path) {
    const std::string extension = std::filesystem::path(path).extension().string();
    return extension.empty() ? extension : extension.substr(1);
}

std::string oneLine(std::string text) {
    std::replace_if(
        text.begin(), text.end(), [](char c) { return c == '\n' || c == '\r'; }, ' ');
    while (!text.empty() && text.back() == ' ')
        text.pop_back();
    return text;
}

void collectInstances(const aiScene& scene, const aiNode& node, const aiMatrix4x4& parent,
                      std::vector<MeshInstance>& out, std::vector<bool>& referenced,
                      std::size_t& nodes) {
    const aiMatrix4x4 world = parent * node.mTransformation;
    const std::size_t this_node = nodes++;
    for (unsigned i = 0; i < node.mNumMeshes; ++i) {
        const unsigned mesh_index = node.mMeshes[i];
        if (mesh_index >= scene.mNumMeshes)
            continue; // ValidateDataStructure rejects this first
        referenced[mesh_index] = true;
        // The root's name is usually the file name, not an object name.
        out.push_back(
            {mesh_index, world, &node == scene.mRootNode ? "" : node.mName.C_Str(), this_node});
    }
    for (unsigned i = 0; i < node.mNumChildren; ++i)
        collectInstances(scene, *node.mChildren[i], world, out, referenced, nodes);
}

/// Every mesh instance: in mesh (file) order, instances of one mesh in node order; for node
/// grouping in node order (depth first), so that a node's meshes are together. Meshes no node
/// references still count, placed with the identity transform, last under node grouping.
std::vector<MeshInstance> meshInstances(const aiScene& scene, ObjectGrouping grouping) {
    std::vector<MeshInstance> instances;
    std::vector<bool> referenced(scene.mNumMeshes, false);
    std::size_t nodes = 0;
    if (scene.mRootNode)
        collectInstances(scene, *scene.mRootNode, aiMatrix4x4(), instances, referenced, nodes);
    for (unsigned i = 0; i < scene.mNumMeshes; ++i)
        if (!referenced[i])
            instances.push_back({i, aiMatrix4x4(), "", nodes++});
    if (grouping != ObjectGrouping::node)
        std::stable_sort(instances.begin(), instances.end(),
                         [](const MeshInstance& a, const MeshInstance& b) {
                             return a.mesh_index < b.mesh_index;
                         });
    return instances;
}

/// Under node or file grouping, consecutive meshes of one group become one object whose parts
/// they are (a group of one mesh is that mesh): named after the node (the file under file
/// grouping; "object_<id>" for the root or an unnamed node), its colour the largest part's with
/// the least alpha of any part.
std::vector<SceneObject> groupedObjects(std::vector<SceneObject> meshes,
                                        const std::vector<std::size_t>& group_of,
                                        const std::vector<std::string>& group_name) {
    std::vector<SceneObject> objects;
    for (std::size_t first = 0; first < meshes.size();) {
        std::size_t end = first + 1;
        while (end < meshes.size() && group_of[end] == group_of[first])
            ++end;
        if (end == first + 1) { // one mesh: the object, named after its node or file
            objects.push_back(std::move(meshes[first]));
            if (!group_name[first].empty())
                objects.back().name = group_name[first];
            first = end;
            continue;
        }
        SceneObject object;
        object.name = group_name[first].empty() ? "object_" + std::to_string(objects.size())
                                                : group_name[first];
        object.first_triangle = meshes[first].first_triangle;
        const SceneObject* largest = &meshes[first];
        float least_alpha = 1.0f;
        for (std::size_t m = first; m < end; ++m) {
            const SceneObject& mesh = meshes[m];
            object.triangle_count += mesh.triangle_count;
            object.parts.push_back(
                {mesh.name, mesh.colour, mesh.first_triangle, mesh.triangle_count});
            if (mesh.triangle_count > largest->triangle_count)
                largest = &mesh;
            least_alpha = std::min(least_alpha, mesh.colour.a);
        }
        object.colour = largest->colour;
        object.colour.a = least_alpha;
        object.transparent = least_alpha < 1.0f;
        objects.push_back(std::move(object));
        first = end;
    }
    return objects;
}

uint64_t fanTriangleCount(const aiMesh& mesh) {
    uint64_t count = 0;
    for (unsigned f = 0; f < mesh.mNumFaces; ++f)
        if (mesh.mFaces[f].mNumIndices >= 3)
            count += mesh.mFaces[f].mNumIndices - 2;
    return count;
}

/// The material's diffuse colour and opacity, or the default grey when the file has no
/// material of its own (assimp then supplies one named AI_DEFAULT_MATERIAL_NAME).
Rgba materialColour(const aiScene& scene, unsigned material_index) {
    Rgba colour;
    if (material_index >= scene.mNumMaterials)
        return colour;
    const aiMaterial& material = *scene.mMaterials[material_index];
    aiString name;
    if (material.Get(AI_MATKEY_NAME, name) == AI_SUCCESS &&
        name == aiString(AI_DEFAULT_MATERIAL_NAME))
        return colour;
    aiColor4D diffuse;
    if (material.Get(AI_MATKEY_COLOR_DIFFUSE, diffuse) == AI_SUCCESS)
        colour = {diffuse.r, diffuse.g, diffuse.b, diffuse.a};
    // The opacity wins over the diffuse alpha: glTF sets both from the same base colour alpha.
    float opacity = 1.0f;
    if (material.Get(AI_MATKEY_OPACITY, opacity) == AI_SUCCESS)
        colour.a = opacity;
    // Colours outside [0, 1] (HDR, bad files) carry no meaning for ordering.
    const auto unit = [](float v) { return std::isfinite(v) ? std::clamp(v, 0.0f, 1.0f) : 1.0f; };
    return {unit(colour.r), unit(colour.g), unit(colour.b), unit(colour.a)};
}

/// The mesh's name; the node's when the mesh has none; "node/mesh" for a mesh placed by several
/// nodes, so that instances stay distinguishable; else "object_<id>".
std::string objectName(const aiMesh& mesh, const MeshInstance& instance, unsigned instance_count,
                       std::size_t object_id) {
    // assimp's OBJ reader calls the geometry before any `o` or `g` line "defaultobject".
    const auto named = [](std::string name) {
        return name == "defaultobject" ? std::string() : name;
    };
    const std::string mesh_name = named(mesh.mName.C_Str()), node_name = named(instance.node_name);
    const std::string name = mesh_name.empty() ? node_name
                             : instance_count > 1 && !node_name.empty()
                                 ? node_name + "/" + mesh_name
                                 : mesh_name;
    return name.empty() ? "object_" + std::to_string(object_id) : name;
}

Result<Scene> convertScene(const aiScene& ai_scene, const std::string& label,
                           const std::string& scene_name, const std::string& extension,
                           ObjectGrouping grouping) {
    const std::vector<MeshInstance> instances = meshInstances(ai_scene, grouping);
    uint64_t total = 0;
    for (const MeshInstance& instance : instances)
        total += fanTriangleCount(*ai_scene.mMeshes[instance.mesh_index]);
    if (total == 0)
        return Result<Scene>::failure(label + ": no triangles in the file");
    if (total > kMaxTriangles)
        return Result<Scene>::failure(label + ": " + std::to_string(total) +
                                      " triangles, more than the limit of " +
                                      std::to_string(kMaxTriangles));

    std::vector<unsigned> instance_counts(ai_scene.mNumMeshes, 0);
    for (const MeshInstance& instance : instances)
        ++instance_counts[instance.mesh_index];

    Scene scene;
    scene.name = scene_name;
    scene.positions.resize(static_cast<std::size_t>(total));
    std::size_t corner = 0;
    std::vector<std::size_t> group_of;
    std::vector<std::string> group_name;
    for (const MeshInstance& instance : instances) {
        const aiMesh& mesh = *ai_scene.mMeshes[instance.mesh_index];
        const uint64_t count = fanTriangleCount(mesh);
        if (count == 0)
            continue; // points and lines only
        group_of.push_back(grouping == ObjectGrouping::mesh   ? group_of.size()
                           : grouping == ObjectGrouping::node ? instance.node
                                                              : 0);
        group_name.push_back(grouping == ObjectGrouping::file ? scene_name : instance.node_name);
        SceneObject object;
        object.name =
            objectName(mesh, instance, instance_counts[instance.mesh_index], scene.objects.size());
        object.colour = materialColour(ai_scene, mesh.mMaterialIndex);
        object.transparent = object.colour.a < 1.0f;
        object.first_triangle = static_cast<uint32_t>(corner / 3);
        object.triangle_count = static_cast<uint32_t>(count);

        const auto put = [&](unsigned vertex) {
            const aiVector3D p = instance.world * mesh.mVertices[vertex];
            scene.positions.x[corner] = p.x;
            scene.positions.y[corner] = p.y;
            scene.positions.z[corner] = p.z;
            ++corner;
        };
        for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
            const aiFace& face = mesh.mFaces[f];
            for (unsigned i = 0; i < face.mNumIndices; ++i)
                if (face.mIndices[i] >= mesh.mNumVertices)
                    return Result<Scene>::failure(label + ": mesh " +
                                                  std::to_string(instance.mesh_index) +
                                                  " has a vertex index out of range");
            for (unsigned i = 1; i + 1 < face.mNumIndices; ++i) {
                put(face.mIndices[0]);
                put(face.mIndices[i]);
                put(face.mIndices[i + 1]);
            }
        }
        scene.objects.push_back(std::move(object));
    }
    if (grouping != ObjectGrouping::mesh)
        scene.objects = groupedObjects(std::move(scene.objects), group_of, group_name);

    // Checked after the transform: a finite vertex can still overflow float once moved.
    PositionsView p = scene.positions;
    for (std::size_t i = 0; i < p.x.size(); ++i)
        if (!std::isfinite(p.x[i]) || !std::isfinite(p.y[i]) || !std::isfinite(p.z[i]))
            return Result<Scene>::failure(label + ": triangle " + std::to_string(i / 3) +
                                          " has a non-finite coordinate");
    scene.cameras = fileCameras(ai_scene, extension, scene.positions.bounds());
    if (const std::optional<std::size_t> first = defaultStoredCamera(scene))
        scene.camera = scene.cameras[*first].camera;
    return {std::move(scene), {}};
}

// No welding, triangulation or optimisation steps: they renumber triangles. Validation only
// rejects malformed data structures (indices out of range, empty meshes).
constexpr unsigned kImportFlags = aiProcess_ValidateDataStructure;

// assimp's own file access, noting every file it opens: a mesh file's readers open others
// beside it (an OBJ's .mtl, a glTF's .bin), and the scene lists them all (Scene::source_files)
// so that no output replaces one.
class RecordingIOSystem : public Assimp::DefaultIOSystem {
public:
    explicit RecordingIOSystem(std::vector<std::string>& opened) : opened_(opened) {}
    Assimp::IOStream* Open(const char* file, const char* mode) override {
        Assimp::IOStream* stream = DefaultIOSystem::Open(file, mode);
        if (stream && std::find(opened_.begin(), opened_.end(), file) == opened_.end())
            opened_.push_back(file);
        return stream;
    }

private:
    std::vector<std::string>& opened_;
};

// Before a reason assimp gave: the file passed vissort's own checks, and assimp refused it.
constexpr const char* kAssimpFailed = "assimp could not read it: ";

// Runs an assimp read: most readers report failures through GetErrorString, but some throw;
// what they throw is assimp's reason (running out of memory aside, which callers report).
template <class Read> Status readWithAssimp(Read&& read) {
    try {
        read();
    } catch (const std::bad_alloc&) {
        throw;
    } catch (const std::exception& e) {
        return Status::failure(kAssimpFailed + oneLine(e.what()));
    }
    return Status::ok();
}

Result<Scene> finishImport(Assimp::Importer& importer, const aiScene* ai_scene,
                           const std::string& label, const std::string& scene_name,
                           const std::string& extension, ObjectGrouping grouping) {
    if (!ai_scene) {
        // assimp's own reason, said to be assimp's: a user then knows whom to ask.
        const std::string reason = oneLine(importer.GetErrorString());
        if (reason == "std::bad_alloc") // assimp catches it and keeps its what()
            return Result<Scene>::failure(label + ": " + kOutOfMemory);
        return Result<Scene>::failure(label + ": " + kAssimpFailed +
                                      (reason.empty() ? "it gave no reason" : reason));
    }
    return convertScene(*ai_scene, label, scene_name, extension, grouping);
}

// An OFF file's scene, checked against its own face list (off_faces.h): assimp's reader drops
// large polygons and clamps bad indices without a word.
Result<Scene> checkedOff(Result<Scene> scene, std::istream& in, const std::string& label) {
    if (!scene)
        return scene;
    const Result<OffFaces> faces = readOffFaces(in);
    if (!faces)
        return Result<Scene>::failure(label + ": " + faces.error);
    const uint64_t loaded = scene.value->triangleCount(), expected = faces.value->fan_triangles;
    if (loaded == expected)
        return scene;
    return Result<Scene>::failure(
        label + ": assimp's OFF reader made " + std::to_string(loaded) + " of the " +
        std::to_string(expected) + " triangles the faces describe" +
        (faces.value->most_corners >= 10
             ? " (it drops polygons of 10 or more corners; this file has one of " +
                   std::to_string(faces.value->most_corners) + "): convert it to OBJ or PLY"
             : ""));
}

bool isOff(const std::string& extension) {
    return lowerCase(extension) == "off";
}

} // namespace

Result<Scene> loadMeshFile(const std::string& path, ObjectGrouping grouping) {
    std::error_code ec;
    const std::filesystem::path file(path);
    if (!std::filesystem::exists(file, ec))
        return Result<Scene>::failure(path + ": file not found");
    if (!std::filesystem::is_regular_file(file, ec))
        return Result<Scene>::failure(path + ": not a regular file");
    const uintmax_t file_size = std::filesystem::file_size(file, ec);
    if (ec)
        return Result<Scene>::failure(path + ": cannot read the file's size");
    if (file_size == 0)
        return Result<Scene>::failure(path + ": empty file");
    try {
        // Only the header is read here (the whole file for formats whose counts can be
        // anywhere); assimp reads the file itself.
        const std::string extension = extensionOf(path);
        std::string head(
            static_cast<std::size_t>(std::min<uintmax_t>(file_size, kDeclaredSizeHeadBytes)), '\0');
        std::ifstream stream(file, std::ios::binary);
        stream.read(head.data(), static_cast<std::streamsize>(head.size()));
        head.resize(static_cast<std::size_t>(stream.gcount()));
        if (head.size() < file_size && file_size <= kDeclaredSizeWholeFileBytes &&
            declaredSizesNeedWholeFile(extension, head)) {
            const std::size_t read = head.size();
            head.resize(static_cast<std::size_t>(file_size));
            stream.read(head.data() + read, static_cast<std::streamsize>(head.size() - read));
            head.resize(read + static_cast<std::size_t>(stream.gcount()));
        }
        if (const std::string problem = declaredSizeProblem(head, file_size, extension);
            !problem.empty())
            return Result<Scene>::failure(path + ": " + problem);
        Assimp::Importer importer;
        std::vector<std::string> opened{path};
        importer.SetIOHandler(new RecordingIOSystem(opened)); // the importer owns it
        const aiScene* ai_scene = nullptr;
        if (Status read = readWithAssimp([&] { ai_scene = importer.ReadFile(path, kImportFlags); });
            !read)
            return Result<Scene>::failure(path + ": " + read.error);
        Result<Scene> scene = finishImport(importer, ai_scene, path, file.stem().string(),
                                           lowerCase(extension), grouping);
        if (scene)
            scene.value->source_files = std::move(opened);
        if (!isOff(extension))
            return scene;
        std::ifstream again(file, std::ios::binary);
        return checkedOff(std::move(scene), again, path);
    } catch (const std::bad_alloc&) {
        return Result<Scene>::failure(path + ": " + kOutOfMemory);
    } catch (const std::exception& e) {
        return Result<Scene>::failure(path + ": " + oneLine(e.what()));
    }
}

Result<Scene> loadMeshMemory(const void* data, std::size_t size, const std::string& format_hint,
                             const std::string& label, ObjectGrouping grouping) {
    if (!data || size == 0)
        return Result<Scene>::failure(label + ": empty input");
    try {
        const std::string_view bytes(static_cast<const char*>(data), size);
        if (const std::string problem = declaredSizeProblem(
                declaredSizesNeedWholeFile(format_hint, bytes.substr(0, kDeclaredSizeHeadBytes))
                    ? bytes
                    : bytes.substr(0, kDeclaredSizeHeadBytes),
                size, format_hint);
            !problem.empty())
            return Result<Scene>::failure(label + ": " + problem);
        Assimp::Importer importer;
        const aiScene* ai_scene = nullptr;
        if (Status read = readWithAssimp([&] {
                ai_scene =
                    importer.ReadFileFromMemory(data, size, kImportFlags, format_hint.c_str());
            });
            !read)
            return Result<Scene>::failure(label + ": " + read.error);
        Result<Scene> scene =
            finishImport(importer, ai_scene, label, std::filesystem::path(label).stem().string(),
                         lowerCase(format_hint), grouping);
        if (!isOff(format_hint))
            return scene;
        std::istringstream again{std::string(bytes)};
        return checkedOff(std::move(scene), again, label);
    } catch (const std::bad_alloc&) {
        return Result<Scene>::failure(label + ": " + kOutOfMemory);
    } catch (const std::exception& e) {
        return Result<Scene>::failure(label + ": " + oneLine(e.what()));
    }
}

} // namespace vissort::detail
