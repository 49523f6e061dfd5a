#pragma once
// The per-pixel walk of one depth tile for CpuOracle (cpu_oracle.h): edge tests, rule 6's
// depth expression and the depth test, a row of the tile at a time. Two implementations give the
// same bits: a portable scalar loop, and 8 lanes with AVX2 (fast_rows_avx2.cpp) that is only ever
// called where the CPU reports AVX2 (selectRowKernels).
//
// Number formats: edge functions are exact int64_t values in 24.8 fixed point (cpu_rasterizer.h),
// covered iff E + bias > 0 on all three edges; depths are the double expression
// ((d0 + ddx ((px + 0.5) - x0)) + ddy ((py + 0.5) - y0)) + offset, rounded to float to nearest.

#include <cstddef>
#include <cstdint>

namespace vissort::detail {

/// Depths are stored a tile at a time: a tile's rows of kTileRowFloats floats follow each other
/// (a tile at the viewport's right or bottom edge is padded to full size; its padding is never
/// walked, so it keeps whatever a clear wrote). Why: a tile then spans 4 cache lines of one page,
/// where a row-major buffer put each of its rows on a different page.
constexpr int32_t kTileRowFloats = 8;
/// Floats in one tile.
constexpr std::size_t kTileFloats = std::size_t(kTileRowFloats) * kTileRowFloats;

/// What every walk of one fan triangle shares, whichever pixels it covers.
struct TriangleWalk {
    bool narrow;       // every walked value of every edge fits in int32_t (decided at bind
                       // for the whole triangle; the AVX2 walks then test on 32 bits)
    int64_t step_x[3]; // change of E_e from column px to px + 1
    int64_t step_y[3]; // change of E_e from row py to py + 1
    double d0, ddx, ddy, x0, y0_plane; // the depth plane (TriangleSetup's d0, ddx, ddy, x0, y0)
    // Added to each fragment's double value before rounding: under the blending rule the snap
    // slack, moved as
    // exactFragmentOffset says (cpu_rasterizer.h, cpu_reference_oracle.h rule 7); -0.0 (nothing)
    // under the exact rule.
    double offset;
    // A query's thresholds: a fragment is behind when frag > stored + behind_above (float sum),
    // else undecided when frag > stored + undecided_above. The exact rule: +B and -B, B the
    // decision band (cpu_rasterizer.h); the blending rule: the depth tolerance and +infinity
    // (never undecided).
    float behind_above, undecided_above;
};

/// What a query's walk found.
enum class QueryResult : uint8_t {
    none,      // no fragment behind, none undecided
    behind,    // a fragment behind: the walk stopped there
    undecided, // no fragment behind, but some undecided (the caller arbitrates them)
};

/// The pixels of one tile that a fan triangle's bounding box overlaps. Lane k is column vx0 + k.
struct TileWalk : TriangleWalk {
    float* origin;      // depth of pixel (vx0, y0): the tile's first column, first row walked
    int32_t vx0, y0;    // column of lane 0; first row walked
    int32_t lane_first; // walked lanes [lane_first, lane_last], within the viewport
    int32_t lane_last;
    int32_t rows;     // rows walked, y0 .. y0 + rows - 1
    bool all_covered; // every walked pixel is inside all three edges: no edge tests
    int64_t edge[3];  // E_e + bias_e at pixel (vx0 + lane_first, y0)
};

/// What a draw did to its tile: the least depth it wrote (+infinity if none) and the greatest
/// stored depth it saw at a covered pixel after the test (-infinity if none).
struct TileDraw {
    float written_min, stored_max;
};

/// Draws the covered pixels with depth test LESS, writes on.
using DrawTileFn = void (*)(const TileWalk& walk, TileDraw& out);
/// Whether some covered pixel's fragment is behind, or else undecided (TriangleWalk).
using QueryTileFn = QueryResult (*)(const TileWalk& walk);
/// Draws the covered pixels when the caller has shown that every fragment passes LESS (all lie
/// before the tile's least stored depth): the same stores as DrawTileFn, without the depth test.
using FillTileFn = void (*)(const TileWalk& walk);

/// Tiles on a side of the largest triangle walked whole (SmallWalk): 3 x 3 tiles hold every
/// triangle whose pixel bounds are at most 17 pixels on a side.
constexpr int32_t kSmallTiles = 3;

/// A small triangle walked whole, row by row over its pixel bounds, in 8-pixel chunks aligned to
/// the tiles (chunk c of a row lies in tile column (px_min >> 3) + c): no per-tile set-up, which
/// costs more than the few pixels a small triangle has in each tile. The caller has cleared the
/// tiles it touches and decided which ones to walk.
struct SmallWalk : TriangleWalk {
    float* depth;           // the tile-major depth buffer
    std::size_t tiles_x;    // tiles per row of the buffer
    int32_t px_min, px_max; // pixels walked, inclusive, within kSmallTiles tile columns
    int32_t py_min, py_max; // rows walked, inclusive, within kSmallTiles tile rows
    bool live[kSmallTiles][kSmallTiles]; // [tile row][tile column], from the first: walk it
    int64_t edge[3]; // E_e + bias_e at pixel (px_min, py_min); covered iff all > 0
};

/// What a small draw did: the least depth it wrote in each tile (+infinity where none).
struct SmallDraw {
    float written_min[kSmallTiles][kSmallTiles];
};

/// Draws the covered pixels of the live tiles with depth test LESS, writes on.
using DrawSmallFn = void (*)(const SmallWalk& walk, SmallDraw& out);
/// Whether some covered pixel of a live tile is behind, or else undecided (TriangleWalk).
using QuerySmallFn = QueryResult (*)(const SmallWalk& walk);

struct RowKernels {
    DrawTileFn draw;
    QueryTileFn query;
    FillTileFn fill;
    // The AVX2 small walks need SmallWalk::narrow; the scalar ones take any walk.
    DrawSmallFn draw_small;
    QuerySmallFn query_small;
};

/// The portable loops.
RowKernels scalarRowKernels();
/// AVX2 loops when allowed and the CPU has AVX2 (checked once per process), else the scalar ones.
RowKernels selectRowKernels(bool allow_simd, bool& uses_simd);

/// The AVX2 loops (fast_rows_avx2.cpp): only to be called on a CPU with AVX2. Null where the
/// compiler or the target cannot build them.
DrawTileFn avx2DrawTile();
QueryTileFn avx2QueryTile();
FillTileFn avx2FillTile();
DrawSmallFn avx2DrawSmall();
QuerySmallFn avx2QuerySmall();

} // namespace vissort::detail
