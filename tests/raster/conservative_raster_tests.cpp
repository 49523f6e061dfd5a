// Conservative rasterization (RasterMode::conservative) may only add "behind" answers: on every
// sequence of draws and queries, each answer the exact mode gives as "behind" is "behind" in
// conservative mode too. Checked against the exact-mode CpuOracle run on the same operations.
#include <random>

#include <gtest/gtest.h>

#include "vissort/cpu_oracle.h"
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

Counts compareModes(const TrianglePositions& positions, const ViewProjection& view,
                    uint32_t seed) {
    std::vector<PrimitiveRange> primitives;
    for (uint32_t t = 0; t < positions.triangleCount(); ++t) primitives.push_back({t, 1});
    CpuOracle exact(RasterMode::exact), conservative(RasterMode::conservative);
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
    CpuOracle exact(RasterMode::exact), conservative(RasterMode::conservative);
    for (CpuOracle* o : {&exact, &conservative}) {
        o->bind(p, view, primitives);
        o->draw(0);
    }
    EXPECT_FALSE(exact.anyBehind(1));
    EXPECT_TRUE(conservative.anyBehind(1));
}

} // namespace
} // namespace vissort
