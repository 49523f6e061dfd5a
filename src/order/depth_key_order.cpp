#include <algorithm>
#include <limits>
#include <numeric>

#include "vissort/scene_orderer.h"

namespace vissort {

std::vector<uint32_t> depthKeyOrder(PositionsView positions, const ViewProjection& view,
                                    std::span<const PrimitiveRange> primitives) {
    // The nearest corner's distance along the view direction: affine, so cheaper than depthOf
    // and it gives the same order for corners in front of the near plane.
    const Vec3 f = view.forward, e = view.eye_position;
    std::vector<double> key(primitives.size(), std::numeric_limits<double>::infinity());
    for (std::size_t p = 0; p < primitives.size(); ++p) {
        const std::size_t first = std::size_t(primitives[p].first_triangle) * 3;
        const std::size_t last = first + std::size_t(primitives[p].triangle_count) * 3;
        double nearest = std::numeric_limits<double>::infinity(), farthest = -nearest;
        for (std::size_t c = first; c < last; ++c) {
            const double z = (positions.x[c] - e.x) * f.x + (positions.y[c] - e.y) * f.y +
                             (positions.z[c] - e.z) * f.z;
            nearest = std::min(nearest, z);
            farthest = std::max(farthest, z);
        }
        // A primitive crossing the near plane starts at it; one wholly behind it is invisible.
        if (farthest >= view.near)
            key[p] = std::max(nearest, view.near);
    }
    std::vector<uint32_t> order(primitives.size());
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(),
                     [&](uint32_t a, uint32_t b) { return key[a] < key[b]; });
    return order;
}

} // namespace vissort
