// The reference occlusion oracle: Vis-sort's queries (Govindaraju, Henson, Lin, Manocha, I3D 2005,
// section 4) answered by the plain depth rasterizer of cpu_rasterizer.h, and by the exact
// fragment model (geometry/exact_fragments.h) wherever the rasterizer's floats cannot decide.

#include "vissort/cpu_reference_oracle.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <limits>

#include "raster/cpu_rasterizer.h"
#include "raster/depth_arbiter.h"

namespace vissort {
namespace {

template <class Corner> detail::ClipVertex toClipVertex(const Corner& corner) {
    return {corner.x, corner.y, corner.z, corner.w};
}

} // namespace

CpuReferenceOracle::CpuReferenceOracle() : arbiter_(std::make_unique<detail::DepthArbiter>()) {}

CpuReferenceOracle::~CpuReferenceOracle() = default;

void CpuReferenceOracle::bind(PositionsView positions, const ViewProjection& view,
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
    positions_ = positions;
    arbiter_->bind(view, positions);
    const detail::ScreenErrors errors = detail::screenErrorsOf(m, view, positions, primitives);
    screen_position_error_ = errors.position_px;
    screen_depth_error_ = errors.depth;
    // Each triangle's pixel bounds (where the exact rule's arbitration looks for it) are made on
    // first need after each bind: a multi-stage frame binds once per group, and arbitrations
    // are rare.
    bounds_stamps_.resize(positions.triangleCount(), 0);
    if (++bind_number_ == 0) { // wrapped: every stamp is stale
        std::fill(bounds_stamps_.begin(), bounds_stamps_.end(), 0);
        bind_number_ = 1;
    }
    triangle_bounds_.resize(positions.triangleCount());
    depth_.resize(std::size_t(width_) * height_);
    error_.resize(depth_.size());
    is_drawn_.assign(primitives_.size(), 0);
    drawn_.clear();
    clear();
}

void CpuReferenceOracle::clear() {
    std::fill(depth_.begin(), depth_.end(), std::numeric_limits<float>::infinity());
    std::fill(error_.begin(), error_.end(), 0.0f);
    for (uint32_t p : drawn_)
        is_drawn_[p] = 0;
    drawn_.clear();
}

void CpuReferenceOracle::draw(uint32_t primitive) {
    assert(primitive < primitives_.size());
    ++stats_.draws;
    if (depth_tolerance_ == 0) {
        drawExact(primitive);
        return;
    }
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
        detail::rasterizeTriangleBlending(true, depth_tolerance_, a, b, d, width_, height_, write);
    }
    stats_.fragments_drawn += fragments;
}

bool CpuReferenceOracle::anyBehind(uint32_t primitive) {
    assert(primitive < primitives_.size());
    ++stats_.queries;
    if (depth_tolerance_ == 0)
        return anyBehindExact(primitive);
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
        behind = detail::rasterizeTriangleBlending(false, depth_tolerance_, a, b, d, width_,
                                                   height_, test);
    }
    stats_.fragments_tested += fragments;
    return behind;
}

void CpuReferenceOracle::drawExact(uint32_t primitive) {
    if (!is_drawn_[primitive]) {
        is_drawn_[primitive] = 1;
        drawn_.push_back(primitive);
    }
    const detail::ScreenErrors errors{screen_position_error_, screen_depth_error_};
    const PrimitiveRange range = primitives_[primitive];
    for (uint32_t t = range.first_triangle; t < range.first_triangle + range.triangle_count; ++t) {
        const std::size_t c = std::size_t(t) * 3;
        const detail::TriangleCorners corners = detail::TriangleCorners::of(positions_, t);
        detail::rasterizeTriangleExact(
            toClipVertex(corners_[c]), toClipVertex(corners_[c + 1]), toClipVertex(corners_[c + 2]),
            width_, height_, errors,
            [&](uint32_t px, uint32_t py) {
                const detail::ExactFragments& model = arbiter_->model();
                return model.covers(model.rays().centre(px, py), corners);
            },
            [&](uint32_t px, uint32_t py, float depth, double error) {
                ++stats_.fragments_drawn;
                const std::size_t i = std::size_t(py) * width_ + px;
                depth_[i] = std::min(depth_[i], depth);
                const float bound = error < 1e30 ? float(error) * (1 + 0x1p-20f)
                                                 : std::numeric_limits<float>::infinity();
                error_[i] = std::max(error_[i], bound);
                return false;
            });
    }
}

