#pragma once
// CpuOracle's insides (cpu_oracle.h), shared by the files that implement them, one concern each:
//   cpu_oracle.cpp               construction, the interface, draw and query of one primitive
//   cpu_oracle_bind.cpp          bind and rebind: the triangles' set-ups, kept for the groups
//   cpu_oracle_images.cpp        the depth images of objects, and draws and queries through them
//   cpu_oracle_tiles.cpp         the tile rasterizer: a set-up's walk over tiles and pixels
//   cpu_oracle_arbitration.cpp   the exact rule's undecided fragments, decided by the exact model
//   cpu_oracle_bands.cpp         the passes, split into screen bands on a worker pool
// Why every shortcut there is exact: the comment at the top of cpu_oracle.cpp. Internal to
// src/raster/.

#include "vissort/cpu_oracle.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>
#include <memory>
#include <mutex>
#include <span>
#include <thread>
#include <type_traits>
#include <unordered_map>
#include <vector>

#include "raster/cpu_rasterizer.h"
#include "raster/depth_arbiter.h"
#include "raster/depth_images.h"
#include "raster/fast_rows.h"
#include "raster/fast_setup.h"
#include "vissort/worker_pool.h"

namespace vissort::cpu_oracle_detail {

constexpr float kInfinity = std::numeric_limits<float>::infinity();
constexpr int kTileShift = 3; // kTileSize = 8
static_assert(CpuOracle::kTileSize == 1u << kTileShift);
static_assert(CpuOracle::kTileSize == detail::kTileRowFloats);
constexpr std::size_t kTilePixels = detail::kTileFloats;

// Relative bound on the rounding of the depth expression (about 8 ulps of the summed magnitudes,
// with a wide safety factor on the 4 roundings it takes).
constexpr double kDepthMargin = 0x1p-48;

// A set-up as the oracle keeps it from bind to bind and the walks read it: FastSetup's values in
// 128 bytes (two cache lines) instead of 176, since a large input keeps one per triangle. Pixel
// bounds lie in a viewport of at most 2^16 pixels a side; the narrow flag (a byte, not 8 of
// padding), the spread (the snap slack) and the exact rule's error
// bound are kept beside them, and the margins are derived from the steps where the blending rule
// needs them (marginsFromSteps). The edge steps stay int64_t: as int32_t quotients by
// kSubpixelScale (snapped coordinates are at most 2^29) the set-up would take fewer bytes, but
// widening them back in every draw and query cost 6% more instructions on builtin:bunnies at
// object level.
struct StoredSetup {
    int64_t edge_at_origin[3]; // with the exact rule's bias (-margin)
    int64_t edge_step_x[3], edge_step_y[3];
    double x0, y0, d0, ddx, ddy;
    uint16_t px_min, px_max, py_min, py_max;
    // The triangle of positions it is a fan triangle of (below 2^31), and in the top bit whether
    // its exact-rule error bound exceeds the common one (kCommonErrorCap: errors_ has it).
    uint32_t triangle_and_flag;
    uint32_t band_first; // the exact rule's band pixels: an entry of band_pixels_, 0 for none

