// The CPU oracle's occlusion-query semantics on hand-made fixtures, and its depth buffer on a real
// mesh against a brute-force double-precision ray cast.

#include "vissort/cpu_reference_oracle.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "raster_references.h"
#include "scenes/scene_library.h"
#include "vissort/scene.h"

namespace vissort {
namespace {

// A negative tolerance, as the transparency renderer sets (kBlendingDepthTolerance): near ties
// count as occlusion.
constexpr float kNegativeTolerance = -1.0f / (1 << 16);

constexpr float kInfinity = std::numeric_limits<float>::infinity();

// Appends the square [x0, x1] x [y0, y1] at height z as two triangles; returns its range.
PrimitiveRange addQuad(TrianglePositions& p, double x0, double y0, double x1, double y1, double z) {
    const PrimitiveRange range{uint32_t(p.triangleCount()), 2};
    const double corners[6][2] = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y0}, {x1, y1}, {x0, y1}};
    for (const auto& c : corners) {
        p.x.push_back(float(c[0]));
        p.y.push_back(float(c[1]));
        p.z.push_back(float(z));
    }
    return range;
}

ViewProjection viewOf(const TrianglePositions& p, Projection projection, uint32_t width = 32,
                      uint32_t height = 24) {
    CameraSpec spec;
    spec.projection = projection;
    spec.eye = {0.2, 0.1, 6};
    spec.target = {0, 0, 0};
    spec.ortho_direction = {0, 0, -1};
    return frameCamera(spec, p.bounds(), width, height);
}

std::size_t finitePixels(const CpuReferenceOracle& oracle) {
    const auto depth = oracle.depthBuffer();
    return std::size_t(
        std::count_if(depth.begin(), depth.end(), [](float d) { return std::isfinite(d); }));
}

class CpuReferenceOracleSemantics : public ::testing::TestWithParam<Projection> {};

TEST_P(CpuReferenceOracleSemantics, FrontQuadHidesBackQuad) {
    TrianglePositions p;
    std::vector<PrimitiveRange> primitives;
    primitives.push_back(addQuad(p, -1, -1, 1, 1, 0.5));  // 0: A, in front
    primitives.push_back(addQuad(p, -1, -1, 1, 1, -0.5)); // 1: B, behind A
    CpuReferenceOracle oracle;
    oracle.bind(p, viewOf(p, GetParam()), primitives);
    EXPECT_EQ(oracle.primitiveCount(), 2u);
    EXPECT_EQ(oracle.width(), 32u);
    EXPECT_EQ(oracle.depthBuffer().size(), 32u * 24u);
    EXPECT_EQ(finitePixels(oracle), 0u);

    oracle.draw(0);
    EXPECT_GT(finitePixels(oracle), 0u);
    const std::vector<float> after_draw(oracle.depthBuffer().begin(), oracle.depthBuffer().end());
    EXPECT_TRUE(oracle.anyBehind(1));
    EXPECT_FALSE(oracle.anyBehind(0)); // itself: coplanar
    // Queries leave the buffer alone.
    EXPECT_TRUE(std::equal(after_draw.begin(), after_draw.end(), oracle.depthBuffer().begin()));

    oracle.clear();
    EXPECT_EQ(finitePixels(oracle), 0u);
    EXPECT_FALSE(oracle.anyBehind(1)); // nothing drawn: nothing is in front
    oracle.draw(1);
    EXPECT_FALSE(oracle.anyBehind(0));

    // Drawing B then A leaves A's depths: LESS keeps the nearer surface.
    oracle.draw(0);
    EXPECT_TRUE(std::equal(after_draw.begin(), after_draw.end(), oracle.depthBuffer().begin()));
}

TEST_P(CpuReferenceOracleSemantics, CoplanarAndIdenticalPrimitivesNeverOcclude) {
    TrianglePositions p;
    std::vector<PrimitiveRange> primitives;
    primitives.push_back(addQuad(p, -1, -1, 1, 1, 0));         // 0
    primitives.push_back(addQuad(p, -1, -1, 1, 1, 0));         // 1: identical to 0
    primitives.push_back(addQuad(p, -0.5, -0.7, 1.3, 0.8, 0)); // 2: coplanar, overlapping
    // 3: the same square split along the other diagonal.
    primitives.push_back({uint32_t(p.triangleCount()), 2});
    for (const auto& c :
         {std::array<float, 2>{-1, -1}, {1, -1}, {-1, 1}, {1, -1}, {1, 1}, {-1, 1}}) {
        p.x.push_back(c[0]);
        p.y.push_back(c[1]);
        p.z.push_back(0);
    }
    CpuReferenceOracle oracle;
    oracle.bind(p, viewOf(p, GetParam()), primitives);
    for (uint32_t a = 0; a < 4; ++a)
        for (uint32_t b = 0; b < 4; ++b) {
            oracle.clear();
            oracle.draw(a);
            EXPECT_FALSE(oracle.anyBehind(b)) << a << " then " << b;
        }
}

