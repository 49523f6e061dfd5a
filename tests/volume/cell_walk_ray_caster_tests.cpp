// The cell-walking ray caster against a pixel worked out by hand, and against the tests' brute
// force (tests/volume/brute_force_volume.h) on convex and non-convex grids, both projections.
#include <gtest/gtest.h>

#include <cmath>

#include "brute_force_volume.h"
#include "volume_test_support.h"

namespace vissort {
namespace {

using test::largestDifference;
using test::settingsWith;

ViewProjection viewOf(const TetGrid& grid, Projection projection, uint32_t size,
                      double azimuth = 30) {
    return test::gridView(grid, projection, size, azimuth, 20);
}

TEST(CellWalkRayCaster, ConstantFieldThroughACubeIsOneSegmentOfItsLength) {
    // Orthographic along -z through builtin:cube's 6 n^3 tetrahedra: every ray crosses length 2 of
    // a diagonal 2 sqrt(3), whatever cells it is cut into, and a constant colour composites as one.
    TetGrid grid = *loadGrid("builtin:cube?n=3").value;
    std::fill(grid.scalars.begin(), grid.scalars.end(), 0.5);
    VolumeSettings settings;
    settings.transfer.points = {{0.0, 0.9, 0.5, 0.1, 1.5}};
    settings.density = 2.0;
    settings.background = {0.1f, 0.2f, 0.3f, 1.0f};
    CameraSpec camera;
    camera.projection = Projection::orthographic;
    camera.eye = {0, 0, 10};
    camera.target = {0, 0, 0};
    camera.ortho_direction = {0, 0, -1};
    Bounds bounds;
    for (const Vec3& p : grid.points)
        bounds.add(p);
    const ViewProjection view = frameCamera(camera, bounds, 33, 33);
    Result<Image> image = castVolume(grid, settings, view, 2);
    ASSERT_TRUE(image) << image.error;
    const double alpha = 1 - std::exp(-2.0 * 1.5 * 2 / (2 * std::sqrt(3.0)));
    const float* centre = &image.value->rgba[(16 * 33 + 16) * 4];
    EXPECT_NEAR(centre[0], 0.9 * alpha + (1 - alpha) * 0.1, 1e-6);
    EXPECT_NEAR(centre[1], 0.5 * alpha + (1 - alpha) * 0.2, 1e-6);
    EXPECT_NEAR(centre[2], 0.1 * alpha + (1 - alpha) * 0.3, 1e-6);
    EXPECT_NEAR(centre[3], 1.0, 1e-6);
    // A corner pixel misses the cube: the background.
    EXPECT_FLOAT_EQ(image.value->rgba[0], 0.1f);
}

struct Case {
    const char* grid;
    const char* preset;
    Projection projection;
};

class AgainstBruteForce : public ::testing::TestWithParam<Case> {};

TEST_P(AgainstBruteForce, EveryPixelAgrees) {
    const Case c = GetParam();
    Result<TetGrid> grid = loadGrid(c.grid);
    ASSERT_TRUE(grid) << grid.error;
    const VolumeSettings settings = settingsWith(c.preset);
    for (const double azimuth : {30.0, 75.0}) {
        const ViewProjection view = viewOf(*grid.value, c.projection, 40, azimuth);
        Result<Image> walked = castVolume(*grid.value, settings, view, 2);
        ASSERT_TRUE(walked) << walked.error;
        const Image brute = test::bruteForceVolume(*grid.value, settings, view);
        EXPECT_LT(largestDifference(*walked.value, brute), 1e-5)
            << c.grid << " azimuth " << azimuth;
        // The picture is not just background: the grid is there.
        EXPECT_GT(
            largestDifference(*walked.value, Image{40, 40, std::vector<float>(40 * 40 * 4, 0.0f)}),
            0.3);
    }
}

INSTANTIATE_TEST_SUITE_P(
    Grids, AgainstBruteForce,
    ::testing::Values(Case{"builtin:cube?n=4", "cool-warm", Projection::perspective},
                      Case{"builtin:cube?n=4", "bands", Projection::orthographic},
                      Case{"builtin:torus?n=10", "fire", Projection::perspective},
                      Case{"builtin:torus?n=10", "bands", Projection::orthographic},
                      Case{"builtin:knot?n=14", "cool-warm", Projection::perspective},
                      Case{"builtin:knot?n=14", "grey", Projection::orthographic}),
    [](const auto& info) {
        std::string name =
            std::string(info.param.grid).substr(8, 4) + "_" + info.param.preset + "_" +
            (info.param.projection == Projection::perspective ? "perspective" : "orthographic");
        std::replace_if(
            name.begin(), name.end(), [](char ch) { return !std::isalnum(ch) && ch != '_'; }, '_');
        return name;
    });

TEST(CellWalkRayCaster, ThreadCountDoesNotChangeThePicture) {
    const TetGrid grid = *loadGrid("builtin:knot?n=14").value;
    const VolumeSettings settings = settingsWith("bands");
    const ViewProjection view = viewOf(grid, Projection::perspective, 48);
    const Image one = *castVolume(grid, settings, view, 1).value;
    const Image three = *castVolume(grid, settings, view, 3).value;
    EXPECT_EQ(one.rgba, three.rgba);
}

TEST(CellWalkRayCaster, SettingsAreChecked) {
    TetGrid grid = *loadGrid("builtin:cube?n=2").value;
    const ViewProjection view = viewOf(grid, Projection::perspective, 8);
    VolumeSettings settings = settingsWith("grey");
    settings.density = -1;
    EXPECT_EQ(castVolume(grid, settings, view).error, "the density must be a finite number >= 0");
    settings.density = 1;
    settings.background.g = 2;
    EXPECT_EQ(castVolume(grid, settings, view).error,
              "the background's channels must be within [0, 1]");
    grid.scalars.clear();
    EXPECT_EQ(
        castVolume(grid, settingsWith("grey"), view).error,
        "builtin:cube?n=2 has no point scalars to render (volume rendering maps a scalar per point "
        "through the transfer function)");
}

} // namespace
} // namespace vissort