    int64_t edgeStepX(int e) const { return edge_step_x[e]; }
    int64_t edgeStepY(int e) const { return edge_step_y[e]; }
    uint32_t triangle() const { return triangle_and_flag & ~kLargeError; }
    bool largeError() const { return (triangle_and_flag & kLargeError) != 0; }
    static constexpr uint32_t kLargeError = 1u << 31;
};
static_assert(sizeof(StoredSetup) == 128);
// The bytes that make a set-up's shape (all but the triangle and its band list's place): equal
// for the set-ups of two copies of a triangle.
constexpr std::size_t kSetupShapeBytes = offsetof(StoredSetup, triangle_and_flag);
static_assert(kSetupShapeBytes == 120);
static_assert(detail::kMaxViewportSize <= 65536);

// The exact rule's common error bound: almost every fragment's is the float rounding, 2^-24, and
// a few steep or sliver triangles' more; only those keep their own (StoredSetup::largeError) and
// write it into the tiles they draw, so that a draw need not touch every tile's state.
constexpr float kCommonErrorCap = 0x1p-22f;

// An error bound as a float no smaller than it (+infinity beyond float's range).
inline float roundedUp(double error) {
    return error < 1e30 ? float(error) * (1 + 0x1p-20f) : std::numeric_limits<float>::infinity();
}

inline StoredSetup storedSetup(const detail::FastSetup& s, uint32_t triangle, uint32_t band_first) {
    StoredSetup c;
    assert(triangle < StoredSetup::kLargeError);
    c.triangle_and_flag =
        triangle | (roundedUp(s.error) > kCommonErrorCap ? StoredSetup::kLargeError : 0);
    c.band_first = band_first;
    for (int e = 0; e < 3; ++e) {
        c.edge_at_origin[e] = s.edge_at_origin[e];
        c.edge_step_x[e] = s.edge_step_x[e];
        c.edge_step_y[e] = s.edge_step_y[e];
    }
    c.x0 = s.x0;
    c.y0 = s.y0;
    c.d0 = s.d0;
    c.ddx = s.ddx;
    c.ddy = s.ddy;
    c.px_min = uint16_t(s.px_min);
    c.px_max = uint16_t(s.px_max);
    c.py_min = uint16_t(s.py_min);
    c.py_max = uint16_t(s.py_max);
    return c;
}

// The exact rule's decision band as a float sum of floats (decisionBand of cpu_rasterizer.h, in
// float): the sum rounded, then widened by far more than that rounding.
inline float bandOf(float error, float stored_error) {
    return (error + stored_error) * (1 + 0x1p-20f) + 0x1p-22f;
}

// What a draw or a query adds to each fragment's double value before rounding (fast_rows.h):
// the slack as the reference moves it (detail::exactFragmentOffset).
template <bool kDraw> double fragmentOffset(double spread, float tolerance) {
    return detail::exactFragmentOffset(spread, kDraw, tolerance);
}

// What every walk of s shares (fast_rows.h), for a draw or a query.
template <bool kDraw>
detail::TriangleWalk triangleWalk(const StoredSetup& s, bool narrow, double spread,
                                  float tolerance) {
    detail::TriangleWalk walk;
    // The blending rule's threshold; the exact rule sets its own per tile (decisionBand).
    walk.behind_above = tolerance;
    walk.undecided_above = std::numeric_limits<float>::infinity();
    walk.narrow = narrow;
    for (int e = 0; e < 3; ++e) {
        walk.step_x[e] = s.edgeStepX(e);
        walk.step_y[e] = s.edgeStepY(e);
    }
    walk.d0 = s.d0;
    walk.ddx = s.ddx;
    walk.ddy = s.ddy;
    walk.x0 = s.x0;
    walk.y0_plane = s.y0;
    // The exact rule moves nothing (tolerance 0).
    walk.offset = tolerance == 0 ? -0.0 : fragmentOffset<kDraw>(spread, tolerance);
    return walk;
}

// s with its depth plane negated: the same coverage, and each fragment value v becomes -v
// exactly (every operation of rule 6 rounds to nearest, which is symmetric).
inline StoredSetup negatedPlane(const StoredSetup& s) {
    StoredSetup negated = s;
    negated.d0 = -s.d0;
    negated.ddx = -s.ddx;
    negated.ddy = -s.ddy;
    return negated;
}

// The plane's column and row terms of rule 6: ddx ((x + 0.5) - x0) and ddy ((y + 0.5) - y0).
inline double columnTerm(const StoredSetup& s, int32_t x) {
    return s.ddx * ((double(x) + 0.5) - s.x0);
}
inline double rowTerm(const StoredSetup& s, int32_t y) {
    return s.ddy * ((double(y) + 0.5) - s.y0);
}

// Bounds on the double depth value v of every fragment over a rectangle whose corner columns have
// terms ax0, ax1 and corner rows by0, by1 (see cpu_oracle.cpp's file comment), offset included (its
// rounding is within the margin, spread its size). Inlined: it runs once per tile a triangle
// visits, and a call with results through memory cost 7% of tile-culled queries.
[[gnu::always_inline]] inline void depthBounds(const StoredSetup& s, double ax0, double ax1,
                                               double by0, double by1, double offset, double spread,
                                               double& lowest, double& highest) {
    const double margin = kDepthMargin * (std::abs(s.d0) + std::max(std::abs(ax0), std::abs(ax1)) +
                                          std::max(std::abs(by0), std::abs(by1)) + spread);
    lowest = s.d0 + std::min(ax0, ax1) + std::min(by0, by1) + offset - margin;
    highest = s.d0 + std::max(ax0, ax1) + std::max(by0, by1) + offset + margin;
}

} // namespace vissort::cpu_oracle_detail

namespace vissort {

using namespace cpu_oracle_detail; // the helpers above, for Impl and its files

// Everything behind CpuOracle's interface. Its methods are the oracle's: each public method
// makes one call here, and the per-tile and per-pixel loops run without further indirection.
struct CpuOracle::Impl {
    explicit Impl(const Options& options);

    void bind(PositionsView positions, const ViewProjection& view,
              std::span<const PrimitiveRange> primitives);
    /// CpuOracle::rebind: the set-ups copied from the bind's where it made them all.
    void rebind(PositionsView positions, const ViewProjection& view,
                std::span<const PrimitiveRange> primitives);
    /// What bind and rebind do after the set-ups: the depth buffer sized and cleared, the
    /// primitives given images found.
    void finishBind();
    /// True when positions and view are those of the last bind (not checked: unchanged since).
    bool sameAsBound(PositionsView positions, const ViewProjection& view) const;
    void draw(uint32_t primitive);
    bool anyBehind(uint32_t primitive);

