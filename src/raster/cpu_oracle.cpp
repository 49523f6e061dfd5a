// A tiled CPU depth rasterizer answering Vis-sort's occlusion queries (Govindaraju, Henson, Lin,
// Manocha, I3D 2005, section 4) with CpuReferenceOracle's answers, bit for bit.
// This work is based on: Juan Pineda. A Parallel Algorithm for Polygon Rasterization. 1988 (edge
// functions, evaluated incrementally and at tile corners); Ned Greene, Michael Kass, Gavin Miller.
// Hierarchical Z-Buffer Visibility. 1993 (per-tile depth bounds); Nicolas Capens. Advanced
// Rasterization. 2004 (8 x 8 blocks: trivial reject and full coverage from the block corners).
//
// Why every shortcut is exact:
//  - Edge functions are affine in the pixel indices and exact in int64_t, so over a rectangle of
//    pixel centres their minimum and maximum are at its corners: a tile is outside an edge when
//    the maximum of E + bias is <= 0, inside when the minimum is > 0 (the top-left rule is the
//    bias, so nothing changes there).
//  - A fragment's depth is float(v) with v = (d0 + ddx (cx - x0)) + ddy (cy - y0) rounded in
//    double. The exact affine value over a tile lies between its corner values, and v differs
//    from it by at most a few units in the last place of |d0| + |ddx (cx - x0)| + |ddy (cy - y0)|:
//    a margin of 2^-48 of that sum bounds v from both sides. Rounding to float is monotone, so
//    bounds on v bound the fragments, and comparisons against float depths stay exact.
//  - The exact rule's decisions (cpu_reference_oracle.h, rule 7) compare a fragment with the
//    stored depth within a band made of the fragment's error bound and one for every fragment drawn
//    into the tile since its clear (TileState::error, at least each pixel's): a wider band than the
//    reference's per-pixel one decides fewer fragments by floats and sends more to the exact model,
//    whose answers are the same.

#include "vissort/cpu_oracle.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>
#include <mutex>
#include <span>
#include <thread>
#include <type_traits>
#include <vector>

#include "raster/cpu_rasterizer.h"
#include "raster/depth_arbiter.h"
#include "raster/depth_images.h"
#include "raster/fast_rows.h"
#include "raster/fast_setup.h"
#include "vissort/worker_pool.h"

namespace vissort {
namespace {

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
// padding), the spread (the snap slack, or the conservative spread) and the exact rule's error
// bound are kept beside them, and the margins are derived from the steps where the blending rule
// needs them (marginsFromSteps). The edge steps stay int64_t: as int32_t quotients by
// kSubpixelScale (snapped coordinates are at most 2^29) the set-up would take fewer bytes, but
// widening them back in every draw and query cost 6% more instructions on builtin:bunnies at
// object level.
struct StoredSetup {
    int64_t edge_at_origin[3]; // with the exact rule's bias (-margin), or conservative mode's
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
float roundedUp(double error) {
    return error < 1e30 ? float(error) * (1 + 0x1p-20f) : std::numeric_limits<float>::infinity();
}

StoredSetup storedSetup(const detail::FastSetup& s, uint32_t triangle, uint32_t band_first) {
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
// conservative mode, the nearest depth over the pixel for a draw and the farthest for a query;
// exact mode, the slack as the reference moves it (detail::exactFragmentOffset).
template <bool kDraw> double fragmentOffset(double spread, bool conservative, float tolerance) {
    return conservative ? (kDraw ? -spread : spread)
                        : detail::exactFragmentOffset(spread, kDraw, tolerance);
}

// What every walk of s shares (fast_rows.h), for a draw or a query.
template <bool kDraw>
detail::TriangleWalk triangleWalk(const StoredSetup& s, bool narrow, double spread,
                                  bool conservative, float tolerance) {
    detail::TriangleWalk walk;
    // The blending rule's and conservative mode's thresholds; the exact rule sets its own per
    // tile (decisionBand).
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
    // The exact rule moves nothing (tolerance 0, not conservative).
    walk.offset = !conservative && tolerance == 0
                      ? -0.0
                      : fragmentOffset<kDraw>(spread, conservative, tolerance);
    return walk;
}

// s with its depth plane negated: the same coverage, and each fragment value v becomes -v
// exactly (every operation of rule 6 rounds to nearest, which is symmetric).
StoredSetup negatedPlane(const StoredSetup& s) {
    StoredSetup negated = s;
    negated.d0 = -s.d0;
    negated.ddx = -s.ddx;
    negated.ddy = -s.ddy;
    return negated;
}

// The plane's column and row terms of rule 6: ddx ((x + 0.5) - x0) and ddy ((y + 0.5) - y0).
double columnTerm(const StoredSetup& s, int32_t x) {
    return s.ddx * ((double(x) + 0.5) - s.x0);
}
double rowTerm(const StoredSetup& s, int32_t y) {
    return s.ddy * ((double(y) + 0.5) - s.y0);
}

// Bounds on the double depth value v of every fragment over a rectangle whose corner columns have
// terms ax0, ax1 and corner rows by0, by1 (see the file comment), offset included (its rounding
// is within the margin, spread its size). Inlined: it runs once per tile a triangle visits, and a
// call with results through memory cost 7% of tile-culled queries.
[[gnu::always_inline]] inline void depthBounds(const StoredSetup& s, double ax0, double ax1,
                                               double by0, double by1, double offset, double spread,
                                               double& lowest, double& highest) {
    const double margin = kDepthMargin * (std::abs(s.d0) + std::max(std::abs(ax0), std::abs(ax1)) +
                                          std::max(std::abs(by0), std::abs(by1)) + spread);
    lowest = s.d0 + std::min(ax0, ax1) + std::min(by0, by1) + offset - margin;
    highest = s.d0 + std::max(ax0, ax1) + std::max(by0, by1) + offset + margin;
}

} // namespace

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

    // Tiles of rows [row_first, row_last) and columns [column_first, column_last].
    struct TileRect {
        int32_t row_first, row_last, column_first, column_last;
    };

