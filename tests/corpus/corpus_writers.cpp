#include "corpus_writers.h"

#include <assimp/Exporter.hpp>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <fstream>
#include <memory>
#include <sstream>

namespace vissort::test {
namespace {

aiNode* toAiNode(const CorpusNode& node, aiNode* parent) {
    auto* ai_node = new aiNode(node.name);
    ai_node->mParent = parent;
    const auto& t = node.transform;
    ai_node->mTransformation = aiMatrix4x4(t[0], t[1], t[2], t[3], t[4], t[5], t[6], t[7], t[8],
                                           t[9], t[10], t[11], t[12], t[13], t[14], t[15]);
    ai_node->mNumMeshes = unsigned(node.meshes.size());
    if (!node.meshes.empty()) {
        ai_node->mMeshes = new unsigned[node.meshes.size()];
        for (std::size_t i = 0; i < node.meshes.size(); ++i)
            ai_node->mMeshes[i] = node.meshes[i];
    }
    ai_node->mNumChildren = unsigned(node.children.size());
    if (!node.children.empty()) {
        ai_node->mChildren = new aiNode*[node.children.size()];
        for (std::size_t i = 0; i < node.children.size(); ++i)
            ai_node->mChildren[i] = toAiNode(node.children[i], ai_node);
    }
    return ai_node;
}

// The model as an aiScene that owns everything (aiScene's destructor frees it).
std::unique_ptr<aiScene> toAiScene(const CorpusModel& model) {
    auto scene = std::make_unique<aiScene>();
    scene->mNumMaterials = unsigned(model.materials.size());
    scene->mMaterials = new aiMaterial*[model.materials.size()];
    for (std::size_t i = 0; i < model.materials.size(); ++i) {
        const CorpusMaterial& m = model.materials[i];
        auto* material = new aiMaterial();
        const aiString name(m.name);
        material->AddProperty(&name, AI_MATKEY_NAME);
        const aiColor4D diffuse(m.r, m.g, m.b, m.a);
        material->AddProperty(&diffuse, 1, AI_MATKEY_COLOR_DIFFUSE);
        material->AddProperty(&diffuse, 1, AI_MATKEY_BASE_COLOR);
        material->AddProperty(&m.a, 1, AI_MATKEY_OPACITY);
        scene->mMaterials[i] = material;
    }
    scene->mNumMeshes = unsigned(model.meshes.size());
    scene->mMeshes = new aiMesh*[model.meshes.size()];
    for (std::size_t i = 0; i < model.meshes.size(); ++i) {
        const CorpusMesh& m = model.meshes[i];
        auto* mesh = new aiMesh();
        mesh->mName = aiString(m.name);
        mesh->mMaterialIndex = m.material;
        mesh->mNumVertices = unsigned(m.vertices.size());
        mesh->mVertices = new aiVector3D[m.vertices.size()];
        for (std::size_t v = 0; v < m.vertices.size(); ++v)
            mesh->mVertices[v] = aiVector3D(m.vertices[v][0], m.vertices[v][1], m.vertices[v][2]);
        mesh->mNumFaces = unsigned(m.faces.size());
        mesh->mFaces = new aiFace[m.faces.size()];
        for (std::size_t f = 0; f < m.faces.size(); ++f) {
            aiFace& face = mesh->mFaces[f];
            face.mNumIndices = unsigned(m.faces[f].size());
            face.mIndices = new unsigned[m.faces[f].size()];
            for (std::size_t k = 0; k < m.faces[f].size(); ++k)
                face.mIndices[k] = m.faces[f][k];
            mesh->mPrimitiveTypes |=
                face.mNumIndices == 3 ? aiPrimitiveType_TRIANGLE : aiPrimitiveType_POLYGON;
        }
        scene->mMeshes[i] = mesh;
    }
    scene->mRootNode = toAiNode(model.root, nullptr);
    return scene;
}

std::string writeText(const std::filesystem::path& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
    out.close();
    return out ? std::string() : "cannot write " + path.string();
}

// Shortest exact text of a float: every coordinate of the models has few digits.
std::string number(float v) {
    std::ostringstream out;
    out.precision(9);
    out << v;
    return out.str();
}

std::string point(const std::array<float, 3>& p) {
    return number(p[0]) + " " + number(p[1]) + " " + number(p[2]);
}

// The triangles (v0, vi, vi+1) of every face.
template <class Visit> void forEachFanTriangle(const WorldMesh& mesh, Visit visit) {
    for (const auto& face : mesh.faces)
        for (std::size_t i = 1; i + 1 < face.size(); ++i)
            visit(mesh.vertices[face[0]], mesh.vertices[face[i]], mesh.vertices[face[i + 1]]);
}

} // namespace

std::string exportWithAssimp(const CorpusModel& model, const std::string& format_id,
                             const std::filesystem::path& path, bool triangulate) {
    const std::unique_ptr<aiScene> scene = toAiScene(model);
    Assimp::Exporter exporter;
    const aiReturn result = exporter.Export(scene.get(), format_id, path.string(),
                                            triangulate ? aiProcess_Triangulate : 0u);
    if (result != aiReturn_SUCCESS)
        return "assimp cannot export " + format_id + ": " + exporter.GetErrorString();
    return {};
}

std::string writeObjWithMaterials(const CorpusModel& model, const std::filesystem::path& path) {
    std::filesystem::path mtl_path = path;
    mtl_path.replace_extension(".mtl");
    std::ostringstream mtl;
    for (const CorpusMaterial& m : model.materials)
        mtl << "newmtl " << m.name << "\nKa 0.1 0.1 0.1\nKd " << m.r << ' ' << m.g << ' ' << m.b
            << "\nd " << m.a << "\n\n";
    if (std::string error = writeText(mtl_path, mtl.str()); !error.empty())
        return error;
    std::ostringstream obj;
    obj << "# " << model.name << ", written by the vissort corpus test\nmtllib "
        << mtl_path.filename().string() << '\n';
    uint32_t base = 1;
    for (const WorldMesh& mesh : worldMeshes(model)) {
        obj << "o " << mesh.name << "\nusemtl " << model.materials[mesh.material].name << '\n';
        for (const auto& v : mesh.vertices)
            obj << "v " << point(v) << '\n';
        for (const auto& face : mesh.faces) {
            obj << 'f';
            for (uint32_t index : face)
                obj << ' ' << base + index;
            obj << '\n';
        }
        base += uint32_t(mesh.vertices.size());
    }
    return writeText(path, obj.str());
}

std::string writeOff(const CorpusModel& model, const std::filesystem::path& path) {
    const std::vector<WorldMesh> meshes = worldMeshes(model);
    std::size_t vertices = 0, faces = 0;
    for (const WorldMesh& mesh : meshes) {
        vertices += mesh.vertices.size();
        faces += mesh.faces.size();
    }
    std::ostringstream off;
    off << "OFF\n# " << model.name << "\n" << vertices << ' ' << faces << " 0\n";
    for (const WorldMesh& mesh : meshes)
        for (const auto& v : mesh.vertices)
            off << point(v) << '\n';
    uint32_t base = 0;
    for (const WorldMesh& mesh : meshes) {
        for (const auto& face : mesh.faces) {
            off << face.size();
            for (uint32_t index : face)
                off << ' ' << base + index;
            off << '\n';
        }
        base += uint32_t(mesh.vertices.size());
    }
    return writeText(path, off.str());
}

std::string writeAsciiPly(const CorpusModel& model, const std::filesystem::path& path) {
    const std::vector<WorldMesh> meshes = worldMeshes(model);
    std::size_t vertices = 0, faces = 0;
    for (const WorldMesh& mesh : meshes) {
        vertices += mesh.vertices.size();
        faces += mesh.faces.size();
    }
    std::ostringstream ply;
    ply << "ply\nformat ascii 1.0\ncomment " << model.name << "\nelement vertex " << vertices
        << "\nproperty float x\nproperty float y\nproperty float z\nproperty uchar red\n"
           "property uchar green\nproperty uchar blue\nelement face "
        << faces << "\nproperty list uchar int vertex_indices\nend_header\n";
    for (const WorldMesh& mesh : meshes) {
        const CorpusMaterial& m = model.materials[mesh.material];
        for (const auto& v : mesh.vertices)
            ply << point(v) << ' ' << int(m.r * 255) << ' ' << int(m.g * 255) << ' '
                << int(m.b * 255) << '\n';
    }
    uint32_t base = 0;
    for (const WorldMesh& mesh : meshes) {
        for (const auto& face : mesh.faces) {
            ply << face.size();
            for (uint32_t index : face)
                ply << ' ' << base + index;
            ply << '\n';
        }
        base += uint32_t(mesh.vertices.size());
    }
    return writeText(path, ply.str());
}

std::string writeAc3d(const CorpusModel& model, const std::filesystem::path& path) {
    const std::vector<WorldMesh> meshes = worldMeshes(model);
    std::ostringstream ac;
    ac << "AC3Db\n";
    for (const CorpusMaterial& m : model.materials)
        ac << "MATERIAL \"" << m.name << "\" rgb " << m.r << ' ' << m.g << ' ' << m.b
           << "  amb 0.2 0.2 0.2  emis 0 0 0  spec 0.5 0.5 0.5  shi 10  trans " << 1 - m.a << '\n';
    ac << "OBJECT world\nkids " << meshes.size() << '\n';
    for (const WorldMesh& mesh : meshes) {
        ac << "OBJECT poly\nname \"" << mesh.name << "\"\nnumvert " << mesh.vertices.size() << '\n';
        for (const auto& v : mesh.vertices)
            ac << point(v) << '\n';
        ac << "numsurf " << mesh.faces.size() << '\n';
        for (const auto& face : mesh.faces) {
            ac << "SURF 0x10\nmat " << mesh.material << "\nrefs " << face.size() << '\n';
            for (uint32_t index : face)
                ac << index << " 0 0\n";
        }
        ac << "kids 0\n";
    }
    return writeText(path, ac.str());
}

std::string writeAsciiStlSolids(const CorpusModel& model, const std::filesystem::path& path) {
    std::ostringstream stl;
    for (const WorldMesh& mesh : worldMeshes(model)) {
        stl << "solid " << mesh.name << '\n';
        forEachFanTriangle(mesh, [&](const auto& a, const auto& b, const auto& c) {
            stl << "  facet normal 0 0 0\n    outer loop\n      vertex " << point(a)
                << "\n      vertex " << point(b) << "\n      vertex " << point(c)
                << "\n    endloop\n  endfacet\n";
        });
        stl << "endsolid " << mesh.name << '\n';
    }
    return writeText(path, stl.str());
}

} // namespace vissort::test
