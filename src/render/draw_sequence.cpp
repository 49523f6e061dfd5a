#include "render/draw_sequence.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>

namespace vissort::detail {

void sequenceFromOrder(std::span<const uint32_t> front_to_back,
                       std::span<const PrimitiveRange> primitives,
                       std::span<const uint32_t> group_of, DrawSequence& sequence) {
    sequence.clear();
    uint32_t current = kNoGroup;
    for (std::size_t i = front_to_back.size(); i-- > 0;) {
        const uint32_t p = front_to_back[i];
        const uint32_t g = group_of.empty() ? kNoGroup : group_of[p];
        // A new segment where a group starts or ends; blended primitives share one.
        if (sequence.segments.empty() || g != current)
            sequence.segments.push_back(
                {uint32_t(sequence.triangles.size()), 0, g != kNoGroup, PixelRect{}});
        current = g;
        for (uint32_t t = 0; t < primitives[p].triangle_count; ++t)
            sequence.triangles.push_back(primitives[p].first_triangle + t);
        sequence.segments.back().triangle_count += primitives[p].triangle_count;
    }
}

namespace {

// Distance along the view direction: monotone in depth for both projections, and defined for
// points behind the eye.
double depthAlongView(const Vec3& point, const ViewProjection& view) {
    return dot(point - view.eye_position, view.forward);
}

} // namespace

void blendGroupsInSequence(PositionsView positions, const ViewProjection& view,
                           DrawSequence& sequence) {
    std::vector<std::pair<double, uint32_t>> keyed;
    for (const DrawSegment& segment : sequence.segments) {
        if (!segment.per_pixel)
            continue;
        const std::span<uint32_t> group =
            std::span(sequence.triangles).subspan(segment.first_triangle, segment.triangle_count);
        keyed.clear();
        for (uint32_t t : group) {
            const std::size_t c = std::size_t(t) * 3;
            const Vec3 sum =
                positions.corner(c) + positions.corner(c + 1) + positions.corner(c + 2);
            keyed.push_back({depthAlongView(sum / 3.0, view), t});
        }
        // Farthest first; ties by id, so that the sequence is deterministic.
        std::sort(keyed.begin(), keyed.end(), [](const auto& a, const auto& b) {
            return a.first > b.first || (a.first == b.first && a.second < b.second);
        });
        for (std::size_t i = 0; i < group.size(); ++i)
            group[i] = keyed[i].second;
    }
    if (!sequence.triangles.empty())
        sequence.segments.assign(1, {0, uint32_t(sequence.triangles.size()), false, PixelRect{}});
}

std::vector<uint32_t> centroidBackToFront(PositionsView positions,
                                          std::span<const PrimitiveRange> primitives,
                                          const ViewProjection& view) {
    std::vector<double> depth(primitives.size());
    for (std::size_t p = 0; p < primitives.size(); ++p) {
        Vec3 sum{0, 0, 0};
        const std::size_t first = std::size_t(primitives[p].first_triangle) * 3;
        const std::size_t count = std::size_t(primitives[p].triangle_count) * 3;
        for (std::size_t c = first; c < first + count; ++c)
            sum = {sum.x + positions.x[c], sum.y + positions.y[c], sum.z + positions.z[c]};
        const double n = double(std::max<std::size_t>(count, 1));
        depth[p] = depthAlongView({sum.x / n, sum.y / n, sum.z / n}, view);
    }
    std::vector<uint32_t> order(primitives.size());
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(),
                     [&](uint32_t a, uint32_t b) { return depth[a] > depth[b]; });
    return order;
}

PixelRect screenRectOf(PositionsView positions, std::span<const uint32_t> triangles,
                       const ViewProjection& view) {
    const PixelRect whole{0, 0, view.width, view.height};
    ScreenExtent extent;
    for (uint32_t t : triangles)
        for (std::size_t c = std::size_t(t) * 3; c < std::size_t(t) * 3 + 3; ++c)
            extent.add(view,
                       positions.corner(c)); // as the rasterizers (cpu_reference_oracle.h, rule 4)
    if (extent.wraps)
        return whole; // the projection wraps: no bound from corners
    if (extent.isEmpty())
        return {};
    const double low_x = extent.low_x, high_x = extent.high_x, low_y = extent.low_y,
                 high_y = extent.high_y;
    // A pixel is covered through its centre (px + 0.5): a margin of a pixel covers rounding.
    const double x0 = std::clamp(std::floor(low_x) - 1, 0.0, double(view.width));
    const double x1 = std::clamp(std::ceil(high_x) + 1, 0.0, double(view.width));
    const double y0 = std::clamp(std::floor(low_y) - 1, 0.0, double(view.height));
    const double y1 = std::clamp(std::ceil(high_y) + 1, 0.0, double(view.height));
    return {uint32_t(x0), uint32_t(y0), uint32_t(x1 - x0), uint32_t(y1 - y0)};
}

void trianglesCovering(PositionsView positions, std::span<const uint32_t> triangles,
                       const ViewProjection& view, const MarkedPixels& marked,
                       std::vector<uint32_t>& covering) {
    covering.clear();
    if (marked.count() == 0)
        return;
    for (uint32_t t : triangles)
        if (marked.anyTileIn(screenRectOf(positions, std::span(&t, 1), view)))
            covering.push_back(t);
}

} // namespace vissort::detail