TEST_P(CpuReferenceOracleSemantics, PartialOverlapAndMultiTrianglePrimitives) {
    TrianglePositions p;
    std::vector<PrimitiveRange> primitives;
    // 0: an L of two quads (four triangles), in front; 1: a small quad behind the L's corner
    // only; 2: a small quad behind the L's notch, where the L leaves a hole.
    const PrimitiveRange first = addQuad(p, -1, -1, 1, -0.2, 0.5);
    addQuad(p, -1, -0.2, -0.2, 1, 0.5);
    primitives.push_back({first.first_triangle, 4});
    primitives.push_back(addQuad(p, -0.9, -0.9, -0.4, -0.4, -0.5));
    primitives.push_back(addQuad(p, 0.3, 0.3, 0.8, 0.8, -0.5));
    // 3: a quad half behind the L and half in the notch.
    primitives.push_back(addQuad(p, -0.6, 0.3, 0.4, 0.6, -0.5));
    // 4: an empty primitive.
    primitives.push_back({uint32_t(p.triangleCount()), 0});
    CpuReferenceOracle oracle;
    oracle.bind(p, viewOf(p, GetParam()), primitives);
    oracle.draw(0);
    EXPECT_TRUE(oracle.anyBehind(1));
    EXPECT_FALSE(oracle.anyBehind(2));
    EXPECT_TRUE(oracle.anyBehind(3));
    EXPECT_FALSE(oracle.anyBehind(4));
    oracle.draw(4);
    oracle.clear();
    oracle.draw(2);
    oracle.draw(3);
    EXPECT_FALSE(oracle.anyBehind(0)); // 0 is in front of both
    oracle.draw(0);
    EXPECT_TRUE(oracle.anyBehind(2) == false && oracle.anyBehind(3));
    EXPECT_EQ(oracle.stats().draws, 5u);
    EXPECT_EQ(oracle.stats().queries, 7u);
}

TEST_P(CpuReferenceOracleSemantics, EveryDepthDifferenceOccludesExactly) {
    // Quads facing the camera behind a first one by the smallest float steps of z, far inside
    // the floats' own rounding of depth: under the default (exact) rule each is behind, the
    // coplanar one is not; under a positive tolerance none of them is.
    TrianglePositions p;
    std::vector<PrimitiveRange> primitives;
    primitives.push_back(addQuad(p, -1, -1, 1, 1, 0.5f));
    CameraSpec spec;
    spec.projection = GetParam();
    spec.eye = {0, 0, 6};
    spec.ortho_direction = {0, 0, -1};
    const ViewProjection vp = frameCamera(spec, p.bounds(), 32, 24);
    const float one_step = std::nextafter(0.5f, 0.0f), two_steps = std::nextafter(one_step, 0.0f);
    primitives.push_back(addQuad(p, -1, -1, 1, 1, one_step));         // 1: one float below
    primitives.push_back(addQuad(p, -1, -1, 1, 1, two_steps));        // 2: two
    primitives.push_back(addQuad(p, -0.5, -0.5, 0.7, 0.3, 0.5f));     // 3: coplanar
    ASSERT_LT(vp.depthOf({0, 0, 0.5}), vp.depthOf({0, 0, one_step})); // farther from the eye
    CpuReferenceOracle oracle;
    oracle.bind(p, vp, primitives);
    const auto behind = [&](uint32_t drawn, uint32_t queried) {
        oracle.clear();
        oracle.draw(drawn);
        return oracle.anyBehind(queried);
    };
    EXPECT_TRUE(behind(0, 1));
    EXPECT_TRUE(behind(0, 2));
    EXPECT_TRUE(behind(1, 2));
    EXPECT_FALSE(behind(1, 0));
    EXPECT_FALSE(behind(2, 1));
    EXPECT_FALSE(behind(0, 3));
    EXPECT_FALSE(behind(3, 0));
    EXPECT_GT(oracle.stats().arbitrations, 0u); // the floats could not tell them apart
    oracle.setDepthTolerance(1.0f / (1 << 20));
    EXPECT_FALSE(behind(0, 1));
    EXPECT_FALSE(behind(0, 2));
}

