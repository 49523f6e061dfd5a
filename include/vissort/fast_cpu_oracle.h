#pragma once
// A faster CPU depth rasterizer as an occlusion oracle. It gives the same answers as CpuOracle
// (cpu_oracle.h), and leaves the same depth buffer, bit for bit: the same clipping, snapping,
// int64_t edge functions with the top-left rule, and the same double depth expression rounded to
// float (rules 1-7 of cpu_oracle.h). What differs is only how much work it takes:
//  - every triangle is clipped, snapped and set up once per bind, not once per draw or query,
//    four at a time with AVX2 where the CPU has it (the scalar set-up finishes the rest);
//  - the depth buffer is divided into 8 x 8 pixel tiles, each with bounds on its stored depths,
//    so that whole tiles are skipped (a query that cannot find a fragment behind, a draw that
//    cannot pass the depth test) or accepted (a query that must find one) without per-pixel work;
//  - tiles outside an edge are skipped, and tiles inside all three edges are walked without
//    edge tests, decided exactly from the edge functions at the tile's corner pixels;
//  - clears are lazy, per tile (a pass clears once but often touches few tiles);
//  - queries stop at the first fragment behind; draws and queries allocate nothing;
//  - the pixels of a tile are walked a row at a time, 8 lanes wide with AVX2 where the CPU has it
//    (chosen once at run time; the scalar loop is the portable fallback, same bits);
//  - a small triangle (pixel bounds within 3 x 3 tiles: most triangles of a detailed mesh) is
//    walked whole, row by row in tile-aligned chunks of 8 pixels, its tiles cleared and culled
//    before and their bounds updated after, without the per-tile set-up that costs more than
//    the few pixels it has in each tile;
//  - backToFrontPass and queryAgainst can split the tile rows into screen bands (one per thread,
//    claimed in turn): each band runs the whole sequence on its own tiles, and the answers are
//    OR-ed across bands. Off by default (FastCpuOracleOptions::threads).
// Conservative mode (FastCpuOracleOptions::mode, for collision culling) matches
// CpuOracle(RasterMode::conservative) the same way: each edge's bias grows to its rise over half a
// pixel and the snapping margin, the pixel range to every square the grown snapped box touches,
// and each fragment moves by the set-up's depth spread over the pixel (nearer for draws, farther
// for queries) before it is rounded; the tile shortcuts then hold unchanged.

#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "vissort/geometry_oracle.h"

namespace vissort {

/// What the oracle did since bind (or resetStats), for benchmarks and tests.
struct FastCpuOracleStats {
    uint64_t draws = 0;            // draw calls
    uint64_t queries = 0;          // anyBehind calls
    uint64_t tiles_visited = 0;    // tiles of fan triangles' bounding boxes looked at
    uint64_t tiles_culled = 0;     // ... decided without per-pixel work: outside an edge, or by
                                   // depth bounds (query: nothing behind; draw: nothing passes)
    uint64_t tiles_accepted = 0;   // query tiles answered "behind" without per-pixel work
};

/// How FastCpuOracle may use the machine. The answers and the depth buffer never depend on it.
struct FastCpuOracleOptions {
    /// Exact or conservative sampling, with CpuOracle's rules for each (cpu_oracle.h): the same
    /// answers and depth buffer as CpuOracle(mode).
    RasterMode mode = RasterMode::exact;
    /// Walk rows 8 pixels at a time with AVX2 when the CPU supports it (checked once). The
    /// environment variable VISSORT_SIMD=0 also turns it off (for benchmarks of the fallback).
    bool allow_simd = true;
    /// Threads for the pass-level batches (backToFrontPass, queryAgainst), the calling thread
    /// included; 1 = all work on the calling thread. 0 (the default) = the environment variable
    /// VISSORT_THREADS if set (VISSORT_THREADS=0: std::thread::hardware_concurrency()), else 1.
    /// Why not every core by default: on the 2-core reference machine a banded pass 1 alone runs
    /// 1.7x faster, but triangle-level Vis-sort of the bunnies got slower per frame (the set-ups
    /// and tiles a worker touched migrate back to the calling thread's core for the next bind,
    /// pass 2 and the group tests). The workers start on the first parallel pass and live as long
    /// as the oracle.
    uint32_t threads = 0;
    /// Passes with fewer primitives than this stay on the calling thread: waking the workers
    /// costs more than a small pass (tests set 0 to exercise the bands on small inputs).
    uint32_t parallel_threshold = 1024;
};

namespace detail {
class FastWorkerPool;
struct TileWalk;
struct TileDraw;
struct SmallWalk;
struct SmallDraw;
struct FastSetup;
enum class LaneSetup : uint8_t;
} // namespace detail

class FastCpuOracle final : public GeometryOracle {
public:
    /// Side of a depth tile in pixels; tiles are stored row-major, the last row and column may
    /// be partial.
    static constexpr uint32_t kTileSize = 8;
    using Options = FastCpuOracleOptions;

