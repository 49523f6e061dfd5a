// loadGrid's dispatch and its errors about files, before any reader sees them.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "vissort/tet_grid.h"

namespace vissort {
namespace {

namespace fs = std::filesystem;

TEST(LoadGrid, FileProblemsNameTheFile) {
    EXPECT_EQ(loadGrid("/nonexistent/grid.vtk").error, "/nonexistent/grid.vtk: file not found");
    EXPECT_EQ(loadGrid("/tmp").error.substr(0, 5), "/tmp:");
    const fs::path dir = fs::temp_directory_path() / "vissort_load_grid_tests";
    fs::create_directories(dir);
    const std::string empty = (dir / "empty.vtu").string();
    std::ofstream(empty).close();
    EXPECT_EQ(loadGrid(empty).error, empty + ": empty file");
    const std::string lone_node = (dir / "lone.node").string();
    std::ofstream(lone_node) << "4 3 0 0\n";
    EXPECT_EQ(loadGrid(lone_node).error,
              (dir / "lone.ele").string() +
                  ": file not found (tetgen's grid is a .node and a .ele file)");
    EXPECT_EQ(
        loadGrid("model.obj").error,
        "model.obj: not a grid file (vissort reads grids from .vtk, .vtu, tetgen's .node/.ele and "
        "Medit's .mesh, or builtin:NAME, NAME one of cube, torus, knot)");
}

TEST(LoadGrid, GridSpecsAreToldFromScenes) {
    EXPECT_TRUE(isGridSpec("builtin:torus?n=8"));
    EXPECT_TRUE(isGridSpec("a/b/C.VTU"));
    EXPECT_TRUE(isGridSpec("x.1.ele"));
    EXPECT_TRUE(isGridSpec("part.mesh"));
    EXPECT_FALSE(isGridSpec("builtin:bunnies"));
    EXPECT_FALSE(isGridSpec("bunny.obj"));
}

} // namespace
} // namespace vissort