    /// OcclusionOracle::occlusionGraph, under the exact rule (cpu_oracle_graph.cpp); false
    /// under another rule, for a very large set, or where ties stack so high that the pairs to
    /// visit would pass a budget linear in the fragments.
    bool occlusionGraph(std::span<const uint32_t> members, std::vector<Occlusion>& edges);

    // Tiles of rows [row_first, row_last) and columns [column_first, column_last].
    struct TileRect {
        int32_t row_first, row_last, column_first, column_last;
    };

    // The exact rule (depth tolerance 0, exact mode): its undecided fragments, collected by a
    // query's walks and decided by the exact model once the walks found nothing behind.
    bool exactRule() const { return depth_tolerance_ == 0; }
    struct Undecided {
        enum class Kind : uint8_t {
            setup_tile,  // some fragment of set-up `what` in tile `where`
            setup_pixel, // set-up `what`'s band pixel `where` (py << 16 | px)
            image_tile,  // primitive `what`'s far image entry `where`
        };
        Kind kind;
        uint32_t what, where;
    };
    // What a query's walks share: its undecided fragments and its time (drawnBefore).
    struct QueryContext {
        std::vector<Undecided>* undecided;
        uint32_t time;
    };
    /// Whether some undecided fragment of context, within rect's rows, is behind by the exact
    /// model; clears the list.
    bool resolve(QueryContext& context, const TileRect& rect, CpuOracleStats& stats);
    /// Whether set-up query_setup's triangle's fragment at pixel (px, py) (its float
    /// `fragment`, within `error` of the exact depth) lies strictly behind a fragment of a
    /// primitive drawn there before `time`, by the exact model.
    bool behindSomethingDrawn(uint32_t query_setup, uint32_t px, uint32_t py, QueryContext& context,
                              float fragment, float error, CpuOracleStats& stats);
    /// Whether no fragment of set-up query_setup in tile `tile` can be behind, by pairs of
    /// triangles instead of pixels (issue 57's per-pair decisions): every set-up drawn before
    /// `time` whose bounds meet the query's pixels there is of its own triangle, certainly
    /// farther over those pixels by the floats, a copy of its triangle (a tie everywhere), or
    /// of a triangle the arbiter already found nearer at no shared pixel (touching, coplanar,
    /// one-sided: DepthArbiter::knownNeverNearer). The first tile of a pair is arbitrated
    /// pixel by pixel, which teaches the arbiter the pair; the pair's other tiles then cost a
    /// look-up each. False means: decide pixel by pixel.
    bool tileSettledByPairs(uint32_t query_setup, uint32_t tile, uint32_t time);
    /// The set-ups whose draws cover pixel (px, py) (certainly, or as a band pixel the exact
    /// model gave them), `count` of them: the pixel's list, its tile's made on first need after
    /// each (re)bind; thread-safe.
    const uint32_t* pixelList(uint32_t px, uint32_t py, uint32_t& count);
    /// A tile's pixel lists: kTilePixels + 1 starts into the same vector, then the set-ups.
    /// Under tile_index_mutex_ (its scratch: pixel_list_entries_ and pixel_list_sorted_).
    void makePixelLists(std::size_t tile, std::vector<uint32_t>& lists);
    /// The set-up's fragment value at a pixel (rule 6, no offset) and whether it certainly
    /// covers it (every edge function beyond the margin).
    float fragmentAt(const StoredSetup& s, uint32_t px, uint32_t py) const {
        return float((s.d0 + s.ddx * ((double(px) + 0.5) - s.x0)) +
                     s.ddy * ((double(py) + 0.5) - s.y0));
    }
    bool certainlyCovers(const StoredSetup& s, uint32_t px, uint32_t py) const {
        if (px < s.px_min || px > s.px_max || py < s.py_min || py > s.py_max)
            return false;
        for (int e = 0; e < 3; ++e)
            if (s.edge_at_origin[e] + int64_t(px) * s.edge_step_x[e] +
                    int64_t(py) * s.edge_step_y[e] <=
                0)
                return false;
        return true;
    }
    /// The pixels of row py that s certainly covers (certainlyCovers), [x_first, x_last]: false
    /// when none. Each edge function is affine along the row, so each bounds the row's run on
    /// one side, found by one division: a long thin triangle's row costs three divisions, not a
    /// test per pixel of its bounding box.
    bool certainRowSpan(const StoredSetup& s, uint32_t py, uint32_t& x_first,
                        uint32_t& x_last) const {
        if (py < s.py_min || py > s.py_max)
            return false;
        int64_t lo = s.px_min, hi = s.px_max;
        // floor(a / b) for b > 0.
        const auto floorDiv = [](int64_t a, int64_t b) {
            const int64_t q = a / b;
            return (a % b != 0 && a < 0) ? q - 1 : q;
        };
        for (int e = 0; e < 3 && lo <= hi; ++e) {
            // c + px * step > 0, c the edge at (0, py).
            const int64_t c = s.edge_at_origin[e] + int64_t(py) * s.edge_step_y[e];
            const int64_t step = s.edge_step_x[e];
            if (step == 0) {
                if (c <= 0)
                    return false;
            } else if (step > 0) {
                lo = std::max(lo, floorDiv(-c, step) + 1); // px > -c / step
            } else {
                hi = std::min(hi, floorDiv(c - 1, -step)); // px * -step < c, i.e. <= c - 1
            }
        }
        if (lo > hi)
            return false;
        assert(certainlyCovers(s, uint32_t(lo), py) && certainlyCovers(s, uint32_t(hi), py));
        assert(lo == s.px_min || !certainlyCovers(s, uint32_t(lo - 1), py));
        assert(hi == s.px_max || !certainlyCovers(s, uint32_t(hi + 1), py));
        x_first = uint32_t(lo);
        x_last = uint32_t(hi);
        return true;
    }
    /// The primitive whose set-ups hold set-up k.
    uint32_t primitiveOfSetup(uint32_t k) const {
        return uint32_t(std::upper_bound(primitive_setups_.begin(),
                                         primitive_setups_.begin() + primitive_count_ + 1, k) -
                        primitive_setups_.begin()) -
               1;
    }
    /// The index of set-ups by tiles (by their pixel bounds), made on first need after each
    /// (re)bind, and the pixel lists emptied; thread-safe.
    void ensureTileIndex();
    /// When primitive p was first drawn since the clear (drawnBefore): the clock of draws, which
    /// runs on across clears (a clear notes where it stood: clear_time_), at its first draw.
    void stamp(uint32_t p) {
        if (drawn_time_[p] < clear_time_) {
            reserveClock(1);
            drawn_time_[p] = clock_++;
        }
    }
    bool drawnBefore(uint32_t p, uint32_t time) const {
        return drawn_time_[p] >= clear_time_ && drawn_time_[p] < time;
    }
    /// Before `draws` more stamps: where the clock would pass 2^32 - 1, its stamps since the last
    /// clear move down to start at 1 and the older ones to 0 (after 4 billion draws).
    void reserveClock(std::size_t draws) {
        if (uint64_t(clock_) + draws < std::numeric_limits<uint32_t>::max())
            return;
        for (uint32_t& time : drawn_time_)
            time = time >= clear_time_ ? time - clear_time_ + 1 : 0;
        clock_ -= clear_time_ - 1;
        clear_time_ = 1;
    }
    /// The common bound of a (re)bind: the largest error bound of its set-ups, up to
    /// kCommonErrorCap; set-ups above it raise the tiles they draw into instead.
    void setGlobalError() {
        global_error_ = 0;
        for (float error : errors_)
            global_error_ = std::max(global_error_, std::min(error, kCommonErrorCap));
    }
    /// A new epoch of the buffer in use (a wrap of the 32-bit count resets every tile's).
    void newEpoch() {
        if (++epoch_ == 0) {
            for (TileState& tile : tiles_)
                tile.epoch = 0;
            epoch_ = 1;
        }
    }
    /// clear(): a new epoch, and no primitive drawn since.
    void clearBuffer() {
        newEpoch();
        clear_time_ = clock_;
    }
    /// The bind's band pixel lists (forEachFastBandPixel, then the exact model's coverage):
    /// appended to band_pixels_ for set-up `setup` of triangle t; returns its band_first.
    uint32_t bandPixelsOf(const detail::FastSetup& setup, uint32_t t);
    // The banded passes; bands >= 2 (bandsFor), else the oracle runs the sequential definition.
    // queryAgainst takes any band count (1: on the calling thread).
    void backToFrontPass(uint32_t bands, std::span<const uint32_t> sequence,
                         std::span<const uint8_t> query, std::span<uint8_t> behind);
    void queryAgainst(uint32_t bands, std::span<const uint32_t> occluders,
                      std::span<const uint32_t> targets, std::span<uint8_t> behind);
    std::span<const float> depthBuffer() const;

