#include "corpus_files.h"

#include <cstdint>
#include <fstream>
#include <iterator>

#include "corpus_models.h"
#include "corpus_writers.h"

namespace vissort::test {
namespace {

namespace fs = std::filesystem;

using Writer = std::string (*)(const CorpusModel&, const fs::path&);

std::string writeBytes(const fs::path& path, const std::string& bytes) {
    std::ofstream out(path, std::ios::binary);
    out << bytes;
    out.close();
    return out ? std::string() : "cannot write " + path.string();
}

std::string readBytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Deterministic bytes (a linear congruential generator): the same garbage every run.
std::string garbage(std::size_t size, uint32_t seed) {
    std::string bytes(size, '\0');
    for (char& c : bytes) {
        seed = seed * 1664525u + 1013904223u;
        c = char(seed >> 24);
    }
    return bytes;
}

struct Good {
    CorpusModel (*model)();
    std::string base; // model's short name in file names
};

// A good file written by assimp's exporter.
CorpusFile exported(const Good& good, const std::string& format_id, const std::string& extension,
                    bool triangulate) {
    const std::string file = good.base + "_" + format_id + "." + extension;
    CorpusFile entry{good.base + "_" + format_id, file, format_id + " (assimp exporter)", false,
                     triangleCount(good.model()), {}};
    entry.write = [good, format_id, file, triangulate](const fs::path& folder) {
        return exportWithAssimp(good.model(), format_id, folder / file, triangulate);
    };
    return entry;
}

// A good file written here, by hand.
CorpusFile handWritten(const Good& good, const std::string& kind, const std::string& extension,
                       Writer writer) {
    const std::string file = good.base + "_" + kind + "." + extension;
    CorpusFile entry{good.base + "_" + kind,      file, kind + " (hand-written)", false,
                     triangleCount(good.model()), {}};
    entry.write = [good, file, writer](const fs::path& folder) {
        return writer(good.model(), folder / file);
    };
    return entry;
}

CorpusFile broken(const std::string& name, const std::string& file, const std::string& what,
                  std::function<std::string(const fs::path&)> write) {
    return {name, file, what, true, 0, std::move(write)};
}

// A broken file from the first `keep` bytes (or fraction) of an exported one.
CorpusFile truncatedExport(const std::string& name, const std::string& format_id,
                           const std::string& extension, double keep_fraction) {
    const std::string file = name + "." + extension;
    return broken(
        name, file, format_id + " export cut to " + std::to_string(int(keep_fraction * 100)) + "%",
        [=](const fs::path& folder) {
            const fs::path full = folder / ("whole_" + file);
            if (std::string error = exportWithAssimp(gridOfBoxes(), format_id, full, true);
                !error.empty())
                return error;
            const std::string bytes = readBytes(full);
            fs::remove(full);
            return writeBytes(folder / file,
                              bytes.substr(0, std::size_t(double(bytes.size()) * keep_fraction)));
        });
}

CorpusFile textFile(const std::string& name, const std::string& file, const std::string& what,
                    const std::string& text) {
    return broken(name, file, what,
                  [=](const fs::path& folder) { return writeBytes(folder / file, text); });
}

std::vector<CorpusFile> makeCorpus() {
    const Good grid{gridOfBoxes, "grid"}, house{smallHouse, "house"}, floor{coplanarFloor, "floor"},
        nested{nestedBoxes, "nested"}, crossing{interpenetrating, "crossing"},
        pipes{pipeRun, "pipes"}, shelf{shelves, "shelves"}, glass{glassCase, "glass"},
        steps{stairs, "stairs"};
    std::vector<CorpusFile> files = {
        // Boxes sharing faces, as assimp's 3DS/test1.3ds.
        exported(grid, "3ds", "3ds", true),
        exported(grid, "stlb", "stl", true),
        handWritten(grid, "obj_mtl", "obj", writeObjWithMaterials),
        handWritten(grid, "ac3d", "ac", writeAc3d),
        // Walls on a slab, a roof on the walls, a door on a wall, a chimney through the roof.
        exported(house, "collada", "dae", false),
        exported(house, "glb2", "glb", true),
        exported(house, "fbxa", "fbx", false),
        exported(house, "obj", "obj", false),
        handWritten(house, "off", "off", writeOff),
        // Tiles sharing edges, a rug and a mat coplanar on them.
        handWritten(floor, "ply_ascii", "ply", writeAsciiPly),
        exported(floor, "plyb", "ply", false),
        exported(floor, "gltf2", "gltf", true),
        exported(floor, "x", "x", false),
        // Boxes in boxes.
        exported(nested, "x3d", "x3d", true),
        exported(nested, "assbin", "assbin", false),
        handWritten(nested, "stl_solids", "stl", writeAsciiStlSolids),
        exported(nested, "collada", "dae", false),
        // Bars through a block, three sticks in a cycle.
        exported(crossing, "collada", "dae", false),
        exported(crossing, "x", "x", false),
        exported(crossing, "fbxa", "fbx", false),
        handWritten(crossing, "ac3d", "ac", writeAc3d),
        // A pipe run.
        exported(pipes, "gltf2", "gltf", true),
        exported(pipes, "stl", "stl", true),
        handWritten(pipes, "obj_mtl", "obj", writeObjWithMaterials),
        // The pipe run's 12-sided caps: assimp's OFF reader drops polygons of 10 or more
        // corners, so the loader refuses the file (src/scene/off_faces.h) rather than lose them.
        broken("pipes_off", "pipes_off.off", "off (hand-written), with 12-sided polygons",
               [pipes](const fs::path& folder) {
                   return writeOff(pipes.model(), folder / "pipes_off.off");
               }),
        // A node hierarchy placing two meshes 18 times.
        exported(shelf, "collada", "dae", false),
        exported(shelf, "glb2", "glb", true),
        exported(shelf, "fbxa", "fbx", false),
        exported(shelf, "assbin", "assbin", false),
        exported(shelf, "x", "x", false),
        exported(shelf, "obj", "obj", false),
        // Transparent materials.
        exported(glass, "gltf2", "gltf", true),
        exported(glass, "3ds", "3ds", true),
        handWritten(glass, "obj_mtl", "obj", writeObjWithMaterials),
        handWritten(glass, "ac3d", "ac", writeAc3d),
        // Steps resting on steps.
        exported(steps, "ply", "ply", false),
        exported(steps, "x3d", "x3d", true),
        exported(steps, "assbin", "assbin", false),
        handWritten(steps, "stl_solids", "stl", writeAsciiStlSolids),
    };

    // Broken files: each must be refused with one line naming it.
    const std::string cube_obj = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n";
    files.push_back(textFile("empty_obj", "empty.obj", "empty OBJ", ""));
    files.push_back(textFile("empty_stl", "empty.stl", "empty STL", ""));
    files.push_back(textFile("empty_gltf", "empty.gltf", "empty glTF", ""));
    files.push_back(
        broken("garbage_fbx", "garbage.fbx", "random bytes named .fbx", [](const fs::path& folder) {
            return writeBytes(folder / "garbage.fbx", garbage(4096, 1));
        }));
    files.push_back(
        broken("garbage_3ds", "garbage.3ds", "random bytes named .3ds", [](const fs::path& folder) {
            return writeBytes(folder / "garbage.3ds", garbage(4096, 2));
        }));
    files.push_back(broken("garbage_glb", "garbage.glb", "glTF binary magic, then random bytes",
                           [](const fs::path& folder) {
                               return writeBytes(folder / "garbage.glb",
                                                 std::string("glTF\x02\0\0\0", 8) +
                                                     garbage(2048, 3));
                           }));
    files.push_back(textFile("garbage_dae", "garbage.dae", "XML that is not COLLADA",
                             "<?xml version=\"1.0\"?>\n<COLLADA><library_geometries><geometry>"
                             "<mesh><source><float_array count=\"9\">1 2"));
    files.push_back(textFile("garbage_ply", "garbage.ply", "PLY header, then text that is not data",
                             "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                             "property float y\nproperty float z\nelement face 1\nproperty list "
                             "uchar int vertex_indices\nend_header\nnot numbers at all\n"));
    files.push_back(truncatedExport("truncated_glb", "glb2", "glb", 0.5));
    files.push_back(truncatedExport("truncated_stlb", "stlb", "stl", 0.6));
    files.push_back(truncatedExport("truncated_3ds", "3ds", "3ds", 0.5));
    files.push_back(truncatedExport("truncated_plyb", "plyb", "ply", 0.6));
    files.push_back(truncatedExport("truncated_fbx", "fbx", "fbx", 0.5));
    files.push_back(textFile("nan_obj", "nan.obj", "a NaN coordinate",
                             "v 0 0 0\nv 1 0 0\nv nan 1 0\nv 0 1 0\nf 1 2 3 4\n"));
    files.push_back(
        textFile("nan_ply", "nan.ply", "a NaN coordinate",
                 "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                 "property float y\nproperty float z\nelement face 1\nproperty list "
                 "uchar int vertex_indices\nend_header\n0 0 0\n1 0 nan\n0 1 0\n3 0 1 2\n"));
    files.push_back(textFile("infinite_stl", "infinite.stl", "a coordinate beyond float",
                             "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n"
                             "vertex 1e39 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid s\n"));
    files.push_back(textFile("wrong_count_off", "wrong_count.off",
                             "more vertices and faces announced than given",
                             "OFF\n40 12 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n"));
    files.push_back(
        textFile("wrong_count_ply", "wrong_count.ply", "more vertices announced than given",
                 "ply\nformat ascii 1.0\nelement vertex 20\nproperty float x\n"
                 "property float y\nproperty float z\nelement face 1\nproperty list "
                 "uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"));
    files.push_back(textFile("bad_index_obj", "bad_index.obj", "a face index beyond the vertices",
                             cube_obj + "f 1 2 99\n"));
    files.push_back(textFile("bad_index_off", "bad_index.off", "a face index beyond the vertices",
                             "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 7\n"));
    return files;
}

} // namespace

const std::vector<CorpusFile>& corpusFiles() {
    static const std::vector<CorpusFile> files = makeCorpus();
    return files;
}

} // namespace vissort::test
