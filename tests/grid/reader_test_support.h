#pragma once
// What the readers' tests share: the test files' bytes, a cell's corners, and the grid that
// tests/data/grids/vtk_make_test_files.py wrote in every VTK format.

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "grid/raw_grid.h"

namespace vissort::detail::test {

/// The bytes of tests/data/grids/NAME (a failed expectation when it cannot be read).
inline std::string readGridData(const std::string& name) {
    std::ifstream file(VISSORT_SOURCE_DIR "/tests/data/grids/" + name, std::ios::binary);
    EXPECT_TRUE(file) << name;
    std::ostringstream bytes;
    bytes << file.rdbuf();
    return bytes.str();
}

/// Cell `cell`'s corners.
inline std::vector<uint32_t> cornersOf(const RawGrid& grid, std::size_t cell) {
    return {grid.cell_points.begin() + std::ptrdiff_t(grid.cell_offsets[cell]),
            grid.cell_points.begin() + std::ptrdiff_t(grid.cell_offsets[cell + 1])};
}

/// The grid of vtk_make_test_files.py: 17 points, a hexahedron, a tetrahedron, a triangle, a
/// voxel, a wedge, a pyramid and a vertex.
inline void expectMixedGrid(const RawGrid& grid) {
    ASSERT_EQ(grid.points.size(), 17u);
    EXPECT_EQ(grid.points[8], (Vec3{0.5, 0.5, 2}));
    EXPECT_EQ(grid.points[10], (Vec3{3, 0, 0}));
    EXPECT_EQ(grid.points[16], (Vec3{3, 1, 1}));
    EXPECT_EQ(grid.cell_types,
              (std::vector<CellType>{CellType::hexahedron, CellType::tetrahedron,
                                     CellType::hexahedron, CellType::wedge, CellType::pyramid}));
    EXPECT_EQ(grid.cell_offsets, (std::vector<uint64_t>{0, 8, 12, 20, 26, 31}));
    // The voxel's 9 10 11 12 13 14 15 16 (x fastest) goes round its faces as 9 10 12 11 ...
    EXPECT_EQ(grid.cell_points,
              (std::vector<uint32_t>{0,  1,  2,  3,  4, 5, 6, 7, 4, 5, 6, 8, 9, 10, 12, 11,
                                     13, 14, 16, 15, 0, 1, 3, 4, 5, 7, 4, 5, 6, 7,  8}));
    EXPECT_EQ(grid.skipped_cells, 2u);
}

} // namespace vissort::detail::test
