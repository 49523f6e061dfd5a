// Depth complexity by ray casting: the hits of each pixel's ray (the Embree caster of the exact
// oracle), counted per pixel, those at the same depth once.

#include "vissort/depth_complexity.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <vector>

#include "exact/ray_caster.h"

namespace vissort {

DepthComplexity measureDepthComplexity(PositionsView positions, const ViewProjection& view,
                                       unsigned thread_count) {
    const detail::AllHits hits = detail::castAllHits(positions, view, thread_count);
    DepthComplexity result;
    result.width = hits.width;
    result.height = hits.height;
    std::vector<double> depths;
    for (std::size_t p = 0; p < hits.pixelCount(); ++p) {
        // Hits at the same depth are one surface: a ray through an edge or a corner shared by
        // several triangles hits each of them (a quad's diagonal counted twice), as it does
        // faces lying on each other.
        depths.assign(hits.depths.begin() + long(hits.firstHit(p)),
                      hits.depths.begin() + long(hits.endHit(p)));
        std::sort(depths.begin(), depths.end());
        uint64_t n = 0;
        for (std::size_t i = 0; i < depths.size(); ++i)
            n += i == 0 || depths[i] - depths[i - 1] > kSameSurfaceDepth ? 1 : 0;
        result.hits += n;
        result.covered_pixels += n > 0 ? 1 : 0;
        result.max = std::max(result.max, n);
        if (n >= result.histogram.size())
            result.histogram.resize(n + 1, 0);
        ++result.histogram[n];
    }
    if (result.histogram.empty())
        result.histogram.assign(1, 0);
    result.mean = result.covered_pixels ? double(result.hits) / double(result.covered_pixels) : 0.0;
    return result;
}

DepthComplexity estimateDepthComplexity(PositionsView positions, const CameraSpec& camera,
                                        const Bounds& framing, uint32_t width, uint32_t height,
                                        uint32_t max_side) {
    assert(width > 0 && height > 0 && max_side > 0);
    const double scale = std::min(1.0, double(max_side) / std::max(width, height));
    const uint32_t w = std::max<uint32_t>(1, uint32_t(std::lround(width * scale)));
    const uint32_t h = std::max<uint32_t>(1, uint32_t(std::lround(height * scale)));
    return measureDepthComplexity(positions, frameCamera(camera, framing, w, h));
}

} // namespace vissort