    FastCpuOracle();
    explicit FastCpuOracle(const Options& options);
    ~FastCpuOracle() override;
    FastCpuOracle(const FastCpuOracle&) = delete;
    FastCpuOracle& operator=(const FastCpuOracle&) = delete;

    /// See GeometryOracle::bind. Sets up every triangle (clip, snap, edges, depth plane) once.
    /// The view's width and height must be in [1, 65536]; every range must lie within positions.
    void bind(PositionsView positions, const ViewProjection& view,
              std::span<const PrimitiveRange> primitives) override;

    uint32_t primitiveCount() const override { return uint32_t(primitives_.size()); }
    void clear() override;
    /// Depth test LESS, writes on. primitive must be < primitiveCount().
    void draw(uint32_t primitive) override;
    /// True when a fragment lies behind the stored depth by more than depthTolerance().
    /// primitive must be < primitiveCount(). Leaves the buffer unchanged.
    bool anyBehind(uint32_t primitive) override;

    /// Vis-sort's pass 1 (occlusion_oracle.h), split into screen bands over the threads; the same
    /// answers and depth buffer as the sequential definition.
    void backToFrontPass(std::span<const uint32_t> sequence, std::span<const uint8_t> query,
                         std::span<uint8_t> behind) override;
    /// The group test (occlusion_oracle.h), split into screen bands over the threads; the same
    /// answers and depth buffer as the sequential definition.
    void queryAgainst(std::span<const uint32_t> occluders, std::span<const uint32_t> targets,
                      std::span<uint8_t> behind) override;

    /// True when rows are walked with AVX2 (allowed, and the CPU has it).
    bool usesSimd() const { return use_simd_; }
    /// Threads the pass-level batches use (at least 1).
    uint32_t threadCount() const { return threads_; }

    /// The depth buffer: width() * height() floats, row-major from the top row; equal bit for bit
    /// to CpuOracle's after the same clears and draws. (Clears are lazy, per tile: this writes
    /// out the tiles still waiting for one.)
    std::span<const float> depthBuffer() const;
    uint32_t width() const { return width_; }
    uint32_t height() const { return height_; }
    /// Fan triangles set up by the last bind (clipping may split or drop triangles).
    std::size_t setupCount() const;