    /// Walks the tiles of set-up s in tile rows [ty_begin, ty_end); counts into stats. Each
    /// fragment moves as fragmentOffset says for a draw or a query, or with kFarImage (a draw of
    /// a negated plane, buildImage) by the negated query offset.
    /// A query's undecided fragments go to context (k: the set-up's index, for them).
    template <bool kDraw, bool kFarImage = false>
    bool rasterize(const StoredSetup& s, bool narrow, double spread, float error, int32_t ty_begin,
                   int32_t ty_end, CpuOracleStats& stats, QueryContext* context = nullptr,
                   uint32_t k = 0);
    /// rasterize of set-up k.
    template <bool kDraw>
    bool rasterize(uint32_t k, int32_t ty_begin, int32_t ty_end, CpuOracleStats& stats,
                   QueryContext* context = nullptr) {
        const StoredSetup& s = setups_[k];
        // Under the exact rule no fragment moves (the spread is unused) and the common error
        // bound covers most set-ups: their arrays are not read.
        const bool exact = exactRule();
        return rasterize<kDraw>(s, narrow_[k] != 0, exact ? 0.0 : spreadOf(k),
                                !exact || s.largeError() ? errors_[k] : global_error_, ty_begin,
                                ty_end, stats, context, k);
    }
    /// The exact rule's band pixels of s within tile rows [ty_begin, ty_end): drawn, or queried
    /// (undecided ones to context).
    template <bool kDraw>
    bool rasterizeBand(const StoredSetup& s, float error, int32_t ty_begin, int32_t ty_end,
                       QueryContext* context, uint32_t k);
    /// The edge functions at the centre of pixel (0, 0) under the oracle's rule: the stored ones,
    /// or under the blending rule the top-left rule's (blendingBias).
    void edgeOrigins(const StoredSetup& s, int64_t origin[3]) const {
        for (int e = 0; e < 3; ++e)
            origin[e] = s.edge_at_origin[e];
        if (depth_tolerance_ == 0)
            return;
        const std::array<int64_t, 3> margins =
            detail::marginsFromSteps(s.edge_step_x, s.edge_step_y, screen_errors_);
        for (int e = 0; e < 3; ++e)
            origin[e] += detail::blendingBias(margins[e], s.edge_step_x[e], s.edge_step_y[e]);
    }
    /// What a walk of s shares; a far image's moves each fragment by the negated query offset.
    /// (A separate step, not a parameter of triangleWalk: passing the offset in made the
    /// triangle-level walks 11 to 25% slower on the bunnies, the same instructions laid out
    /// worse.)
    template <bool kDraw, bool kFarImage>
    detail::TriangleWalk walkOf(const StoredSetup& s, bool narrow, double spread) const {
        detail::TriangleWalk walk = triangleWalk<kDraw>(s, narrow, spread, depth_tolerance_);
        if constexpr (kFarImage)
            walk.offset = exactRule() ? -0.0 : -fragmentOffset<false>(spread, depth_tolerance_);
        return walk;
    }
    /// rasterize for a triangle whose pixel bounds span at most detail::kSmallTiles tiles each
    /// way (most triangles of a detailed mesh): one walk over its bounds (fast_rows.h), the tiles
    /// cleared and culled beforehand, their bounds updated after, none of the per-tile set-up that
    /// costs more than the few pixels a small triangle has in each tile. Rows of tile rows
    /// [ty_first, ty_last] only.
    template <bool kDraw, bool kFarImage>
    bool rasterizeSmall(const StoredSetup& s, bool narrow, double spread, float error,
                        int32_t ty_first, int32_t ty_last, CpuOracleStats& stats,
                        QueryContext* context, uint32_t k);
    /// Runs band(b, stats of b) for b = 0..bands-1 on the calling thread and the pool's workers
    /// (each claims the next band when done); then adds the bands' tile counts to stats_.
    template <class Band> void runBands(uint32_t bands, Band&& band);
    /// Bands for a pass over count primitives: 1 when small or single-threaded, else a few per
    /// thread, at most one per tile row.
    uint32_t bandsFor(std::size_t count) const;
    /// Tile rows of band b of bands: [first, last).
    void bandRows(uint32_t b, uint32_t bands, int32_t& first, int32_t& last) const;
    /// The depths of one tile, kTileSize rows of kTileSize floats (fast_rows.h).
    float* tileDepths(std::size_t tile) const {
        return depth_.data() + tile * kTileSize * kTileSize;
    }
    /// Where pixel (x, y) is stored.
    float* pixel(uint32_t x, uint32_t y) const {
        return tileDepths(std::size_t(y / kTileSize) * tiles_x_ + x / kTileSize) +
               (y % kTileSize) * kTileSize + x % kTileSize;
    }
    /// Writes out the pending clear of one tile: its pixels +infinity, bounds +infinity.
    void clearTile(std::size_t tile) const {
        std::fill_n(depth_.begin() + std::ptrdiff_t(tile * kTilePixels), kTilePixels, kInfinity);
        tiles_[tile] = {kInfinity, kInfinity, 0.0f, epoch_};
    }
    /// Set-up k's FastSetup::spread: the snap slack (cpu_rasterizer.h).
    double spreadOf(uint32_t k) const { return spreads_[k]; }
    /// Appends the set-ups of triangle t's fan triangles to setups_ (and narrow_, spreads_,
    /// errors_), with their band pixels under the exact rule.
    void store(std::span<const detail::FastSetup> fan, uint32_t t);

