// loadGrid: a grid file by its extension, or a built-in grid; the files read whole (each reader
// bounds what it allocates by the bytes it was given) and every error prefixed with the file.
#include <algorithm>
#include <filesystem>
#include <fstream>

#include "grid/builtin_grids.h"
#include "grid/raw_grid.h"
#include "grid/token_scanner.h"

namespace vissort {
namespace {

namespace fs = std::filesystem;
using detail::RawGrid;

// A grid file larger than this is refused before reading: 4 GB holds far more than
// kMaxGridTets cells in any of the formats read.
constexpr uint64_t kMaxGridFileBytes = uint64_t(4) << 30;

constexpr std::string_view kBuiltinPrefix = "builtin:";

std::string lowerExtension(const std::string& path) {
    return detail::lowerCase(fs::path(path).extension().string());
}

Result<std::string> readWhole(const std::string& path) {
    using R = Result<std::string>;
    std::error_code error;
    if (!fs::exists(path, error))
        return R::failure(path + ": file not found");
    if (!fs::is_regular_file(path, error))
        return R::failure(path + ": not a regular file");
    const uint64_t size = fs::file_size(path, error);
    if (error)
        return R::failure(path + ": cannot read the file's size");
    if (size == 0)
        return R::failure(path + ": empty file");
    if (size > kMaxGridFileBytes)
        return R::failure(path + ": " + std::to_string(size) + " bytes, more than the " +
                          std::to_string(kMaxGridFileBytes) + " a grid file may have");
    std::ifstream in(path, std::ios::binary);
    std::string bytes(size, '\0');
    if (!in.read(bytes.data(), std::streamsize(size)))
        return R::failure(path + ": cannot read the file");
    return R{std::move(bytes), {}};
}

// tetgen's pair: X.node and X.ele, either named.
Result<RawGrid> readTetgenPair(const std::string& path) {
    using R = Result<RawGrid>;
    const fs::path stem = fs::path(path).replace_extension();
    const std::string node_path = stem.string() + ".node", ele_path = stem.string() + ".ele";
    Result<std::string> node = readWhole(node_path);
    if (!node)
        return R::failure(node.error + " (tetgen's grid is a .node and a .ele file)");
    Result<std::string> ele = readWhole(ele_path);
    if (!ele)
        return R::failure(ele.error + " (tetgen's grid is a .node and a .ele file)");
    Result<RawGrid> raw = detail::readTetgen(*node.value, *ele.value);
    if (!raw)
        return R::failure(stem.string() + ".node/.ele: " + raw.error);
    return raw;
}

} // namespace

bool isGridSpec(const std::string& spec) {
    if (spec.starts_with(kBuiltinPrefix)) {
        const std::string name =
            spec.substr(kBuiltinPrefix.size(), spec.find('?') - kBuiltinPrefix.size());
        for (const BuiltinGridInfo& info : detail::builtinGrids())
            if (name == info.name)
                return true;
        return false;
    }
    const std::string ext = lowerExtension(spec);
    return ext == ".vtk" || ext == ".vtu" || ext == ".node" || ext == ".ele" || ext == ".mesh";
}

std::vector<BuiltinGridInfo> builtinGridNames() {
    return detail::builtinGrids();
}

std::vector<std::string> gridSourceFiles(const std::string& spec) {
    if (spec.starts_with(kBuiltinPrefix))
        return {};
    const std::string ext = lowerExtension(spec);
    if (ext == ".node" || ext == ".ele") { // as readTetgenPair names them
        const fs::path stem = fs::path(spec).replace_extension();
        return {stem.string() + ".node", stem.string() + ".ele"};
    }
    if (ext == ".mesh") { // as loadGrid looks for the .sol
        const std::string sol_path = fs::path(spec).replace_extension(".sol").string();
        std::error_code error;
        if (fs::exists(sol_path, error))
            return {spec, sol_path};
    }
    return {spec};
}

Result<TetGrid> loadGrid(const std::string& spec) {
    using R = Result<TetGrid>;
    if (spec.starts_with(kBuiltinPrefix))
        return detail::makeBuiltinGrid(spec.substr(kBuiltinPrefix.size()));
    const std::string ext = lowerExtension(spec);
    Result<RawGrid> raw = Result<RawGrid>::failure("");
    std::string label = spec;
    if (ext == ".node" || ext == ".ele") {
        raw = readTetgenPair(spec);
        label = fs::path(spec).replace_extension().string() + ".node/.ele";
        if (!raw)
            return R::failure(raw.error);
    } else if (ext == ".vtk" || ext == ".vtu" || ext == ".mesh") {
        Result<std::string> bytes = readWhole(spec);
        if (!bytes)
            return R::failure(bytes.error);
        if (ext == ".vtk") {
            raw = detail::readVtkLegacy(*bytes.value);
        } else if (ext == ".vtu") {
            raw = detail::readVtu(*bytes.value);
        } else {
            const std::string sol_path = fs::path(spec).replace_extension(".sol").string();
            std::error_code error;
            if (fs::exists(sol_path, error)) {
                Result<std::string> sol = readWhole(sol_path);
                if (!sol)
                    return R::failure(sol.error);
                raw = detail::readMedit(*bytes.value, &*sol.value);
                label = spec + " (with " + sol_path + ")";
            } else {
                raw = detail::readMedit(*bytes.value, nullptr);
            }
        }
        if (!raw)
            return R::failure(label + ": " + raw.error);
    } else {
        return R::failure(spec +
                          ": not a grid file (vissort reads grids from .vtk, .vtu, tetgen's "
                          ".node/.ele and Medit's .mesh, or builtin:NAME, NAME one of " +
                          detail::builtinGridList() + ")");
    }
    Result<TetGrid> grid =
        detail::tetrahedralize(std::move(*raw.value), fs::path(spec).filename().string());
    if (!grid)
        return R::failure(label + ": " + grid.error);
    return grid;
}

} // namespace vissort
