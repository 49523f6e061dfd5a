// The built-in grids: sizes, shapes (convex or not), determinism and their parameters' errors.
#include <gtest/gtest.h>

#include "grid_test_support.h"

namespace vissort {
namespace {

TEST(BuiltinGrids, CubeIsConvexWithSixTetrahedraPerCell) {
    Result<TetGrid> grid = loadGrid("builtin:cube?n=4");
    ASSERT_TRUE(grid) << grid.error;
    EXPECT_EQ(grid.value->tets.size(), 6u * 4 * 4 * 4);
    EXPECT_EQ(grid.value->points.size(), 5u * 5 * 5);
    EXPECT_NEAR(test::totalVolume(*grid.value), 8.0, 1e-9);
    const GridFacts facts = describeGrid(*grid.value);
    EXPECT_TRUE(facts.convex);
    EXPECT_EQ(facts.boundary_faces, 6u * 4 * 4 * 2);
    EXPECT_TRUE(facts.has_scalars);
    EXPECT_GT(facts.scalar_max, facts.scalar_min);
    EXPECT_EQ(grid.value->name, "builtin:cube?n=4");
}

TEST(BuiltinGrids, TorusAndKnotAreNotConvex) {
    for (const char* spec : {"builtin:torus?n=12", "builtin:knot?n=16"}) {
        Result<TetGrid> grid = loadGrid(spec);
        ASSERT_TRUE(grid) << spec << ": " << grid.error;
        EXPECT_GT(grid.value->tets.size(), 100u) << spec;
        EXPECT_FALSE(describeGrid(*grid.value).convex) << spec;
    }
}

TEST(BuiltinGrids, AreDeterministicAndGrowWithN) {
    Result<TetGrid> a = loadGrid("builtin:torus?n=10"), b = loadGrid("builtin:torus?n=10");
    Result<TetGrid> larger = loadGrid("builtin:torus?n=20");
    ASSERT_TRUE(a && b && larger);
    EXPECT_EQ(a.value->tets, b.value->tets);
    EXPECT_EQ(a.value->scalars, b.value->scalars);
    EXPECT_GT(larger.value->tets.size(), 6 * a.value->tets.size());
}

TEST(BuiltinGrids, ParametersAreChecked) {
    EXPECT_EQ(loadGrid("builtin:cub").error, "unknown built-in grid 'cub' (did you mean 'cube'?); "
                                             "the built-in grids are cube, torus, knot");
    EXPECT_EQ(
        loadGrid("builtin:cube?m=3").error,
        "builtin:cube has no parameter 'm'; it takes n (cells along each side of its lattice)");
    EXPECT_EQ(loadGrid("builtin:cube?n=0").error,
              "builtin:cube's n must be a whole number from 1 to 200, not '0'");
    EXPECT_EQ(loadGrid("builtin:cube?n=x").error,
              "builtin:cube's n must be a whole number from 1 to 200, not 'x'");
    EXPECT_EQ(loadGrid("builtin:torus?n=1").error,
              "builtin:torus has no cells at n=1: take a larger n");
    EXPECT_EQ(loadGrid("builtin:cube?n=2&n=3").error,
              "builtin:cube?n=2&n=3: parameter 'n' given twice");
    EXPECT_EQ(loadGrid("builtin:cube?n").error,
              "builtin:cube?n: parameter 'n' needs a value (key=value)");
    EXPECT_EQ(
        loadGrid("builtin:cube?\n=2").error,
        "builtin:cube has no parameter '\\x0a'; it takes n (cells along each side of its lattice)");
    EXPECT_EQ(builtinGridNames().size(), 3u);
}

} // namespace
} // namespace vissort