    // Depth images (depth_images.h): a primitive of image_min_triangles_ set-ups or more is
    // rasterized once per bind into an image of its nearest fragments (for draws) and once into
    // one of its farthest (for queries), each on first use; its draws and queries then walk
    // its tiles. Tiles of rows [row_first, row_last) and columns [column_first, column_last].
    TileRect wholeScreen() const { return {0, int32_t(tiles_y_), 0, int32_t(tiles_x_) - 1}; }
    static constexpr uint32_t kNoSlot = ~uint32_t(0);
    /// primitive's place among imaged_, or kNoSlot when it has too few set-ups for images.
    uint32_t slotOf(uint32_t primitive) const {
        if (imaged_.empty() ||
            primitive_setups_[primitive + 1] - primitive_setups_[primitive] < image_min_triangles_)
            return kNoSlot;
        return uint32_t(std::lower_bound(imaged_.begin(), imaged_.end(), primitive) -
                        imaged_.begin());
    }
    /// The slot of primitive's image of the kind (near: for draws) if it has one made, else
    /// kNoSlot. Reads only: what bands call.
    template <bool kNear> uint32_t builtSlot(uint32_t primitive) const {
        const uint32_t slot = slotOf(primitive);
        return slot != kNoSlot && images<kNear>().state(slot) == detail::DepthImages::State::built
                   ? slot
                   : kNoSlot;
    }
    /// Makes primitive's image of the kind if it may have one and has none yet. Not
    /// thread-safe: passes make what their bands need before starting them.
    template <bool kNear> void makeImage(uint32_t primitive) {
        const uint32_t slot = slotOf(primitive);
        if (slot != kNoSlot && images<kNear>().state(slot) == detail::DepthImages::State::unbuilt)
            buildImage<kNear>(primitive, slot);
    }
    template <bool kNear> void buildImage(uint32_t primitive, uint32_t slot);
    template <bool kNear> detail::DepthImages& images() {
        return kNear ? near_images_ : far_images_;
    }
    template <bool kNear> const detail::DepthImages& images() const {
        return kNear ? near_images_ : far_images_;
    }
    /// Draws primitive within rect: through its near image if it has one made (and its bounds
    /// meet rect), else set-up by set-up (those whose pixel bounds meet rect's columns).
    void drawIn(uint32_t primitive, const TileRect& rect, CpuOracleStats& stats);
    /// Queries primitive within rect's rows: through its far image if it has one made, else
    /// set-up by set-up. Under the exact rule, undecided fragments go to context, and true
    /// means behind without them.
    bool anyBehindIn(uint32_t primitive, const TileRect& rect, CpuOracleStats& stats,
                     QueryContext& context);
    /// anyBehindIn, then the undecided fragments: the answer.
    bool queryIn(uint32_t primitive, const TileRect& rect, CpuOracleStats& stats,
                 QueryContext& context) {
        context.undecided->clear(); // what an earlier query found behind before resolving
        if (anyBehindIn(primitive, rect, stats, context))
            return true;
        return !context.undecided->empty() && resolve(context, rect, stats);
    }
    /// Calls visit(entry, tile) for the entries of an image whose tiles lie in rect, in tile
    /// order, until it returns true; returns whether it did.
    template <class Visit>
    bool forImageTiles(const detail::DepthImages& images, uint32_t slot, const TileRect& rect,
                       Visit&& visit) const;
    /// Sets the tolerance of the coming draws and queries; images made with another are dropped
    /// (exact mode moves fragments by the snap slack in a direction that depends on its sign).
    void setTolerance(float tolerance) {
        if (tolerance != depth_tolerance_)
            changeTolerance(tolerance);
    }
    void changeTolerance(float tolerance);

