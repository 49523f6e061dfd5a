// The AVX2 batch set-up against the scalar one (fast_setup.h), bit for bit, on random triangles of
// every kind: inside the view, crossing the near plane and the guard band, behind the eye,
// sub-pixel, degenerate, with non-finite corners; both projections; viewports from 1 x 1 to the
// largest allowed. The scalar set-up is itself the reference's (checked against ray casting in
// cpu_rasterizer_tests.cpp), and CpuOracle's answers against CpuReferenceOracle's in
// cpu_oracle_tests.cpp.

#include "raster/fast_setup.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "raster/fast_rows.h"
#include "vissort/camera.h"

namespace vissort::detail {
namespace {

enum class Kind { inside, crossing, tiny, degenerate, non_finite };

// Appends one triangle of that kind around a unit cube seen from the camera below.
void addTriangle(TrianglePositions& p, std::mt19937_64& rng, Kind kind) {
    std::uniform_real_distribution<double> unit(-1, 1);
    Vec3 c[3];
    for (Vec3& v : c)
        v = {unit(rng), unit(rng), unit(rng)};
    switch (kind) {
    case Kind::inside:
        break;
    case Kind::crossing:
        // Far outside the frame on every side, and through the eye's plane.
        for (Vec3& v : c)
            v = {v.x * 300, v.y * 300, v.z * 8};
        break;
    case Kind::tiny:
        for (int k = 1; k < 3; ++k)
            c[k] = {c[0].x + unit(rng) * 1e-3, c[0].y + unit(rng) * 1e-3,
                    c[0].z + unit(rng) * 1e-3};
        break;
    case Kind::degenerate:
        c[2] = {0.5 * (c[0].x + c[1].x), 0.5 * (c[0].y + c[1].y), 0.5 * (c[0].z + c[1].z)};
        if (unit(rng) < 0)
            c[1] = c[0];
        break;
    case Kind::non_finite: {
        const double bad[] = {std::numeric_limits<double>::quiet_NaN(),
                              std::numeric_limits<double>::infinity(),
                              -std::numeric_limits<double>::infinity()};
        c[std::size_t(unit(rng) < 0)].y = bad[std::size_t(3 * (unit(rng) + 1) / 2) % 3];
        break;
    }
    }
    for (const Vec3& v : c) {
        p.x.push_back(float(v.x));
        p.y.push_back(float(v.y));
        p.z.push_back(float(v.z));
    }
}

// Field by field, bit for bit (the struct has padding, which memcmp would compare too).
bool sameBits(const FastSetup& a, const FastSetup& b) {
    const auto same = [](const auto& x, const auto& y) {
        return std::memcmp(&x, &y, sizeof(x)) == 0;
    };
    return same(a.edge_at_origin, b.edge_at_origin) && same(a.edge_step_x, b.edge_step_x) &&
           same(a.edge_step_y, b.edge_step_y) && same(a.x0, b.x0) && same(a.y0, b.y0) &&
           same(a.d0, b.d0) && same(a.ddx, b.ddx) && same(a.ddy, b.ddy) &&
           same(a.spread, b.spread) && same(a.error, b.error) && same(a.margin, b.margin) &&
           a.flat == b.flat && a.px_min == b.px_min && a.px_max == b.px_max &&
           a.py_min == b.py_min && a.py_max == b.py_max && a.narrow == b.narrow;
}

// A set-up's band pixels, sorted.
std::vector<std::pair<uint32_t, uint32_t>> bandPixels(const FastSetup& s) {
    std::vector<std::pair<uint32_t, uint32_t>> pixels;
    forEachFastBandPixel(s, [&](uint32_t px, uint32_t py) { pixels.push_back({px, py}); });
    std::sort(pixels.begin(), pixels.end());
    return pixels;
}

TEST(FastSetup, Avx2QuadsMatchTheScalarSetup) {
    bool uses_simd = false;
    selectRowKernels(true, uses_simd); // the same run-time check CpuOracle makes
    if (!uses_simd || avx2SetupQuad() == nullptr)
        GTEST_SKIP() << "this CPU has no AVX2: only the scalar set-up runs here";
    const SetupQuadFn quad = avx2SetupQuad();
    std::mt19937_64 rng(7);
    TrianglePositions p;
    const Kind kinds[] = {Kind::inside, Kind::crossing, Kind::tiny, Kind::degenerate,
                          Kind::non_finite};
    for (int i = 0; i < 4000; ++i)
        addTriangle(p, rng, kinds[i % 5]);
    Bounds bounds;
    bounds.add({-1, -1, -1});
    bounds.add({1, 1, 1});
    const uint32_t sizes[][2] = {{1, 1},     {3, 5},       {17, 13},
                                 {640, 480}, {1920, 1080}, {65536, 65536}};
    std::size_t ready = 0, empty = 0, scalar_by_kind[5] = {}, screened_edges = 0;
    for (Projection projection : {Projection::perspective, Projection::orthographic})
        for (const auto& size : sizes) {
            CameraSpec spec;
            spec.projection = projection;
            spec.eye = {0.4, 0.3, 2.5}; // inside the crossing triangles' depth range
            spec.ortho_direction = {-0.2, -0.1, -1};
            const ViewProjection view = frameCamera(spec, bounds, size[0], size[1]);
            const Matrix4 m = multiply(view.projection_matrix, view.view);
            const PrimitiveRange all{0, uint32_t(p.triangleCount())};
            const ScreenErrors errors = screenErrorsOf(m, view, p, {&all, 1});
            std::uniform_int_distribution<uint32_t> pick(0, uint32_t(p.triangleCount()) - 1);
            for (int q = 0; q < 2000; ++q) {
                const uint32_t triangles[4] = {pick(rng), pick(rng), pick(rng), pick(rng)};
                FastSetup out[4];
                LaneSetup lanes[4];
                quad(m, p.x.data(), p.y.data(), p.z.data(), triangles, size[0], size[1], errors,
                     out, lanes);
                for (int l = 0; l < 4; ++l) {
                    SCOPED_TRACE("triangle " + std::to_string(triangles[l]) + ", " +
                                 std::to_string(size[0]) + "x" + std::to_string(size[1]));
                    std::vector<FastSetup> expected;
                    appendFastSetups(m, p, triangles[l], size[0], size[1], errors, expected);
                    switch (lanes[l]) {
                    case LaneSetup::ready:
                        ++ready;
                        ASSERT_EQ(expected.size(), 1u);
                        out[l].narrow = edgesFitInt32(out[l]);
                        ASSERT_TRUE(sameBits(expected[0], out[l]));
                        // The batch's band screen keeps every edge with a band pixel: the same
                        // pixels as the scalar set-up's, which walks all three.
                        ASSERT_EQ(bandPixels(out[l]), bandPixels(expected[0]));
                        screened_edges += 3 - std::popcount(unsigned(out[l].band_walk));
                        break;
                    case LaneSetup::empty:
                        ++empty;
                        ASSERT_TRUE(expected.empty());
                        break;
                    case LaneSetup::scalar:
                        ++scalar_by_kind[triangles[l] % 5];
                        break;
                    }
                }
            }
        }
    // Every outcome happened; the batch finished every triangle that needs no clipping (triangle
    // i is of kind i % 5) and handed back the ones that do.
    EXPECT_GT(ready, 20000u);
    EXPECT_GT(screened_edges, 10000u); // the screen skips most edges
    EXPECT_GT(empty, 10000u);
    // An inside triangle whose snapped corners are collinear (no snapped area: on the smallest
    // viewports) goes back too.
    EXPECT_LT(scalar_by_kind[int(Kind::inside)], 50u);
    // A tiny triangle that snapping leaves without area, and a degenerate one (either way: no
    // snapped area, or a plane with none), go back to the scalar set-up.
    EXPECT_GT(scalar_by_kind[int(Kind::tiny)], 0u);
    EXPECT_GT(scalar_by_kind[int(Kind::degenerate)], 0u);
    EXPECT_GT(scalar_by_kind[int(Kind::crossing)], 10000u);
    EXPECT_GT(scalar_by_kind[int(Kind::non_finite)], 10000u);
}

} // namespace
} // namespace vissort::detail

