// The ray-cast A-buffer (a_buffer.h).

#include "a_buffer.h"

#include <algorithm>
#include <cmath>

#include "exact/ray_caster.h"

namespace vissort::test {

ABuffer rayCastComposite(const TrianglePositions& positions, const ViewProjection& view,
                         std::span<const Rgba> triangle_colours, Rgba background) {
    const detail::AllHits hits = detail::castAllHits(positions, view, 0, true);
    ABuffer out;
    out.width = hits.width;
    out.height = hits.height;
    out.rgb.resize(hits.pixelCount() * 3);
    out.decided.resize(hits.pixelCount());
    std::vector<uint32_t> order; // a pixel's transparent hits, nearest first, ties by id
    for (std::size_t pixel = 0; pixel < hits.pixelCount(); ++pixel) {
        // Hits come sorted by depth: those that show end at the first opaque one.
        const uint64_t first = hits.firstHit(pixel);
        uint64_t end = first;
        while (end < hits.endHit(pixel) && triangle_colours[hits.triangles[end]].a < 1.0f)
            ++end;
        const bool opaque_hit = end < hits.endHit(pixel);
        const uint64_t last = opaque_hit ? end + 1 : end; // shown hits: [first, last)
        // The tie rule (docs/robustness.md): hits at exactly the same depth (the same face in
        // two objects) show the lower triangle id in front.
        order.assign(hits.triangles.begin() + first, hits.triangles.begin() + end);
        for (std::size_t i = 1; i < order.size(); ++i)
            for (std::size_t j = i; j > 0 && hits.depths[first + j] == hits.depths[first + j - 1] &&
                                    order[j] < order[j - 1];
                 --j)
                std::swap(order[j], order[j - 1]);
        // An edge that passes within the margin of the centre, of a triangle the ray misses, may
        // cover the pixel in a rasterizer. Near ties that are not exact are left undecided.
        // Only copies of one triangle (the same corners in the same order) rasterize to the same
        // depths bit for bit; other hits at one depth here may differ in the renderer's floats.
        const auto same_corners = [&](uint32_t a, uint32_t b) {
            for (int k = 0; k < 3; ++k) {
                const std::size_t i = std::size_t(a) * 3 + k, j = std::size_t(b) * 3 + k;
                if (positions.x[i] != positions.x[j] || positions.y[i] != positions.y[j] ||
                    positions.z[i] != positions.z[j])
                    return false;
            }
            return true;
        };
        const auto near_tie = [&](uint64_t a, uint64_t b) {
            const double gap = hits.depths[b] - hits.depths[a];
            return gap <= kTieDepth &&
                   !(gap == 0 && same_corners(hits.triangles[a], hits.triangles[b]));
        };
        bool decided = !hits.near_edge[pixel];
        for (uint64_t h = first; h < last; ++h) {
            decided = decided && hits.robust[h];
            if (h + 1 < last)
                decided = decided && !near_tie(h, h + 1);
        }
        // A hit just behind the last shown one may be a tie with it too (an exact one with the
        // opaque hit is not decided either: which one shows is the driver's).
        if (last < hits.endHit(pixel) && last > first)
            decided = decided && hits.depths[last] - hits.depths[last - 1] > kTieDepth;
        if (opaque_hit && end > first)
            decided = decided && hits.depths[end] != hits.depths[end - 1];
        out.decided[pixel] = decided;
        out.max_layers = std::max(out.max_layers, uint32_t(end - first));

        double c[3] = {background.r, background.g, background.b};
        if (opaque_hit) {
            const Rgba& o = triangle_colours[hits.triangles[end]];
            c[0] = o.r;
            c[1] = o.g;
            c[2] = o.b;
        }
        for (std::size_t i = order.size(); i-- > 0;) { // back to front
            const Rgba& t = triangle_colours[order[i]];
            const double a = t.a;
            c[0] = a * t.r + (1 - a) * c[0];
            c[1] = a * t.g + (1 - a) * c[1];
            c[2] = a * t.b + (1 - a) * c[2];
        }
        std::copy(c, c + 3, &out.rgb[pixel * 3]);
    }
    return out;
}

ABuffer resolveSamples(const ABuffer& samples, uint32_t columns, uint32_t rows) {
    ABuffer out;
    out.width = samples.width / columns;
    out.height = samples.height / rows;
    out.rgb.assign(std::size_t(out.width) * out.height * 3, 0.0);
    out.decided.assign(std::size_t(out.width) * out.height, 1);
    out.max_layers = samples.max_layers;
    for (uint32_t y = 0; y < out.height; ++y)
        for (uint32_t x = 0; x < out.width; ++x) {
            const std::size_t pixel = std::size_t(y) * out.width + x;
            for (uint32_t row = 0; row < rows; ++row)
                for (uint32_t column = 0; column < columns; ++column) {
                    const std::size_t sample =
                        std::size_t(y * rows + row) * samples.width + x * columns + column;
                    out.decided[pixel] &= samples.decided[sample];
                    for (int k = 0; k < 3; ++k)
                        out.rgb[pixel * 3 + k] += samples.rgb[sample * 3 + k] / (columns * rows);
                }
        }
    return out;
}

ABufferComparison compareWithABuffer(const std::vector<uint8_t>& rgba8, const ABuffer& reference) {
    ABufferComparison result;
    if (rgba8.size() != std::size_t(reference.width) * reference.height * 4) {
        result.max_abs = 255;
        return result;
    }
    for (std::size_t pixel = 0; pixel < reference.decided.size(); ++pixel) {
        if (!reference.decided[pixel])
            continue;
        ++result.compared;
        for (int k = 0; k < 3; ++k) {
            const double v = std::clamp(reference.rgb[pixel * 3 + k], 0.0, 1.0);
            const int expected = int(std::lround(v * 255));
            const int difference = std::abs(int(rgba8[pixel * 4 + k]) - expected);
            if (difference > result.max_abs) {
                result.max_abs = difference;
                result.worst_x = uint32_t(pixel % reference.width);
                result.worst_y = uint32_t(pixel / reference.width);
            }
        }
    }
    return result;
}

} // namespace vissort::test
