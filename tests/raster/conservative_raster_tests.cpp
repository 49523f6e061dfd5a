// Conservative rasterization (RasterMode::conservative) may only add "behind" answers: on every
// sequence of draws and queries, each answer the exact mode gives as "behind" is "behind" in
// conservative mode too. Checked against the exact-mode CpuReferenceOracle run on the same
// operations.
#include <random>

#include <gtest/gtest.h>

#include "raster/cpu_rasterizer.h"
#include "vissort/cpu_reference_oracle.h"
#include "vissort/scene.h"

namespace vissort {
namespace {

TrianglePositions randomSoup(uint32_t count, double spread, uint32_t seed) {
    std::mt19937_64 rng(seed);
    auto unit = [&] { return double(rng() >> 11) * 0x1.0p-53; };
    TrianglePositions p;
    p.resize(count);
    for (uint32_t t = 0; t < count; ++t) {
        const double cx = (unit() - 0.5) * spread, cy = (unit() - 0.5) * spread;
        const double cz = (unit() - 0.5) * spread, size = 0.05 + unit() * 0.6;
        for (int c = 0; c < 3; ++c) {
            p.x[3 * t + c] = float(cx + (unit() - 0.5) * size);
            p.y[3 * t + c] = float(cy + (unit() - 0.5) * size);
            p.z[3 * t + c] = float(cz + (unit() - 0.5) * size);
        }
    }
    return p;
}

ViewProjection viewOf(const TrianglePositions& p, Projection projection, uint32_t w, uint32_t h) {
    CameraSpec camera;
    camera.projection = projection;
    camera.eye = {0.4, 0.3, 3.0};
    camera.target = {0, 0, 0};
    camera.ortho_direction = {-0.2, -0.1, -1};
    return frameCamera(camera, p.bounds(), w, h);
}

struct Counts {
    uint64_t exact_behind = 0, added = 0, queries = 0;
};

Counts compareModes(const TrianglePositions& positions, const ViewProjection& view, uint32_t seed) {
    std::vector<PrimitiveRange> primitives;
    for (uint32_t t = 0; t < positions.triangleCount(); ++t)
        primitives.push_back({t, 1});
    CpuReferenceOracle exact(RasterMode::exact), conservative(RasterMode::conservative);
    exact.bind(positions, view, primitives);
    conservative.bind(positions, view, primitives);
    std::mt19937 rng(seed);
    Counts counts;
    for (int round = 0; round < 20; ++round) {
        exact.clear();
        conservative.clear();
        for (uint32_t op = 0; op < 3 * primitives.size(); ++op) {
            const uint32_t p = rng() % primitives.size();
            if (rng() % 3 == 0) {
                exact.draw(p);
                conservative.draw(p);
                continue;
            }
            const bool e = exact.anyBehind(p), c = conservative.anyBehind(p);
            ++counts.queries;
            counts.exact_behind += e;
            counts.added += c && !e;
            EXPECT_TRUE(!e || c) << "conservative mode lost a behind answer for " << p;
        }
    }
    return counts;
}

TEST(ConservativeRaster, BehindAnswersAreASupersetOfTheExactModes) {
    Counts total;
    uint32_t seed = 1;
    for (Projection projection : {Projection::perspective, Projection::orthographic}) {
        for (auto [w, h] : {std::pair{1u, 1u}, {3u, 5u}, {17u, 13u}, {64u, 48u}, {160u, 120u}}) {
            const TrianglePositions soup = randomSoup(60, 2.0, seed++);
            const Counts c = compareModes(soup, viewOf(soup, projection, w, h), seed);
            total.exact_behind += c.exact_behind;
            total.added += c.added;
            total.queries += c.queries;
        }
    }
    // The comparison saw real occlusion, and conservative mode did add answers.
    EXPECT_GT(total.exact_behind, 100u);
    EXPECT_GT(total.added, 0u);
}

TEST(ConservativeRaster, CameraInsideTheSoupCrossesTheNearPlane) {
    const TrianglePositions soup = randomSoup(80, 3.0, 77);
    CameraSpec camera;
    camera.eye = {0, 0, 0};
    camera.target = {0.3, 0.1, -1};
    const ViewProjection view = frameCamera(camera, soup.bounds(), 96, 64);
    const Counts c = compareModes(soup, view, 5);
    EXPECT_GT(c.exact_behind, 0u);
}

// A triangle inside one pixel that misses its centre: the exact mode draws nothing, the
// conservative mode covers the pixel, so a triangle behind it is behind only conservatively.
TEST(ConservativeRaster, SubPixelTriangleCoversItsPixel) {
    TrianglePositions p;
    p.resize(2);
    // World = pixels through an orthographic camera looking down -z at a 20x20 image of [0,20]^2.
    const float tiny[3][3] = {{10.1f, 10.1f, 1.0f}, {10.3f, 10.1f, 1.0f}, {10.1f, 10.3f, 1.0f}};
    const float big[3][3] = {{0, 0, -1.0f}, {20, 0, -1.0f}, {0, 20, -1.0f}};
    for (int c = 0; c < 3; ++c) {
        p.x[c] = tiny[c][0], p.y[c] = tiny[c][1], p.z[c] = tiny[c][2];
        p.x[3 + c] = big[c][0], p.y[3 + c] = big[c][1], p.z[3 + c] = big[c][2];
    }
    Bounds b;
    b.add({0, 0, -2});
    b.add({20, 20, 2});
    CameraSpec camera;
    camera.projection = Projection::orthographic;
    camera.ortho_direction = {0, 0, -1};
    const ViewProjection view = frameCamera(camera, b, 20, 20);
    const std::vector<PrimitiveRange> primitives{{0, 1}, {1, 1}};
    CpuReferenceOracle exact(RasterMode::exact), conservative(RasterMode::conservative);
    for (CpuReferenceOracle* o : {&exact, &conservative}) {
        o->bind(p, view, primitives);
        o->draw(0);
    }
    EXPECT_FALSE(exact.anyBehind(1));
    EXPECT_TRUE(conservative.anyBehind(1));
}

// The guarantee collision culling rests on (cpu_reference_oracle.h, conservative mode): every point
// of the unsnapped triangle lies in a covered pixel whose depth range holds the point's depth.
// Checked at random points of random triangles (slivers, sub-pixel ones, edge-on ones whose screen
// area is zero, and points on their edges) against depths interpolated independently in double.
TEST(ConservativeRaster, EveryPointOfTheTriangleIsInACoveredPixelWithItsDepth) {
    constexpr uint32_t kWidth = 24, kHeight = 20;
    std::mt19937_64 rng(11);
    const auto unit = [&] { return double(rng() >> 11) * 0x1.0p-53; };
    uint64_t points = 0, degenerate = 0;
    for (int round = 0; round < 3000; ++round) {
        // Screen positions and depths first; clip coordinates (w = 1) map onto them.
        detail::ScreenVertex v[3];
        const double size = round % 3 == 0 ? 0.3 : round % 3 == 1 ? 3.0 : 15.0;
        const double cx = unit() * kWidth, cy = unit() * kHeight;
        for (auto& p : v)
            p = {cx + (unit() - 0.5) * size, cy + (unit() - 0.5) * size, unit()};
        if (round % 5 == 0) { // edge-on: three collinear screen points, different depths
            const double t = unit() * 2 - 0.5;
            v[2].x = v[0].x + t * (v[1].x - v[0].x);
            v[2].y = v[0].y + t * (v[1].y - v[0].y);
        }
        detail::ClipVertex clip[3];
        for (int i = 0; i < 3; ++i)
            clip[i] = {2 * v[i].x / kWidth - 1, 1 - 2 * v[i].y / kHeight, v[i].d, 1};
        // The screen positions the rasterizer itself computes (rule 4): the ground truth's input.
        for (int i = 0; i < 3; ++i)
            v[i] = detail::toScreen(clip[i], kWidth, kHeight);
        const double area =
            (v[1].x - v[0].x) * (v[2].y - v[0].y) - (v[1].y - v[0].y) * (v[2].x - v[0].x);
        degenerate += std::abs(area) < 1e-9;
        std::vector<float> nearest(kWidth * kHeight, INFINITY),
            farthest(kWidth * kHeight, -INFINITY);
        detail::rasterizeTriangleConservative(clip[0], clip[1], clip[2], kWidth, kHeight,
                                              [&](uint32_t x, uint32_t y, float lo, float hi) {
                                                  nearest[y * kWidth + x] =
                                                      std::min(nearest[y * kWidth + x], lo);
                                                  farthest[y * kWidth + x] =
                                                      std::max(farthest[y * kWidth + x], hi);
                                                  return false;
                                              });
        for (int k = 0; k < 40; ++k) {
            // A random point, on an edge for every fourth one (a barycentric coordinate of 0).
            double b[3] = {unit(), unit(), unit()};
            if (k % 4 == 0)
                b[k % 3] = 0;
            const double sum = b[0] + b[1] + b[2];
            double px = 0, py = 0, pd = 0;
            for (int i = 0; i < 3; ++i) {
                px += b[i] / sum * v[i].x;
                py += b[i] / sum * v[i].y;
                pd += b[i] / sum * v[i].d;
            }
            if (px < 0 || py < 0 || px >= kWidth || py >= kHeight)
                continue;
            const uint32_t x = uint32_t(px), y = uint32_t(py);
            ++points;
            ASSERT_LE(nearest[y * kWidth + x], pd + 1e-6) << "round " << round << " point " << k;
            ASSERT_GE(farthest[y * kWidth + x], pd - 1e-6) << "round " << round << " point " << k;
        }
    }
    EXPECT_GT(points, 50000u);
    EXPECT_GT(degenerate, 300u);
}

// Snapping moves vertices by up to half a sub-pixel unit, and with them the height where a nearly
// vertical edge crosses a pixel border: a square the unsnapped edge enters by a hair must still
// be walked (the margin's promise; the edges' reach over whole squares also covers these cases
// on its own, so this guards the property rather than the margin alone). Points on a random
// edge just left of a pixel border, the rest of the triangle to the right.
TEST(ConservativeRaster, SnappingMarginKeepsSquaresTouchedByAHair) {
    constexpr uint32_t kSize = 32;
    std::mt19937_64 rng(5);
    const auto unit = [&] { return double(rng() >> 11) * 0x1.0p-53; };
    int checked = 0;
    for (int round = 0; round < 20000; ++round) {
        // Edge AB, steep and long, crossing the border x = k at a random height.
        const double k = 8 + double(rng() % 16);
        const double inside = (0.05 + 0.4 * unit()) / 256; // how far left of the border
        // dx per unit of y: the ends differ by about a sub-pixel unit, so that snapping can move
        // the height where the edge crosses the border by whole pixels.
        const double half_height = 2 + unit() * 5;
        const double slope = (unit() - 0.5) * 3.0 / 256 / half_height;
        const double y_cross = 8 + unit() * 16, half = half_height;
        detail::ScreenVertex v[3];
        v[0] = {k - inside - slope * half, y_cross - half, 0.5};
        v[1] = {k - inside + slope * half, y_cross + half, 0.5};
        v[2] = {k + 1 + unit() * 4, y_cross + (unit() - 0.5) * 4, 0.5}; // right of the border
        detail::ClipVertex clip[3];
        for (int i = 0; i < 3; ++i)
            clip[i] = {2 * v[i].x / kSize - 1, 1 - 2 * v[i].y / kSize, v[i].d, 1};
        for (int i = 0; i < 3; ++i)
            v[i] = detail::toScreen(clip[i], kSize, kSize);
        // The point of AB at height y_cross lies left of x = k: pixel (k - 1, y).
        const double t = (y_cross - v[0].y) / (v[1].y - v[0].y);
        const double px = v[0].x + t * (v[1].x - v[0].x);
        if (!(px < k && px > k - 0.5))
            continue;
        const uint32_t want_x = uint32_t(k) - 1, want_y = uint32_t(y_cross);
        bool covered = false;
        detail::rasterizeTriangleConservative(clip[0], clip[1], clip[2], kSize, kSize,
                                              [&](uint32_t x, uint32_t y, float, float) {
                                                  covered |= x == want_x && y == want_y;
                                                  return covered;
                                              });
        ++checked;
        ASSERT_TRUE(covered) << "round " << round;
    }
    EXPECT_GT(checked, 15000);
}

} // namespace
} // namespace vissort
