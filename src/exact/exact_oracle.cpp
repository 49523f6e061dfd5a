// The ray-cast reference oracle: the occlusion queries of Govindaraju, Henson, Lin, Manocha
// ("Interactive Visibility Ordering and Transparency Computations among Geometric Primitives in
// Complex Environments", I3D 2005) answered from all-hits ray casting instead of a depth buffer
// rasterized on a GPU.

#include "vissort/exact_oracle.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

#include "exact/ray_caster.h"

namespace vissort {

namespace {

constexpr uint32_t kNothing = std::numeric_limits<uint32_t>::max(); // an empty pixel

} // namespace

ExactOracle::ExactOracle(unsigned thread_count) : thread_count_(thread_count) {}

void ExactOracle::bind(PositionsView positions, const ViewProjection& view,
                       std::span<const PrimitiveRange> primitives) {
    constexpr uint32_t kNoPrimitive = std::numeric_limits<uint32_t>::max();
    assert(primitives.size() < kNoPrimitive);
    primitive_count_ = uint32_t(primitives.size());

    std::vector<uint32_t> primitive_of(positions.triangleCount(), kNoPrimitive);
    for (uint32_t p = 0; p < primitive_count_; ++p) {
        const PrimitiveRange& range = primitives[p];
        assert(uint64_t(range.first_triangle) + range.triangle_count <= primitive_of.size());
        for (uint32_t t = range.first_triangle; t < range.first_triangle + range.triangle_count;
             ++t) {
            assert(primitive_of[t] == kNoPrimitive && "primitive ranges overlap");
            primitive_of[t] = p;
        }
    }

    const detail::AllHits hits = detail::castHitsOf(positions, primitives, view, thread_count_);

    // Two passes over the hits: count each primitive's fragments, then fill them. Within a
    // pixel the hits are sorted by depth, so a primitive's first hit there is its nearest.
    // last_pixel[p] is the pixel of p's latest fragment, kNoPixel before the first one.
    constexpr uint64_t kNoPixel = std::numeric_limits<uint64_t>::max();
    std::vector<uint64_t> last_pixel(primitive_count_, kNoPixel);
    fragment_offsets_.assign(std::size_t(primitive_count_) + 1, 0);
    for (std::size_t pixel = 0; pixel < hits.pixelCount(); ++pixel) {
        for (uint64_t h = hits.firstHit(pixel); h < hits.endHit(pixel); ++h) {
            const uint32_t p = primitive_of[hits.triangles[h]];
            if (p == kNoPrimitive || last_pixel[p] == pixel)
                continue;
            last_pixel[p] = pixel;
            ++fragment_offsets_[p + 1];
        }
    }
    for (uint32_t p = 0; p < primitive_count_; ++p)
        fragment_offsets_[p + 1] += fragment_offsets_[p];

    fragments_.resize(fragment_offsets_.back());
    std::vector<uint64_t> next_fragment(fragment_offsets_.begin(), fragment_offsets_.end() - 1);
    std::fill(last_pixel.begin(), last_pixel.end(), kNoPixel);
    for (std::size_t pixel = 0; pixel < hits.pixelCount(); ++pixel) {
        for (uint64_t h = hits.firstHit(pixel); h < hits.endHit(pixel); ++h) {
            const uint32_t p = primitive_of[hits.triangles[h]];
            if (p == kNoPrimitive)
                continue;
            const uint32_t rank = hits.ranks[h];
            const double depth = hits.depths[h];
            if (last_pixel[p] == pixel) {
                Fragment& fragment = fragments_[next_fragment[p] - 1];
                fragment.farthest = rank; // hits come front to back
                fragment.farthest_depth = depth;
            } else {
                last_pixel[p] = pixel;
                fragments_[next_fragment[p]++] = {uint32_t(pixel), rank, rank, depth, depth};
            }
        }
    }

    rank_buffer_.resize(hits.pixelCount());
    depth_buffer_.resize(hits.pixelCount());
    clear();
}

void ExactOracle::clear() {
    std::fill(rank_buffer_.begin(), rank_buffer_.end(), kNothing);
    std::fill(depth_buffer_.begin(), depth_buffer_.end(), std::numeric_limits<double>::infinity());
}

std::span<const ExactOracle::Fragment> ExactOracle::fragments(uint32_t primitive) const {
    assert(primitive < primitive_count_);
    return {fragments_.data() + fragment_offsets_[primitive],
            fragments_.data() + fragment_offsets_[primitive + 1]};
}

void ExactOracle::draw(uint32_t primitive) {
    for (const Fragment& fragment : fragments(primitive)) {
        uint32_t& rank = rank_buffer_[fragment.pixel];
        rank = std::min(rank, fragment.nearest);
        double& depth = depth_buffer_[fragment.pixel];
        depth = std::min(depth, fragment.nearest_depth);
    }
}

bool ExactOracle::anyBehind(uint32_t primitive) {
    // An empty pixel holds kNothing, which no rank exceeds, and +infinity, which no depth does.
    if (depth_tolerance_ == 0) {
        for (const Fragment& fragment : fragments(primitive))
            if (fragment.farthest > rank_buffer_[fragment.pixel])
                return true;
        return false;
    }
    // An approximate rule: the depths, rounded to double, within the tolerance.
    for (const Fragment& fragment : fragments(primitive))
        if (fragment.farthest_depth > depth_buffer_[fragment.pixel] + depth_tolerance_)
            return true;
    return false;
}

} // namespace vissort