    const FastCpuOracleStats& stats() const { return stats_; }
    void resetStats() { stats_ = {}; }

private:
    /// Walks the tiles of s in tile rows [ty_begin, ty_end); counts into stats.
    template <bool kDraw>
    bool rasterize(const detail::FastSetup& s, int32_t ty_begin, int32_t ty_end,
                   FastCpuOracleStats& stats);
    /// rasterize for a triangle whose pixel bounds span at most detail::kSmallTiles tiles each
    /// way (most triangles of a detailed mesh): one walk over its bounds (fast_rows.h), the tiles
    /// cleared and culled beforehand, their bounds updated after, none of the per-tile set-up that
    /// costs more than the few pixels a small triangle has in each tile. Rows of tile rows
    /// [ty_first, ty_last] only.
    template <bool kDraw>
    bool rasterizeSmall(const detail::FastSetup& s, int32_t ty_first, int32_t ty_last,
                        FastCpuOracleStats& stats);
    /// Runs band(b, stats of b) for b = 0..bands-1 on the calling thread and the workers (each
    /// claims the next band when done); then adds the bands' tile counts to stats_.
    template <class Band>
    void runBands(uint32_t bands, Band&& band);
    /// Bands for a pass over count primitives: 1 when small or single-threaded, else a few per
    /// thread, at most one per tile row.
    uint32_t bandsFor(std::size_t count) const;
    /// Tile rows of band b of bands: [first, last).
    void bandRows(uint32_t b, uint32_t bands, int32_t& first, int32_t& last) const;
    /// The depths of one tile, kTileSize rows of kTileSize floats (fast_rows.h).
    float* tileDepths(std::size_t tile) const { return depth_.data() + tile * kTileSize * kTileSize; }
    /// Where pixel (x, y) is stored.
    float* pixel(uint32_t x, uint32_t y) const {
        return tileDepths(std::size_t(y / kTileSize) * tiles_x_ + x / kTileSize) +
               (y % kTileSize) * kTileSize + x % kTileSize;
    }
    /// Writes out the pending clear of one tile: its pixels +infinity, bounds +infinity.
    void clearTile(std::size_t tile) const;

    uint32_t width_ = 0, height_ = 0;
    uint32_t tiles_x_ = 0, tiles_y_ = 0;
    std::vector<PrimitiveRange> primitives_;
    // Primitive p's fan triangles are setups_[primitive_setups_[p], primitive_setups_[p + 1]).
    std::vector<uint32_t> primitive_setups_;
    std::vector<detail::FastSetup> setups_;
    std::vector<uint32_t> bind_triangles_;  // the triangles of every primitive, in bind order
    // Per tile, in one struct so that a tile's bounds and epoch share a cache line (the tiles a
    // pass touches are scattered over a buffer larger than the caches: one miss, not three).
    // Clearing is lazy: clear() starts a new epoch, and a tile whose epoch is older holds only
    // +infinity, whatever its pixels say, until clearTile writes that out (on its first draw, or
    // in depthBuffer(), which is why the states are mutable: the logical contents never change).
    // min is a lower bound on every stored depth (exact after a depth-tested draw; after a draw
    // whose fragments all pass, its depth bounds' lower end rounded to float); max is an upper
    // bound on every stored depth (exact after clear and after a depth-tested draw that covers
    // the whole tile, the upper end rounded after a passing draw that covers it, otherwise left
    // as it was: stored depths only decrease).
    struct TileState {
        float min, max;
        uint64_t epoch;
    };
    mutable std::vector<float> depth_;      // tile by tile (fast_rows.h), padded to whole tiles
    mutable std::vector<float> row_major_;  // depthBuffer()'s copy
    mutable std::vector<TileState> tiles_;
    uint64_t epoch_ = 1;
    FastCpuOracleStats stats_;

    bool conservative_ = false;
    bool use_simd_ = false;
    // The pixel walks (src/raster/fast_rows.h): AVX2 or scalar, chosen at construction.
    void (*draw_tile_)(const detail::TileWalk&, detail::TileDraw&) = nullptr;
    bool (*query_tile_)(const detail::TileWalk&) = nullptr;
    void (*fill_tile_)(const detail::TileWalk&) = nullptr;
    void (*draw_small_)(const detail::SmallWalk&, detail::SmallDraw&) = nullptr;
    bool (*query_small_)(const detail::SmallWalk&) = nullptr;
    // The batch set-up (src/raster/fast_setup.h): AVX2, or null for the scalar one only.
    void (*setup_quad_)(const std::array<double, 16>&, const float*, const float*, const float*,
                        const uint32_t*, uint32_t, uint32_t, detail::FastSetup*,
                        detail::LaneSetup*) = nullptr;
    uint32_t threads_ = 1;
    uint32_t parallel_threshold_ = 0;
    std::unique_ptr<detail::FastWorkerPool> pool_;  // started on the first parallel pass
    std::vector<FastCpuOracleStats> band_stats_;    // one per band, reused
};

} // namespace vissort
