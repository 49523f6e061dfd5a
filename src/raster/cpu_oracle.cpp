// The reference occlusion oracle: Vis-sort's queries (Govindaraju, Henson, Lin, Manocha, I3D 2005,
// section 4) answered by the plain depth rasterizer of cpu_rasterizer.h.

#include "vissort/cpu_oracle.h"

#include <algorithm>
#include <cassert>
#include <limits>

#include "raster/cpu_rasterizer.h"

namespace vissort {
namespace {

template <class Corner> detail::ClipVertex toClipVertex(const Corner& corner) {
    return {corner.x, corner.y, corner.z, corner.w};
}

} // namespace

void CpuOracle::bind(PositionsView positions, const ViewProjection& view,
                     std::span<const PrimitiveRange> primitives) {
    assert(view.width >= 1 && view.width <= detail::kMaxViewportSize);
    assert(view.height >= 1 && view.height <= detail::kMaxViewportSize);
    assert(positions.y.size() == positions.x.size() && positions.z.size() == positions.x.size());
    width_ = view.width;
    height_ = view.height;
    primitives_.assign(primitives.begin(), primitives.end());
    for ([[maybe_unused]] const PrimitiveRange& range : primitives_)
        assert(uint64_t(range.first_triangle) + range.triangle_count <= positions.triangleCount());

    const detail::Matrix4 m = detail::multiply(view.projection_matrix, view.view);
    const std::size_t corner_count = positions.triangleCount() * 3;
    corners_.resize(corner_count);
    for (std::size_t i = 0; i < corner_count; ++i) {
        const detail::ClipVertex c =
            detail::toClipSpace(m, positions.x[i], positions.y[i], positions.z[i]);
        corners_[i] = {c.x, c.y, c.z, c.w};
    }
    depth_.resize(std::size_t(width_) * height_);
    clear();
}

void CpuOracle::clear() {
    std::fill(depth_.begin(), depth_.end(), std::numeric_limits<float>::infinity());
}

void CpuOracle::draw(uint32_t primitive) {
    assert(primitive < primitives_.size());
    ++stats_.draws;
    const PrimitiveRange range = primitives_[primitive];
    uint64_t fragments = 0;
    const auto write = [&](uint32_t px, uint32_t py, float depth) {
        ++fragments;
        float& stored = depth_[std::size_t(py) * width_ + px];
        if (depth < stored)
            stored = depth;
        return false;
    };
    for (uint32_t t = range.first_triangle; t < range.first_triangle + range.triangle_count; ++t) {
        const std::size_t c = std::size_t(t) * 3;
        const auto a = toClipVertex(corners_[c]), b = toClipVertex(corners_[c + 1]),
                   d = toClipVertex(corners_[c + 2]);
        if (mode_ == RasterMode::exact) {
            detail::rasterizeTriangleFor(true, depth_tolerance_, a, b, d, width_, height_, write);
        } else {
            detail::rasterizeTriangleConservative(a, b, d, width_, height_,
                                                  [&](uint32_t px, uint32_t py, float nearest,
                                                      float) { return write(px, py, nearest); });
        }
    }
    stats_.fragments_drawn += fragments;
}

bool CpuOracle::anyBehind(uint32_t primitive) {
    assert(primitive < primitives_.size());
    ++stats_.queries;
    const PrimitiveRange range = primitives_[primitive];
    uint64_t fragments = 0;
    bool behind = false;
    const auto test = [&](uint32_t px, uint32_t py, float depth) {
        ++fragments;
        return depth > depth_[std::size_t(py) * width_ + px] + depth_tolerance_;
    };
    for (uint32_t t = range.first_triangle;
         t < range.first_triangle + range.triangle_count && !behind; ++t) {
        const std::size_t c = std::size_t(t) * 3;
        const auto a = toClipVertex(corners_[c]), b = toClipVertex(corners_[c + 1]),
                   d = toClipVertex(corners_[c + 2]);
        if (mode_ == RasterMode::exact) {
            behind = detail::rasterizeTriangleFor(false, depth_tolerance_, a, b, d, width_, height_,
                                                  test);
        } else {
            behind = detail::rasterizeTriangleConservative(
                a, b, d, width_, height_, [&](uint32_t px, uint32_t py, float, float farthest) {
                    return test(px, py, farthest);
                });
        }
    }
    stats_.fragments_tested += fragments;
    return behind;
}

} // namespace vissort
