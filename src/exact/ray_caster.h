#pragma once
// All-hits ray casting through every pixel centre, the reference behind the exact oracle, depth
// complexity and the tests' A-buffer. The hits are those of the exact fragment model
// (geometry/exact_fragments.h): Embree's BVH proposes every triangle whose slightly enlarged box
// the ray crosses, and the model decides, exactly, which of them the ray meets and in which
// order, so that no answer depends on Embree's float arithmetic.

#include <cassert>
#include <cstdint>
#include <span>
#include <vector>

#include "vissort/camera.h"
#include "vissort/geometry.h"

namespace vissort::detail {

/// A hit is robust when all three barycentric coordinates exceed this: not on an edge or corner,
/// where a neighbouring triangle may or may not also be hit.
inline constexpr double kRobustBarycentric = 1e-6;

/// A robust hit's triangle also covers the square of half-side kRobustPixelMargin pixels around
/// the pixel centre: the centre is that far from every edge in screen space, farther than a
/// rasterizer's 8-bit sub-pixel snapping can move an edge (at most about 0.003 px).
inline constexpr double kRobustPixelMargin = 0.01;

/// Every hit of every pixel's ray, in compressed rows: pixel i = py * width + px owns the hits
/// [offsets[i], offsets[i + 1]), sorted front to back by the exact model, exact ties by
/// triangle id, one per triangle.
struct AllHits {
    uint32_t width = 0, height = 0;
    std::vector<uint64_t> offsets;   // pixelCount() + 1 entries
    std::vector<uint32_t> triangles; // triangle id of each hit
    std::vector<uint32_t> ranks;     // exact depth rank at its pixel: 0 nearest, ties share one
    std::vector<double> depths;      // depth d (camera.h), rounded: ranks order the hits
    std::vector<uint8_t> robust;     // 1 when every barycentric coordinate > kRobustBarycentric
    /// With mark_near_edges, one per pixel: 1 when a triangle the centre's ray misses covers a
    /// corner of the square of half-side kRobustPixelMargin around it (an edge passes that close:
    /// a rasterizer may cover the pixel with it); empty otherwise.
    std::vector<uint8_t> near_edge;

    std::size_t pixelCount() const { return std::size_t(width) * height; }
    std::size_t hitCount() const { return triangles.size(); }
    uint64_t firstHit(std::size_t pixel) const {
        assert(pixel < pixelCount());
        return offsets[pixel];
    }
    uint64_t endHit(std::size_t pixel) const {
        assert(pixel < pixelCount());
        return offsets[pixel + 1];
    }
};

/// Casts the ray through the centre of every pixel of view (ViewProjection::pixelRay at
/// (px + 0.5, py + 0.5), row 0 at the top) and records all its hits: the fragments of the exact
/// fragment model, which keeps hits within the depth range (0 <= d, and d <= 1 orthographic).
/// Degenerate triangles (zero area, non-finite corners) and triangles seen edge-on are never hit.
/// thread_count 0 uses the hardware concurrency; the result is the same for any thread count.
/// mark_near_edges also casts the four corner rays of each pixel's margin square (five rays a
/// pixel) to fill AllHits::near_edge. Throws std::runtime_error when no Embree device can be
/// created.
AllHits castAllHits(PositionsView positions, const ViewProjection& view, unsigned thread_count = 0,
                    bool mark_near_edges = false);

/// castAllHits over the triangles of ranges only (the others are not there): what an oracle bound
/// to some of the triangles needs (a multi-stage frame binds each group's). Ranks order the
/// hits among those triangles.
AllHits castHitsOf(PositionsView positions, std::span<const PrimitiveRange> ranges,
                   const ViewProjection& view, unsigned thread_count = 0);

} // namespace vissort::detail