bool CpuReferenceOracle::anyBehindExact(uint32_t primitive) {
    const detail::ScreenErrors errors{screen_position_error_, screen_depth_error_};
    struct Undecided {
        uint32_t triangle, px, py;
    };
    std::vector<Undecided> undecided; // the reference allocates: plain rather than fast
    const PrimitiveRange range = primitives_[primitive];
    for (uint32_t t = range.first_triangle; t < range.first_triangle + range.triangle_count; ++t) {
        const std::size_t c = std::size_t(t) * 3;
        const detail::TriangleCorners corners = detail::TriangleCorners::of(positions_, t);
        const bool behind = detail::rasterizeTriangleExact(
            toClipVertex(corners_[c]), toClipVertex(corners_[c + 1]), toClipVertex(corners_[c + 2]),
            width_, height_, errors,
            [&](uint32_t px, uint32_t py) {
                const detail::ExactFragments& model = arbiter_->model();
                return model.covers(model.rays().centre(px, py), corners);
            },
            [&](uint32_t px, uint32_t py, float depth, double error) {
                ++stats_.fragments_tested;
                const std::size_t i = std::size_t(py) * width_ + px;
                const float band = detail::decisionBand(error, error_[i]);
                switch (detail::decide(depth, depth_[i], band)) {
                case detail::Decision::behind:
                    return true;
                case detail::Decision::undecided:
                    undecided.push_back({t, px, py});
                    return false;
                case detail::Decision::not_behind:
                    return false;
                }
                return false;
            });
        if (behind)
            return true;
    }
    // The undecided fragments come triangle by triangle: each triangle's candidates are made
    // once, and thinned as pairs turn out never nearer (touching, coplanar and duplicated faces,
    // where every pixel is undecided: a stack of copies must not cost the stack at each pixel).
    std::vector<uint32_t> candidates;
    uint32_t candidates_of = 0;
    for (std::size_t i = 0; i < undecided.size(); ++i) {
        const Undecided& u = undecided[i];
        if (i == 0 || u.triangle != candidates_of) {
            // Copies are looked for (a sort) only where the triangle arbitrates at many pixels.
            std::size_t pixels = 1;
            while (i + pixels < undecided.size() && undecided[i + pixels].triangle == u.triangle)
                ++pixels;
            candidates = arbitrationCandidates(u.triangle, pixels >= 16);
            candidates_of = u.triangle;
        }
        if (behindSomethingDrawn(u.triangle, u.px, u.py, candidates))
            return true;
    }
    return false;
}

std::vector<uint32_t> CpuReferenceOracle::arbitrationCandidates(uint32_t triangle,
                                                                bool drop_copies) {
    const PixelBounds own = boundsOf(triangle);
    std::vector<uint32_t> candidates;
    for (uint32_t p : drawn_) {
        const PrimitiveRange range = primitives_[p];
        for (uint32_t t = range.first_triangle; t < range.first_triangle + range.triangle_count;
             ++t) {
            const PixelBounds& b = boundsOf(t);
            if (t != triangle && b.x_min <= own.x_max && own.x_min <= b.x_max &&
                b.y_min <= own.y_max && own.y_min <= b.y_max)
                candidates.push_back(t);
        }
    }
    if (!drop_copies)
        return candidates;
    // Copies (the same corners) answer alike: one of each is enough, and none of the query's
    // own. A triangle with a non-finite corner has no fragment (and would break the sort).
    using Key = std::array<float, 9>;
    const auto keyOf = [&](uint32_t t) {
        return detail::TriangleCorners::of(positions_, t).sortedKey();
    };
    const Key own_key = keyOf(triangle);
    std::vector<std::pair<Key, uint32_t>> keyed;
    keyed.reserve(candidates.size());
    for (uint32_t t : candidates) {
        const Key key = keyOf(t);
        if (std::all_of(key.begin(), key.end(), [](float v) { return std::isfinite(v); }) &&
            key != own_key)
            keyed.push_back({key, t});
    }
    std::sort(keyed.begin(), keyed.end());
    candidates.clear();
    for (std::size_t i = 0; i < keyed.size(); ++i)
        if (i == 0 || keyed[i].first != keyed[i - 1].first)
            candidates.push_back(keyed[i].second);
    return candidates;
}

const CpuReferenceOracle::PixelBounds& CpuReferenceOracle::boundsOf(uint32_t t) {
    PixelBounds& b = triangle_bounds_[t];
    if (bounds_stamps_[t] == bind_number_)
        return b;
    bounds_stamps_[t] = bind_number_;
    b = {int32_t(width_), -1, int32_t(height_), -1};
    const detail::ScreenErrors errors{screen_position_error_, screen_depth_error_};
    detail::forEachFanTriangle(
        toClipVertex(corners_[3 * t]), toClipVertex(corners_[3 * t + 1]),
        toClipVertex(corners_[3 * t + 2]), width_, height_,
        [&](const detail::TriangleSetup& s) {
            b.x_min = std::min(b.x_min, int32_t(s.px_min));
            b.x_max = std::max(b.x_max, int32_t(s.px_max));
            b.y_min = std::min(b.y_min, int32_t(s.py_min));
            b.y_max = std::max(b.y_max, int32_t(s.py_max));
            return false;
        },
        errors);
    return b;
}

bool CpuReferenceOracle::behindSomethingDrawn(uint32_t triangle, uint32_t px, uint32_t py,
                                              std::vector<uint32_t>& candidates) {
    ++stats_.arbitrations;
    return arbiter_->anyNearer(
        arbiter_->query(triangle, px, py), candidates, [](uint32_t t) { return t; },
        [&](uint32_t t) {
            const PixelBounds& b = boundsOf(t);
            return int32_t(px) < b.x_min || int32_t(px) > b.x_max || int32_t(py) < b.y_min ||
                   int32_t(py) > b.y_max;
        });
}

} // namespace vissort
