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

// The snap slack of triangle t (exact_oracle.h): max(|dd/dx|, |dd/dy|) / 256 of its plane, from
// the depths where the rays through three screen points meet the plane (d is affine in screen
// space for both projections: camera.h). Infinite for a plane seen edge-on.
double snapSlackOf(PositionsView positions, const ViewProjection& view, std::size_t t) {
    const auto corner = [&](std::size_t i) {
        return Vec3{positions.x[i], positions.y[i], positions.z[i]};
    };
    const Vec3 a = corner(3 * t), b = corner(3 * t + 1), c = corner(3 * t + 2);
    const Vec3 normal = cross(b - a, c - a);
    const auto depthAt = [&](double sx, double sy, double& depth) {
        Vec3 origin, direction;
        view.pixelRay(sx, sy, origin, direction);
        const double along = dot(normal, direction);
        if (along == 0)
            return false;
        depth = view.depthOf(origin + direction * (dot(normal, a - origin) / along));
        return std::isfinite(depth);
    };
    const double cx = 0.5 * view.width, cy = 0.5 * view.height;
    double d0 = 0, dx = 0, dy = 0;
    if (!depthAt(cx, cy, d0) || !depthAt(cx + 1, cy, dx) || !depthAt(cx, cy + 1, dy))
        return std::numeric_limits<double>::infinity();
    return std::max(std::abs(dx - d0), std::abs(dy - d0)) / 256;
}

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

    const detail::AllHits hits = detail::castAllHits(positions, view, thread_count_);

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

    std::vector<double> slack(positions.triangleCount(), 0.0);
    for (std::size_t t = 0; t < slack.size(); ++t)
        if (primitive_of[t] != kNoPrimitive)
            slack[t] = snapSlackOf(positions, view, t);
    fragments_.resize(fragment_offsets_.back());
    std::vector<uint64_t> next_fragment(fragment_offsets_.begin(), fragment_offsets_.end() - 1);
    std::fill(last_pixel.begin(), last_pixel.end(), kNoPixel);
    for (std::size_t pixel = 0; pixel < hits.pixelCount(); ++pixel) {
        for (uint64_t h = hits.firstHit(pixel); h < hits.endHit(pixel); ++h) {
            const uint32_t p = primitive_of[hits.triangles[h]];
            if (p == kNoPrimitive)
                continue;
            const double depth = hits.depths[h], s = slack[hits.triangles[h]];
            if (last_pixel[p] == pixel) {
                Fragment& fragment = fragments_[next_fragment[p] - 1];
                fragment.farthest = depth; // depths ascend
                fragment.farthest_slack = s;
            } else {
                last_pixel[p] = pixel;
                fragments_[next_fragment[p]++] = {uint32_t(pixel), depth, depth, s, s};
            }
        }
    }

    depth_buffer_.resize(hits.pixelCount());
    clear();
}

void ExactOracle::clear() {
    std::fill(depth_buffer_.begin(), depth_buffer_.end(), std::numeric_limits<double>::infinity());
}

std::span<const ExactOracle::Fragment> ExactOracle::fragments(uint32_t primitive) const {
    assert(primitive < primitive_count_);
    return {fragments_.data() + fragment_offsets_[primitive],
            fragments_.data() + fragment_offsets_[primitive + 1]};
}

void ExactOracle::draw(uint32_t primitive) {
    // Farther by the slack for a tolerance >= 0 (fewer "behind" answers), nearer for a negative.
    const double side = depth_tolerance_ >= 0 ? 1.0 : -1.0;
    for (const Fragment& fragment : fragments(primitive)) {
        double& stored = depth_buffer_[fragment.pixel];
        stored = std::min(stored, fragment.nearest + side * fragment.nearest_slack);
    }
}

bool ExactOracle::anyBehind(uint32_t primitive) {
    // An empty pixel holds +infinity, and +infinity + tolerance is never exceeded.
    const double side = depth_tolerance_ >= 0 ? 1.0 : -1.0;
    for (const Fragment& fragment : fragments(primitive)) {
        if (fragment.farthest - side * fragment.farthest_slack >
            depth_buffer_[fragment.pixel] + depth_tolerance_)
            return true;
    }
    return false;
}

} // namespace vissort