    // The exact rule (depth tolerance 0, exact mode): its undecided fragments, collected by a
    // query's walks and decided by the exact model once the walks found nothing behind.
    bool exactRule() const { return !conservative_ && depth_tolerance_ == 0; }
    struct Undecided {
        enum class Kind : uint8_t {
            setup_tile,  // some fragment of set-up `what` in tile `where`
            setup_pixel, // set-up `what`'s band pixel `where` (py << 16 | px)
            image_tile,  // primitive `what`'s far image entry `where`
        };
        Kind kind;
        uint32_t what, where;
    };
    // The set-ups one query's arbitrations may meet, per cell of the index: a cell's list is
    // made at the query's first arbitration there (the set-ups drawn before the query, of other
    // triangles) and thinned as pairs turn out never nearer (DepthArbiter::Nearness::never:
    // copies of the query's triangle, faces touching or coplanar with it). Where a query ties
    // with a stack of faces at every pixel (a duplicated face: assimp's OBJ/box_longline.obj
    // has 236 copies of each), each pixel then costs what could still be nearer, not the stack.
    // Copies of a triangle are dropped from a list once it has served kDedupeAfterScans
    // arbitrations: the sort that finds them costs a dozen scans, paid only where a stack of
    // ties arbitrates pixel after pixel, not where each triangle of a query ties at one pixel.
    // A query's first arbitration in a cell scans the cell's index directly (most queries
    // arbitrate once or twice, each triangle of a primitive at its own pixels); the list is made
    // at the second.
    struct CellList {
        uint32_t cell = 0, scans = 0;
        bool built = false, deduplicated = false;
        std::vector<uint32_t> setups;
    };
    static constexpr uint32_t kDedupeAfterScans = 16;
    struct ArbitrationLists {
        uint32_t triangle = 0, time = 0;
        uint64_t generation = 0; // arbitration_generation_ when made; 0: never
        std::size_t used = 0;    // cells[0, used) are this query's; the rest kept for reuse
        std::vector<CellList> cells;
    };
    // What a query's walks share: its undecided fragments, its time (drawnBefore) and its
    // arbitration lists.
    struct QueryContext {
        std::vector<Undecided>* undecided;
        uint32_t time;
        ArbitrationLists* lists;
    };
    /// Whether some undecided fragment of context, within rect's rows, is behind by the exact
    /// model; clears the list.
    bool resolve(QueryContext& context, const TileRect& rect, CpuOracleStats& stats);
    /// Whether triangle's fragment at pixel (px, py) (its float `fragment`, within `error` of
    /// the exact depth) lies strictly behind a fragment of a primitive drawn there before
    /// `time`, by the exact model.
    bool behindSomethingDrawn(uint32_t triangle, uint32_t px, uint32_t py, QueryContext& context,
                              float fragment, float error, CpuOracleStats& stats);
    /// The list of set-ups context's query may meet in a cell (ArbitrationLists).
    /// Null at the query's first arbitration in the cell (scan the index directly).
    std::vector<uint32_t>* arbitrationList(QueryContext& context, uint32_t triangle, uint32_t cell);
    /// Keeps one set-up of each set of copies in list (the same shape: kSetupShapeBytes).
    void dropCopies(std::vector<uint32_t>& list) const;
    /// Whether set-up s covers pixel (px, py) as its draws do: certainly, or as a band pixel the
    /// exact model gave it.
    bool setupCovers(const StoredSetup& s, uint32_t px, uint32_t py) const;
    /// The set-up's fragment value at a pixel (rule 6, no offset) and whether it certainly
    /// covers it (every edge function beyond the margin).
    float fragmentAt(const StoredSetup& s, uint32_t px, uint32_t py) const;
    bool certainlyCovers(const StoredSetup& s, uint32_t px, uint32_t py) const;
    /// The primitive whose set-ups hold set-up k.
    uint32_t primitiveOfSetup(uint32_t k) const {
        return uint32_t(std::upper_bound(primitive_setups_.begin(),
                                         primitive_setups_.begin() + primitive_count_ + 1, k) -
                        primitive_setups_.begin()) -
               1;
    }
    /// The index of set-ups by cells of the screen (by their pixel bounds), made on first need
    /// after each (re)bind; thread-safe.
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
        ++arbitration_generation_;
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
        if (conservative_ || depth_tolerance_ == 0)
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
        detail::TriangleWalk walk =
            triangleWalk<kDraw>(s, narrow, spread, conservative_, depth_tolerance_);
        if constexpr (kFarImage)
            walk.offset = exactRule()
                              ? -0.0
                              : -fragmentOffset<false>(spread, conservative_, depth_tolerance_);
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
    void clearTile(std::size_t tile) const;
    /// Set-up k's FastSetup::spread: conservative mode, the spread over a pixel; exact mode,
    /// the snap slack (cpu_rasterizer.h).
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
    // The exact rule's common error bound of the set-ups bound (setGlobalError): almost every
    // fragment's is the float rounding, 2^-24, and a few steep or sliver triangles' more; only
    // those write it into the tiles they draw, so that a draw need not touch every tile's state.
    static constexpr float kCommonErrorCap = 0x1p-22f;
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
    // The index of set-ups by cells of 32 x 32 pixels (a small triangle's bounds meet one or two,
    // so the index is about a set-up long): cell c's are cell_setups_[cell_starts_[c], [c + 1]).
    static constexpr int kCellShift = 5;
    uint32_t cellsX() const { return (width_ + (1u << kCellShift) - 1) >> kCellShift; }
    uint32_t cellsY() const { return (height_ + (1u << kCellShift) - 1) >> kCellShift; }
    std::vector<uint32_t> cell_starts_, cell_setups_;
    std::atomic<bool> tile_index_built_{false};
    std::mutex tile_index_mutex_;
    std::vector<Undecided> undecided_;                   // a sequential query's
    std::vector<std::vector<Undecided>> band_undecided_; // per band
    ArbitrationLists arbitration_lists_;                 // a sequential query's
    std::vector<ArbitrationLists> band_lists_;           // per band
    uint64_t arbitration_generation_ = 1;                // a clear or bind makes every list stale
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

