// The split of mixed cells into tetrahedra (src/grid/cell_split.cpp): volumes kept, every piece
// positive, and neighbouring cells cut the faces they share the same way, whatever the numbering.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

#include "grid_test_support.h"

namespace vissort {
namespace {

using detail::CellType;
using detail::RawGrid;
using detail::tetrahedralize;
using test::totalVolume;

RawGrid oneCell(CellType type, std::vector<Vec3> points, std::vector<uint32_t> corners) {
    RawGrid raw;
    raw.points = std::move(points);
    raw.addCell(type, corners.data());
    return raw;
}

TEST(CellSplit, HexahedronBecomesSixPositiveTetrahedraOfItsVolume) {
    Result<TetGrid> grid = tetrahedralize(
        oneCell(CellType::hexahedron, test::unitCubeCorners(), {0, 1, 2, 3, 4, 5, 6, 7}), "cube");
    ASSERT_TRUE(grid) << grid.error;
    EXPECT_EQ(grid.value->tets.size(), 6u);
    for (const Tet& t : grid.value->tets)
        EXPECT_GT(test::tetVolume(*grid.value, t), 0);
    EXPECT_NEAR(totalVolume(*grid.value), 1.0, 1e-12);
    EXPECT_EQ(grid.value->source_cells, std::vector<uint32_t>(6, 0));
    EXPECT_EQ(describeGrid(*grid.value).boundary_faces, 12u); // two triangles per cube face
    EXPECT_TRUE(describeGrid(*grid.value).convex);
}

TEST(CellSplit, WedgeAndPyramidKeepTheirVolumes) {
    // vtkWedge: the first triangle's normal points away from the second.
    Result<TetGrid> wedge = tetrahedralize(
        oneCell(CellType::wedge,
                {{0, 1, 0}, {0, 0, 0}, {0, 0.5, 0.5}, {1, 1, 0}, {1, 0, 0}, {1, 0.5, 0.5}},
                {0, 1, 2, 3, 4, 5}),
        "wedge");
    ASSERT_TRUE(wedge) << wedge.error;
    EXPECT_EQ(wedge.value->tets.size(), 3u);
    EXPECT_NEAR(totalVolume(*wedge.value), 0.25, 1e-12);
    Result<TetGrid> pyramid = tetrahedralize(
        oneCell(CellType::pyramid, {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 1}},
                {0, 1, 2, 3, 4}),
        "pyramid");
    ASSERT_TRUE(pyramid) << pyramid.error;
    EXPECT_EQ(pyramid.value->tets.size(), 2u);
    EXPECT_NEAR(totalVolume(*pyramid.value), 1.0 / 3, 1e-12);
}

TEST(CellSplit, TetrahedraOfEitherOrientationArePositive) {
    const std::vector<Vec3> points{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (const auto& corners :
         {std::vector<uint32_t>{0, 1, 2, 3}, std::vector<uint32_t>{0, 2, 1, 3}}) {
        Result<TetGrid> grid =
            tetrahedralize(oneCell(CellType::tetrahedron, points, corners), "tet");
        ASSERT_TRUE(grid) << grid.error;
        EXPECT_NEAR(test::tetVolume(*grid.value, grid.value->tets[0]), 1.0 / 6, 1e-12);
    }
}

// A lattice of 3 x 2 x 2 hexahedra whose points are numbered in a random order: every shared
// quad is then cut through a corner that is the smallest of neither cell's own corner 0, and the
// tetrahedra still meet face to face (a cut chosen per cell would leave faces unmatched, counted
// as boundary).
TEST(CellSplit, NeighboursCutSharedFacesAlikeUnderAnyNumbering) {
    constexpr int nx = 3, ny = 2, nz = 2;
    const auto index = [](int i, int j, int k) {
        return uint32_t((k * (ny + 1) + j) * (nx + 1) + i);
    };
    const uint32_t point_count = (nx + 1) * (ny + 1) * (nz + 1);
    for (unsigned seed = 0; seed < 50; ++seed) {
        std::vector<uint32_t> numbering(point_count);
        std::iota(numbering.begin(), numbering.end(), 0u);
        std::shuffle(numbering.begin(), numbering.end(), std::mt19937(seed));
        RawGrid raw;
        raw.points.resize(point_count);
        for (int k = 0; k <= nz; ++k)
            for (int j = 0; j <= ny; ++j)
                for (int i = 0; i <= nx; ++i)
                    raw.points[numbering[index(i, j, k)]] = Vec3{double(i), double(j), double(k)};
        for (int k = 0; k < nz; ++k)
            for (int j = 0; j < ny; ++j)
                for (int i = 0; i < nx; ++i) {
                    const uint32_t cell[8] = {numbering[index(i, j, k)],
                                              numbering[index(i + 1, j, k)],
                                              numbering[index(i + 1, j + 1, k)],
                                              numbering[index(i, j + 1, k)],
                                              numbering[index(i, j, k + 1)],
                                              numbering[index(i + 1, j, k + 1)],
                                              numbering[index(i + 1, j + 1, k + 1)],
                                              numbering[index(i, j + 1, k + 1)]};
                    raw.addCell(CellType::hexahedron, cell);
                }
        Result<TetGrid> grid = tetrahedralize(std::move(raw), "lattice");
        ASSERT_TRUE(grid) << grid.error;
        EXPECT_NEAR(totalVolume(*grid.value), nx * ny * nz, 1e-9);
        // The outside: 2 (3x2 + 3x2 + 2x2) quads, two triangles each.
        EXPECT_EQ(describeGrid(*grid.value).boundary_faces, 2u * 2 * (nx * ny + nx * nz + ny * nz))
            << "seed " << seed;
        EXPECT_TRUE(describeGrid(*grid.value).convex);
    }
}

TEST(CellSplit, AFileMayUseTheMirrorConventionThroughout) {
    // Both hexahedra listed with their top quad first: mirrored, consistently.
    RawGrid raw;
    raw.points = test::unitCubeCorners();
    for (const Vec3& p : test::unitCubeCorners())
        raw.points.push_back(p + Vec3{1, 0, 0});
    const uint32_t first[8] = {4, 5, 6, 7, 0, 1, 2, 3}, second[8] = {12, 13, 14, 15, 8, 9, 10, 11};
    raw.addCell(CellType::hexahedron, first);
    raw.addCell(CellType::hexahedron, second);
    Result<TetGrid> grid = tetrahedralize(raw, "mirrored");
    ASSERT_TRUE(grid) << grid.error;
    EXPECT_NEAR(totalVolume(*grid.value), 2.0, 1e-12);
}

TEST(CellSplit, ACellAgainstTheFilesOrientationIsInverted) {
    RawGrid raw;
    raw.points = test::unitCubeCorners();
    for (const Vec3& p : test::unitCubeCorners())
        raw.points.push_back(p + Vec3{1, 0, 0});
    const uint32_t upright[8] = {0, 1, 2, 3, 4, 5, 6, 7},
                   mirrored[8] = {12, 13, 14, 15, 8, 9, 10, 11};
    raw.addCell(CellType::hexahedron, upright);
    raw.addCell(CellType::hexahedron, mirrored);
    Result<TetGrid> grid = tetrahedralize(raw, "inverted");
    ASSERT_FALSE(grid);
    EXPECT_EQ(grid.error, "cell 1 (hexahedron) is inverted: its corners are ordered against the "
                          "orientation of the file's earlier hexahedron cells");
}

TEST(CellSplit, AHexahedronCollapsedToAWedgeIsTheWedge) {
    // Corners 2 and 3 merged, and 6 and 7: the cube cut along a diagonal plane, half its volume.
    Result<TetGrid> grid = tetrahedralize(
        oneCell(CellType::hexahedron, test::unitCubeCorners(), {0, 1, 2, 2, 4, 5, 6, 6}),
        "collapsed");
    ASSERT_TRUE(grid) << grid.error;
    EXPECT_NEAR(totalVolume(*grid.value), 0.5, 1e-12);
}

TEST(CellSplit, BadCellsAreRefusedByName) {
    const auto error = [](RawGrid raw) { return tetrahedralize(std::move(raw), "bad").error; };
    std::vector<Vec3> flat = test::unitCubeCorners();
    for (Vec3& p : flat)
        p.z = 0;
    EXPECT_NE(error(oneCell(CellType::hexahedron, flat, {0, 1, 2, 3, 4, 5, 6, 7}))
                  .find("cell 0 (hexahedron) is degenerate"),
              std::string::npos);
    EXPECT_EQ(error(oneCell(CellType::tetrahedron, test::unitCubeCorners(), {0, 1, 2, 9})),
              "cell 0 (tetrahedron) names point 9 of 8");
    EXPECT_EQ(error(oneCell(CellType::tetrahedron, test::unitCubeCorners(), {0, 0, 0, 0})),
              "cell 0 (tetrahedron) is degenerate: it repeats corners until it has no volume");
    std::vector<Vec3> nan = test::unitCubeCorners();
    nan[3].y = std::nan("");
    EXPECT_EQ(error(oneCell(CellType::tetrahedron, nan, {0, 1, 3, 4})),
              "point 3 has a coordinate that is not finite");
    RawGrid scalars = oneCell(CellType::tetrahedron, test::unitCubeCorners(), {0, 1, 3, 4});
    scalars.scalars = {1, 2, 3};
    EXPECT_EQ(error(scalars), "3 scalars for 8 points");
    EXPECT_EQ(error(RawGrid{}), "no 3D cells (tetrahedra, hexahedra, wedges, pyramids)");
    // A hexahedron twisted so that its cone split has pieces of both orientations.
    std::vector<Vec3> twisted = test::unitCubeCorners();
    twisted[6] = {-1, -1, 1};
    EXPECT_NE(
        error(oneCell(CellType::hexahedron, twisted, {0, 1, 2, 3, 4, 5, 6, 7})).find("tangled"),
        std::string::npos);
}

} // namespace
} // namespace vissort
