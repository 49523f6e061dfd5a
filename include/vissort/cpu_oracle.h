#pragma once
// A faster CPU depth rasterizer as an occlusion oracle. It gives the same answers as
// CpuReferenceOracle (cpu_reference_oracle.h), and leaves the same depth buffer, bit for bit: the
// same clipping, snapping, int64_t edge functions with the exact rule's margin (or the top-left
// rule under the blending rule), the same band pixels decided by the exact model, and the same
// double depth expression rounded to float (rules 1-7 of cpu_reference_oracle.h). Under the exact
// rule its "undecided" fragments go to the exact model, which finds the triangles drawn at that
// pixel through a per-tile index of the set-ups (built on first need, per bind) and each
// primitive's drawing time. What differs from the reference is only how much work it takes:
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
//  - a primitive of many triangles (CpuOracleOptions::image_min_triangles: an object) is
//    rasterized once per bind into a depth image of its nearest fragments and once into one of
//    its farthest (src/raster/depth_images.h), each on first use: every later draw is a
//    pixelwise minimum with the first over the tiles it covers, every query a comparison of the
//    second with the stored depths, skipped per tile by the same bounds;
//  - backToFrontPass and queryAgainst can split the tile rows into screen bands (one per thread,
//    claimed in turn) on a WorkerPool (worker_pool.h): each band runs the whole sequence on its
//    own tiles, and the answers are OR-ed across bands. Off by default
//    (CpuOracleOptions::threads).
//
// Layer: vissort::raster (the package's `order` component; docs/architecture.md).

#include <cstdint>
#include <memory>
#include <span>

#include "vissort/geometry_oracle.h"

namespace vissort {

class WorkerPool; // worker_pool.h

/// What the oracle did since bind (or resetStats), for benchmarks and tests.
struct CpuOracleStats {
    uint64_t draws = 0;          // draw calls
    uint64_t queries = 0;        // anyBehind calls
    uint64_t tiles_visited = 0;  // tiles of fan triangles' bounding boxes looked at
    uint64_t tiles_culled = 0;   // ... decided without per-pixel work: outside an edge, or by
                                 // depth bounds (query: nothing behind; draw: nothing passes)
    uint64_t tiles_accepted = 0; // query tiles answered "behind" without per-pixel work
    uint64_t images_built = 0;   // depth images made (CpuOracleOptions::image_min_triangles)
    uint64_t band_pixels = 0;    // the exact rule's band pixels the last bind decided (all binds)
    uint64_t arbitrations = 0;   // (fragment, pixel) pairs the exact model decided in queries
};

/// How CpuOracle may use the machine. The answers and the depth buffer never depend on it.
struct CpuOracleOptions {
    /// Walk rows 8 pixels at a time with AVX2 when the CPU supports it (checked once); false
    /// forces the scalar fallback (for benchmarks of it).
    bool allow_simd = true;
    /// Threads for the pass-level batches (backToFrontPass, queryAgainst), the calling thread
    /// included, clamped to [1, 256]: 1 (the default) = all work on the calling thread;
    /// 0 = std::thread::hardware_concurrency(). Ignored when pool is given (its threads are used).
    /// Why not every core by default: on the 2-core reference machine a banded pass 1 alone runs
    /// 1.7x faster, but triangle-level Vis-sort of the bunnies got slower per frame (the set-ups
    /// and tiles a worker touched migrate back to the calling thread's core for the next bind,
    /// pass 2 and the group tests).
    uint32_t threads = 1;
    /// Passes with fewer primitives than this stay on the calling thread: waking the workers
    /// costs more than a small pass (tests set 0 to exercise the bands on small inputs).
    uint32_t parallel_threshold = 1024;
    /// The workers for the bands; must outlive the oracle. Null = WorkerPool::shared(), grown to
    /// threads on the first parallel pass (one pool per process, however many oracles).
    WorkerPool* pool = nullptr;
    /// A primitive of at least this many triangles (after clipping) is rasterized once per bind
    /// into a depth image of its nearest fragments, on its first draw, and once into one of its
    /// farthest, on its first query; its draws and queries then compare its image with the
    /// stored depths, tile by tile, with the same answers and depths (src/raster/depth_images.h
    /// says why). 0: never. Measured on builtin:bunnies at object level (3,674 triangles an
    /// object, about 4 draws and 4 queries each a frame): docs/benchmarks.md.
    uint32_t image_min_triangles = 32;
    /// The images' memory at most (each covered 8 x 8 tile takes 264 bytes); a primitive whose
    /// image would pass it is drawn and queried triangle by triangle.
    std::size_t image_budget_bytes = std::size_t(256) << 20;
};

class CpuOracle final : public GeometryOracle {
public:
    /// Side of a depth tile in pixels; tiles are stored row-major, the last row and column may
    /// be partial.
    static constexpr uint32_t kTileSize = 8;
    using Options = CpuOracleOptions;

    CpuOracle();
    explicit CpuOracle(const Options& options);
    ~CpuOracle() override;
    CpuOracle(const CpuOracle&) = delete;
    CpuOracle& operator=(const CpuOracle&) = delete;

    /// See GeometryOracle::bind. Sets up every triangle (clip, snap, edges, depth plane) once.
    /// The view's width and height must be in [1, 65536]; every range must lie within positions.
    void bind(PositionsView positions, const ViewProjection& view,
              std::span<const PrimitiveRange> primitives) override;
    /// See GeometryOracle::rebind. Copies each triangle's set-ups from the last bind when it
    /// made them all (same positions arrays, triangle count, view and size), else binds. Binds
    /// after the first rebind keep where each triangle's set-ups are (8 bytes a triangle of
    /// positions) and their set-ups while groups are rebound (about 130 bytes a set-up).
    void rebind(PositionsView positions, const ViewProjection& view,
                std::span<const PrimitiveRange> primitives) override;

    uint32_t primitiveCount() const override;
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
    /// answers as the sequential definition. Occluders are drawn only over the tiles of the
    /// targets' pixel bounds (a cycle search tests a few targets against much of the list), so
    /// the depth buffer equals the definition's only there.
    void queryAgainst(std::span<const uint32_t> occluders, std::span<const uint32_t> targets,
                      std::span<uint8_t> behind) override;

    /// The occlusion graph of members in one pass (occlusion_oracle.h), under the exact rule
    /// only: each member's fragments listed per pixel and ordered there by the exact model,
    /// consecutive depths giving the edges. False under another depth tolerance.
    bool occlusionGraph(std::span<const uint32_t> members, std::vector<Occlusion>& edges) override;

    /// True when rows are walked with AVX2 (allowed, and the CPU has it).
    bool usesSimd() const;
    /// Threads the pass-level batches use (at least 1).
    uint32_t threadCount() const;

    /// The depth buffer: width() * height() floats, row-major from the top row; equal bit for bit
    /// to CpuReferenceOracle's after the same clears, draws and passes (after queryAgainst: within
    /// the targets' pixel bounds). (Clears are lazy, per tile: this writes out the tiles still
    /// waiting for one.)
    std::span<const float> depthBuffer() const;
    uint32_t width() const;
    uint32_t height() const;

    const CpuOracleStats& stats() const;
    void resetStats();

private:
    struct Impl; // src/raster/cpu_oracle_impl.h
    std::unique_ptr<Impl> impl_;
};

} // namespace vissort
