#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "scene_checks.h"
#include "scenes/builtin_scenes.h"
#include "scenes/scene_library.h"

namespace vissort {
namespace {

constexpr double kWobble = 0.05;     // the deformation's amplitude, from the specification
constexpr double kFloatSlack = 1e-4; // positions are floats of magnitude < 10
constexpr std::size_t kTrianglesPerBunny = 3674;

/// The bunny read straight from assets/models/bunny-lowres.obj (only `v` and `f` lines), scaled
/// as specified: bounding box centre at the origin, half the box diagonal = 1. Corners in file
/// order, three per face.
std::vector<Vec3> referenceBunnyCorners() {
    std::ifstream file(std::string(VISSORT_SOURCE_DIR) + "/assets/models/bunny-lowres.obj");
    EXPECT_TRUE(file.good());
    std::vector<Vec3> vertices;
    std::vector<std::size_t> corner_indices;
    std::string line;
    while (std::getline(file, line)) {
        std::istringstream in(line);
        std::string tag;
        in >> tag;
        if (tag == "v") {
            Vec3 v;
            in >> v.x >> v.y >> v.z;
            vertices.push_back(v);
        } else if (tag == "f") {
            for (std::size_t index; in >> index;)
                corner_indices.push_back(index - 1);
        }
    }
    Vec3 low{1e30, 1e30, 1e30}, high{-1e30, -1e30, -1e30};
    for (const Vec3& v : vertices) {
        low = {std::min(low.x, v.x), std::min(low.y, v.y), std::min(low.z, v.z)};
        high = {std::max(high.x, v.x), std::max(high.y, v.y), std::max(high.z, v.z)};
    }
    const Vec3 centre{(low.x + high.x) / 2, (low.y + high.y) / 2, (low.z + high.z) / 2};
    const double radius = length(high - low) / 2;
    std::vector<Vec3> corners;
    for (const std::size_t index : corner_indices) {
        const Vec3 v = vertices[index] - centre;
        corners.push_back({v.x / radius, v.y / radius, v.z / radius});
    }
    return corners;
}

Scene makeBunnies(const std::string& n, const std::string& seed = "1") {
    return test::makeCountedScene("bunnies", n, seed);
}

using test::frameAt;

Vec3 centreOf(const Scene& scene, std::size_t bunny, double t) {
    Vec3 centre;
    EXPECT_TRUE(detail::bunnyCentreAt(*scene.animation, bunny, t, centre));
    return centre;
}

double cubeSide(std::size_t n) {
    return 6 * std::cbrt(n / 18.0);
}

TEST(BunniesScene, CountsObjectsAndMaterials) {
    const Scene scene = makeBunnies("3");
    EXPECT_EQ(scene.name, "builtin:bunnies");
    EXPECT_TRUE(scene.isDynamic());
    test::expectNumberedObjects(scene, "bunny_", 3, kTrianglesPerBunny, 0.5f);

    const Result<Scene> defaults = samples::makeBuiltinScene("bunnies", {});
    ASSERT_TRUE(defaults);
    EXPECT_EQ(defaults.value->objects.size(), 18u);
    EXPECT_EQ(defaults.value->triangleCount(), 18 * kTrianglesPerBunny);
    TrianglePositions resized; // positionsAt sizes its output
    resized.resize(5);
    defaults.value->animation->positionsAt(1.0, resized);
    EXPECT_EQ(resized.triangleCount(), 18 * kTrianglesPerBunny);
}

TEST(BunniesScene, FramesArePureFunctionsOfTimeAndSeed) {
    const Scene a = makeBunnies("4", "9"), b = makeBunnies("4", "9"), c = makeBunnies("4", "10");
    EXPECT_EQ(a.positions.x, b.positions.x);
    EXPECT_EQ(a.positions.y, b.positions.y);
    EXPECT_EQ(a.positions.z, b.positions.z);
    EXPECT_NE(a.positions.x, c.positions.x);

    const TrianglePositions zero = frameAt(a, 0);
    EXPECT_EQ(zero.x, a.positions.x);
    EXPECT_EQ(zero.z, a.positions.z);
    const TrianglePositions first = frameAt(a, 7.25);
    frameAt(a, 1.0);
    TrianglePositions again = frameAt(a, 1.0);
    a.animation->positionsAt(7.25, again); // reusing a buffer holding another frame
    EXPECT_EQ(first.x, again.x);
    EXPECT_EQ(first.y, again.y);
    EXPECT_EQ(first.z, again.z);
    const TrianglePositions other_scene = frameAt(b, 7.25);
    EXPECT_EQ(first.y, other_scene.y);
}

// Every corner is the reference corner, rotated, deformed by at most kWobble and moved to the
// bunny's centre: so its distance to the centre is the reference one to within kWobble, and the
// triangle's edges keep their lengths to within 2 kWobble. A wrong scale, centre, corner order or
// a non-rigid rotation breaks this.
TEST(BunniesScene, EachBunnyIsTheUnitScaledMeshRigidlyMovedAndSlightlyDeformed) {
    const std::vector<Vec3> reference = referenceBunnyCorners();
    ASSERT_EQ(reference.size(), 3 * kTrianglesPerBunny);
    double reference_reach = 0;
    for (const Vec3& v : reference)
        reference_reach = std::max(reference_reach, length(v));
    EXPECT_LE(reference_reach, 1.0);

    const Scene scene = makeBunnies("5", "4");
    for (const double t : {0.0, 3.7, 41.0}) {
        const TrianglePositions positions = frameAt(scene, t);
        for (std::size_t bunny = 0; bunny < 5; ++bunny) {
            const Vec3 centre = centreOf(scene, bunny, t);
            double reach = 0, largest_radial_change = 0, largest_edge_change = 0;
            for (std::size_t k = 0; k < reference.size(); ++k) {
                const Vec3 world = positions.corner(bunny * reference.size() + k);
                const double radial = length(world - centre);
                reach = std::max(reach, radial);
                largest_radial_change =
                    std::max(largest_radial_change, std::abs(radial - length(reference[k])));
                const std::size_t next = k - k % 3 + (k + 1) % 3; // the next corner of the triangle
                const double edge =
                    length(positions.corner(bunny * reference.size() + next) - world);
                largest_edge_change = std::max(
                    largest_edge_change, std::abs(edge - length(reference[next] - reference[k])));
            }
            EXPECT_LE(largest_radial_change, kWobble + kFloatSlack)
                << "bunny " << bunny << " t " << t;
            EXPECT_GT(largest_radial_change, kWobble / 3) << "no visible deformation";
            EXPECT_LE(largest_edge_change, 2 * kWobble + kFloatSlack);
            EXPECT_NEAR(reach, reference_reach, kWobble + kFloatSlack);
            EXPECT_LE(reach, 1 + kWobble + kFloatSlack); // inside the deformed bounding sphere
        }
    }
}

TEST(BunniesScene, BunniesMoveAndDeformBetweenFrames) {
    const Scene scene = makeBunnies("6", "2");
    const TrianglePositions before = frameAt(scene, 1.0), after = frameAt(scene, 1.3);
    for (std::size_t bunny = 0; bunny < 6; ++bunny) {
        EXPECT_GT(length(centreOf(scene, bunny, 1.3) - centreOf(scene, bunny, 1.0)), 1e-3);
        // Rigid motion keeps every edge length; the deformation must change some.
        double largest_edge_change = 0;
        for (std::size_t k = 0; k < 3 * kTrianglesPerBunny; k += 3) {
            const std::size_t i = bunny * 3 * kTrianglesPerBunny + k;
            const double edge_before = length(before.corner(i + 1) - before.corner(i));
            const double edge_after = length(after.corner(i + 1) - after.corner(i));
            largest_edge_change = std::max(largest_edge_change, std::abs(edge_after - edge_before));
        }
        EXPECT_GT(largest_edge_change, 1e-3) << "bunny " << bunny;
    }
}

TEST(BunniesScene, CentresMoveAtConstantSpeedAndBounceInsideTheCube) {
    const std::size_t n = 10;
    const Scene scene = makeBunnies(std::to_string(n), "3");
    const double half_range = cubeSide(n) / 2 - 1;
    const double dt = 0.01;
    for (std::size_t bunny = 0; bunny < n; ++bunny) {
        std::vector<double> speeds;
        double nearest_wall = 1e30;
        Vec3 previous = centreOf(scene, bunny, 0);
        for (int step = 1; step <= 3000; ++step) {
            const Vec3 centre = centreOf(scene, bunny, step * dt);
            for (const double c : {centre.x, centre.y, centre.z}) {
                EXPECT_LE(std::abs(c), half_range + 1e-9);
                nearest_wall = std::min(nearest_wall, half_range - std::abs(c));
            }
            speeds.push_back(length(centre - previous) / dt);
            previous = centre;
        }
        std::sort(speeds.begin(), speeds.end());
        const double speed = speeds[speeds.size() / 2];
        EXPECT_GE(speed, 0.5 - 1e-9);
        EXPECT_LE(speed, 1.5 + 1e-9);
        // A bounce only shortens one step; all others have the same speed.
        EXPECT_LE(speeds.back(), speed + 1e-6);
        std::size_t steady = 0;
        for (const double s : speeds)
            steady += std::abs(s - speed) < 1e-6;
        EXPECT_GT(steady, speeds.size() * 9 / 10);
        EXPECT_LT(nearest_wall, 0.02) << "bunny " << bunny << " never reached a wall in 30 s";
    }
}

TEST(BunniesScene, GeometryStaysInsideTheCube) {
    for (const std::size_t n : {1, 18, 60}) {
        const Scene scene = makeBunnies(std::to_string(n), "5");
        const double limit = cubeSide(n) / 2 + kWobble + kFloatSlack;
        for (const double t : {0.0, 10.0, 1234.5}) {
            const Bounds bounds = frameAt(scene, t).bounds();
            for (const double c : {bounds.min.x, bounds.min.y, bounds.min.z, bounds.max.x,
                                   bounds.max.y, bounds.max.z})
                EXPECT_LE(std::abs(c), limit) << "n " << n << " t " << t;
        }
    }
}

TEST(BunniesScene, SomeBunniesComeIntoContact) {
    const Scene scene = makeBunnies("18");
    double closest = 1e30, closest_time = 0;
    std::size_t closest_a = 0, closest_b = 0, pairs_in_contact = 0;
    for (int step = 0; step <= 200; ++step) {
        const double t = step * 0.05;
        for (std::size_t a = 0; a < 18; ++a)
            for (std::size_t b = a + 1; b < 18; ++b) {
                const double distance = length(centreOf(scene, a, t) - centreOf(scene, b, t));
                pairs_in_contact += distance < 2;
                if (distance < closest)
                    closest = distance, closest_time = t, closest_a = a, closest_b = b;
            }
    }
    EXPECT_GT(pairs_in_contact, 0u);
    EXPECT_LT(closest, 2.0);
    // The bounding spheres are honest: at the closest approach, the meshes themselves nearly meet.
    const TrianglePositions positions = frameAt(scene, closest_time);
    double nearest_corners = 1e30;
    const std::size_t corners = 3 * kTrianglesPerBunny;
    for (std::size_t i = closest_a * corners; i < (closest_a + 1) * corners; i += 3)
        for (std::size_t j = closest_b * corners; j < (closest_b + 1) * corners; j += 3)
            nearest_corners =
                std::min(nearest_corners, length(positions.corner(i) - positions.corner(j)));
    EXPECT_LT(nearest_corners, 0.2);
}

// The default camera frames the bunnies over their first 10 s (their bounding spheres at
// sampled times, inside the 5% margin): every corner of every frame is in the picture, and the
// picture is filled (some corner beyond 80% of the half-width; the spheres are a little larger
// than the bunnies). The camera is not aimed at the t = 0 pose alone.
TEST(BunniesScene, DefaultCameraSeesEveryBunnyForTenSeconds) {
    const Scene scene = makeBunnies("18");
    ASSERT_TRUE(scene.camera.has_value());
    const ViewProjection view = frameCamera(*scene.camera, scene.positions.bounds(), 512, 512);
    double widest = 0, widest_at_start = 0;
    TrianglePositions positions;
    for (int frame = 0; frame < 300; frame += 3) {
        scene.frame(frame * kFrameInterval, positions);
        for (std::size_t i = 0; i < positions.x.size(); ++i) {
            const auto clip = view.toClip(positions.view().corner(i));
            ASSERT_GT(clip[3], 0.0);
            const double extent = std::max(std::abs(clip[0]), std::abs(clip[1])) / clip[3];
            ASSERT_LE(extent, 1.0) << "frame " << frame << " corner " << i;
            widest = std::max(widest, extent);
            if (frame == 0)
                widest_at_start = std::max(widest_at_start, extent);
        }
    }
    EXPECT_GT(widest, 0.8);
    EXPECT_LT(widest_at_start, widest);
}

} // namespace
} // namespace vissort
