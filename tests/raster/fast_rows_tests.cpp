// The AVX2 tile walks against the portable ones (fast_rows.h), kernel by kernel, on random walks:
// edge values small enough for the 32-bit lanes, right at the int32_t limit, and far beyond it
// (the 64-bit lanes), partial and whole rows, both fill-rule outcomes. The portable loops are
// themselves checked against the reference rasterizer in cpu_oracle_tests.cpp.

#include "raster/fast_rows.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "vissort/geometry_oracle.h"

namespace vissort::detail {
namespace {

// A negative tolerance, as the transparency renderer sets (kBlendingDepthTolerance): near ties
// count as occlusion.
constexpr float kNegativeTolerance = -1.0f / (1 << 16);

using TileDepths = std::array<float, kTileRowFloats * kTileRowFloats>;

enum class EdgeScale { small, at_int32_limit, huge };

struct RandomWalk {
    TileWalk walk;
    TileDepths depths;
};

// A depth plane through a point near pixel (x, y), exact mode's -0.0 offset or a conservative
// spread either way (+0.0 included: it is not -0.0), and the thresholds of the exact rule (a
// band both ways, some fragments undecided) or of the blending tolerance (never undecided).
void randomPlane(std::mt19937_64& rng, int32_t x, int32_t y, TriangleWalk& w) {
    std::uniform_real_distribution<double> unit(0, 1);
    w.d0 = 0.2 + 0.6 * unit(rng);
    w.ddx = (unit(rng) - 0.5) * 0.02;
    w.ddy = (unit(rng) - 0.5) * 0.02;
    w.x0 = x + 8 * unit(rng);
    w.y0_plane = y + 8 * unit(rng);
    const double offsets[] = {-0.0, 0.0, (unit(rng) - 0.5) * 0.01};
    w.offset = offsets[std::uniform_int_distribution<int>(0, 2)(rng)];
    if (unit(rng) < 0.5) {
        const float band = float(unit(rng) * 0.02);
        w.behind_above = band;
        w.undecided_above = -band;
    } else {
        w.behind_above = kNegativeTolerance;
        w.undecided_above = std::numeric_limits<float>::infinity();
    }
}

RandomWalk makeWalk(std::mt19937_64& rng, EdgeScale scale) {
    std::uniform_real_distribution<double> unit(0, 1);
    const auto between = [&](int64_t lo, int64_t hi) {
        return std::uniform_int_distribution<int64_t>(lo, hi)(rng);
    };
    RandomWalk r{};
    for (float& d : r.depths)
        d = unit(rng) < 0.2 ? std::numeric_limits<float>::infinity() : float(0.3 + 0.4 * unit(rng));
    TileWalk& w = r.walk;
    w.origin = nullptr; // set by the caller to its copy of the depths
    w.vx0 = int32_t(8 * between(0, 200));
    w.y0 = int32_t(between(0, 1600));
    w.lane_first = int32_t(between(0, 7));
    w.lane_last = int32_t(between(w.lane_first, 7));
    w.rows = int32_t(between(1, 8));
    w.all_covered = unit(rng) < 0.1;
    for (int e = 0; e < 3; ++e) {
        switch (scale) {
        case EdgeScale::small:
            w.step_x[e] = between(-(1 << 20), 1 << 20);
            w.step_y[e] = between(-(1 << 20), 1 << 20);
            w.edge[e] = between(-(1 << 23), 1 << 23);
            break;
        case EdgeScale::at_int32_limit: {
            w.step_x[e] = between(-(1 << 24), 1 << 24);
            w.step_y[e] = between(-(1 << 24), 1 << 24);
            const int64_t reach = int64_t(w.lane_last - w.lane_first) * std::abs(w.step_x[e]) +
                                  int64_t(w.rows - 1) * std::abs(w.step_y[e]);
            const int64_t sign = between(0, 1) ? 1 : -1;
            w.edge[e] = sign * (int64_t(INT32_MAX) - reach + between(-2, 2));
            break;
        }
        case EdgeScale::huge:
            w.step_x[e] = between(-(int64_t(1) << 38), int64_t(1) << 38);
            w.step_y[e] = between(-(int64_t(1) << 38), int64_t(1) << 38);
            w.edge[e] = between(-(int64_t(1) << 42), int64_t(1) << 42);
            break;
        }
    }
    randomPlane(rng, w.vx0, w.y0, w);
    // The caller's promise that every walked edge value fits in int32_t, made where it holds (the
    // 64-bit lanes must give the same results where it is not made).
    bool fits = true;
    for (int e = 0; e < 3; ++e)
        fits &= std::abs(w.edge[e]) + int64_t(w.lane_last - w.lane_first) * std::abs(w.step_x[e]) +
                    int64_t(w.rows - 1) * std::abs(w.step_y[e]) <=
                INT32_MAX;
    w.narrow = fits && unit(rng) < 0.8;
    return r;
}

bool sameBits(const TileDepths& a, const TileDepths& b) {
    return std::memcmp(a.data(), b.data(), sizeof(float) * a.size()) == 0;
}

TEST(FastRows, Avx2WalksMatchThePortableOnes) {
    bool uses_simd = false;
    const RowKernels simd = selectRowKernels(true, uses_simd);
    if (!uses_simd)
        GTEST_SKIP() << "this CPU has no AVX2: only the portable walks run here";
    const RowKernels scalar = scalarRowKernels();
    std::mt19937_64 rng(41);
    for (EdgeScale scale : {EdgeScale::small, EdgeScale::at_int32_limit, EdgeScale::huge}) {
        std::size_t queries_behind = 0, queries_undecided = 0, pixels_written = 0;
        for (int i = 0; i < 20000; ++i) {
            SCOPED_TRACE("scale " + std::to_string(int(scale)) + ", walk " + std::to_string(i));
            RandomWalk r = makeWalk(rng, scale);
            const int32_t first_row = kTileRowFloats - r.walk.rows; // the walk's rows of the tile
            TileDepths a = r.depths, b = r.depths;
            TileWalk wa = r.walk, wb = r.walk;
            wa.origin = a.data() + first_row * kTileRowFloats;
            wb.origin = b.data() + first_row * kTileRowFloats;

            const QueryResult result = scalar.query(wa);
            ASSERT_EQ(simd.query(wb), result);
            queries_behind += result == QueryResult::behind;
            queries_undecided += result == QueryResult::undecided;

            TileDraw da{}, db{};
            scalar.draw(wa, da);
            simd.draw(wb, db);
            ASSERT_TRUE(sameBits(a, b));
            ASSERT_EQ(da.written_min, db.written_min);
            ASSERT_EQ(da.stored_max, db.stored_max);
            for (std::size_t k = 0; k < a.size(); ++k)
                pixels_written += a[k] != r.depths[k];

            a = r.depths;
            b = r.depths;
            scalar.fill(wa);
            simd.fill(wb);
            ASSERT_TRUE(sameBits(a, b));
        }
        // Both answers and real writes were exercised at every scale.
        EXPECT_GT(queries_behind, 100u);
        EXPECT_GT(queries_undecided, 20u);
        EXPECT_GT(pixels_written, 1000u);
    }
}

// A small walk over a 5 x 4 tile buffer: bounds within kSmallTiles tiles each way, random live
// tiles, edge functions whose walked values fit in int32_t (the AVX2 walk's condition).
struct RandomSmallWalk {
    static constexpr std::size_t kTilesX = 5, kTilesY = 4;
    std::vector<float> depths;
    SmallWalk walk;
};

RandomSmallWalk makeSmallWalk(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> unit(0, 1);
    const auto between = [&](int64_t lo, int64_t hi) {
        return std::uniform_int_distribution<int64_t>(lo, hi)(rng);
    };
    RandomSmallWalk r;
    r.depths.resize(RandomSmallWalk::kTilesX * RandomSmallWalk::kTilesY * 64);
    for (float& d : r.depths)
        d = unit(rng) < 0.2 ? std::numeric_limits<float>::infinity() : float(0.3 + 0.4 * unit(rng));
    SmallWalk& w = r.walk;
    w.depth = nullptr; // set by the caller to its copy of the depths
    w.tiles_x = RandomSmallWalk::kTilesX;
    const int32_t tx = int32_t(between(0, 2)), ty = int32_t(between(0, 1));
    const int32_t tiles_wide = int32_t(between(1, kSmallTiles)),
                  tiles_high = int32_t(between(1, 3));
    w.px_min = int32_t(8 * tx + between(0, 7));
    w.px_max = int32_t(std::max<int64_t>(w.px_min, 8 * (tx + tiles_wide) - 1 - between(0, 7)));
    w.py_min = int32_t(8 * ty + between(0, 7));
    w.py_max = int32_t(std::max<int64_t>(w.py_min, 8 * (ty + tiles_high) - 1 - between(0, 7)));
    for (auto& row : w.live)
        for (bool& live : row)
            live = unit(rng) < 0.8;
    w.narrow = true;
    const int64_t span = int64_t(w.px_max - w.px_min) + (w.py_max - w.py_min);
    for (int e = 0; e < 3; ++e) {
        w.step_x[e] = between(-(1 << 20), 1 << 20);
        w.step_y[e] = between(-(1 << 20), 1 << 20);
        const int64_t reach = span * (1 << 20); // at most 24 * 2^20 < 2^25
        w.edge[e] =
            between(-(int64_t(INT32_MAX) - reach), int64_t(INT32_MAX) - reach) >> between(0, 8);
    }
    randomPlane(rng, w.px_min, w.py_min, w);
    return r;
}

TEST(FastRows, Avx2SmallWalksMatchThePortableOnes) {
    bool uses_simd = false;
    const RowKernels simd = selectRowKernels(true, uses_simd);
    if (!uses_simd)
        GTEST_SKIP() << "this CPU has no AVX2: only the portable walks run here";
    const RowKernels scalar = scalarRowKernels();
    std::mt19937_64 rng(43);
    std::size_t queries_behind = 0, queries_undecided = 0, pixels_written = 0;
    for (int i = 0; i < 20000; ++i) {
        SCOPED_TRACE("walk " + std::to_string(i));
        RandomSmallWalk r = makeSmallWalk(rng);
        std::vector<float> a = r.depths, b = r.depths;
        SmallWalk wa = r.walk, wb = r.walk;
        wa.depth = a.data();
        wb.depth = b.data();

        const QueryResult result = scalar.query_small(wa);
        ASSERT_EQ(simd.query_small(wb), result);
        queries_behind += result == QueryResult::behind;
        queries_undecided += result == QueryResult::undecided;

        SmallDraw da{}, db{};
        scalar.draw_small(wa, da);
        simd.draw_small(wb, db);
        ASSERT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(float)), 0);
        ASSERT_EQ(std::memcmp(&da, &db, sizeof(SmallDraw)), 0);
        for (std::size_t k = 0; k < a.size(); ++k)
            pixels_written += a[k] != r.depths[k];
    }
    // Both answers and real writes were exercised.
    EXPECT_GT(queries_behind, 1000u);
    EXPECT_GT(queries_undecided, 20u);
    EXPECT_GT(pixels_written, 10000u);
}

} // namespace
} // namespace vissort::detail
