// Every method of VolumeRenderer on every frame of an orbit against the tests' brute force
// (tests/volume/brute_force_volume.h), convex and non-convex grids, both projections: lists and
// raycast agree within rounding on every frame, vissort within 1/255, centroid and mpvo are wrong
// where the grid is not convex (and mpvo is exact where it is).
#include <gtest/gtest.h>

#include <cmath>

#include "brute_force_volume.h"
#include "volume_test_support.h"

namespace vissort {
namespace {

using test::largest8BitDifference;
using test::largestDifference;

ViewProjection orbitView(const TetGrid& grid, Projection projection, uint32_t size, int frame) {
    return test::gridView(grid, projection, size, 25.0 + 35.0 * frame, 20.0 + 10.0 * frame, 3.5);
}

VolumeSettings settingsWith(const char* preset) {
    return test::settingsWith(preset, 6.0);
}

struct Case {
    const char* grid;
    Projection projection;
};

std::string caseName(const Case& c) {
    std::string name = std::string(c.grid).substr(8, 4) +
                       (c.projection == Projection::perspective ? "_perspective" : "_orthographic");
    return name;
}

class ExactMethods : public ::testing::TestWithParam<std::tuple<Case, VolumeMethod>> {};

TEST_P(ExactMethods, EveryFrameOfAnOrbitMatchesBruteForce) {
    const auto [c, method] = GetParam();
    const TetGrid grid = *loadGrid(c.grid).value;
    const VolumeSettings settings = settingsWith("bands");
    VolumeRenderer renderer(grid, method, OracleKind::cpu, 2);
    for (int frame = 0; frame < 4; ++frame) { // one renderer: the later frames are coherent
        const ViewProjection view = orbitView(grid, c.projection, 40, frame);
        Result<Image> image = renderer.render(settings, view);
        ASSERT_TRUE(image) << image.error;
        const Image truth = test::bruteForceVolume(grid, settings, view);
        // vissort's queries answer in float (visibility_cell_order.cpp): within the picture's
        // resolution, not to rounding.
        EXPECT_LT(largestDifference(*image.value, truth),
                  method == VolumeMethod::vissort ? 2e-3 : 1e-5)
            << "frame " << frame;
        EXPECT_LE(largest8BitDifference(*image.value, truth), 1) << "frame " << frame;
        EXPECT_GT(renderer.stats().segments, 0u);
    }
}

INSTANTIATE_TEST_SUITE_P(
    Grids, ExactMethods,
    ::testing::Combine(::testing::Values(Case{"builtin:cube?n=4", Projection::perspective},
                                         Case{"builtin:torus?n=10", Projection::perspective},
                                         Case{"builtin:torus?n=10", Projection::orthographic},
                                         Case{"builtin:knot?n=14", Projection::perspective},
                                         Case{"builtin:knot?n=14", Projection::orthographic}),
                       ::testing::Values(VolumeMethod::vissort, VolumeMethod::lists,
                                         VolumeMethod::raycast)),
    [](const auto& info) {
        return caseName(std::get<0>(info.param)) + "_" + volumeMethodName(std::get<1>(info.param));
    });

TEST(VolumeRenderer, MpvoIsExactOnAConvexGrid) {
    const TetGrid grid = *loadGrid("builtin:cube?n=4").value;
    const VolumeSettings settings = settingsWith("bands");
    VolumeRenderer renderer(grid, VolumeMethod::mpvo, OracleKind::cpu, 2);
    for (int frame = 0; frame < 3; ++frame) {
        const ViewProjection view = orbitView(grid, Projection::perspective, 40, frame);
        const Image image = *renderer.render(settings, view).value;
        EXPECT_LT(largestDifference(image, test::bruteForceVolume(grid, settings, view)), 1e-5)
            << "frame " << frame;
    }
}

TEST(VolumeRenderer, MpvoIsWrongOnANonConvexGrid) {
    const TetGrid grid = *loadGrid("builtin:knot?n=14").value;
    const VolumeSettings settings = settingsWith("bands");
    VolumeRenderer renderer(grid, VolumeMethod::mpvo, OracleKind::cpu, 2);
    int worst = 0;
    for (int frame = 0; frame < 3; ++frame) {
        const ViewProjection view = orbitView(grid, Projection::perspective, 48, frame);
        worst =
            std::max(worst, largest8BitDifference(*renderer.render(settings, view).value,
                                                  test::bruteForceVolume(grid, settings, view)));
    }
    EXPECT_GT(worst, 16);
}

// A long cell tilted towards the eye, and a small one behind its near end whose centre is nearer
// than the long cell's: centres put the small cell first, which is wrong where they overlap.
TEST(VolumeRenderer, CentroidIsWrongWhereALongCellHidesASmallOne) {
    TetGrid grid;
    grid.name = "long and small";
    grid.points = {{-1, -1, 0},        {1, -1, 0},
                   {0, 1, 0},          {0, 0, -10}, // long: nearest at z = 0
                   {-0.3, -0.3, -1.5}, {0.3, -0.3, -1.5},
                   {0, 0.3, -1.5},     {0, 0, -2.5}};
    grid.tets = {{0, 2, 1, 3}, {4, 6, 5, 7}};
    grid.source_cells = {0, 1};
    grid.scalars = {0, 0, 0, 0, 1, 1, 1, 1};
    ASSERT_TRUE(validateGrid(grid)) << validateGrid(grid).error;
    VolumeSettings settings;
    settings.transfer.points = {{0.0, 1.0, 0.1, 0.1, 4.0}, {1.0, 0.1, 0.1, 1.0, 4.0}};
    CameraSpec camera;
    camera.eye = {0, 0, 6};
    camera.target = {0, 0, -1};
    Bounds bounds;
    for (const Vec3& p : grid.points)
        bounds.add(p);
    const ViewProjection view = frameCamera(camera, bounds, 32, 32);
    const Image truth = test::bruteForceVolume(grid, settings, view);
    VolumeRenderer centroid(grid, VolumeMethod::centroid, OracleKind::cpu, 1),
        exact(grid, VolumeMethod::vissort);
    EXPECT_GT(largest8BitDifference(*centroid.render(settings, view).value, truth), 32);
    EXPECT_LE(largest8BitDifference(*exact.render(settings, view).value, truth), 1);
}

// A real grid (assets/grids/bunny: tetgen's graded tetrahedra of the bunny): vissort exact on
// every frame of an orbit, centroid plainly wrong where large inner cells hide small ones.
TEST(VolumeRenderer, RealGridFromTetgen) {
    Result<TetGrid> loaded = loadGrid(VISSORT_SOURCE_DIR "/assets/grids/bunny.node");
    ASSERT_TRUE(loaded) << loaded.error;
    const TetGrid& grid = *loaded.value;
    EXPECT_EQ(grid.tets.size(), 6045u);
    EXPECT_FALSE(describeGrid(grid).convex);
    const VolumeSettings settings = settingsWith("bands");
    VolumeRenderer vissort(grid, VolumeMethod::vissort, OracleKind::cpu, 2);
    int centroid_worst = 0;
    for (int frame = 0; frame < 3; ++frame) {
        const ViewProjection view = orbitView(grid, Projection::perspective, 64, frame);
        const Image truth = test::bruteForceVolume(grid, settings, view);
        EXPECT_LE(largest8BitDifference(*vissort.render(settings, view).value, truth), 1)
            << "frame " << frame;
        VolumeRenderer centroid(grid, VolumeMethod::centroid, OracleKind::cpu, 2);
        centroid_worst = std::max(
            centroid_worst, largest8BitDifference(*centroid.render(settings, view).value, truth));
    }
    EXPECT_GT(centroid_worst, 16);
}

TEST(VolumeRenderer, ThreadCountDoesNotChangeThePicture) {
    const TetGrid grid = *loadGrid("builtin:torus?n=10").value;
    const VolumeSettings settings = settingsWith("fire");
    const ViewProjection view = orbitView(grid, Projection::perspective, 37, 1);
    for (const VolumeMethod method :
         {VolumeMethod::vissort, VolumeMethod::lists, VolumeMethod::centroid}) {
        VolumeRenderer one(grid, method, OracleKind::cpu, 1),
            three(grid, method, OracleKind::cpu, 3);
        EXPECT_EQ(one.render(settings, view).value->rgba, three.render(settings, view).value->rgba)
            << volumeMethodName(method);
    }
}

TEST(VolumeRenderer, ReportsItsCosts) {
    const TetGrid grid = *loadGrid("builtin:torus?n=10").value;
    const VolumeSettings settings = settingsWith("fire");
    const ViewProjection view = orbitView(grid, Projection::perspective, 32, 0);
    VolumeRenderer vissort(grid, VolumeMethod::vissort, OracleKind::cpu, 2);
    ASSERT_TRUE(vissort.render(settings, view));
    EXPECT_EQ(vissort.stats().cells, grid.tets.size());
    EXPECT_GE(vissort.stats().queries, grid.tets.size() - 1); // pass 1: all but the first drawn
    VolumeRenderer lists(grid, VolumeMethod::lists, OracleKind::cpu, 2);
    ASSERT_TRUE(lists.render(settings, view));
    EXPECT_EQ(lists.stats().list_segments, lists.stats().segments);
    EXPECT_EQ(lists.stats().segments,
              vissort.stats().segments); // the same segments, in another order
    EXPECT_EQ(lists.stats().queries, 0u);
}

TEST(VolumeRenderer, RefusesBadSettings) {
    TetGrid grid = *loadGrid("builtin:cube?n=2").value;
    grid.scalars.clear();
    VolumeRenderer renderer(grid, VolumeMethod::vissort);
    EXPECT_NE(renderer.render(settingsWith("grey"), orbitView(grid, Projection::perspective, 8, 0))
                  .error.find("no point scalars"),
              std::string::npos);
}

} // namespace
} // namespace vissort