    uint32_t width_ = 0, height_ = 0;
    uint32_t tiles_x_ = 0, tiles_y_ = 0;
    uint32_t primitive_count_ = 0;
    // Primitive p's fan triangles are setups_[primitive_setups_[p], primitive_setups_[p + 1]).
    std::vector<uint32_t> primitive_setups_;
    std::vector<StoredSetup> setups_;
    std::vector<uint8_t> narrow_; // FastSetup::narrow, beside setups_
    std::vector<double> spreads_; // FastSetup::spread, beside setups_
    std::vector<float> errors_;   // FastSetup::error rounded up, beside setups_
    // The exact rule's common error bound of the set-ups bound (setGlobalError, at most
    // kCommonErrorCap above).
    float global_error_ = 0;
    std::vector<detail::FastSetup> fan_; // bind's scratch: one triangle's fan set-ups
    // The exact rule's band pixels: at a set-up's band_first, their count, then each covered one
    // as py << 16 | px. Entry 0 is unused (band_first 0: none). Made by bind, kept by rebinds.
    std::vector<uint32_t> band_pixels_;
    // The exact model of the last bind and its arbitration, its positions (the exact model reads
    // the corners), and the bind's screen errors.
    detail::DepthArbiter arbiter_;
    PositionsView positions_;
    detail::ScreenErrors screen_errors_;
    bool orthographic_ = false;
    // When each primitive was first drawn since the clear (stamp), on a clock of draws that the
    // clears do not reset (4 bytes a primitive); where the clock stood at the last clear.
    std::vector<uint32_t> drawn_time_;
    uint32_t clock_ = 1, clear_time_ = 1;
    // The exact rule's arbitration needs, at a pixel, the set-ups that cover it. The index of
    // set-ups by tiles (by their pixel bounds): tile t's are
    // tile_setups_[tile_starts_[t], [t + 1]). From it, per tile on its first arbitration after
    // a (re)bind, every pixel's list of the set-ups covering it (pixelList). A pixel's list is
    // the fragments there, a few in most scenes; a tile's index holds every set-up whose bounds
    // meet it, hundreds where a CAD assembly's long thin triangles cross, and scanning it per
    // arbitration cost 45% of ordering assimp's 2CylinderEngine.glb (issue 57).
    std::vector<uint32_t> tile_starts_, tile_setups_;
    std::atomic<bool> tile_index_built_{false};
    std::mutex tile_index_mutex_;                    // also makes pixel lists
    std::vector<std::vector<uint32_t>> pixel_lists_; // per tile
    // Per tile, whether its pixel lists are made since the index was; as many as the largest
    // screen's tiles, kept across binds (a coherent frame allocates nothing: they and the
    // lists' vectors are reused).
    std::unique_ptr<std::atomic<bool>[]> pixel_lists_made_;
    std::size_t pixel_lists_made_capacity_ = 0;
    // makePixelLists' (pixel of the tile, plane's d0, set-up) entries, reused.
    struct PixelEntry {
        uint32_t pixel;
        double d0;
        uint32_t setup;
    };
    std::vector<PixelEntry> pixel_list_entries_, pixel_list_sorted_;
    std::vector<Undecided> undecided_;                   // a sequential query's
    std::vector<std::vector<Undecided>> band_undecided_; // per band
    std::vector<uint32_t> query_times_;                  // a banded pass's, per element

