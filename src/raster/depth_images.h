#pragma once
// Depth images of CpuOracle's large primitives (cpu_oracle.h): what a primitive of many
// triangles leaves in an empty depth buffer, kept per bind so that each later draw or query of it
// is one pass over its tiles instead of a rasterization of every triangle.
//
// Why the answers stay exact: a draw with depth test LESS leaves, at each pixel, the least of the
// stored depth and the fragments drawn there, in whatever order they come, so drawing the
// primitive equals taking the pixelwise minimum with its near image (its least fragment per
// pixel, +infinity where it has none). A query asks whether some fragment exceeds stored +
// tolerance, which holds exactly when the greatest one does: the far image (its greatest fragment
// per pixel, -infinity where it has none). Both images are made by the same rasterizer, so they
// hold the very floats the direct walks compute (the far one drawn with the depth plane negated:
// rounding to nearest is symmetric, so -float(-v) == float(v)).

#include <cstddef>
#include <cstdint>
#include <vector>

#include "raster/fast_rows.h"

namespace vissort::detail {

/// The images of one kind (near or far) of the large primitives of a bind, each at a slot (the
/// oracle maps primitives to slots). Each slot's image is
/// a list of the screen tiles it covers, in increasing tile order, each with its 64 depths and a
/// bound on them (near: their least; far: their greatest).
class DepthImages {
public:
    enum class Kind : uint8_t {
        near, // least fragment per pixel: for draws
        far,  // greatest fragment per pixel, rasterized with the depth plane negated: queries
    };
    explicit DepthImages(Kind kind) : kind_(kind) {}

    enum class State : uint8_t {
        unbuilt, // not asked for since the last reset
        built,   // entries [first, first + count)
        direct,  // drawn and queried triangle by triangle: its image passed the budget
    };

    /// Forgets every image; each of slot_count slots becomes unbuilt.
    void reset(uint32_t slot_count);
    State state(uint32_t slot) const { return state_[slot]; }

    /// Starts slot's image: add its tiles, then finish it.
    void begin(uint32_t slot);
    /// Adds one tile of the image being built, as rasterized (a far image's negated), unless it
    /// holds no fragment (every depth +infinity).
    void addTile(uint32_t tile, const float* rasterized);
    /// Keeps the image begun last if the images' memory stays within budget_bytes; else drops
    /// it and marks the slot direct. Returns whether it was kept.
    bool finish(std::size_t budget_bytes);

    std::size_t firstEntry(uint32_t slot) const { return first_[slot]; }
    std::size_t entryCount(uint32_t slot) const { return count_[slot]; }
    uint32_t tile(std::size_t entry) const { return tiles_[entry]; }
    float bound(std::size_t entry) const { return bounds_[entry]; }
    const float* depths(std::size_t entry) const { return depths_.data() + entry * kTileFloats; }
    std::size_t bytes() const;

private:
    Kind kind_;
    std::vector<State> state_;
    std::vector<uint32_t> first_, count_; // per slot, valid when built
    std::vector<uint32_t> tiles_;         // per entry
    std::vector<float> bounds_;           // per entry
    std::vector<float> depths_;           // kTileFloats per entry
    uint32_t building_ = 0;
};

/// Draws a near image's tile into a stored tile with depth test LESS: stored = min(stored,
/// image) pixelwise. Returns the least and greatest stored depths after it.
void drawImageTile(const float* image, float* stored, float& stored_min, float& stored_max);

/// Whether some depth of a far image's tile is behind the stored depth, or else undecided, by
/// the thresholds of TriangleWalk (fast_rows.h).
QueryResult queryImageTile(const float* image, const float* stored, float behind_above,
                           float undecided_above);

} // namespace vissort::detail
