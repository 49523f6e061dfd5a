#pragma once
// The corpus's scenes, built in code in the shapes real files have: boxes sharing faces in a grid
// (like assimp's 3DS/test1.3ds), walls standing on a slab under a roof (a small house), coplanar
// faces of different objects, nested boxes, interpenetrating objects (true cycles), a pipe run
// with flanges, a node hierarchy placing one mesh several times, transparent materials.
//
// Coordinates are multiples of 1/8 (or rounded to 4 decimals where a circle needs them) so that
// every text format writes and reads them back exactly: faces that touch in the model still touch
// in each file.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace vissort::test {

struct CorpusMaterial {
    std::string name;
    float r = 0.7f, g = 0.7f, b = 0.7f, a = 1.0f; // a < 1: transparent
};

struct CorpusMesh {
    std::string name;
    std::vector<std::array<float, 3>> vertices;
    std::vector<std::vector<uint32_t>> faces; // convex polygons, counter-clockwise from outside
    uint32_t material = 0;
};

/// A node: a transform (row-major 4x4, column vector convention as assimp's aiMatrix4x4), the
/// meshes it places, and its children.
struct CorpusNode {
    std::string name;
    std::array<float, 16> transform = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    std::vector<uint32_t> meshes;
    std::vector<CorpusNode> children;
};

struct CorpusModel {
    std::string name;
    std::vector<CorpusMaterial> materials;
    std::vector<CorpusMesh> meshes;
    CorpusNode root;
};

/// One mesh instance in world coordinates, in the order loaders produce them (mesh order, then
/// node order), for the formats that have no node hierarchy.
struct WorldMesh {
    std::string name;
    std::vector<std::array<float, 3>> vertices;
    std::vector<std::vector<uint32_t>> faces;
    uint32_t material = 0;
};
std::vector<WorldMesh> worldMeshes(const CorpusModel& model);

/// Triangles of the model's instances once polygons are fanned.
std::size_t triangleCount(const CorpusModel& model);

CorpusModel gridOfBoxes();      // nine unit boxes in a 3x3 grid, neighbours share faces
CorpusModel smallHouse();       // slab, four walls on it, roof on them, a door on a wall's face
CorpusModel coplanarFloor();    // tiles sharing edges, a rug and a mat coplanar on them
CorpusModel nestedBoxes();      // four boxes inside each other around a solid core
CorpusModel interpenetrating(); // crossed bars through a block, three sticks in a cycle
CorpusModel pipeRun();          // tubes end to end through an elbow, flanges on the joints
CorpusModel shelves();          // a node hierarchy: planks instanced by rotated, moved nodes
CorpusModel glassCase();        // a transparent case around a statue on a table
CorpusModel stairs();           // steps each resting on the last, a landing, a railing

} // namespace vissort::test
