#include "exact/ray_caster.h"

#include <cmath>
#include <functional>
#include <limits>
#include <numbers>

#include <gtest/gtest.h>

#include "test_scenes.h"

namespace vissort {
namespace {

using detail::AllHits;
using detail::castAllHits;
using test::addQuad;
using test::addTriangle;

struct QuadSpec {
    double half_size, z;
};

// Where the ray of a pixel centre meets the plane of a quad, and the depth there: worked out by
// hand from the camera's definition, not from pixelRay.
struct PlaneHit {
    double x, y, depth;
};
using PlaneHitFunction = std::function<PlaneHit(uint32_t px, uint32_t py, double z)>;

// Checks every pixel against the quads (triangles 2q, 2q + 1 form quad q): one robust hit per
// quad inside it, only non-robust hits on its diagonal, nothing outside.
void expectQuadHits(const AllHits& hits, const std::vector<QuadSpec>& quads,
                    const PlaneHitFunction& plane_hit) {
    constexpr double kMargin = 1e-5; // pixels this close to a border or diagonal are skipped
    int robust_hits = 0, diagonal_pixels = 0;
    for (uint32_t py = 0; py < hits.height; ++py) {
        for (uint32_t px = 0; px < hits.width; ++px) {
            const std::size_t pixel = std::size_t(py) * hits.width + px;
            for (uint32_t q = 0; q < quads.size(); ++q) {
                const PlaneHit expected = plane_hit(px, py, quads[q].z);
                const double h = quads[q].half_size;
                const double inside = h - std::max(std::abs(expected.x), std::abs(expected.y));
                const double diagonal = std::abs(expected.x - expected.y);
                std::vector<uint64_t> mine;
                for (uint64_t i = hits.firstHit(pixel); i < hits.endHit(pixel); ++i) {
                    if (hits.triangles[i] / 2 == q)
                        mine.push_back(i);
                }
                if (inside < -kMargin) {
                    EXPECT_TRUE(mine.empty()) << "pixel " << px << "," << py << " quad " << q;
                } else if (inside > kMargin && diagonal > kMargin) {
                    ASSERT_EQ(mine.size(), 1u) << "pixel " << px << "," << py << " quad " << q;
                    const uint32_t triangle = expected.y < expected.x ? 2 * q : 2 * q + 1;
                    EXPECT_EQ(hits.triangles[mine[0]], triangle);
                    EXPECT_TRUE(hits.robust[mine[0]]);
                    EXPECT_NEAR(hits.depths[mine[0]], expected.depth, 1e-12);
                    ++robust_hits;
                } else if (inside > kMargin && diagonal < 1e-9) {
                    // Exactly on the shared edge: watertight, so at least one triangle is hit.
                    ASSERT_GE(mine.size(), 1u) << "pixel " << px << "," << py << " quad " << q;
                    for (uint64_t i : mine) {
                        EXPECT_FALSE(hits.robust[i]);
                        EXPECT_NEAR(hits.depths[i], expected.depth, 1e-12);
                    }
                    ++diagonal_pixels;
                }
            }
        }
    }
    EXPECT_GT(robust_hits, 100);
    EXPECT_GT(diagonal_pixels, 4);
}

TrianglePositions twoParallelQuads() {
    TrianglePositions positions;
    addQuad(positions, 1.0, 0.0);  // front
    addQuad(positions, 2.0, -1.0); // behind, larger
    return positions;
}

TEST(RayCaster, ParallelQuadsPerspectiveMatchHandComputedDepths) {
    const TrianglePositions positions = twoParallelQuads();
    const uint32_t width = 64, height = 48;
    const ViewProjection view = test::perspectiveView(positions, {0, 0, 5}, width, height);
    // Bounds [-2,2]^2 x [-1,0]: centre (0,0,-0.5), radius sqrt(33)/2, eye 5.5 from the centre.
    const double near = (5.5 - std::sqrt(33.0) / 2) * 0.99;
    ASSERT_NEAR(view.near, near, 1e-12);
    const double tan_half = std::tan(22.5 * std::numbers::pi / 180), aspect = 64.0 / 48.0;
    const AllHits hits = castAllHits(positions, view, 1);
    ASSERT_EQ(hits.offsets.size(), std::size_t(width) * height + 1);
    expectQuadHits(hits, {{1.0, 0.0}, {2.0, -1.0}}, [&](uint32_t px, uint32_t py, double z) {
        const double x_ndc = 2.0 * (px + 0.5) / width - 1, y_ndc = 1 - 2.0 * (py + 0.5) / height;
        const double distance = 5 - z;
        return PlaneHit{distance * x_ndc * aspect * tan_half, distance * y_ndc * tan_half,
                        1 - near / distance};
    });
}

TEST(RayCaster, ParallelQuadsOrthographicMatchHandComputedDepths) {
    const TrianglePositions positions = twoParallelQuads();
    const uint32_t width = 40, height = 40; // square: diagonal pixel centres lie on x = y
    const ViewProjection view = test::orthographicView(positions, {0, 0, -1}, width, height);
    const double r = std::sqrt(33.0) / 2, eye_z = -0.5 + 2 * r;
    const AllHits hits = castAllHits(positions, view, 1);
    expectQuadHits(hits, {{1.0, 0.0}, {2.0, -1.0}}, [&](uint32_t px, uint32_t py, double z) {
        const double x_ndc = 2.0 * (px + 0.5) / width - 1, y_ndc = 1 - 2.0 * (py + 0.5) / height;
        return PlaneHit{x_ndc * r, y_ndc * r, (eye_z - z - 0.5 * r) / (3 * r)};
    });
}

TEST(RayCaster, NearEdgesAreMarkedWhereACentreJustMisses) {
    // A big quad behind, and in front a rectangle whose right edge passes 0.005 pixels left of the
    // centre of column 25: that pixel's ray misses the rectangle, but a rasterizer's snapping could
    // cover it. Columns farther away are clear.
    const uint32_t width = 40, height = 30;
    Bounds bounds;
    bounds.add({-1, -1, 0});
    bounds.add({1, 1, 0.5});
    CameraSpec spec;
    spec.projection = Projection::orthographic;
    spec.ortho_direction = {0, 0, -1};
    const ViewProjection view = frameCamera(spec, bounds, width, height);
    Vec3 origin, direction;
    view.pixelRay(25.5 - 0.005, 15.5, origin, direction);
    const double edge = origin.x;
    TrianglePositions positions;
    addQuad(positions, 1.0, 0.0);
    addTriangle(positions, {-0.5, -0.5, 0.5}, {edge, -0.5, 0.5}, {edge, 0.5, 0.5});
    addTriangle(positions, {-0.5, -0.5, 0.5}, {edge, 0.5, 0.5}, {-0.5, 0.5, 0.5});
    const AllHits plain = castAllHits(positions, view, 1);
    EXPECT_TRUE(plain.near_edge.empty());
    const AllHits hits = castAllHits(positions, view, 1, true);
    ASSERT_EQ(hits.near_edge.size(), hits.pixelCount());
    const auto at = [&](uint32_t px) { return std::size_t(15) * width + px; };
    EXPECT_EQ(hits.endHit(at(25)) - hits.firstHit(at(25)), 1u); // the quad behind only
    EXPECT_EQ(hits.near_edge[at(25)], 1);
    EXPECT_EQ(hits.near_edge[at(28)], 0);
    EXPECT_EQ(hits.near_edge[at(22)], 0);
    EXPECT_EQ(hits.endHit(at(22)) - hits.firstHit(at(22)), 2u);
    // Marking changes no hit.
    EXPECT_EQ(hits.triangles, plain.triangles);
    EXPECT_EQ(hits.robust, plain.robust);
}

TEST(RayCaster, EmptyGeometryGivesNoHits) {
    const TrianglePositions empty;
    Bounds bounds;
    bounds.add({-1, -1, -1});
    bounds.add({1, 1, 1});
    const ViewProjection view = frameCamera(CameraSpec{}, bounds, 7, 5);
    const AllHits hits = castAllHits(empty, view);
    EXPECT_EQ(hits.pixelCount(), 35u);
    ASSERT_EQ(hits.offsets.size(), 36u);
    EXPECT_EQ(hits.offsets.back(), 0u);
    EXPECT_EQ(hits.hitCount(), 0u);
}

TEST(RayCaster, DegenerateTrianglesAreNeverHit) {
    TrianglePositions positions;
    addQuad(positions, 1.0, -0.5);                                       // 0, 1: a real target
    addTriangle(positions, {-1, -1, 0}, {0, 0, 0}, {1, 1, 0});           // 2: collinear
    addTriangle(positions, {0.1, 0.1, 0}, {0.1, 0.1, 0}, {0.1, 0.1, 0}); // 3: a point
    addTriangle(positions, {-1, 0, 0}, {1, 0, 0}, {0, 1, 0});            // 4: NaN corner, set below
    addTriangle(positions, {-1, 0, 0.2}, {1, 0, 0.2}, {0, 1, 0.2}); // 5: infinite corner, below
    addTriangle(positions, {0, -1, 0.3}, {0, 1, 0.3}, {0, 0, 0.9}); // 6: seen edge-on
    Bounds bounds;
    bounds.add({-1, -1, -1});
    bounds.add({1, 1, 1});
    positions.x[12] = std::numeric_limits<float>::quiet_NaN();
    positions.z[16] = std::numeric_limits<float>::infinity();
    for (const Projection projection : {Projection::perspective, Projection::orthographic}) {
        CameraSpec camera;
        camera.projection = projection;
        const ViewProjection view = frameCamera(camera, bounds, 33, 31);
        const AllHits hits = castAllHits(positions, view);
        int quad_hits = 0;
        for (std::size_t i = 0; i < hits.hitCount(); ++i) {
            EXPECT_TRUE(hits.triangles[i] <= 1 || hits.triangles[i] == 6) << hits.triangles[i];
            if (hits.triangles[i] == 6) {
                EXPECT_FALSE(hits.robust[i]);
            }
            quad_hits += hits.triangles[i] <= 1;
        }
        EXPECT_GT(quad_hits, 50);
    }
}

TEST(RayCaster, HitsAreSortedUniqueAndInDepthRange) {
    const TrianglePositions positions = test::randomLayeredSoup(60, 7);
    const ViewProjection view = test::perspectiveView(positions, {0.4, 0.3, 4}, 50, 40);
    const AllHits hits = castAllHits(positions, view);
    for (std::size_t pixel = 0; pixel < hits.pixelCount(); ++pixel) {
        ASSERT_LE(hits.firstHit(pixel), hits.endHit(pixel));
        for (uint64_t i = hits.firstHit(pixel); i < hits.endHit(pixel); ++i) {
            EXPECT_GE(hits.depths[i], 0.0);
            EXPECT_LE(hits.depths[i], 1.0);
            if (i > hits.firstHit(pixel)) {
                EXPECT_LT(hits.depths[i - 1], hits.depths[i]); // layers never coincide
            }
        }
    }
}

TEST(RayCaster, SameHitsForAnyThreadCount) {
    const TrianglePositions positions = test::randomLayeredSoup(200, 11);
    const ViewProjection view = test::perspectiveView(positions, {-0.5, 0.8, 3.5}, 97, 83);
    const AllHits one = castAllHits(positions, view, 1);
    for (unsigned threads : {2u, 3u, 8u}) {
        const AllHits many = castAllHits(positions, view, threads);
        EXPECT_EQ(one.offsets, many.offsets);
        EXPECT_EQ(one.triangles, many.triangles);
        EXPECT_EQ(one.depths, many.depths);
        EXPECT_EQ(one.robust, many.robust);
    }
    EXPECT_GT(one.hitCount(), 1000u);
}

// The Embree caster against a plain double-precision loop over every triangle.
void expectSameAsBruteForce(const TrianglePositions& positions, const ViewProjection& view) {
    const AllHits hits = castAllHits(positions, view);
    const auto reference = test::bruteForceHits(positions, view);
    ASSERT_EQ(reference.size(), hits.pixelCount());
    std::size_t overlapped_pixels = 0;
    for (std::size_t pixel = 0; pixel < hits.pixelCount(); ++pixel) {
        auto expected = reference[pixel];
        std::sort(
            expected.begin(), expected.end(),
            [](const test::BruteHit& a, const test::BruteHit& b) { return a.depth < b.depth; });
        ASSERT_EQ(hits.endHit(pixel) - hits.firstHit(pixel), expected.size()) << "pixel " << pixel;
        for (std::size_t k = 0; k < expected.size(); ++k) {
            const uint64_t i = hits.firstHit(pixel) + k;
            EXPECT_EQ(hits.triangles[i], expected[k].triangle);
            EXPECT_NEAR(hits.depths[i], expected[k].depth, 1e-12);
            EXPECT_EQ(bool(hits.robust[i]), expected[k].robust);
        }
        overlapped_pixels += expected.size() >= 2;
    }
    EXPECT_GT(overlapped_pixels, 100u); // the comparison must see depth order, not just coverage
}

TEST(RayCaster, MatchesBruteForcePerspective) {
    for (uint32_t seed : {1u, 2u, 3u}) {
        const TrianglePositions positions = test::randomLayeredSoup(40, seed);
        expectSameAsBruteForce(positions, test::perspectiveView(positions, {0.3, -0.2, 3}, 48, 40));
    }
}

TEST(RayCaster, MatchesBruteForceOrthographic) {
    for (uint32_t seed : {4u, 5u}) {
        const TrianglePositions positions = test::randomLayeredSoup(40, seed);
        expectSameAsBruteForce(positions,
                               test::orthographicView(positions, {0.2, 0.1, -1}, 45, 41));
    }
}

} // namespace
} // namespace vissort
