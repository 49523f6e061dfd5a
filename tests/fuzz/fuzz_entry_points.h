#pragma once
// The fuzz targets' entry points, shared by the libFuzzer executables (VISSORT_FUZZ=ON,
// scripts/fuzz.sh) and by the replay test of the normal build, which runs every file of
// tests/fuzz/corpus/<target>/ and tests/fuzz/crashes/<target>/ through the same function.
// Each takes untrusted bytes and must return (a scene or a one-line error) without crashing,
// hanging, leaking or allocating out of proportion; a broken rule is reported by aborting.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace vissort::fuzz {

/// The bytes as a JSON scene file (written to a temporary folder) through loadScene.
void jsonScene(const uint8_t* data, std::size_t size);

/// "builtin:" + the bytes as a scene specification through loadScene: the query parser and
/// every scene's parameter reader. Inputs asking for large scenes (n or layers above 64, the
/// power plant without a scale or above scale=0.1) are
/// skipped: generating them is slow, not wrong, and their ranges have unit tests.
void sceneParameters(const uint8_t* data, std::size_t size);

/// The bytes after the first as a mesh file through loadScene; the first byte picks the
/// extension (obj, ply, stl, off, gltf, glb, nff), that is which of assimp's readers gets it.
void meshFile(const uint8_t* data, std::size_t size);

/// The bytes after the first as a grid file through loadGrid; the first byte picks the format
/// (vtk, vtu, tetgen's pair, Medit with its .sol), and a line "====" splits a pair's two files.
void gridFile(const uint8_t* data, std::size_t size);

struct Target {
    const char* name; // the folder under tests/fuzz/corpus and tests/fuzz/crashes
    void (*run)(const uint8_t* data, std::size_t size);
};

/// Every target, in the order scripts/fuzz.sh runs them.
const std::vector<Target>& targets();

} // namespace vissort::fuzz