namespace vissort::detail {
namespace {

// The exact rule's band pixels of the fast form (forEachFastBandPixel: along each edge) are the
// reference's (forEachBandPixel: each row's interval), one for one, on random triangles of every
// kind and size, at a screen error of none and of a few units.
TEST(FastSetup, BandPixelsAreTheReferences) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> unit(0, 1);
    std::size_t compared = 0, found = 0;
    for (int i = 0; i < 20000; ++i) {
        const double size = i % 3 == 0 ? 2 : i % 3 == 1 ? 12 : 90;
        ScreenVertex v[3];
        for (ScreenVertex& c : v)
            c = {5 + size * unit(rng), 5 + size * unit(rng), unit(rng)};
        if (i % 7 == 0) // nearly collinear: a sliver, or no snapped area at all
            v[2] = {0.5 * (v[0].x + v[1].x) + 1e-3 * unit(rng), 0.5 * (v[0].y + v[1].y), 0.5};
        if (i % 11 == 0) // an axis-aligned edge through pixel centres
            v[1] = {v[0].x + 7, std::floor(v[0].y) + 0.5, v[1].d},
            v[0].y = std::floor(v[0].y) + 0.5;
        const ScreenErrors errors{i % 5 == 0 ? 0.01 : 0.0, 0};
        TriangleSetup reference;
        if (!setupTriangle(v[0], v[1], v[2], 128, 128, errors, reference))
            continue;
        std::vector<std::pair<uint32_t, uint32_t>> expected, actual;
        forEachBandPixel(reference, [&](uint32_t px, uint32_t py, float) {
            expected.push_back({px, py});
            return false;
        });
        FastSetup fast{};
        fast.band_walk = 7;
        constexpr int64_t half = kSubpixelScale / 2;
        for (int e = 0; e < 3; ++e) {
            const int j = (e + 1) % 3;
            const int64_t dx = reference.x[j] - reference.x[e],
                          dy = reference.y[j] - reference.y[e];
            fast.edge_at_origin[e] =
                dx * (half - reference.y[e]) - dy * (half - reference.x[e]) - reference.margin[e];
            fast.edge_step_x[e] = -dy * kSubpixelScale;
            fast.edge_step_y[e] = dx * kSubpixelScale;
            fast.margin[e] = reference.margin[e];
        }
        fast.flat = reference.flat;
        fast.px_min = int32_t(reference.px_min);
        fast.px_max = int32_t(reference.px_max);
        fast.py_min = int32_t(reference.py_min);
        fast.py_max = int32_t(reference.py_max);
        forEachFastBandPixel(fast, [&](uint32_t px, uint32_t py) { actual.push_back({px, py}); });
        std::sort(expected.begin(), expected.end());
        std::sort(actual.begin(), actual.end());
        ASSERT_EQ(actual, expected) << "triangle " << i;
        ++compared;
        found += expected.size();
    }
    EXPECT_GT(compared, 15000u);
    EXPECT_GT(found, 1000u);
}

} // namespace
} // namespace vissort::detail