TEST_P(CpuReferenceOracleSemantics, BlendingToleranceMakesNearTiesOccludeBothWays) {
    // Coplanar quads: with the default tolerance neither occludes the other. Quads a quarter of
    // the blending tolerance apart: the back one is behind, only. With the blending tolerance
    // both pairs occlude each other both ways (a cycle, composited per pixel); quads clearly
    // apart keep one direction only.
    TrianglePositions p;
    std::vector<PrimitiveRange> primitives;
    primitives.push_back(addQuad(p, -1, -1, 1, 1, 0));
    CameraSpec spec;
    spec.projection = GetParam();
    spec.eye = {0, 0, 6};
    spec.ortho_direction = {0, 0, -1};
    const ViewProjection vp = frameCamera(spec, p.bounds(), 32, 24);
    const double slope = (vp.depthOf({0, 0, -1e-3}) - vp.depthOf({0, 0, 0})) / 1e-3;
    primitives.push_back(addQuad(p, -0.5, -0.5, 1.5, 1.5, 0)); // 1: coplanar with 0
    primitives.push_back(addQuad(p, -1, -1, 1, 1, 0.25 * kNegativeTolerance / slope)); // 2
    primitives.push_back(addQuad(p, -1, -1, 1, 1, -0.1)); // 3: clearly behind 0
    CpuReferenceOracle oracle;
    oracle.bind(p, vp, primitives);
    const auto behind = [&](uint32_t drawn, uint32_t queried) {
        oracle.clear();
        oracle.draw(drawn);
        return oracle.anyBehind(queried);
    };
    EXPECT_EQ(oracle.depthTolerance(), kDepthTolerance);
    EXPECT_FALSE(behind(0, 1));
    EXPECT_FALSE(behind(1, 0));
    EXPECT_TRUE(behind(0, 2));
    EXPECT_FALSE(behind(2, 0));
    oracle.setDepthTolerance(kNegativeTolerance);
    for (uint32_t other : {1u, 2u}) {
        EXPECT_TRUE(behind(0, other)) << other;
        EXPECT_TRUE(behind(other, 0)) << other;
    }
    EXPECT_TRUE(behind(0, 3));
    EXPECT_FALSE(behind(3, 0));
    // An empty pixel holds +infinity: never behind it, whatever the tolerance.
    oracle.clear();
    EXPECT_FALSE(oracle.anyBehind(0));
}

INSTANTIATE_TEST_SUITE_P(BothProjections, CpuReferenceOracleSemantics,
                         ::testing::Values(Projection::perspective, Projection::orthographic));

TEST(CpuReferenceOracle, RebindAndDegenerateGeometry) {
    TrianglePositions p;
    std::vector<PrimitiveRange> primitives;
    primitives.push_back(addQuad(p, -1, -1, 1, 1, 0));
    // A degenerate triangle (a point) and one with a non-finite corner: they draw nothing.
    primitives.push_back({uint32_t(p.triangleCount()), 2});
    for (int i = 0; i < 3; ++i) {
        p.x.push_back(0.25f);
        p.y.push_back(0.25f);
        p.z.push_back(0.5f);
    }
    const ViewProjection vp = viewOf(p, Projection::perspective, 16, 16);
    p.x.push_back(std::numeric_limits<float>::quiet_NaN());
    p.y.push_back(0);
    p.z.push_back(0.5f);
    p.x.push_back(1);
    p.y.push_back(0);
    p.z.push_back(0.5f);
    p.x.push_back(0);
    p.y.push_back(1);
    p.z.push_back(0.5f);
    CpuReferenceOracle oracle;
    oracle.bind(p, vp, primitives);
    oracle.draw(1);
    EXPECT_EQ(finitePixels(oracle), 0u);
    oracle.draw(0);
    const std::size_t quad_pixels = finitePixels(oracle);
    EXPECT_GT(quad_pixels, 0u);
    EXPECT_FALSE(oracle.anyBehind(1));

    // Binding again clears, and a new viewport size resizes the buffer.
    const ViewProjection bigger = viewOf(p, Projection::perspective, 40, 30);
    oracle.bind(p, bigger, std::span(primitives).first(1));
    EXPECT_EQ(oracle.primitiveCount(), 1u);
    EXPECT_EQ(oracle.depthBuffer().size(), 40u * 30u);
    EXPECT_EQ(finitePixels(oracle), 0u);
}

