// See fuzz_entry_points.h. The inputs go through the library's public entry point, loadScene,
// as files: that is how the tool meets them.

#include "fuzz_entry_points.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string_view>

#include "scenes/scene_library.h"
#include "vissort/scene.h"
#include "vissort/tet_grid.h"

namespace vissort::fuzz {
namespace {

namespace fs = std::filesystem;

/// One private folder per process, for the input files (removed at exit). The path is never
/// destroyed: the exit handler that removes the folder runs after static destructors would
/// have (valgrind found the handler reading a destroyed path).
const fs::path& scratchFolder() {
    static const fs::path& folder = *new fs::path([] {
        std::string pattern = (fs::temp_directory_path() / "vissort_fuzz_XXXXXX").string();
        if (!mkdtemp(pattern.data()))
            std::abort();
        std::atexit([] {
            std::error_code ignored;
            fs::remove_all(scratchFolder(), ignored);
        });
        // A small mesh for JSON scenes to refer to ("mesh": "tri.obj").
        std::ofstream(fs::path(pattern) / "tri.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
        return fs::path(pattern);
    }());
    return folder;
}

std::string writeInput(const std::string& name, const uint8_t* data, std::size_t size) {
    const fs::path file = scratchFolder() / name;
    std::ofstream stream(file, std::ios::binary | std::ios::trunc);
    stream.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    return file.string();
}

/// Files outside the scratch folder are off limits: a fuzzed JSON or OBJ naming "/dev/stdin",
/// "/proc/..." or "../x" would make the fuzzer read (or wait on) the machine's files.
bool namesOtherFiles(std::string_view text) {
    for (const std::string_view needle : {"..", "/dev", "/proc", "/sys", "\"/", " /", "\t/"})
        if (text.find(needle) != std::string_view::npos)
            return true;
    return !text.empty() && text.front() == '/';
}

/// The loader's contract on a refusal: one line that starts with the source's name.
void checkResult(const Result<Scene>& scene, const std::string& source) {
    if (scene)
        return;
    if (scene.error.empty() || scene.error.find('\n') != std::string::npos ||
        (!source.empty() && scene.error.rfind(source, 0) != 0)) {
        std::fprintf(stderr, "fuzz: bad error message for %s: '%s'\n", source.c_str(),
                     scene.error.c_str());
        std::abort();
    }
}

} // namespace

void jsonScene(const uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    if (namesOtherFiles(text))
        return;
    const std::string path = writeInput("scene.json", data, size);
    checkResult(samples::loadScene(path), path);
}

void sceneParameters(const uint8_t* data, std::size_t size) {
    const std::string specification =
        "builtin:" + std::string(reinterpret_cast<const char*>(data), size);
    // Skip n=V or layers=V with V in (64, 10^7], the largest maximum of any scene (see the
    // header); larger values are refused by the range checks at once, so they stay in.
    for (const std::string_view key : {"n=", "layers="}) {
        for (std::size_t at = specification.find(key); at != std::string::npos;
             at = specification.find(key, at + 1)) {
            if (at > 0 && specification[at - 1] != '?' && specification[at - 1] != '&')
                continue;
            std::size_t end = at + key.size(), digits = 0;
            uint64_t value = 0;
            while (end < specification.size() && specification[end] >= '0' &&
                   specification[end] <= '9' && digits < 19) {
                value = value * 10 + uint64_t(specification[end] - '0');
                ++end, ++digits;
            }
            if (digits > 0 && value > 64 && value <= 10'000'000)
                return;
        }
    }
    // The power plant is 820K triangles at its default scale (seconds under the sanitizers) and
    // up to 8 million at scale=10: only scales up to 0.1 are built (120K triangles, the least
    // it has). Larger scales are slow, not wrong, and covered by the scene's tests.
    if (specification.find("powerplant") != std::string::npos) {
        const std::size_t at = specification.find("scale=");
        if (at == std::string::npos)
            return;
        const double scale = std::strtod(specification.c_str() + at + 6, nullptr);
        if (!(scale <= 0.1))
            return;
    }
    // Likewise the soup (a triangle an object) and the bunnies (3674 triangles each) are built up
    // to a million triangles: 8 million one-triangle objects took over 10 s instrumented (seen by
    // CI's fuzzer); the limit of 10 million is the scenes' own tests' and the benchmarks'.
    for (const auto& [name, triangles_each] : {std::pair{"soup", 1.0}, {"bunnies", 3674.0}})
        if (specification.find(name) != std::string::npos) {
            const std::size_t at = specification.find("n=");
            if (at != std::string::npos &&
                !(std::strtod(specification.c_str() + at + 2, nullptr) * triangles_each <= 1e6))
                return;
        }
    checkResult(samples::loadScene(specification), "");
}

void meshFile(const uint8_t* data, std::size_t size) {
    static constexpr const char* kExtensions[] = {"obj", "ply", "stl", "off", "gltf", "glb", "nff"};
    if (size == 0)
        return;
    const std::string_view text(reinterpret_cast<const char*>(data + 1), size - 1);
    if (namesOtherFiles(text))
        return;
    const char* extension = kExtensions[data[0] % std::size(kExtensions)];
    const std::string path = writeInput(std::string("mesh.") + extension, data + 1, size - 1);
    checkResult(samples::loadScene(path), path);
}

void gridFile(const uint8_t* data, std::size_t size) {
    if (size == 0)
        return;
    const std::string_view text(reinterpret_cast<const char*>(data + 1), size - 1);
    // Two files (tetgen's .node and .ele, Medit's .mesh and .sol) are split at the first line of
    // "====": without one, the second is empty.
    constexpr std::string_view kSplit = "\n====\n";
    const std::size_t split = text.find(kSplit);
    const std::string_view first = text.substr(0, split);
    const std::string_view second =
        split == std::string_view::npos ? std::string_view() : text.substr(split + kSplit.size());
    const auto write = [](const std::string& name, std::string_view bytes) {
        return writeInput(name, reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
    };
    std::string path;
    switch (data[0] % 4) {
    case 0:
        path = write("grid.vtk", text);
        break;
    case 1:
        path = write("grid.vtu", text);
        break;
    case 2:
        path = write("grid.node", first);
        write("grid.ele", second);
        break;
    default:
        path = write("grid.mesh", first);
        std::filesystem::remove(std::filesystem::path(path).replace_extension(".sol"));
        if (!second.empty())
            write("grid.sol", second);
        break;
    }
    const Result<TetGrid> grid = loadGrid(path);
    if (grid) {
        if (Status valid = validateGrid(*grid.value); !valid) {
            std::fprintf(stderr, "fuzz: a loaded grid is invalid: %s\n", valid.error.c_str());
            std::abort();
        }
        return;
    }
    // tetgen's errors name the pair ("DIR/grid.node/.ele: ...").
    const std::string source = path.substr(0, path.size() - (data[0] % 4 == 2 ? 5 : 0));
    if (grid.error.empty() || grid.error.find('\n') != std::string::npos ||
        grid.error.rfind(source, 0) != 0) {
        std::fprintf(stderr, "fuzz: bad error message for %s: '%s'\n", path.c_str(),
                     grid.error.c_str());
        std::abort();
    }
}

const std::vector<Target>& targets() {
    static const std::vector<Target> all = {{"json_scene", jsonScene},
                                            {"scene_parameters", sceneParameters},
                                            {"mesh_file", meshFile},
                                            {"grid_file", gridFile}};
    return all;
}

} // namespace vissort::fuzz
