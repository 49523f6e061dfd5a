#include <cmath>

#include <gtest/gtest.h>

#include "harnesses/oracle_workloads.h"
#include "vissort/cpu_reference_oracle.h"

namespace vissort {
namespace {

// The workload's camera maps world x, y to pixels one to one, with depth = world z.
TEST(OracleWorkloads, TrianglesLandOnTheirPixelsAtTheirDepth) {
    const ScreenTriangleWorkload w = makeRightTriangleWorkload(50, 16, 200, 120, 7);
    ASSERT_EQ(w.primitives.size(), 51u);
    for (uint32_t c = 0; c < 3 * 50; ++c) {
        const Vec3 p = w.positions.corner(c);
        const auto clip = w.view.toClip(p);
        EXPECT_NEAR((clip[0] / clip[3] + 1) / 2 * 200, p.x, 1e-9);
        EXPECT_NEAR((1 - clip[1] / clip[3]) / 2 * 120, p.y, 1e-9);
        EXPECT_NEAR(w.view.depthOf(p), p.z, 1e-9);
        EXPECT_GE(p.x, 0);
        EXPECT_LE(p.x, 200);
        EXPECT_GE(p.y, 0);
        EXPECT_LE(p.y, 120);
    }
    // Legs of 16 px along x and y, and depth falling with the id (back to front).
    for (uint32_t t = 0; t < 50; ++t) {
        EXPECT_NEAR(w.positions.x[3 * t + 1] - w.positions.x[3 * t], 16.0, 1e-4);
        EXPECT_NEAR(w.positions.y[3 * t + 2] - w.positions.y[3 * t], 16.0, 1e-4);
        if (t > 0)
            EXPECT_LT(w.positions.z[3 * t], w.positions.z[3 * (t - 1)]);
    }
}

TEST(OracleWorkloads, DrawsPassInIdOrderAndQueriesFindNothingBehindTheBackground) {
    const ScreenTriangleWorkload w = makeRightTriangleWorkload(300, 10, 160, 90, 3);
    CpuReferenceOracle oracle;
    oracle.bind(w.positions, w.view, w.primitives);
    oracle.draw(w.background);
    for (uint32_t i = 0; i < 300; ++i)
        EXPECT_FALSE(oracle.anyBehind(i));
    // Back to front: once drawn, a triangle is never behind what was drawn before it.
    for (uint32_t i = 0; i < 300; ++i) {
        EXPECT_FALSE(oracle.anyBehind(i));
        oracle.draw(i);
    }
    // And an earlier (farther) triangle overlapped by a later one is now behind something.
    uint32_t behind = 0;
    for (uint32_t i = 0; i < 300; ++i)
        behind += oracle.anyBehind(i) ? 1 : 0;
    EXPECT_GT(behind, 0u);
}

} // namespace
} // namespace vissort