// The depth buffer of a whole mesh equals, at every pixel away from an edge, the nearest hit of
// a double-precision ray cast against every triangle, up to the snap slack of the triangles
// there (draws write the plane's depth moved farther by it: cpu_reference_oracle.h, rule 7).
TEST(CpuReferenceOracle, SpotDepthBufferMatchesRayCast) {
    const Result<Scene> loaded =
        samples::loadScene(std::string(VISSORT_SOURCE_DIR) + "/assets/models/spot.obj");
    ASSERT_TRUE(loaded) << loaded.error;
    const Scene& scene = *loaded.value;
    const TrianglePositions& p = scene.positions;
    const uint32_t size = 64;
    const ViewProjection vp = frameCamera(defaultCamera(p.bounds()), p.bounds(), size, size);
    const std::vector<PrimitiveRange> primitives = scene.trianglePrimitives();
    CpuReferenceOracle oracle;
    oracle.bind(p, vp, primitives);
    for (uint32_t i = 0; i < oracle.primitiveCount(); ++i)
        oracle.draw(i);
    const auto depth = oracle.depthBuffer();

    // Pixels within the margin of any projected edge are skipped; the camera frames the whole
    // mesh, so every corner is in front of the eye and edges project to straight segments.
    const double margin = 4e-3;
    std::vector<uint8_t> near_edge(std::size_t(size) * size, 0);
    std::vector<std::vector<uint32_t>> candidates(std::size_t(size) * size);
    std::vector<double> slack(p.triangleCount(), 0.0);
    for (uint32_t t = 0; t < p.triangleCount(); ++t) {
        std::array<std::array<double, 2>, 3> s;
        for (int k = 0; k < 3; ++k) {
            const auto c = vp.toClip(p.corner(3 * t + k));
            ASSERT_GT(c[3], 0);
            s[k] = {(c[0] / c[3] + 1) * 0.5 * size, (1 - c[1] / c[3]) * 0.5 * size};
        }
        // The plane's slopes in depth per pixel, from the corners' screen positions and depths.
        std::array<double, 3> d;
        for (int k = 0; k < 3; ++k)
            d[k] = vp.depthOf(p.corner(3 * t + k));
        const double e1x = s[1][0] - s[0][0], e1y = s[1][1] - s[0][1], e1d = d[1] - d[0];
        const double e2x = s[2][0] - s[0][0], e2y = s[2][1] - s[0][1], e2d = d[2] - d[0];
        const double det = e1x * e2y - e2x * e1y;
        if (det != 0)
            slack[t] = std::max(std::abs((e1d * e2y - e2d * e1y) / det),
                                std::abs((e2d * e1x - e1d * e2x) / det)) /
                       256;
        const auto [min_x, max_x] = std::minmax({s[0][0], s[1][0], s[2][0]});
        const auto [min_y, max_y] = std::minmax({s[0][1], s[1][1], s[2][1]});
        const int x0 = std::max(0, int(std::floor(min_x - 1))),
                  x1 = std::min(int(size) - 1, int(max_x + 1));
        const int y0 = std::max(0, int(std::floor(min_y - 1))),
                  y1 = std::min(int(size) - 1, int(max_y + 1));
        for (int py = y0; py <= y1; ++py)
            for (int px = x0; px <= x1; ++px) {
                const std::size_t pixel = std::size_t(py) * size + px;
                candidates[pixel].push_back(t);
                const double cx = px + 0.5, cy = py + 0.5;
                for (int k = 0; k < 3; ++k) {
                    const auto& a = s[k];
                    const auto& b = s[(k + 1) % 3];
                    const double ex = b[0] - a[0], ey = b[1] - a[1], len2 = ex * ex + ey * ey;
                    const double u =
                        len2 > 0
                            ? std::clamp(((cx - a[0]) * ex + (cy - a[1]) * ey) / len2, 0.0, 1.0)
                            : 0.0;
                    if (std::hypot(cx - a[0] - u * ex, cy - a[1] - u * ey) < margin)
                        near_edge[pixel] = 1;
                }
            }
    }
    int compared = 0, hit = 0;
    for (uint32_t py = 0; py < size; ++py)
        for (uint32_t px = 0; px < size; ++px) {
            const std::size_t pixel = std::size_t(py) * size + px;
            if (near_edge[pixel])
                continue;
            double nearest = INFINITY, most_slack = 0;
            for (uint32_t t : candidates[pixel]) {
                most_slack = std::max(most_slack, slack[t]);
                const auto d = test::castDepth(vp, px + 0.5, py + 0.5, p.corner(3 * t),
                                               p.corner(3 * t + 1), p.corner(3 * t + 2));
                if (d)
                    nearest = std::min(nearest, *d);
            }
            ++compared;
            if (std::isinf(nearest)) {
                EXPECT_EQ(depth[pixel], kInfinity) << px << "," << py;
            } else {
                ++hit;
                EXPECT_NEAR(depth[pixel], nearest, 1e-6 * nearest + most_slack) << px << "," << py;
            }
        }
    EXPECT_GT(compared, int(size * size) * 3 / 4);
    EXPECT_GT(hit, int(size * size) / 8);
}

} // namespace
} // namespace vissort
