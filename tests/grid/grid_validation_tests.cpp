// validateGrid, faceNeighbours and describeGrid on grids made by hand.
#include <gtest/gtest.h>

#include "grid_test_support.h"

namespace vissort {
namespace {

// Two tetrahedra sharing the face (0, 1, 2), apexes 3 above and 4 below.
TetGrid twoTets(Vec3 lower_apex = {0.2, 0.2, -1}) {
    TetGrid grid;
    grid.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.2, 0.2, 1}, lower_apex};
    grid.tets = {{0, 1, 2, 3}, {0, 2, 1, 4}};
    grid.source_cells = {0, 1};
    return grid;
}

TEST(GridValidation, NeighboursMeetAcrossTheSharedFace) {
    const TetGrid grid = twoTets();
    ASSERT_TRUE(validateGrid(grid)) << validateGrid(grid).error;
    Result<std::vector<TetNeighbours>> neighbours = faceNeighbours(grid);
    ASSERT_TRUE(neighbours);
    // The shared face is opposite corner 3 in both.
    EXPECT_EQ((*neighbours.value)[0], (TetNeighbours{kNoNeighbour, kNoNeighbour, kNoNeighbour, 1}));
    EXPECT_EQ((*neighbours.value)[1], (TetNeighbours{kNoNeighbour, kNoNeighbour, kNoNeighbour, 0}));
    const GridFacts facts = describeGrid(grid);
    EXPECT_EQ(facts.boundary_faces, 6u);
    EXPECT_TRUE(facts.convex); // a bipyramid over a triangle
}

TEST(GridValidation, FaceCornersPointIntoTheTetrahedron) {
    const TetGrid grid = twoTets();
    for (const Tet& t : grid.tets)
        for (int f = 0; f < 4; ++f) {
            const Vec3& a = grid.points[t[kTetFaceCorners[f][0]]];
            const Vec3 normal = cross(grid.points[t[kTetFaceCorners[f][1]]] - a,
                                      grid.points[t[kTetFaceCorners[f][2]]] - a);
            EXPECT_GT(dot(normal, grid.points[t[f]] - a), 0) << "face " << f;
        }
}

TEST(GridValidation, OverlappingTetrahedraAreNotConforming) {
    TetGrid grid = twoTets({0.3, 0.3, 0.5}); // the second apex above the face too
    grid.tets[1] = {0, 1, 2, 4};             // oriented positively, as validateGrid asks
    EXPECT_EQ(validateGrid(grid).error, "the grid is not conforming: tetrahedra 0 and 1 overlap "
                                        "(both lie on the same side of their "
                                        "face of points 0, 1 and 2)");
}

TEST(GridValidation, AFaceOfThreeTetrahedraIsNotConforming) {
    TetGrid grid = twoTets();
    grid.points.push_back({0.1, 0.1, 2});
    grid.tets.push_back({0, 1, 2, 5});
    grid.source_cells.push_back(2);
    EXPECT_EQ(validateGrid(grid).error, "the grid is not conforming: the face of points 0, 1 and 2 "
                                        "belongs to 3 tetrahedra (0, 1, 2)");
}

TEST(GridValidation, BadTetrahedraAndScalarsAreNamed) {
    TetGrid inverted = twoTets();
    std::swap(inverted.tets[1][0], inverted.tets[1][1]);
    EXPECT_EQ(validateGrid(inverted).error, "tetrahedron 1 is inverted (negative volume)");
    TetGrid flat = twoTets({0.5, 0.5, 0});
    EXPECT_EQ(validateGrid(flat).error, "tetrahedron 1 is degenerate (no volume)");
    TetGrid repeated = twoTets();
    repeated.tets[0][3] = 0;
    EXPECT_EQ(validateGrid(repeated).error, "tetrahedron 0 repeats a point");
    TetGrid scalars = twoTets();
    scalars.scalars = {0, 1, 2, std::numeric_limits<double>::infinity(), 4};
    EXPECT_EQ(validateGrid(scalars).error, "the scalar of point 3 is not finite");
    TetGrid out_of_range = twoTets();
    out_of_range.tets[1][3] = 7;
    EXPECT_EQ(validateGrid(out_of_range).error, "tetrahedron 1 names point 7 of 5");
    EXPECT_EQ(validateGrid(TetGrid{}).error, "the grid has no tetrahedra");
}

TEST(GridValidation, DescribeGridGivesRangesAndConvexity) {
    TetGrid grid = twoTets();
    grid.scalars = {3, -1, 2, 5, 0.5};
    const GridFacts facts = describeGrid(grid);
    EXPECT_EQ(facts.points, 5u);
    EXPECT_EQ(facts.tets, 2u);
    EXPECT_TRUE(facts.has_scalars);
    EXPECT_EQ(facts.scalar_min, -1);
    EXPECT_EQ(facts.scalar_max, 5);
    EXPECT_EQ(facts.bounds.min.z, -1);
    EXPECT_EQ(facts.bounds.max.z, 1);
    // Two tetrahedra meeting at one corner only: two closed surfaces, not one convex region.
    TetGrid apart;
    apart.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}};
    apart.tets = {{0, 1, 2, 3}, {0, 5, 4, 6}};
    apart.source_cells = {0, 1};
    ASSERT_TRUE(validateGrid(apart)) << validateGrid(apart).error;
    EXPECT_FALSE(describeGrid(apart).convex);
}

} // namespace
} // namespace vissort
