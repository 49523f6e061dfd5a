// Mesh files through assimp: triangle ids, objects, materials, transforms and every rejection.

#include "scene/mesh_loader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace vissort {
namespace {

namespace fs = std::filesystem;
using detail::loadMeshFile;
using detail::loadMeshMemory;

const std::string kSource = VISSORT_SOURCE_DIR;
const std::string kModels = kSource + "/assets/models/";
const std::string kMeshes = kSource + "/tests/data/meshes/";

/// A fresh folder per test, removed at the end.
class TempDir {
public:
    TempDir() {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        path_ = fs::temp_directory_path() /
                ("vissort_scene_" + std::to_string(::getpid()) + "_" + info->name());
        fs::remove_all(path_);
        fs::create_directories(path_);
    }
    ~TempDir() { fs::remove_all(path_); }
    std::string write(const std::string& name, const std::string& bytes) const {
        const fs::path file = path_ / name;
        std::ofstream(file, std::ios::binary) << bytes;
        return file.string();
    }
    const fs::path& path() const { return path_; }

private:
    fs::path path_;
};

std::string readBytes(const std::string& path) {
    std::ifstream stream(path, std::ios::binary);
    std::ostringstream text;
    text << stream.rdbuf();
    return text.str();
}

/// Reference reader for the bundled OBJ files (v and f lines only, fan per face), independent of
/// assimp: the triangle soup the loader must reproduce exactly.
std::vector<Vec3> referenceObjTriangles(const std::string& path) {
    std::vector<Vec3> vertices, corners;
    std::istringstream lines(readBytes(path));
    std::string line;
    while (std::getline(lines, line)) {
        std::istringstream words(line);
        std::string tag;
        words >> tag;
        if (tag == "v") {
            Vec3 v;
            words >> v.x >> v.y >> v.z;
            vertices.push_back(v);
        } else if (tag == "f") {
            std::vector<std::size_t> face;
            std::string corner;
            while (words >> corner) {
                const long index = std::stol(corner.substr(0, corner.find('/')));
                face.push_back(index > 0 ? std::size_t(index - 1) : vertices.size() + index);
            }
            for (std::size_t i = 1; i + 1 < face.size(); ++i)
                for (std::size_t k : {face[0], face[i], face[i + 1]})
                    corners.push_back(vertices.at(k));
        }
    }
    return corners;
}

void expectCorner(const Scene& scene, std::size_t corner, Vec3 expected) {
    const Vec3 got = scene.positions.corner(corner);
    EXPECT_NEAR(got.x, expected.x, 1e-5) << "corner " << corner;
    EXPECT_NEAR(got.y, expected.y, 1e-5) << "corner " << corner;
    EXPECT_NEAR(got.z, expected.z, 1e-5) << "corner " << corner;
}

void expectRejected(const Result<Scene>& loaded, const std::string& label,
                    const std::string& contains = "") {
    ASSERT_FALSE(loaded) << label;
    EXPECT_EQ(loaded.error.rfind(label, 0), 0u)
        << "message must start with the source: " << loaded.error;
    EXPECT_EQ(loaded.error.find('\n'), std::string::npos)
        << "message must be one line: " << loaded.error;
    if (!contains.empty()) {
        EXPECT_NE(loaded.error.find(contains), std::string::npos) << loaded.error;
    }
}

TEST(MeshLoader, BundledModelsMatchTheirDocumentedCountsAndAReferenceReader) {
    // suzanne.obj has 500 faces (468 quads, 32 triangles): 968 triangles once fanned.
    const std::pair<const char*, std::size_t> models[] = {
        {"bunny-lowres.obj", 3674}, {"spot.obj", 5856},  {"suzanne.obj", 968},
        {"beetle.obj", 2053},       {"woody.obj", 1267}, {"teapot.obj", 6320}};
    for (const auto& [file, triangles] : models) {
        SCOPED_TRACE(file);
        const Result<Scene> loaded = loadMeshFile(kModels + file);
        ASSERT_TRUE(loaded) << loaded.error;
        const Scene& scene = *loaded.value;
        EXPECT_EQ(scene.triangleCount(), triangles);
        ASSERT_EQ(scene.objects.size(), 1u);
        EXPECT_EQ(scene.objects[0].first_triangle, 0u);
        EXPECT_EQ(scene.objects[0].triangle_count, triangles);
        const std::vector<Vec3> reference = referenceObjTriangles(kModels + file);
        ASSERT_EQ(reference.size(), triangles * 3);
        std::size_t mismatches = 0;
        for (std::size_t c = 0; c < reference.size(); ++c) {
            const Vec3 got = scene.positions.corner(c);
            const double tolerance = 1e-5 * (1 + std::abs(reference[c].x) +
                                             std::abs(reference[c].y) + std::abs(reference[c].z));
            if (std::abs(got.x - reference[c].x) > tolerance ||
                std::abs(got.y - reference[c].y) > tolerance ||
                std::abs(got.z - reference[c].z) > tolerance)
                ++mismatches;
        }
        EXPECT_EQ(mismatches, 0u);
    }
}

TEST(MeshLoader, PolygonsAreFannedInFaceOrder) {
    const Result<Scene> loaded = loadMeshFile(kMeshes + "polygons.obj");
    ASSERT_TRUE(loaded) << loaded.error;
    const Scene& scene = *loaded.value;
    ASSERT_EQ(scene.triangleCount(), 5u);
    const Vec3 q[] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    const Vec3 p[] = {{10, 0, 1}, {11, 0, 1}, {12, 1, 1}, {11, 2, 1}, {10, 1, 1}};
    const Vec3 expected[] = {q[0], q[1], q[2], q[0], q[2], q[3],                    // quad
                             p[0], p[1], p[2], p[0], p[2], p[3], p[0], p[3], p[4]}; // pentagon
    for (std::size_t c = 0; c < 15; ++c)
        expectCorner(scene, c, expected[c]);
    // No `o`/`g` line and no material: the fallback name and the default grey, opaque.
    ASSERT_EQ(scene.objects.size(), 1u);
    EXPECT_EQ(scene.objects[0].name, "object_0");
    EXPECT_FLOAT_EQ(scene.objects[0].colour.r, Rgba{}.r);
    EXPECT_FLOAT_EQ(scene.objects[0].colour.a, 1.0f);
    EXPECT_FALSE(scene.objects[0].transparent);
}

TEST(MeshLoader, ObjGroupsBecomeObjectsInFileOrderWithTheirMaterials) {
    const Result<Scene> loaded = loadMeshFile(kMeshes + "groups.obj");
    ASSERT_TRUE(loaded) << loaded.error;
    const Scene& scene = *loaded.value;
    EXPECT_EQ(scene.name, "groups");
    // The `l` and `p` elements are skipped; the quad of "blue" gives two triangles.
    ASSERT_EQ(scene.triangleCount(), 4u);
    ASSERT_EQ(scene.objects.size(), 3u);
    const char* names[] = {"red", "green", "blue"};
    const uint32_t firsts[] = {0, 1, 2}, counts[] = {1, 1, 2};
    for (int i = 0; i < 3; ++i) {
        EXPECT_EQ(scene.objects[i].name, names[i]);
        EXPECT_EQ(scene.objects[i].first_triangle, firsts[i]);
        EXPECT_EQ(scene.objects[i].triangle_count, counts[i]);
    }
    // Each group's triangles sit at z = 0, 2, 4 in the file.
    expectCorner(scene, 0, {0, 0, 0});
    expectCorner(scene, 3, {0, 0, 2});
    expectCorner(scene, 6, {0, 0, 4});
    expectCorner(scene, 11, {0, 1, 4});
    // Materials: red_glass Kd 1 0 0, d 0.5; green opaque; blue d 1.
    EXPECT_FLOAT_EQ(scene.objects[0].colour.r, 1.0f);
    EXPECT_FLOAT_EQ(scene.objects[0].colour.g, 0.0f);
    EXPECT_FLOAT_EQ(scene.objects[0].colour.a, 0.5f);
    EXPECT_TRUE(scene.objects[0].transparent);
    EXPECT_FLOAT_EQ(scene.objects[1].colour.g, 1.0f);
    EXPECT_FALSE(scene.objects[1].transparent);
    EXPECT_FLOAT_EQ(scene.objects[2].colour.b, 1.0f);
    EXPECT_FALSE(scene.objects[2].transparent);
}

TEST(MeshLoader, ObjGGroupsAreObjectsInFileOrder) {
    TempDir dir;
    const std::string path = dir.write("g.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n"
                                                "g first\nf 1 2 3\n"
                                                "g second\nf 1 3 2\nf 2 3 1\n"
                                                "g third\nf 3 1 2\n");
    const Result<Scene> loaded = loadMeshFile(path);
    ASSERT_TRUE(loaded) << loaded.error;
    const Scene& scene = *loaded.value;
    ASSERT_EQ(scene.objects.size(), 3u);
    EXPECT_EQ(scene.objects[0].name, "first");
    EXPECT_EQ(scene.objects[1].name, "second");
    EXPECT_EQ(scene.objects[2].name, "third");
    EXPECT_EQ(scene.objects[1].triangle_count, 2u);
    EXPECT_EQ(scene.objects[2].first_triangle, 3u);
    expectCorner(scene, 3, {0, 0, 0}); // "f 1 3 2"
    expectCorner(scene, 4, {0, 1, 0});
    expectCorner(scene, 9, {0, 1, 0}); // "f 3 1 2"
}

TEST(MeshLoader, AsciiPlyKeepsFaceOrder) {
    TempDir dir;
    const std::string path =
        dir.write("mesh.ply", "ply\nformat ascii 1.0\nelement vertex 5\n"
                              "property float x\nproperty float y\nproperty float z\n"
                              "element face 2\nproperty list uchar int vertex_indices\n"
                              "end_header\n"
                              "0 0 0\n1 0 0\n1 1 0\n0 1 0\n5 5 5\n"
                              "3 4 0 1\n4 0 1 2 3\n");
    const Result<Scene> loaded = loadMeshFile(path);
    ASSERT_TRUE(loaded) << loaded.error;
    const Scene& scene = *loaded.value;
    ASSERT_EQ(scene.triangleCount(), 3u);
    EXPECT_EQ(scene.name, "mesh");
    const Vec3 expected[] = {{5, 5, 5}, {0, 0, 0}, {1, 0, 0}, {0, 0, 0}, {1, 0, 0},
                             {1, 1, 0}, {0, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    for (std::size_t c = 0; c < 9; ++c)
        expectCorner(scene, c, expected[c]);
}

TEST(MeshLoader, AsciiStlKeepsFacetOrder) {
    TempDir dir;
    const std::string path =
        dir.write("mesh.stl", "solid two\n"
                              "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex "
                              "0 1 0\nendloop\nendfacet\n"
                              "facet normal 0 0 1\nouter loop\nvertex 2 0 3\nvertex 3 0 3\nvertex "
                              "2 1 3\nendloop\nendfacet\n"
                              "endsolid two\n");
    const Result<Scene> loaded = loadMeshFile(path);
    ASSERT_TRUE(loaded) << loaded.error;
    const Scene& scene = *loaded.value;
    ASSERT_EQ(scene.triangleCount(), 2u);
    expectCorner(scene, 0, {0, 0, 0});
    expectCorner(scene, 2, {0, 1, 0});
    expectCorner(scene, 3, {2, 0, 3});
    expectCorner(scene, 4, {3, 0, 3});
}

TEST(MeshLoader, GltfInstancesUseTheirNodeWorldTransforms) {
    // One triangle (0,0,0) (1,0,0) (0,1,0), placed by node "moved" (translate 10,0,0) and by
    // node "child" (translate 0,5,0) under "parent" (scale 2): world = S(2) * T(0,5,0).
    const Result<Scene> loaded = loadMeshFile(kMeshes + "instanced.gltf");
    ASSERT_TRUE(loaded) << loaded.error;
    const Scene& scene = *loaded.value;
    ASSERT_EQ(scene.triangleCount(), 2u);
    ASSERT_EQ(scene.objects.size(), 2u);
    expectCorner(scene, 0, {10, 0, 0});
    expectCorner(scene, 1, {11, 0, 0});
    expectCorner(scene, 2, {10, 1, 0});
    expectCorner(scene, 3, {0, 10, 0});
    expectCorner(scene, 4, {2, 10, 0});
    expectCorner(scene, 5, {0, 12, 0});
    EXPECT_EQ(scene.objects[0].name, "moved/tri");
    EXPECT_EQ(scene.objects[1].name, "child/tri");
    // baseColorFactor (0.2, 0.4, 0.6, 0.5), alphaMode BLEND.
    EXPECT_NEAR(scene.objects[0].colour.g, 0.4f, 1e-6);
    EXPECT_NEAR(scene.objects[0].colour.a, 0.5f, 1e-6);
    EXPECT_TRUE(scene.objects[1].transparent);
}

TEST(MeshLoader, FileGroupingMakesOneObjectOfPartsWithTheSameTriangles) {
    const Result<Scene> each = loadMeshFile(kMeshes + "crabs.obj");
    const Result<Scene> whole = loadMeshFile(kMeshes + "crabs.obj", ObjectGrouping::file);
    ASSERT_TRUE(each) << each.error;
    ASSERT_TRUE(whole) << whole.error;
    // Four meshes: two crabs of a shell (a quad, d 0.5 and 0.7) and a claw (opaque).
    ASSERT_EQ(each.value->objects.size(), 4u);
    ASSERT_EQ(whole.value->objects.size(), 1u);
    EXPECT_EQ(whole.value->positions.x, each.value->positions.x);
    EXPECT_EQ(whole.value->positions.y, each.value->positions.y);
    EXPECT_EQ(whole.value->positions.z, each.value->positions.z);
    const SceneObject& crabs = whole.value->objects[0];
    EXPECT_EQ(crabs.name, "crabs");
    EXPECT_EQ(crabs.first_triangle, 0u);
    EXPECT_EQ(crabs.triangle_count, 6u);
    ASSERT_EQ(crabs.parts.size(), 4u);
    for (std::size_t i = 0; i < 4; ++i) {
        const SceneObject& mesh = each.value->objects[i];
        EXPECT_EQ(crabs.parts[i].name, mesh.name);
        EXPECT_EQ(crabs.parts[i].first_triangle, mesh.first_triangle);
        EXPECT_EQ(crabs.parts[i].triangle_count, mesh.triangle_count);
        EXPECT_EQ(crabs.parts[i].colour.g, mesh.colour.g);
        EXPECT_EQ(crabs.parts[i].colour.a, mesh.colour.a);
    }
    // The largest part's colour (the first shell, Kd 1 0.2 0.2) with the least alpha (0.5).
    EXPECT_FLOAT_EQ(crabs.colour.r, 1.0f);
    EXPECT_FLOAT_EQ(crabs.colour.g, 0.2f);
    EXPECT_FLOAT_EQ(crabs.colour.a, 0.5f);
    EXPECT_TRUE(crabs.transparent);
}

TEST(MeshLoader, NodeGroupingMakesOneObjectPerNodeInNodeOrder) {
    // An OBJ group of two materials is one node of two meshes.
    const Result<Scene> crabs = loadMeshFile(kMeshes + "crabs.obj", ObjectGrouping::node);
    ASSERT_TRUE(crabs) << crabs.error;
    ASSERT_EQ(crabs.value->objects.size(), 2u);
    EXPECT_EQ(crabs.value->objects[0].name, "crab");
    EXPECT_EQ(crabs.value->objects[1].name, "crab2");
    EXPECT_EQ(crabs.value->objects[1].first_triangle, 3u);
    EXPECT_EQ(crabs.value->objects[1].parts.size(), 2u);
    EXPECT_FLOAT_EQ(crabs.value->objects[1].colour.a, 0.7f);

    // Nodes first and third place mesh 'pair' (two primitives: two meshes, at z = 1 and 2),
    // third moved 5 along x; node second places 'solo' (z = 0). By mesh, the instances of a
    // mesh come together; by node, each node's meshes do, in node order.
    const Result<Scene> by_mesh = loadMeshFile(kMeshes + "nodes_out_of_mesh_order.gltf");
    const Result<Scene> by_node =
        loadMeshFile(kMeshes + "nodes_out_of_mesh_order.gltf", ObjectGrouping::node);
    ASSERT_TRUE(by_mesh) << by_mesh.error;
    ASSERT_TRUE(by_node) << by_node.error;
    ASSERT_EQ(by_mesh.value->objects.size(), 5u);
    EXPECT_EQ(by_mesh.value->objects[0].name, "first/pair-0");
    EXPECT_EQ(by_mesh.value->objects[1].name, "third/pair-0");
    const Scene& scene = *by_node.value;
    ASSERT_EQ(scene.objects.size(), 3u);
    const char* names[] = {"first", "second", "third"};
    const uint32_t firsts[] = {0, 2, 3}, counts[] = {2, 1, 2};
    for (int i = 0; i < 3; ++i) {
        EXPECT_EQ(scene.objects[i].name, names[i]);
        EXPECT_EQ(scene.objects[i].first_triangle, firsts[i]);
        EXPECT_EQ(scene.objects[i].triangle_count, counts[i]);
    }
    expectCorner(scene, 0, {0, 0, 1}); // first: pair's primitives
    expectCorner(scene, 3, {0, 0, 2});
    expectCorner(scene, 6, {0, 0, 0}); // second: solo
    expectCorner(scene, 9, {5, 0, 1}); // third: pair, moved
    expectCorner(scene, 12, {5, 0, 2});
    // Parts keep their materials: pair's second primitive is blue at alpha 0.5.
    ASSERT_EQ(scene.objects[2].parts.size(), 2u);
    EXPECT_FLOAT_EQ(scene.objects[2].parts[1].colour.b, 1.0f);
    EXPECT_FLOAT_EQ(scene.objects[2].parts[1].colour.a, 0.5f);
    EXPECT_TRUE(scene.objects[2].transparent);
    EXPECT_TRUE(scene.objects[1].parts.empty());
    EXPECT_FALSE(scene.objects[1].transparent);
}

TEST(MeshLoader, MemoryInputGoesThroughTheSameReader) {
    const std::string bytes = readBytes(kModels + "bunny-lowres.obj");
    const Result<Scene> loaded = loadMeshMemory(bytes.data(), bytes.size(), "obj", "bunny.obj");
    ASSERT_TRUE(loaded) << loaded.error;
    const std::vector<Vec3> reference = referenceObjTriangles(kModels + "bunny-lowres.obj");
    ASSERT_EQ(loaded.value->triangleCount() * 3, reference.size());
    expectCorner(*loaded.value, 0, reference[0]);
    expectCorner(*loaded.value, reference.size() - 1, reference.back());

    expectRejected(loadMeshMemory(bytes.data(), 0, "obj", "empty-input"), "empty-input");
    const std::string garbage = "\x01\x02garbage\xff\xfe";
    expectRejected(loadMeshMemory(garbage.data(), garbage.size(), "ply", "garbage-input"),
                   "garbage-input");
}

TEST(MeshLoader, RejectsMissingFilesAndFolders) {
    TempDir dir;
    const std::string missing = (dir.path() / "nope.obj").string();
    expectRejected(loadMeshFile(missing), missing, "not found");
    expectRejected(loadMeshFile(dir.path().string()), dir.path().string(), "not a regular file");
}

TEST(MeshLoader, RejectsGarbageAndEmptyFiles) {
    TempDir dir;
    std::string garbage;
    uint32_t state = 12345; // fixed LCG: the same bytes every run
    for (int i = 0; i < 4096; ++i) {
        state = state * 1664525u + 1013904223u;
        garbage.push_back(static_cast<char>(state >> 24));
    }
    for (const char* name : {"garbage.obj", "garbage.ply", "garbage.stl", "garbage.gltf",
                             "garbage.glb", "garbage.xyz"}) {
        const std::string path = dir.write(name, garbage);
        expectRejected(loadMeshFile(path), path);
    }
    for (const char* name : {"empty.obj", "empty.ply", "empty.stl"}) {
        const std::string path = dir.write(name, "");
        expectRejected(loadMeshFile(path), path);
    }
}

TEST(MeshLoader, RejectsFilesWithoutTriangles) {
    TempDir dir;
    const std::string lines =
        dir.write("lines.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2\nl 2 3\np 1\n");
    expectRejected(loadMeshFile(lines), lines, "no triangles");
    const std::string vertices = dir.write("vertices.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
    expectRejected(loadMeshFile(vertices), vertices);
}

TEST(MeshLoader, RejectsNonFiniteCoordinates) {
    TempDir dir;
    const std::pair<const char*, const char*> cases[] = {
        {"nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n"},
        {"inf.obj", "v 0 0 0\nv 1 0 0\nv 0 inf 0\nf 1 2 3\n"},
        {"minus_inf.obj", "v 0 0 0\nv 1 0 0\nv 0 0 -inf\nf 1 2 3\n"},
        {"float_overflow.obj", "v 0 0 0\nv 1 0 0\nv 0 1e39 0\nf 1 2 3\n"},
        {"nan.ply",
         "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
         "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
         "0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n"},
    };
    for (const auto& [name, text] : cases) {
        const std::string path = dir.write(name, text);
        expectRejected(loadMeshFile(path), path);
    }
    // A non-finite vertex that no face uses is harmless and must not reject the file.
    const std::string unused =
        dir.write("unused_nan.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv nan 0 0\nf 1 2 3\n");
    EXPECT_TRUE(loadMeshFile(unused));
}

} // namespace
} // namespace vissort

namespace vissort {
namespace {

// A file that passes vissort's own checks but that assimp cannot read says so, with assimp's
// reason, from a file and from memory: a user then knows whom to ask. (A binary FBX whose first
// block ends past the file, as assimp's FBX/transparentTest.fbx does.)
TEST(MeshLoader, WhatAssimpRefusesIsSaidToBeAssimps) {
    std::string fbx = std::string("Kaydara FBX Binary  ") + '\0' + '\x1a' + '\0';
    const auto put32 = [&](uint32_t v) {
        for (int i = 0; i < 4; ++i)
            fbx += char((v >> (8 * i)) & 0xff);
    };
    put32(7400);       // version
    put32(0x7fffffff); // the first block's end: far past the file
    put32(0);
    put32(0);
    fbx += "\x03"
           "abc" +
           std::string(40, '\0');
    TempDir dir;
    const std::string path = dir.write("broken.fbx", fbx);
    const Result<Scene> from_file = loadMeshFile(path);
    ASSERT_FALSE(from_file);
    EXPECT_EQ(from_file.error.rfind(path + ": assimp could not read it: ", 0), 0u)
        << from_file.error;
    EXPECT_NE(from_file.error.find("FBX"), std::string::npos) << from_file.error;
    const Result<Scene> from_memory = loadMeshMemory(fbx.data(), fbx.size(), "fbx", "memory.fbx");
    ASSERT_FALSE(from_memory);
    EXPECT_EQ(from_memory.error.rfind("memory.fbx: assimp could not read it: ", 0), 0u)
        << from_memory.error;
}

} // namespace
} // namespace vissort