    // For rebind, once one has been asked for (an oracle never rebound pays nothing for it):
    // where bind put each triangle's set-ups. A triangle's entry is current when its
    // stamp's high bits are bind_stamp_ (the last bind's number: no clearing per bind); the low
    // kCountBits hold its set-up count (a clipped triangle's fan has at most 7).
    static constexpr uint32_t kCountBits = 4;
    struct TriangleSetups {
        uint32_t first, stamp;
        uint32_t count() const { return stamp & ((1u << kCountBits) - 1); }
        bool current(uint32_t bind_stamp) const { return stamp >> kCountBits == bind_stamp; }
    };
    bool keep_for_rebind_ = false;
    std::vector<TriangleSetups> triangle_setups_;
    uint32_t bind_stamp_ = 0;
    std::vector<float> source_errors_;
    // Where the set-ups that triangle_setups_ points into are: still setups_ until the first
    // rebind after a bind moves them to source_ (its set-ups are then copied from there); none
    // when the last bind kept no map.
    enum class Source { none, setups, source };
    Source source_at_ = Source::none;
    std::vector<StoredSetup> source_setups_;
    std::vector<uint8_t> source_narrow_;
    std::vector<double> source_spreads_;
    // What the last bind was given (rebind's check that it is the same geometry and view).
    const float* bound_x_ = nullptr;
    std::size_t bound_triangles_ = 0;
    detail::Matrix4 bound_matrix_{};
    // Per tile, in one struct so that a tile's bounds and epoch share a cache line (the tiles a
    // pass touches are scattered over a buffer larger than the caches: one miss, not three).
    // Clearing is lazy: clear() starts a new epoch, and a tile whose epoch is older holds only
    // +infinity, whatever its pixels say, until clearTile writes that out (on its first draw, or
    // in depthBuffer(), which is why the states are mutable: the logical contents never change).
    // min is a lower bound on every stored depth (exact after a depth-tested draw; after a draw
    // whose fragments all pass, its depth bounds' lower end rounded to float); max is an upper
    // bound on every stored depth (exact after clear and after a depth-tested draw that covers
    // the whole tile, the upper end rounded after a passing draw that covers it, otherwise left
    // as it was: stored depths only decrease). error: the largest exact-rule error bound of a
    // draw that walked the tile since its clear (0 when clear): every stored depth's, and every
    // fragment's drawn there, whether it passed or not (the exact rule's band needs them all).
    // 16 bytes: the epoch is 32 bits, and its wrap resets every tile (newEpoch).
    struct TileState {
        float min, max, error;
        uint32_t epoch;
    };
    /// A bound on the error of every fragment drawn into a tile since its clear: the bind's
    /// common bound, or the tile's own where a fragment above it was drawn there.
    float storedError(const TileState& state) const { return std::max(global_error_, state.error); }
    mutable std::vector<float> depth_;     // tile by tile (fast_rows.h), padded to whole tiles
    mutable std::vector<float> row_major_; // depthBuffer()'s copy
    mutable std::vector<TileState> tiles_;
    uint32_t epoch_ = 1;
    CpuOracleStats stats_;
    // The oracle's depthTolerance(), copied here by every draw, query and pass.
    float depth_tolerance_ = kDepthTolerance;

