#pragma once
// Depth complexity of a view: how many surfaces each pixel's ray crosses (the d of the paper's
// transparency figures, and what bounds depth peeling's passes), by ray casting with Embree.
//
// Layer: vissort::exact (the package's `exact` component; docs/architecture.md).

#include <cstdint>
#include <vector>

#include "vissort/camera.h"
#include "vissort/geometry.h"

namespace vissort {

/// Hits of one ray closer than this in depth d (camera.h) are one surface crossed: a ray through
/// an edge or a corner that several triangles share hits each of them at the same point (a
/// quad's diagonal would count twice); faces lying on each other count once too.
inline constexpr double kSameSurfaceDepth = 1e-12;

/// Surfaces crossed per pixel: the most, the mean over covered pixels, and the histogram.
/// A surface crossed is a hit of the pixel's ray, hits at the same depth (kSameSurfaceDepth)
/// counted once.
struct DepthComplexity {
    uint32_t width = 0, height = 0;  // the grid of rays cast
    uint64_t max = 0;                // the most surfaces one ray crosses
    uint64_t covered_pixels = 0;     // rays that cross at least one triangle
    uint64_t hits = 0;               // surfaces crossed, over every ray
    double mean = 0;                 // hits / covered_pixels; 0 when nothing is covered
    std::vector<uint64_t> histogram; // histogram[d]: pixels whose ray crosses d surfaces,
                                     // d = 0..max (max + 1 entries)
};

/// The largest side of estimateDepthComplexity's ray grid by default: enough for a histogram,
/// fast on big scenes.
inline constexpr uint32_t kDepthComplexityGridSide = 256;

/// Casts one ray through the centre of every pixel of view and counts the surfaces it crosses
/// with depth 0 <= d <= 1 (degenerate triangles never count; hits at the same depth once).
/// thread_count 0 uses the hardware concurrency; the result is the same for any thread count.
/// Throws std::runtime_error when no Embree device can be created.
DepthComplexity measureDepthComplexity(PositionsView positions, const ViewProjection& view,
                                       unsigned thread_count = 0);

/// Estimates the depth complexity of a width x height view of camera framed to `framing` on a
/// grid of at most max_side rays a side with the view's aspect ratio (the full size when it is
/// smaller). width, height and max_side must be positive.
DepthComplexity estimateDepthComplexity(PositionsView positions, const CameraSpec& camera,
                                        const Bounds& framing, uint32_t width, uint32_t height,
                                        uint32_t max_side = kDepthComplexityGridSide);

} // namespace vissort