    bool conservative_ = false;
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

CpuOracle::Impl::Impl(const Options& options)
    : conservative_(options.mode == RasterMode::conservative) {
    const detail::RowKernels kernels = detail::selectRowKernels(options.allow_simd, use_simd_);
    draw_tile_ = kernels.draw;
    query_tile_ = kernels.query;
    fill_tile_ = kernels.fill;
    draw_small_ = kernels.draw_small;
    query_small_ = kernels.query_small;
    if (use_simd_)
        setup_quad_ = detail::avx2SetupQuad(); // the same AVX2 check
    threads_ = options.threads == 0 ? std::thread::hardware_concurrency() : options.threads;
    if (options.pool != nullptr) {
        pool_ = options.pool;
        threads_ = pool_->threadCount();
    }
    threads_ = std::clamp<uint32_t>(threads_, 1, 256);
    parallel_threshold_ = options.parallel_threshold;
    image_min_triangles_ = options.image_min_triangles;
    image_budget_bytes_ = options.image_budget_bytes;
}

void CpuOracle::Impl::bind(PositionsView positions, const ViewProjection& view,
                           std::span<const PrimitiveRange> primitives) {
    assert(view.width >= 1 && view.width <= detail::kMaxViewportSize);
    assert(view.height >= 1 && view.height <= detail::kMaxViewportSize);
    assert(positions.y.size() == positions.x.size() && positions.z.size() == positions.x.size());
    width_ = view.width;
    height_ = view.height;
    tiles_x_ = (width_ + kTileSize - 1) / kTileSize;
    tiles_y_ = (height_ + kTileSize - 1) / kTileSize;
    primitive_count_ = uint32_t(primitives.size());
    for ([[maybe_unused]] const PrimitiveRange& range : primitives)
        assert(uint64_t(range.first_triangle) + range.triangle_count <= positions.triangleCount());

    // Set-ups are laid out in primitive order (a primitive's fan triangles are contiguous), so a
    // walk over primitives in id order reads memory forward; triangles of no primitive are never
    // set up, those of several are set up once each. Triangles are taken four at a time in that
    // order (bind order), for the batch set-up.
    const detail::Matrix4 m = detail::multiply(view.projection_matrix, view.view);
    if (source_at_ == Source::source) { // the larger buffers back: the groups' stay small
        std::swap(setups_, source_setups_);
        std::swap(narrow_, source_narrow_);
        std::swap(spreads_, source_spreads_);
        std::swap(errors_, source_errors_);
    }
    source_at_ = Source::none;
    positions_ = positions;
    if (!conservative_) {
        screen_errors_ = detail::screenErrorsOf(m, view, positions, primitives);
        orthographic_ = view.projection == Projection::orthographic;
        arbiter_.bind(view, positions);
    }
    band_pixels_.assign(1, 0); // entry 0: none
    if (keep_for_rebind_) {
        bound_x_ = positions.x.data();
        bound_triangles_ = positions.triangleCount();
        bound_matrix_ = m;
        if (triangle_setups_.size() != bound_triangles_ ||
            ++bind_stamp_ >> (32 - kCountBits) != 0) {
            triangle_setups_.assign(bound_triangles_, TriangleSetups{0, 0});
            bind_stamp_ = 1;
        }
        source_at_ = Source::setups;
    }
    std::size_t n = 0;
    for (const PrimitiveRange& range : primitives)
        n += range.triangle_count;
    primitive_setups_.resize(primitives.size() + 1);
    setups_.clear();
    setups_.reserve(n);
    narrow_.clear();
    narrow_.reserve(n);
    spreads_.clear();
    spreads_.reserve(n);
    errors_.clear();
    errors_.reserve(n);
    // Before the set-ups of the triangle at bind position i: primitives starting there start here.
    std::size_t next_primitive = 0, next_start = 0;
    const auto reach = [&](std::size_t i) {
        while (next_primitive < primitives.size() && next_start == i) {
            primitive_setups_[next_primitive] = uint32_t(setups_.size());
            next_start += primitives[next_primitive++].triangle_count;
        }
    };
    const bool batch = setup_quad_ != nullptr && !conservative_;
    uint32_t quad_triangles[4];
    std::size_t quad_size = 0, quad_first = 0; // quad_triangles[0] is at bind position quad_first
    const auto setUpQuad = [&] {
        detail::FastSetup quad[4];
        detail::LaneSetup lanes[4];
        if (batch && quad_size == 4)
            setup_quad_(m, positions.x.data(), positions.y.data(), positions.z.data(),
                        quad_triangles, width_, height_, screen_errors_, quad, lanes);
        else
            std::fill_n(lanes, 4, detail::LaneSetup::scalar);
        for (std::size_t l = 0; l < quad_size; ++l) {
            reach(quad_first + l);
            const uint32_t first = uint32_t(setups_.size());
            if (lanes[l] == detail::LaneSetup::ready) {
                quad[l].narrow = detail::edgesFitInt32(quad[l]);
                store({&quad[l], 1}, quad_triangles[l]);
            } else if (lanes[l] == detail::LaneSetup::scalar) {
                fan_.clear();
                detail::appendFastSetups(m, positions, quad_triangles[l], width_, height_,
                                         conservative_, screen_errors_, fan_);
                store(fan_, quad_triangles[l]);
            }
            if (keep_for_rebind_) {
                const uint32_t count = uint32_t(setups_.size()) - first;
                assert(count < 1u << kCountBits);
                triangle_setups_[quad_triangles[l]] = {first, bind_stamp_ << kCountBits | count};
            }
        }
        quad_first += quad_size;
        quad_size = 0;
    };
    for (const PrimitiveRange& range : primitives)
        for (uint32_t t = range.first_triangle; t < range.first_triangle + range.triangle_count;
             ++t) {
            quad_triangles[quad_size++] = t;
            if (quad_size == 4)
                setUpQuad();
        }
    setUpQuad();
    reach(n);
    primitive_setups_[primitives.size()] = uint32_t(setups_.size());
    finishBind();
}

bool CpuOracle::Impl::sameAsBound(PositionsView positions, const ViewProjection& view) const {
    return source_at_ != Source::none && positions.x.data() == bound_x_ &&
           positions.triangleCount() == bound_triangles_ && view.width == width_ &&
           view.height == height_ &&
           detail::multiply(view.projection_matrix, view.view) == bound_matrix_;
}

void CpuOracle::Impl::rebind(PositionsView positions, const ViewProjection& view,
                             std::span<const PrimitiveRange> primitives) {
    keep_for_rebind_ = true; // from now on binds keep their map
    // Binding instead: the groups' buffers grow to the group's size now, not when a later
    // rebind swaps them in, with room for a triangle each and an eighth more for clipped fans
    // (a triangle covering no pixel centre has none: a group's set-ups vary from frame to
    // frame, and steady frames should allocate nothing).
    const auto bindInstead = [&] {
        bind(positions, view, primitives);
        std::size_t triangles = 0;
        for (const PrimitiveRange& range : primitives)
            triangles += range.triangle_count;
        const std::size_t room = std::max(setups_.size(), triangles) + triangles / 8;
        source_setups_.reserve(room);
        source_narrow_.reserve(room);
        source_spreads_.reserve(room);
        source_errors_.reserve(room);
    };
    if (!sameAsBound(positions, view)) {
        bindInstead();
        return;
    }
    std::size_t n = 0;                             // set-ups to copy
    for (const PrimitiveRange& range : primitives) // every triangle set up by the bind?
        for (uint32_t t = range.first_triangle; t < range.first_triangle + range.triangle_count;
             ++t) {
            if (!triangle_setups_[t].current(bind_stamp_)) {
                bindInstead();
                return;
            }
            n += triangle_setups_[t].count();
        }
    if (source_at_ == Source::setups) {
        std::swap(setups_, source_setups_);
        std::swap(narrow_, source_narrow_);
        std::swap(spreads_, source_spreads_);
        std::swap(errors_, source_errors_);
        source_at_ = Source::source;
    }
    primitive_count_ = uint32_t(primitives.size());
    primitive_setups_.resize(primitives.size() + 1);
    // Sized once and copied element by element: a group's triangles come in last frame's order,
    // scattered over the source, and an insert per triangle spent 9% of a multi-stage frame in
    // memmove's start-up.
    setups_.resize(n);
    narrow_.resize(n);
    spreads_.resize(n);
    errors_.resize(n);
    uint32_t k = 0;
    constexpr std::size_t kAhead = 8; // primitives: a few cache misses in flight
    for (std::size_t p = 0; p < primitives.size(); ++p) {
        // Only a range with triangles has an entry, and only one with set-ups a set-up to fetch
        // (an empty range may start at the last triangle's end).
        if (p + kAhead < primitives.size() && primitives[p + kAhead].triangle_count != 0) {
            const TriangleSetups& ahead = triangle_setups_[primitives[p + kAhead].first_triangle];
            if (ahead.count() != 0) {
                const char* setup = reinterpret_cast<const char*>(&source_setups_[ahead.first]);
                __builtin_prefetch(setup);
                __builtin_prefetch(setup + sizeof(StoredSetup) - 1);
                __builtin_prefetch(&source_spreads_[ahead.first]);
                __builtin_prefetch(&source_narrow_[ahead.first]);
            }
        }
        primitive_setups_[p] = k;
        const PrimitiveRange& range = primitives[p];
        for (uint32_t t = range.first_triangle; t < range.first_triangle + range.triangle_count;
             ++t) {
            const TriangleSetups& at = triangle_setups_[t];
            const uint32_t end = at.first + at.count();
            for (uint32_t i = at.first; i < end; ++i, ++k) {
                setups_[k] = source_setups_[i];
                narrow_[k] = source_narrow_[i];
                spreads_[k] = source_spreads_[i];
                errors_[k] = source_errors_[i];
            }
        }
    }
    primitive_setups_[primitives.size()] = k;
    finishBind();
}

void CpuOracle::Impl::finishBind() {
    setGlobalError();
    depth_.resize(std::size_t(tiles_x_) * tiles_y_ * kTilePixels);
    tiles_.assign(std::size_t(tiles_x_) * tiles_y_, TileState{kInfinity, kInfinity, 0, 0});
    epoch_ = 1; // every tile pending a clear
    drawn_time_.assign(primitive_count_, 0);
    clock_ = clear_time_ = 1;
    tile_index_built_.store(false);
    ++arbitration_generation_;

    imaged_.clear();
    imaged_rects_.clear();
    image_errors_.clear();
    for (uint32_t p = 0; image_min_triangles_ != 0 && p < primitive_count_; ++p) {
        if (primitive_setups_[p + 1] - primitive_setups_[p] < image_min_triangles_)
            continue;
        PixelRect rect{int32_t(width_), -1, int32_t(height_), -1};
        for (uint32_t k = primitive_setups_[p]; k < primitive_setups_[p + 1]; ++k) {
            rect.x_min = std::min<int32_t>(rect.x_min, setups_[k].px_min);
            rect.x_max = std::max<int32_t>(rect.x_max, setups_[k].px_max);
            rect.y_min = std::min<int32_t>(rect.y_min, setups_[k].py_min);
            rect.y_max = std::max<int32_t>(rect.y_max, setups_[k].py_max);
        }
        imaged_.push_back(p);
        imaged_rects_.push_back(rect);
        float error = 0;
        for (uint32_t k = primitive_setups_[p]; k < primitive_setups_[p + 1]; ++k)
            error = std::max(error, errors_[k]);
        image_errors_.push_back(error);
    }
    near_images_.reset(uint32_t(imaged_.size()));
    far_images_.reset(uint32_t(imaged_.size()));
}

void CpuOracle::Impl::changeTolerance(float tolerance) {
    depth_tolerance_ = tolerance;
    near_images_.reset(uint32_t(imaged_.size()));
    far_images_.reset(uint32_t(imaged_.size()));
}

template <bool kNear> void CpuOracle::Impl::buildImage(uint32_t primitive, uint32_t slot) {
    const uint32_t first = primitive_setups_[primitive], last = primitive_setups_[primitive + 1];
    // Sized on the first image (a bind that makes none allocates nothing); its stale tiles are
    // cleared by the epochs, whatever an earlier bind of another size left.
    if (image_tiles_.size() != tiles_.size()) {
        image_depth_.resize(depth_.size());
        image_tiles_.assign(tiles_.size(), TileState{kInfinity, kInfinity, 0, 0});
    }
    std::swap(depth_, image_depth_);
    std::swap(tiles_, image_tiles_);
    std::swap(epoch_, image_epoch_);
    newEpoch(); // an empty buffer
    CpuOracleStats unused;
    for (uint32_t k = first; k < last; ++k) {
        if constexpr (kNear) {
            rasterize<true>(k, 0, int32_t(tiles_y_), unused);
        } else {
            // The farthest fragment per pixel: the nearest of the negated ones, each moved as a
            // query moves it.
            rasterize<true, true>(negatedPlane(setups_[k]), narrow_[k] != 0, spreadOf(k),
                                  errors_[k], 0, int32_t(tiles_y_), unused);
        }
    }
    detail::DepthImages& made = images<kNear>();
    made.begin(slot);
    const PixelRect& rect = imaged_rects_[slot];
    if (rect.x_min <= rect.x_max)
        for (int32_t ty = rect.y_min >> kTileShift; ty <= rect.y_max >> kTileShift; ++ty)
            for (int32_t tx = rect.x_min >> kTileShift; tx <= rect.x_max >> kTileShift; ++tx) {
                const std::size_t tile = std::size_t(ty) * tiles_x_ + std::size_t(tx);
                if (tiles_[tile].epoch == epoch_)
                    made.addTile(uint32_t(tile), tileDepths(tile));
            }
    std::swap(depth_, image_depth_);
    std::swap(tiles_, image_tiles_);
    std::swap(epoch_, image_epoch_);
    if (made.finish(image_budget_bytes_))
        ++stats_.images_built;
}

template <class Visit>
bool CpuOracle::Impl::forImageTiles(const detail::DepthImages& images, uint32_t slot,
                                    const TileRect& rect, Visit&& visit) const {
    const std::size_t end = images.firstEntry(slot) + images.entryCount(slot);
    for (std::size_t e = images.firstEntry(slot); e < end; ++e) {
        const uint32_t tile = images.tile(e);
        const int32_t ty = int32_t(tile / tiles_x_), tx = int32_t(tile % tiles_x_);
        if (ty >= rect.row_last)
            break; // entries are in tile order
        if (ty >= rect.row_first && tx >= rect.column_first && tx <= rect.column_last &&
            visit(e, tile))
            return true;
    }
    return false;
}

void CpuOracle::Impl::drawIn(uint32_t primitive, const TileRect& rect, CpuOracleStats& stats) {
    // Pixel columns of rect.
    const int32_t x_first = rect.column_first << kTileShift;
    const int32_t x_last = (rect.column_last << kTileShift) + int32_t(kTileSize) - 1;
    if (const uint32_t slot = builtSlot<true>(primitive); slot != kNoSlot) {
        const PixelRect& bounds = imaged_rects_[slot];
        const int32_t y_first = rect.row_first << kTileShift;
        const int32_t y_last = (rect.row_last << kTileShift) - 1;
        if (bounds.x_min > x_last || bounds.x_max < x_first || bounds.y_min > y_last ||
            bounds.y_max < y_first)
            return; // nothing of it in rect
        const detail::DepthImages& near = near_images_;
        const float error = image_errors_[slot];
        forImageTiles(near, slot, rect, [&](std::size_t e, uint32_t tile) {
            ++stats.tiles_visited;
            TileState& state = tiles_[tile];
            if (state.epoch != epoch_)
                clearTile(tile);
            if (error > global_error_)
                state.error = std::max(state.error, error);
            // Every depth of the image >= the tile's max >= every stored depth: none passes.
            if (near.bound(e) >= state.max)
                ++stats.tiles_culled;
            else
                detail::drawImageTile(near.depths(e), tileDepths(tile), state.min, state.max);
            return false;
        });
        return;
    }
    for (uint32_t k = primitive_setups_[primitive]; k < primitive_setups_[primitive + 1]; ++k)
        if (setups_[k].px_min <= x_last && setups_[k].px_max >= x_first)
            rasterize<true>(k, rect.row_first, rect.row_last, stats);
}

bool CpuOracle::Impl::anyBehindIn(uint32_t primitive, const TileRect& rect, CpuOracleStats& stats,
                                  QueryContext& context) {
    if (const uint32_t slot = builtSlot<false>(primitive); slot != kNoSlot) {
        const detail::DepthImages& far = far_images_;
        const bool exact = exactRule();
        const float error = image_errors_[slot];
        return forImageTiles(far, slot, rect, [&](std::size_t e, uint32_t tile) {
            ++stats.tiles_visited;
            const TileState& state = tiles_[tile];
            // The thresholds of rasterize: the exact rule's band, or the tolerance.
            const float band_width = exact ? bandOf(error, storedError(state)) : 0;
            const float behind_above = exact ? band_width : depth_tolerance_;
            const float undecided_above =
                exact ? -band_width : std::numeric_limits<float>::infinity();
            // Cleared since last touched (nothing is behind +infinity), or every depth of the
            // image <= the tile's min + threshold <= stored + threshold: none behind (or
            // undecided).
            if (state.epoch != epoch_ ||
                far.bound(e) <= state.min + (exact ? undecided_above : behind_above)) {
                ++stats.tiles_culled;
                return false;
            }
            const detail::QueryResult result = detail::queryImageTile(
                far.depths(e), tileDepths(tile), behind_above, undecided_above);
            if (result == detail::QueryResult::undecided)
                context.undecided->push_back({Undecided::Kind::image_tile, primitive, uint32_t(e)});
            return result == detail::QueryResult::behind;
        });
    }
    for (uint32_t k = primitive_setups_[primitive]; k < primitive_setups_[primitive + 1]; ++k)
        if (rasterize<false>(k, rect.row_first, rect.row_last, stats, &context))
            return true;
    return false;
}

void CpuOracle::Impl::ensureTileIndex() {
    if (tile_index_built_.load(std::memory_order_acquire))
        return;
    const std::lock_guard<std::mutex> lock(tile_index_mutex_);
    if (tile_index_built_.load(std::memory_order_relaxed))
        return;
    // Counting sort of (cell, set-up) over each set-up's pixel bounds.
    const std::size_t cells = std::size_t(cellsX()) * cellsY();
    cell_starts_.assign(cells + 1, 0);
    const auto forEachCell = [&](const StoredSetup& s, auto&& visit) {
        for (uint32_t cy = s.py_min >> kCellShift; cy <= uint32_t(s.py_max >> kCellShift); ++cy)
            for (uint32_t cx = s.px_min >> kCellShift; cx <= uint32_t(s.px_max >> kCellShift); ++cx)
                visit(std::size_t(cy) * cellsX() + cx);
    };
    for (const StoredSetup& s : setups_)
        forEachCell(s, [&](std::size_t cell) { ++cell_starts_[cell + 1]; });
    for (std::size_t c = 0; c < cells; ++c)
        cell_starts_[c + 1] += cell_starts_[c];
    cell_setups_.resize(cell_starts_[cells]);
    std::vector<uint32_t> next(cell_starts_.begin(), cell_starts_.end() - 1);
    for (uint32_t k = 0; k < setups_.size(); ++k)
        forEachCell(setups_[k], [&](std::size_t cell) { cell_setups_[next[cell]++] = k; });
    tile_index_built_.store(true, std::memory_order_release);
}

bool CpuOracle::Impl::behindSomethingDrawn(uint32_t triangle, uint32_t px, uint32_t py,
                                           QueryContext& context, float fragment, float error,
                                           CpuOracleStats& stats) {
    ++stats.arbitrations;
    ensureTileIndex();
    const detail::DepthArbiter::Query query = arbiter_.query(triangle, px, py);
    const uint32_t cell = (py >> kCellShift) * cellsX() + (px >> kCellShift);
    // Certainly farther than the query's fragment, by the floats, or not there at all: set-up k
    // decides nothing here.
    const auto irrelevant = [&](uint32_t k) {
        const StoredSetup& s = setups_[k];
        return px < s.px_min || px > s.px_max || py < s.py_min || py > s.py_max ||
               fragmentAt(s, px, py) - double(errors_[k]) > double(fragment) + double(error) ||
               !setupCovers(s, px, py);
    };
    std::vector<uint32_t>* listed = arbitrationList(context, triangle, cell);
    if (listed == nullptr) {
        for (uint32_t i = cell_starts_[cell]; i < cell_starts_[cell + 1]; ++i) {
            const uint32_t k = cell_setups_[i];
            if (setups_[k].triangle() != triangle && !irrelevant(k) &&
                drawnBefore(primitiveOfSetup(k), context.time) &&
                arbiter_.nearness(query, setups_[k].triangle()) ==
                    detail::DepthArbiter::Nearness::nearer)
                return true;
        }
        return false;
    }
    return arbiter_.anyNearer(
        query, *listed, [&](uint32_t k) { return setups_[k].triangle(); }, irrelevant);
}

std::vector<uint32_t>* CpuOracle::Impl::arbitrationList(QueryContext& context, uint32_t triangle,
                                                        uint32_t cell) {
    ArbitrationLists& lists = *context.lists;
    if (lists.generation != arbitration_generation_ || lists.triangle != triangle ||
        lists.time != context.time) {
        lists.generation = arbitration_generation_;
        lists.triangle = triangle;
        lists.time = context.time;
        lists.used = 0;
    }
    for (std::size_t i = 0; i < lists.used; ++i) {
        CellList& found = lists.cells[i];
        if (found.cell != cell)
            continue;
        if (!found.built) {
            found.built = true;
            std::vector<uint32_t>& list = found.setups;
            list.clear();
            for (uint32_t j = cell_starts_[cell]; j < cell_starts_[cell + 1]; ++j) {
                const uint32_t k = cell_setups_[j];
                if (setups_[k].triangle() != triangle &&
                    drawnBefore(primitiveOfSetup(k), context.time))
                    list.push_back(k);
            }
        } else if (!found.deduplicated && ++found.scans >= kDedupeAfterScans) {
            dropCopies(found.setups);
            found.deduplicated = true;
        }
        return &found.setups;
    }
    if (lists.used == lists.cells.size())
        lists.cells.emplace_back();
    CellList& noted = lists.cells[lists.used++];
    noted.cell = cell;
    noted.scans = 1;
    noted.built = noted.deduplicated = false;
    return nullptr;
}

void CpuOracle::Impl::dropCopies(std::vector<uint32_t>& list) const {
    // Copies of a triangle (the same corners in the same order) have the same set-ups but for
    // the triangle and its band list's place, and answer alike: one of each is enough.
    const auto bytes = [&](uint32_t k) {
        return reinterpret_cast<const unsigned char*>(&setups_[k]);
    };
    const auto less = [&](uint32_t a, uint32_t b) {
        const int c = std::memcmp(bytes(a), bytes(b), kSetupShapeBytes);
        return c != 0 ? c < 0 : a < b;
    };
    std::sort(list.begin(), list.end(), less);
    list.erase(std::unique(list.begin(), list.end(),
                           [&](uint32_t a, uint32_t b) {
                               return std::memcmp(bytes(a), bytes(b), kSetupShapeBytes) == 0;
                           }),
               list.end());
}

bool CpuOracle::Impl::setupCovers(const StoredSetup& s, uint32_t px, uint32_t py) const {
    if (certainlyCovers(s, px, py))
        return true;
    if (s.band_first == 0)
        return false;
    const uint32_t count = band_pixels_[s.band_first];
    const uint32_t* pixels = band_pixels_.data() + s.band_first + 1;
    return std::find(pixels, pixels + count, py << 16 | px) != pixels + count;
}

bool CpuOracle::Impl::resolve(QueryContext& context, const TileRect& rect, CpuOracleStats& stats) {
    std::vector<Undecided>& undecided = *context.undecided;
    const uint32_t row_first = uint32_t(rect.row_first) << kTileShift;
    const uint32_t row_end = std::min(uint32_t(rect.row_last) << kTileShift, height_);
    // Whether set-up k's fragment at (px, py) is behind, its float undecided or not.
    const auto setupBehind = [&](uint32_t k, uint32_t px, uint32_t py) {
        const StoredSetup& s = setups_[k];
        const std::size_t tile = std::size_t(py >> kTileShift) * tiles_x_ + (px >> kTileShift);
        const TileState& state = tiles_[tile];
        if (state.epoch != epoch_)
            return false;
        const float fragment = fragmentAt(s, px, py);
        switch (detail::decide(fragment, *pixel(px, py), bandOf(errors_[k], storedError(state)))) {
        case detail::Decision::behind:
            return true;
        case detail::Decision::undecided:
            return behindSomethingDrawn(s.triangle(), px, py, context, fragment, errors_[k], stats);
        case detail::Decision::not_behind:
            return false;
        }
        return false;
    };
    bool behind = false;
    for (const Undecided& u : undecided) {
        if (u.kind == Undecided::Kind::setup_pixel) {
            behind = setupBehind(u.what, u.where & 0xFFFF, u.where >> 16);
        } else if (u.kind == Undecided::Kind::setup_tile) {
            const StoredSetup& s = setups_[u.what];
            const uint32_t tx = u.where % tiles_x_, ty = u.where / tiles_x_;
            for (uint32_t py = std::max(ty << kTileShift, row_first);
                 !behind && py < std::min((ty + 1) << kTileShift, row_end); ++py)
                for (uint32_t px = tx << kTileShift;
                     !behind && px < std::min((tx + 1) << kTileShift, width_); ++px)
                    behind = certainlyCovers(s, px, py) && setupBehind(u.what, px, py);
        } else {
            // A far image's tile: each pixel whose image depth is undecided, against every
            // triangle of the primitive the exact model says covers it.
            const detail::DepthImages& far = far_images_;
            const uint32_t tile = far.tile(u.where);
            const uint32_t slot = slotOf(u.what);
            const TileState& state = tiles_[tile];
            const float band_width = bandOf(image_errors_[slot], storedError(state));
            const uint32_t tx = tile % tiles_x_, ty = tile / tiles_x_;
            const float* image = far.depths(u.where);
            for (uint32_t py = std::max(ty << kTileShift, row_first);
                 !behind && py < std::min((ty + 1) << kTileShift, row_end); ++py)
                for (uint32_t px = tx << kTileShift;
                     !behind && px < std::min((tx + 1) << kTileShift, width_); ++px) {
                    const float depth =
                        image[(py & (kTileSize - 1)) * kTileSize + (px & (kTileSize - 1))];
                    if (detail::decide(depth, *pixel(px, py), band_width) !=
                        detail::Decision::undecided)
                        continue;
                    const detail::ExactFragments& model = arbiter_.model();
                    const detail::PixelRay ray = model.rays().centre(px, py);
                    uint32_t last = std::numeric_limits<uint32_t>::max();
                    for (uint32_t k = primitive_setups_[u.what];
                         !behind && k < primitive_setups_[u.what + 1]; ++k) {
                        const StoredSetup& s = setups_[k];
                        if (s.triangle() == last || px < s.px_min || px > s.px_max ||
                            py < s.py_min || py > s.py_max)
                            continue;
                        last = s.triangle();
                        behind = model.covers(
                                     ray, detail::TriangleCorners::of(positions_, s.triangle())) &&
                                 behindSomethingDrawn(s.triangle(), px, py, context,
                                                      fragmentAt(s, px, py), errors_[k], stats);
                    }
                }
        }
        if (behind)
            break;
    }
    undecided.clear();
    return behind;
}

void CpuOracle::Impl::store(std::span<const detail::FastSetup> fan, uint32_t t) {
    for (const detail::FastSetup& s : fan) {
        const uint32_t band = conservative_ ? 0 : bandPixelsOf(s, t);
        setups_.push_back(storedSetup(s, t, band));
        narrow_.push_back(s.narrow ? 1 : 0);
        spreads_.push_back(s.spread);
        errors_.push_back(roundedUp(s.error));
    }
}

uint32_t CpuOracle::Impl::bandPixelsOf(const detail::FastSetup& setup, uint32_t t) {
    const std::size_t at = band_pixels_.size();
    band_pixels_.push_back(0); // the count, once known
    // A whole triangle well within the depth range: screen space settles most band pixels (the
    // corners stay its own, the depths between its corners' and so in the range).
    constexpr double kDepthRoom = 0x1p-20;
    const bool screen = setup.whole && setup.d_min >= kDepthRoom &&
                        (!orthographic_ || setup.d_max <= 1 - kDepthRoom);
    const std::array<double, 3> ux{setup.ux[0], setup.ux[1], setup.ux[2]};
    const std::array<double, 3> uy{setup.uy[0], setup.uy[1], setup.uy[2]};
    bool have_corners = false; // read only where the exact model must decide
    detail::TriangleCorners corners;
    uint32_t count = 0;
    detail::forEachFastBandPixel(setup, [&](uint32_t px, uint32_t py) {
        ++stats_.band_pixels;
        int covered = screen ? detail::screenCoverage(ux, uy, px, py, screen_errors_) : 0;
        if (covered == 0) {
            if (!have_corners) {
                corners = detail::TriangleCorners::of(positions_, t);
                have_corners = true;
            }
            const detail::ExactFragments& model = arbiter_.model();
            covered = model.covers(model.rays().centre(px, py), corners) ? 1 : -1;
        }
        if (covered > 0) {
            band_pixels_.push_back(py << 16 | px);
            ++count;
        }
    });
    if (count == 0) {
        band_pixels_.pop_back();
        return 0;
    }
    band_pixels_[at] = count;
    return uint32_t(at);
}

float CpuOracle::Impl::fragmentAt(const StoredSetup& s, uint32_t px, uint32_t py) const {
    return float((s.d0 + s.ddx * ((double(px) + 0.5) - s.x0)) +
                 s.ddy * ((double(py) + 0.5) - s.y0));
}

bool CpuOracle::Impl::certainlyCovers(const StoredSetup& s, uint32_t px, uint32_t py) const {
    if (px < s.px_min || px > s.px_max || py < s.py_min || py > s.py_max)
        return false;
    for (int e = 0; e < 3; ++e)
        if (s.edge_at_origin[e] + int64_t(px) * s.edge_step_x[e] + int64_t(py) * s.edge_step_y[e] <=
            0)
            return false;
    return true;
}

void CpuOracle::Impl::clearTile(std::size_t tile) const {
    std::fill_n(depth_.begin() + std::ptrdiff_t(tile * kTilePixels), kTilePixels, kInfinity);
    tiles_[tile] = {kInfinity, kInfinity, 0.0f, epoch_};
}

std::span<const float> CpuOracle::Impl::depthBuffer() const {
    for (std::size_t tile = 0; tile < tiles_.size(); ++tile)
        if (tiles_[tile].epoch != epoch_)
            clearTile(tile);
    row_major_.resize(std::size_t(width_) * height_);
    for (uint32_t y = 0; y < height_; ++y)
        for (uint32_t x = 0; x < width_; ++x)
            row_major_[std::size_t(y) * width_ + x] = *pixel(x, y);
    return row_major_;
}

template <bool kDraw, bool kFarImage>
bool CpuOracle::Impl::rasterize(const StoredSetup& s, bool narrow, double spread, float error,
                                int32_t ty_begin, int32_t ty_end, CpuOracleStats& stats,
                                QueryContext* context, uint32_t k) {
    const int32_t px_min = s.px_min, px_max = s.px_max, py_min = s.py_min, py_max = s.py_max;
    const int32_t tx_first = px_min >> kTileShift, tx_last = px_max >> kTileShift;
    const int32_t ty_first = std::max(py_min >> kTileShift, ty_begin);
    const int32_t ty_last = std::min(py_max >> kTileShift, ty_end - 1);
    if (ty_first > ty_last)
        return false; // outside the band
    const bool exact = exactRule();
    // The band pixels after the walk (the walk covers only the certain ones).
    const auto band = [&] {
        return exact && s.band_first != 0 &&
               rasterizeBand<kDraw>(s, error, ty_begin, ty_end, context, k);
    };
    if (tx_last - tx_first < detail::kSmallTiles && ty_last - ty_first < detail::kSmallTiles)
        return rasterizeSmall<kDraw, kFarImage>(s, narrow, spread, error, ty_first, ty_last, stats,
                                                context, k) ||
               band();
    const int32_t last_x = int32_t(width_) - 1, last_y = int32_t(height_) - 1;
    int64_t origin[3];
    edgeOrigins(s, origin);
    detail::TileWalk walk;
    static_cast<detail::TriangleWalk&>(walk) = walkOf<kDraw, kFarImage>(s, narrow, spread);
    for (int32_t ty = ty_first; ty <= ty_last; ++ty) {
        // Rows of the tile within the viewport, then within the triangle's bounding box.
        const int32_t vy0 = ty << kTileShift, vy1 = std::min(vy0 + int32_t(kTileSize) - 1, last_y);
        const int32_t y0 = std::max(vy0, py_min), y1 = std::min(vy1, py_max);
        const bool whole_rows = y0 == vy0 && y1 == vy1;
        // What the tiles of this row share: each edge at (px_min, y0) and its least and greatest
        // change over the rows, and the depth plane's row terms.
        int64_t edge_at_row[3], rise_low[3], rise_high[3];
        for (int e = 0; e < 3; ++e) {
            edge_at_row[e] =
                origin[e] + int64_t(px_min) * s.edgeStepX(e) + int64_t(y0) * s.edgeStepY(e);
            const int64_t span_y = int64_t(y1 - y0) * s.edgeStepY(e);
            rise_low[e] = std::min<int64_t>(span_y, 0);
            rise_high[e] = std::max<int64_t>(span_y, 0);
        }
        const double by0 = rowTerm(s, y0), by1 = rowTerm(s, y1);
        for (int32_t tx = tx_first; tx <= tx_last; ++tx) {
            ++stats.tiles_visited;
            const int32_t vx0 = tx << kTileShift;
            const int32_t vx1 = std::min(vx0 + int32_t(kTileSize) - 1, last_x);
            const int32_t x0 = std::max(vx0, px_min), x1 = std::min(vx1, px_max);

            // Coverage from the edge functions at the corners of the pixel rectangle.
            int64_t edge_row[3];
            bool inside_all = true, outside_one = false;
            for (int e = 0; e < 3; ++e) {
                edge_row[e] = edge_at_row[e] + int64_t(x0 - px_min) * s.edgeStepX(e);
                const int64_t span_x = int64_t(x1 - x0) * s.edgeStepX(e);
                const int64_t lowest = edge_row[e] + std::min<int64_t>(span_x, 0) + rise_low[e];
                const int64_t highest = edge_row[e] + std::max<int64_t>(span_x, 0) + rise_high[e];
                outside_one |= highest <= 0;
                inside_all &= lowest > 0;
            }
            const std::size_t tile = std::size_t(ty) * tiles_x_ + std::size_t(tx);
            if (outside_one) {
                ++stats.tiles_culled;
                continue;
            }
            TileState& state = tiles_[tile];
            if (state.epoch != epoch_) {
                // Cleared since last touched: a query finds nothing behind +infinity.
                if constexpr (!kDraw) {
                    ++stats.tiles_culled;
                    continue;
                }
                clearTile(tile);
            }
            const bool full_tile = inside_all && whole_rows && x0 == vx0 && x1 == vx1;

            // Rounding to float is monotone: every fragment lies in [float(lowest),
            // float(highest)], and these decide every comparison with a float exactly.
            double lowest, highest;
            depthBounds(s, columnTerm(s, x0), columnTerm(s, x1), by0, by1, walk.offset, spread,
                        lowest, highest);
            bool all_pass = false;
            if constexpr (kDraw) {
                // Every fragment drawn here counts in the tile's error, passing or not.
                if (error > global_error_)
                    state.error = std::max(state.error, error);
                // Every fragment >= the tile's max >= every stored depth: none passes LESS.
                if (float(lowest) >= state.max) {
                    ++stats.tiles_culled;
                    continue;
                }
                // Every fragment < the tile's min <= every stored depth: all pass, no depth test
                // needed (the common case back to front).
                all_pass = float(highest) < state.min;
            } else {
                if (exact) {
                    const float band_width = bandOf(error, storedError(state));
                    walk.behind_above = band_width;
                    walk.undecided_above = -band_width;
                }
                // Every fragment <= the tile's min + threshold <= stored + threshold: none
                // behind, none undecided.
                const float threshold = exact ? walk.undecided_above : walk.behind_above;
                if (float(highest) <= state.min + threshold) {
                    ++stats.tiles_culled;
                    continue;
                }
                // Every pixel covered, every fragment > the tile's max + threshold: behind
                // somewhere.
                if (full_tile && float(lowest) > state.max + walk.behind_above) {
                    ++stats.tiles_accepted;
                    return true;
                }
            }

            // Per pixel (fast_rows.h): rule 6's expression, (d0 + ddx (cx - x0)) + ddy (cy - y0).
            walk.origin = tileDepths(tile) + std::size_t(y0 - vy0) * kTileSize;
            walk.vx0 = vx0;
            walk.y0 = y0;
            walk.lane_first = x0 - vx0;
            walk.lane_last = x1 - vx0;
            walk.rows = y1 - y0 + 1;
            walk.all_covered = inside_all;
            for (int e = 0; e < 3; ++e)
                walk.edge[e] = edge_row[e];
            if constexpr (kDraw) {
                if (all_pass) {
                    fill_tile_(walk);
                    // Bounds from the depth bounds instead of the pixels: every fragment written
                    // lies in [float(lowest), float(highest)].
                    state.min = std::min(state.min, float(lowest));
                    if (full_tile)
                        state.max = float(highest);
                    continue;
                }
                detail::TileDraw result;
                draw_tile_(walk, result);
                state.min = std::min(state.min, result.written_min);
                // A draw covering the whole tile visited every stored depth: the bound is exact.
                if (full_tile)
                    state.max = result.stored_max;
            } else {
                const detail::QueryResult result = query_tile_(walk);
                if (result == detail::QueryResult::behind)
                    return true;
                if (result == detail::QueryResult::undecided)
                    context->undecided->push_back({Undecided::Kind::setup_tile, k, uint32_t(tile)});
            }
        }
    }
    return band();
}

template <bool kDraw>
bool CpuOracle::Impl::rasterizeBand(const StoredSetup& s, float error, int32_t ty_begin,
                                    int32_t ty_end, QueryContext* context, uint32_t k) {
    const uint32_t count = band_pixels_[s.band_first];
    const uint32_t* pixels = band_pixels_.data() + s.band_first + 1;
    const uint32_t row_first = uint32_t(ty_begin) << kTileShift;
    const uint32_t row_end = uint32_t(ty_end) << kTileShift;
    for (uint32_t i = 0; i < count; ++i) {
        const uint32_t px = pixels[i] & 0xFFFF, py = pixels[i] >> 16;
        if (py < row_first || py >= row_end)
            continue;
        const std::size_t tile = std::size_t(py >> kTileShift) * tiles_x_ + (px >> kTileShift);
        TileState& state = tiles_[tile];
        float& stored = *pixel(px, py);
        const float fragment = fragmentAt(s, px, py);
        if constexpr (kDraw) {
            if (state.epoch != epoch_)
                clearTile(tile);
            if (error > global_error_)
                state.error = std::max(state.error, error);
            if (fragment < stored) {
                stored = fragment;
                state.min = std::min(state.min, fragment);
            }
        } else {
            if (state.epoch != epoch_)
                continue; // nothing drawn there
            switch (detail::decide(fragment, stored, bandOf(error, storedError(state)))) {
            case detail::Decision::behind:
                return true;
            case detail::Decision::undecided:
                context->undecided->push_back({Undecided::Kind::setup_pixel, k, pixels[i]});
                break;
            case detail::Decision::not_behind:
                break;
            }
        }
    }
    return false;
}

template <bool kDraw, bool kFarImage>
bool CpuOracle::Impl::rasterizeSmall(const StoredSetup& s, bool narrow, double spread, float error,
                                     int32_t ty_first, int32_t ty_last, CpuOracleStats& stats,
                                     QueryContext* context, uint32_t k) {
    detail::SmallWalk walk;
    walk.depth = depth_.data();
    walk.tiles_x = tiles_x_;
    walk.px_min = s.px_min;
    walk.px_max = s.px_max;
    // The rows of the band.
    walk.py_min = std::max(int32_t(s.py_min), ty_first << kTileShift);
    walk.py_max = std::min(int32_t(s.py_max), (ty_last << kTileShift) + int32_t(kTileSize) - 1);
    int64_t origin[3];
    edgeOrigins(s, origin);
    for (int e = 0; e < 3; ++e)
        walk.edge[e] = origin[e] + int64_t(walk.px_min) * s.edgeStepX(e) +
                       int64_t(walk.py_min) * s.edgeStepY(e);
    // narrow holds over the whole bounds, so over the band's rows too.
    static_cast<detail::TriangleWalk&>(walk) = walkOf<kDraw, kFarImage>(s, narrow, spread);
    double lowest, highest;
    depthBounds(s, columnTerm(s, walk.px_min), columnTerm(s, walk.px_max), rowTerm(s, walk.py_min),
                rowTerm(s, walk.py_max), walk.offset, spread, lowest, highest);
    const bool exact = exactRule();

    // Which tiles to walk, decided as the tile walk decides (rasterize), with the triangle's
    // depth bounds for each tile's. A query's band is the widest of its live tiles'.
    const int32_t tx_first = walk.px_min >> kTileShift, tx_last = walk.px_max >> kTileShift;
    bool any = false;
    float widest = 0;
    for (int32_t ty = ty_first; ty <= ty_last; ++ty)
        for (int32_t tx = tx_first; tx <= tx_last; ++tx) {
            ++stats.tiles_visited;
            const std::size_t tile = std::size_t(ty) * tiles_x_ + std::size_t(tx);
            TileState& state = tiles_[tile];
            bool& live = walk.live[ty - ty_first][tx - tx_first];
            if constexpr (kDraw) {
                if (state.epoch != epoch_)
                    clearTile(tile);
                // Every fragment drawn here counts in the tile's error, passing or not.
                if (error > global_error_)
                    state.error = std::max(state.error, error);
                // Every fragment >= the tile's max >= every stored depth: none passes LESS.
                live = lowest < double(state.max);
            } else if (exact) {
                // Cleared since last touched (nothing is behind +infinity), or every fragment
                // <= the tile's min - band: none behind, none undecided.
                const float band_width = bandOf(error, storedError(state));
                live = state.epoch == epoch_ && float(highest) > state.min - band_width;
                if (live)
                    widest = std::max(widest, band_width);
            } else {
                // Cleared since last touched (nothing is behind +infinity), or every fragment
                // <= the tile's min + tolerance <= stored + tolerance: none behind.
                live = state.epoch == epoch_ && highest > double(state.min + depth_tolerance_);
            }
            stats.tiles_culled += live ? 0 : 1;
            any |= live;
        }
    if (!any)
        return false;
    const bool simd_walk = use_simd_ && walk.narrow;
    if constexpr (kDraw) {
        detail::SmallDraw drawn;
        (simd_walk ? draw_small_ : detail::scalarRowKernels().draw_small)(walk, drawn);
        // Stored depths only fall, so max stays a bound; min follows the writes.
        for (int32_t ty = ty_first; ty <= ty_last; ++ty)
            for (int32_t tx = tx_first; tx <= tx_last; ++tx) {
                float& least = tiles_[std::size_t(ty) * tiles_x_ + std::size_t(tx)].min;
                least = std::min(least, drawn.written_min[ty - ty_first][tx - tx_first]);
            }
        return false;
    } else {
        if (exact) {
            walk.behind_above = widest;
            walk.undecided_above = -widest;
        }
        const detail::QueryResult result =
            (simd_walk ? query_small_ : detail::scalarRowKernels().query_small)(walk);
        if (result == detail::QueryResult::undecided)
            for (int32_t ty = ty_first; ty <= ty_last; ++ty)
                for (int32_t tx = tx_first; tx <= tx_last; ++tx)
                    if (walk.live[ty - ty_first][tx - tx_first])
                        context->undecided->push_back(
                            {Undecided::Kind::setup_tile, k,
                             uint32_t(std::size_t(ty) * tiles_x_ + std::size_t(tx))});
        return result == detail::QueryResult::behind;
    }
}

void CpuOracle::Impl::draw(uint32_t primitive) {
    assert(primitive < primitive_count_);
    ++stats_.draws;
    stamp(primitive);
    makeImage<true>(primitive);
    drawIn(primitive, wholeScreen(), stats_);
}

bool CpuOracle::Impl::anyBehind(uint32_t primitive) {
    assert(primitive < primitive_count_);
    ++stats_.queries;
    makeImage<false>(primitive);
    QueryContext context{&undecided_, clock_, &arbitration_lists_};
    return queryIn(primitive, wholeScreen(), stats_, context);
}

// Bands per thread. Each band repeats the walk over the whole sequence (per triangle: its range,
// its set-ups, the band test), which is most of a small triangle's cost: measured on the bunnies'
// pass 1 (66,132 triangles, 2 threads), 3 bands per thread took 5.0 ms, 1 band per thread 3.5 ms,
// one thread 6.0 ms. Bands are still claimed in turn, so more per thread is one constant away.
constexpr uint32_t kBandsPerThread = 1;

uint32_t CpuOracle::Impl::bandsFor(std::size_t count) const {
    if (threads_ <= 1 || count < parallel_threshold_ || count == 0 || tiles_y_ < 2)
        return 1;
    return std::min(threads_ * kBandsPerThread, tiles_y_);
}

void CpuOracle::Impl::bandRows(uint32_t b, uint32_t bands, int32_t& first, int32_t& last) const {
    first = int32_t(uint64_t(b) * tiles_y_ / bands);
    last = int32_t(uint64_t(b + 1) * tiles_y_ / bands);
}

template <class Band> void CpuOracle::Impl::runBands(uint32_t bands, Band&& band) {
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

// Each band runs the whole sequence on its own tile rows: a tile sees the same draws and queries
// in the same order as with one thread, so it ends with the same depths; a query is behind when
// it is behind in some tile, so the answer is the OR over bands. Answers are set to 0 first, then
// a band that finds a fragment behind stores 1 (a relaxed atomic store: every writer writes the
// same value, and the pool's join publishes it); a band skips a query another band has answered.
void CpuOracle::Impl::backToFrontPass(uint32_t bands, std::span<const uint32_t> sequence,
                                      std::span<const uint8_t> query, std::span<uint8_t> behind) {
    clearBuffer();
    for (std::size_t i = 0; i < sequence.size(); ++i) {
        assert(sequence[i] < primitive_count_);
        if (query[i]) {
            behind[i] = 0;
            ++stats_.queries;
        }
    }
    stats_.draws += sequence.size();
    // Every image the bands use, made before they start; the draws' times, as the sequential
    // pass would stamp them, and each query's (drawnBefore).
    query_times_.resize(sequence.size());
    reserveClock(sequence.size());
    for (std::size_t i = sequence.size(); i-- > 0;) {
        makeImage<true>(sequence[i]);
        if (query[i])
            makeImage<false>(sequence[i]);
        query_times_[i] = clock_;
        stamp(sequence[i]);
    }
    if (band_undecided_.size() < bands) {
        band_undecided_.resize(bands);
        band_lists_.resize(bands);
    }
    runBands(bands, [&](uint32_t b, CpuOracleStats& stats) {
        TileRect rows = wholeScreen();
        bandRows(b, bands, rows.row_first, rows.row_last);
        for (std::size_t i = sequence.size(); i-- > 0;) {
            if (query[i]) {
                std::atomic_ref<uint8_t> answer(behind[i]);
                QueryContext context{&band_undecided_[b], query_times_[i], &band_lists_[b]};
                if (answer.load(std::memory_order_relaxed) == 0 &&
                    queryIn(sequence[i], rows, stats, context))
                    answer.store(1, std::memory_order_relaxed);
            }
            drawIn(sequence[i], rows, stats);
        }
    });
}

// As backToFrontPass: each band draws every occluder into its rows, then answers every target
// there; the answers are OR-ed across bands.
void CpuOracle::Impl::queryAgainst(uint32_t bands, std::span<const uint32_t> occluders,
                                   std::span<const uint32_t> targets, std::span<uint8_t> behind) {
    clearBuffer();
    std::fill(behind.begin(), behind.end(), uint8_t(0));
    stats_.draws += occluders.size();
    stats_.queries += targets.size();
    // Only the pixels of the targets decide the answers, so an occluder's set-up whose bounds miss
    // the targets' bounds is not drawn: the depths there are the same, the answers too. A cycle
    // search tests a few targets against much of the list (source_cycle.cpp), most of it
    // elsewhere on the screen.
    int32_t x_min = int32_t(width_), x_max = -1, y_min = int32_t(height_), y_max = -1;
    for (uint32_t p : targets) {
        assert(p < primitive_count_);
        // A primitive with an image slot has its set-ups' bounds at hand (objects of thousands
        // of triangles: the walk over them was a sixth of the power plant's ordering time).
        if (const uint32_t slot = slotOf(p); slot != kNoSlot) {
            const PixelRect& r = imaged_rects_[slot];
            x_min = std::min(x_min, r.x_min);
            x_max = std::max(x_max, r.x_max);
            y_min = std::min(y_min, r.y_min);
            y_max = std::max(y_max, r.y_max);
            continue;
        }
        for (uint32_t k = primitive_setups_[p]; k < primitive_setups_[p + 1]; ++k) {
            x_min = std::min<int32_t>(x_min, setups_[k].px_min);
            x_max = std::max<int32_t>(x_max, setups_[k].px_max);
            y_min = std::min<int32_t>(y_min, setups_[k].py_min);
            y_max = std::max<int32_t>(y_max, setups_[k].py_max);
        }
    }
    if (x_min > x_max || y_min > y_max)
        return; // no target has a fragment
    const TileRect near_targets{y_min >> kTileShift, (y_max >> kTileShift) + 1, x_min >> kTileShift,
                                x_max >> kTileShift};
    // Every image the bands use, made before they start: the targets', and those of the
    // occluders that reach the targets' bounds.
    for (uint32_t p : occluders) {
        assert(p < primitive_count_);
        const uint32_t slot = slotOf(p);
        if (slot == kNoSlot)
            continue;
        const PixelRect& r = imaged_rects_[slot];
        if (r.x_min <= x_max && r.x_max >= x_min && r.y_min <= y_max && r.y_max >= y_min)
            makeImage<true>(p);
    }
    for (uint32_t p : targets)
        makeImage<false>(p);
    reserveClock(occluders.size());
    for (uint32_t p : occluders)
        stamp(p);
    const uint32_t time = clock_;
    if (band_undecided_.size() < std::max<uint32_t>(bands, 1)) {
        band_undecided_.resize(std::max<uint32_t>(bands, 1));
        band_lists_.resize(std::max<uint32_t>(bands, 1));
    }
    const auto band = [&](uint32_t b, CpuOracleStats& stats) {
        TileRect rect = near_targets; // within the band's rows
        int32_t first_row, last_row;
        bandRows(b, bands, first_row, last_row);
        rect.row_first = std::max(rect.row_first, first_row);
        rect.row_last = std::min(rect.row_last, last_row);
        if (rect.row_first >= rect.row_last)
            return;
        for (uint32_t p : occluders)
            drawIn(p, rect, stats);
        for (std::size_t i = 0; i < targets.size(); ++i) {
            std::atomic_ref<uint8_t> answer(behind[i]);
            QueryContext context{&band_undecided_[b], time, &band_lists_[b]};
            if (answer.load(std::memory_order_relaxed) == 0 &&
                queryIn(targets[i], rect, stats, context))
                answer.store(1, std::memory_order_relaxed);
        }
    };
    if (bands <= 1)
        band(0, stats_);
    else
        runBands(bands, band);
}

// The interface: one call into Impl each.

CpuOracle::CpuOracle() : CpuOracle(Options{}) {}

CpuOracle::CpuOracle(const Options& options) : impl_(std::make_unique<Impl>(options)) {}

CpuOracle::~CpuOracle() = default;

void CpuOracle::bind(PositionsView positions, const ViewProjection& view,
                     std::span<const PrimitiveRange> primitives) {
    impl_->bind(positions, view, primitives);
}

void CpuOracle::rebind(PositionsView positions, const ViewProjection& view,
                       std::span<const PrimitiveRange> primitives) {
    impl_->rebind(positions, view, primitives);
}

uint32_t CpuOracle::primitiveCount() const {
    return impl_->primitive_count_;
}
void CpuOracle::clear() {
    impl_->clearBuffer();
}
std::span<const float> CpuOracle::depthBuffer() const {
    return impl_->depthBuffer();
}
bool CpuOracle::usesSimd() const {
    return impl_->use_simd_;
}
uint32_t CpuOracle::threadCount() const {
    return impl_->threads_;
}
uint32_t CpuOracle::width() const {
    return impl_->width_;
}
uint32_t CpuOracle::height() const {
    return impl_->height_;
}
const CpuOracleStats& CpuOracle::stats() const {
    return impl_->stats_;
}
void CpuOracle::resetStats() {
    impl_->stats_ = {};
}

void CpuOracle::draw(uint32_t primitive) {
    impl_->setTolerance(depth_tolerance_);
    impl_->draw(primitive);
}

bool CpuOracle::anyBehind(uint32_t primitive) {
    impl_->setTolerance(depth_tolerance_);
    return impl_->anyBehind(primitive);
}

void CpuOracle::backToFrontPass(std::span<const uint32_t> sequence, std::span<const uint8_t> query,
                                std::span<uint8_t> behind) {
    assert(query.size() == sequence.size() && behind.size() == sequence.size());
    const uint32_t bands = impl_->bandsFor(sequence.size());
    if (bands <= 1) {
        OcclusionOracle::backToFrontPass(sequence, query, behind);
        return;
    }
    impl_->setTolerance(depth_tolerance_);
    impl_->backToFrontPass(bands, sequence, query, behind);
}

void CpuOracle::queryAgainst(std::span<const uint32_t> occluders, std::span<const uint32_t> targets,
                             std::span<uint8_t> behind) {
    assert(behind.size() == targets.size());
    impl_->setTolerance(depth_tolerance_);
    impl_->queryAgainst(impl_->bandsFor(occluders.size() + targets.size()), occluders, targets,
                        behind);
}

} // namespace vissort