    bool use_simd_ = false;
    // The pixel walks (src/raster/fast_rows.h): AVX2 or scalar, chosen at construction.
    void (*draw_tile_)(const detail::TileWalk&, detail::TileDraw&) = nullptr;
    detail::QueryTileFn query_tile_ = nullptr;
    void (*fill_tile_)(const detail::TileWalk&) = nullptr;
    void (*draw_small_)(const detail::SmallWalk&, detail::SmallDraw&) = nullptr;
    detail::QuerySmallFn query_small_ = nullptr;
    // The batch set-up (src/raster/fast_setup.h): AVX2, or null for the scalar one only.
    detail::SetupQuadFn setup_quad_ = nullptr;
    uint32_t threads_ = 1;
    uint32_t parallel_threshold_ = 0;
    // The caller's pool (Options::pool), or WorkerPool::shared() from the first parallel pass.
    WorkerPool* pool_ = nullptr;
    std::vector<CpuOracleStats> band_stats_; // one per band, reused

    uint32_t image_min_triangles_ = 0; // 0: no images
    std::size_t image_budget_bytes_ = 0;
    // The primitives with image_min_triangles_ set-ups or more (none when it is 0), ascending (a
    // slot is a place here), and per slot the union of its set-ups' pixel bounds (x_min > x_max
    // when empty).
    // Only those have per-primitive entries: a triangle-level bind of millions of primitives
    // pays nothing for the images.
    std::vector<uint32_t> imaged_;
    struct PixelRect {
        int32_t x_min, x_max, y_min, y_max;
    };
    std::vector<PixelRect> imaged_rects_;
    detail::DepthImages near_images_{detail::DepthImages::Kind::near}; // by slot
    detail::DepthImages far_images_{detail::DepthImages::Kind::far};
    // The buffer images are rasterized into: swapped with depth_, tiles_ and epoch_ meanwhile.
    std::vector<float> image_depth_;
    std::vector<TileState> image_tiles_;
    uint32_t image_epoch_ = 1;
    std::vector<float> image_errors_; // per slot: the largest error bound of its set-ups
};

// Bands per thread. Each band repeats the walk over the whole sequence (per triangle: its range,
// its set-ups, the band test), which is most of a small triangle's cost: measured on the bunnies'
// pass 1 (66,132 triangles, 2 threads), 3 bands per thread took 5.0 ms, 1 band per thread 3.5 ms,
// one thread 6.0 ms. Bands are still claimed in turn, so more per thread is one constant away.
constexpr uint32_t kBandsPerThread = 1;

// Defined here: the bands of passes (cpu_oracle_bands.cpp) and of the occlusion graph
// (cpu_oracle_graph.cpp) call it with their own lambdas.
template <class Band> inline void CpuOracle::Impl::runBands(uint32_t bands, Band&& band) {
    if (band_stats_.size() < bands)
        band_stats_.resize(threads_ * kBandsPerThread); // once
    for (uint32_t b = 0; b < bands; ++b)
        band_stats_[b] = {};
    if (pool_ == nullptr) {
        pool_ = &WorkerPool::shared();
        pool_->reserve(threads_); // grown once, to the largest count an oracle asks
    }
    struct Context {
        std::remove_reference_t<Band>* band;
        CpuOracleStats* stats;
        uint32_t bands;
        std::atomic<uint32_t> next{0}; // the next band to claim
    };
    Context context{&band, band_stats_.data(), bands};
    pool_->run(
        std::min(threads_, bands),
        [](void* c, uint32_t) {
            Context& context = *static_cast<Context*>(c);
            for (uint32_t b;
                 (b = context.next.fetch_add(1, std::memory_order_relaxed)) < context.bands;) {
                // Counted on this thread's stack: the bands' entries share cache lines.
                CpuOracleStats stats;
                (*context.band)(b, stats);
                context.stats[b] = stats;
            }
        },
        &context);
    for (uint32_t b = 0; b < bands; ++b) {
        stats_.tiles_visited += band_stats_[b].tiles_visited;
        stats_.tiles_culled += band_stats_[b].tiles_culled;
        stats_.tiles_accepted += band_stats_[b].tiles_accepted;
        stats_.arbitrations += band_stats_[b].arbitrations;
    }
}

} // namespace vissort
