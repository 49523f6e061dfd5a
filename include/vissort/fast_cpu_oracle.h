#pragma once
// A faster CPU depth rasterizer as an occlusion oracle. It gives the same answers as CpuOracle
// (cpu_oracle.h), and leaves the same depth buffer, bit for bit: the same clipping, snapping,
// int64_t edge functions with the top-left rule, and the same double depth expression rounded to
// float (rules 1-7 of cpu_oracle.h). What differs is only how much work it takes:
//  - every triangle is clipped, snapped and set up once per bind, not once per draw or query;
//  - the depth buffer is divided into 8 x 8 pixel tiles, each with bounds on its stored depths,
//    so that whole tiles are skipped (a query that cannot find a fragment behind, a draw that
//    cannot pass the depth test) or accepted (a query that must find one) without per-pixel work;
//  - tiles outside an edge are skipped, and tiles inside all three edges are walked without
//    edge tests, decided exactly from the edge functions at the tile's corner pixels;
//  - clears are lazy, per tile (a pass clears once but often touches few tiles);
//  - queries stop at the first fragment behind; draws and queries allocate nothing.

#include <cstdint>
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

class FastCpuOracle final : public GeometryOracle {
public:
    /// Side of a depth tile in pixels; tiles are stored row-major, the last row and column may
    /// be partial.
    static constexpr uint32_t kTileSize = 8;

    FastCpuOracle() = default;

    /// See GeometryOracle::bind. Sets up every triangle (clip, snap, edges, depth plane) once.
    /// The view's width and height must be in [1, 65536]; every range must lie within positions.
    void bind(const TrianglePositions& positions, const ViewProjection& view,
              std::span<const PrimitiveRange> primitives) override;

    uint32_t primitiveCount() const override { return uint32_t(primitives_.size()); }
    void clear() override;
    /// Depth test LESS, writes on. primitive must be < primitiveCount().
    void draw(uint32_t primitive) override;
    /// True when a fragment lies behind the stored depth by more than kDepthTolerance.
    /// primitive must be < primitiveCount(). Leaves the buffer unchanged.
    bool anyBehind(uint32_t primitive) override;

    /// The depth buffer: width() * height() floats, row-major from the top row; equal bit for bit
    /// to CpuOracle's after the same clears and draws. (Clears are lazy, per tile: this writes
    /// out the tiles still waiting for one.)
    std::span<const float> depthBuffer() const;
    uint32_t width() const { return width_; }
    uint32_t height() const { return height_; }
    /// Fan triangles set up by the last bind (clipping may split or drop triangles).
    std::size_t setupCount() const { return setups_.size(); }

    const FastCpuOracleStats& stats() const { return stats_; }
    void resetStats() { stats_ = {}; }

private:
    /// One fan triangle, ready to walk. Edge functions are exact int64_t values in 24.8 fixed
    /// point (cpu_rasterizer.h); covered iff edge + bias > 0 for all three edges.
    struct Setup {
        int64_t edge_at_origin[3];  // E_i + bias_i at the centre of pixel (0, 0)
        int64_t edge_step_x[3];     // change of E_i from pixel px to px + 1
        int64_t edge_step_y[3];     // change of E_i from row py to py + 1
        double x0, y0, d0, ddx, ddy;  // depth plane, as in detail::TriangleSetup
        int32_t px_min, px_max, py_min, py_max;  // inclusive, clamped to the viewport
    };

    template <bool kDraw>
    bool rasterize(const Setup& s);
    /// Writes out the pending clear of one tile: its pixels +infinity, bounds +infinity.
    void clearTile(std::size_t tile) const;

    uint32_t width_ = 0, height_ = 0;
    uint32_t tiles_x_ = 0, tiles_y_ = 0;
    std::vector<PrimitiveRange> primitives_;
    std::vector<uint32_t> first_setup_;  // per triangle, plus one past the end: its fan triangles
    std::vector<Setup> setups_;
    // Clearing is lazy: clear() starts a new epoch, and a tile whose tile_epoch_ is older holds
    // only +infinity, whatever its pixels say, until clearTile writes that out (on its first draw,
    // or in depthBuffer(), which is why these are mutable: the logical contents never change).
    mutable std::vector<float> depth_;
    // Per tile: tile_min_ is the least stored depth (exact); tile_max_ is an upper bound on every
    // stored depth (exact after clear and after a draw that covers the whole tile, otherwise left
    // as it was: stored depths only decrease, so it stays an upper bound).
    mutable std::vector<float> tile_min_, tile_max_;
    mutable std::vector<uint64_t> tile_epoch_;
    uint64_t epoch_ = 1;
    FastCpuOracleStats stats_;
};

} // namespace vissort
