// CpuOracle's bind and rebind (cpu_oracle_impl.h): every triangle's set-up, four at a time, with
// the exact rule's band pixels, and the map that lets a group's rebind copy them.

#include "raster/cpu_oracle_impl.h"

namespace vissort {

void CpuOracle::Impl::bind(PositionsView positions, const ViewProjection& view,
                           std::span<const PrimitiveRange> primitives) {
    assert(view.width >= 1 && view.width <= detail::kMaxViewportSize);
    assert(view.height >= 1 && view.height <= detail::kMaxViewportSize);
    assert(positions.y.size() == positions.x.size() && positions.z.size() == positions.x.size());
    width_ = view.width;
    height_ = view.height;
    tiles_x_ = (width_ + kTileSize - 1) / kTileSize;
    tiles_y_ = (height_ + kTileSize - 1) / kTileSize;
    primitive_count_ = uint32_t(primitives.size());
    for ([[maybe_unused]] const PrimitiveRange& range : primitives)
        assert(uint64_t(range.first_triangle) + range.triangle_count <= positions.triangleCount());

    // Set-ups are laid out in primitive order (a primitive's fan triangles are contiguous), so a
    // walk over primitives in id order reads memory forward; triangles of no primitive are never
    // set up, those of several are set up once each. Triangles are taken four at a time in that
    // order (bind order), for the batch set-up.
    const detail::Matrix4 m = detail::multiply(view.projection_matrix, view.view);
    if (source_at_ == Source::source) { // the larger buffers back: the groups' stay small
        std::swap(setups_, source_setups_);
        std::swap(narrow_, source_narrow_);
        std::swap(spreads_, source_spreads_);
        std::swap(errors_, source_errors_);
    }
    source_at_ = Source::none;
    positions_ = positions;
    screen_errors_ = detail::screenErrorsOf(m, view, positions, primitives);
    orthographic_ = view.projection == Projection::orthographic;
    arbiter_.bind(view, positions);
    band_pixels_.assign(1, 0); // entry 0: none
    if (keep_for_rebind_) {
        bound_x_ = positions.x.data();
        bound_triangles_ = positions.triangleCount();
        bound_matrix_ = m;
        if (triangle_setups_.size() != bound_triangles_ ||
            ++bind_stamp_ >> (32 - kCountBits) != 0) {
            triangle_setups_.assign(bound_triangles_, TriangleSetups{0, 0});
            bind_stamp_ = 1;
        }
        source_at_ = Source::setups;
    }
    std::size_t n = 0;
    for (const PrimitiveRange& range : primitives)
        n += range.triangle_count;
    primitive_setups_.resize(primitives.size() + 1);
    setups_.clear();
    setups_.reserve(n);
    narrow_.clear();
    narrow_.reserve(n);
    spreads_.clear();
    spreads_.reserve(n);
    errors_.clear();
    errors_.reserve(n);
    // Before the set-ups of the triangle at bind position i: primitives starting there start here.
    std::size_t next_primitive = 0, next_start = 0;
    const auto reach = [&](std::size_t i) {
        while (next_primitive < primitives.size() && next_start == i) {
            primitive_setups_[next_primitive] = uint32_t(setups_.size());
            next_start += primitives[next_primitive++].triangle_count;
        }
    };
    const bool batch = setup_quad_ != nullptr;
    uint32_t quad_triangles[4];
    std::size_t quad_size = 0, quad_first = 0; // quad_triangles[0] is at bind position quad_first
    const auto setUpQuad = [&] {
        detail::FastSetup quad[4];
        detail::LaneSetup lanes[4];
        if (batch && quad_size == 4)
            setup_quad_(m, positions.x.data(), positions.y.data(), positions.z.data(),
                        quad_triangles, width_, height_, screen_errors_, quad, lanes);
        else
            std::fill_n(lanes, 4, detail::LaneSetup::scalar);
        for (std::size_t l = 0; l < quad_size; ++l) {
            reach(quad_first + l);
            const uint32_t first = uint32_t(setups_.size());
            if (lanes[l] == detail::LaneSetup::ready) {
                quad[l].narrow = detail::edgesFitInt32(quad[l]);
                store({&quad[l], 1}, quad_triangles[l]);
            } else if (lanes[l] == detail::LaneSetup::scalar) {
                fan_.clear();
                detail::appendFastSetups(m, positions, quad_triangles[l], width_, height_,
                                         screen_errors_, fan_);
                store(fan_, quad_triangles[l]);
            }
            if (keep_for_rebind_) {
                const uint32_t count = uint32_t(setups_.size()) - first;
                assert(count < 1u << kCountBits);
                triangle_setups_[quad_triangles[l]] = {first, bind_stamp_ << kCountBits | count};
            }
        }
        quad_first += quad_size;
        quad_size = 0;
    };
    for (const PrimitiveRange& range : primitives)
        for (uint32_t t = range.first_triangle; t < range.first_triangle + range.triangle_count;
             ++t) {
            quad_triangles[quad_size++] = t;
            if (quad_size == 4)
                setUpQuad();
        }
    setUpQuad();
    reach(n);
    primitive_setups_[primitives.size()] = uint32_t(setups_.size());
    finishBind();
}

bool CpuOracle::Impl::sameAsBound(PositionsView positions, const ViewProjection& view) const {
    return source_at_ != Source::none && positions.x.data() == bound_x_ &&
           positions.triangleCount() == bound_triangles_ && view.width == width_ &&
           view.height == height_ &&
           detail::multiply(view.projection_matrix, view.view) == bound_matrix_;
}

void CpuOracle::Impl::rebind(PositionsView positions, const ViewProjection& view,
                             std::span<const PrimitiveRange> primitives) {
    keep_for_rebind_ = true; // from now on binds keep their map
    // Binding instead: the groups' buffers grow to the group's size now, not when a later
    // rebind swaps them in, with room for a triangle each and an eighth more for clipped fans
    // (a triangle covering no pixel centre has none: a group's set-ups vary from frame to
    // frame, and steady frames should allocate nothing).
    const auto bindInstead = [&] {
        bind(positions, view, primitives);
        std::size_t triangles = 0;
        for (const PrimitiveRange& range : primitives)
            triangles += range.triangle_count;
        const std::size_t room = std::max(setups_.size(), triangles) + triangles / 8;
        source_setups_.reserve(room);
        source_narrow_.reserve(room);
        source_spreads_.reserve(room);
        source_errors_.reserve(room);
    };
    if (!sameAsBound(positions, view)) {
        bindInstead();
        return;
    }
    std::size_t n = 0;                             // set-ups to copy
    for (const PrimitiveRange& range : primitives) // every triangle set up by the bind?
        for (uint32_t t = range.first_triangle; t < range.first_triangle + range.triangle_count;
             ++t) {
            if (!triangle_setups_[t].current(bind_stamp_)) {
                bindInstead();
                return;
            }
            n += triangle_setups_[t].count();
        }
    if (source_at_ == Source::setups) {
        std::swap(setups_, source_setups_);
        std::swap(narrow_, source_narrow_);
        std::swap(spreads_, source_spreads_);
        std::swap(errors_, source_errors_);
        source_at_ = Source::source;
    }
    primitive_count_ = uint32_t(primitives.size());
    primitive_setups_.resize(primitives.size() + 1);
    // Sized once and copied element by element: a group's triangles come in last frame's order,
    // scattered over the source, and an insert per triangle spent 9% of a multi-stage frame in
    // memmove's start-up.
    setups_.resize(n);
    narrow_.resize(n);
    spreads_.resize(n);
    errors_.resize(n);
    uint32_t k = 0;
    constexpr std::size_t kAhead = 8; // primitives: a few cache misses in flight
    for (std::size_t p = 0; p < primitives.size(); ++p) {
        // Only a range with triangles has an entry, and only one with set-ups a set-up to fetch
        // (an empty range may start at the last triangle's end).
        if (p + kAhead < primitives.size() && primitives[p + kAhead].triangle_count != 0) {
            const TriangleSetups& ahead = triangle_setups_[primitives[p + kAhead].first_triangle];
            if (ahead.count() != 0) {
                const char* setup = reinterpret_cast<const char*>(&source_setups_[ahead.first]);
                __builtin_prefetch(setup);
                __builtin_prefetch(setup + sizeof(StoredSetup) - 1);
                __builtin_prefetch(&source_spreads_[ahead.first]);
                __builtin_prefetch(&source_narrow_[ahead.first]);
            }
        }
        primitive_setups_[p] = k;
        const PrimitiveRange& range = primitives[p];
        for (uint32_t t = range.first_triangle; t < range.first_triangle + range.triangle_count;
             ++t) {
            const TriangleSetups& at = triangle_setups_[t];
            const uint32_t end = at.first + at.count();
            for (uint32_t i = at.first; i < end; ++i, ++k) {
                setups_[k] = source_setups_[i];
                narrow_[k] = source_narrow_[i];
                spreads_[k] = source_spreads_[i];
                errors_[k] = source_errors_[i];
            }
        }
    }
    primitive_setups_[primitives.size()] = k;
    finishBind();
}

void CpuOracle::Impl::finishBind() {
    setGlobalError();
    depth_.resize(std::size_t(tiles_x_) * tiles_y_ * kTilePixels);
    tiles_.assign(std::size_t(tiles_x_) * tiles_y_, TileState{kInfinity, kInfinity, 0, 0});
    epoch_ = 1; // every tile pending a clear
    drawn_time_.assign(primitive_count_, 0);
    clock_ = clear_time_ = 1;
    tile_index_built_.store(false);

    imaged_.clear();
    imaged_rects_.clear();
    image_errors_.clear();
    for (uint32_t p = 0; image_min_triangles_ != 0 && p < primitive_count_; ++p) {
        if (primitive_setups_[p + 1] - primitive_setups_[p] < image_min_triangles_)
            continue;
        PixelRect rect{int32_t(width_), -1, int32_t(height_), -1};
        for (uint32_t k = primitive_setups_[p]; k < primitive_setups_[p + 1]; ++k) {
            rect.x_min = std::min<int32_t>(rect.x_min, setups_[k].px_min);
            rect.x_max = std::max<int32_t>(rect.x_max, setups_[k].px_max);
            rect.y_min = std::min<int32_t>(rect.y_min, setups_[k].py_min);
            rect.y_max = std::max<int32_t>(rect.y_max, setups_[k].py_max);
        }
        imaged_.push_back(p);
        imaged_rects_.push_back(rect);
        float error = 0;
        for (uint32_t k = primitive_setups_[p]; k < primitive_setups_[p + 1]; ++k)
            error = std::max(error, errors_[k]);
        image_errors_.push_back(error);
    }
    near_images_.reset(uint32_t(imaged_.size()));
    far_images_.reset(uint32_t(imaged_.size()));
}

void CpuOracle::Impl::store(std::span<const detail::FastSetup> fan, uint32_t t) {
    for (const detail::FastSetup& s : fan) {
        const uint32_t band = bandPixelsOf(s, t);
        setups_.push_back(storedSetup(s, t, band));
        narrow_.push_back(s.narrow ? 1 : 0);
        spreads_.push_back(s.spread);
        errors_.push_back(roundedUp(s.error));
    }
}

uint32_t CpuOracle::Impl::bandPixelsOf(const detail::FastSetup& setup, uint32_t t) {
    const std::size_t at = band_pixels_.size();
    band_pixels_.push_back(0); // the count, once known
    // A whole triangle well within the depth range: screen space settles most band pixels (the
    // corners stay its own, the depths between its corners' and so in the range).
    constexpr double kDepthRoom = 0x1p-20;
    const bool screen = setup.whole && setup.d_min >= kDepthRoom &&
                        (!orthographic_ || setup.d_max <= 1 - kDepthRoom);
    const std::array<double, 3> ux{setup.ux[0], setup.ux[1], setup.ux[2]};
    const std::array<double, 3> uy{setup.uy[0], setup.uy[1], setup.uy[2]};
    bool have_corners = false; // read only where the exact model must decide
    detail::TriangleCorners corners;
    uint32_t count = 0;
    detail::forEachFastBandPixel(setup, [&](uint32_t px, uint32_t py) {
        ++stats_.band_pixels;
        int covered = screen ? detail::screenCoverage(ux, uy, px, py, screen_errors_) : 0;
        if (covered == 0) {
            if (!have_corners) {
                corners = detail::TriangleCorners::of(positions_, t);
                have_corners = true;
            }
            const detail::ExactFragments& model = arbiter_.model();
            covered = model.covers(model.rays().centre(px, py), corners) ? 1 : -1;
        }
        if (covered > 0) {
            band_pixels_.push_back(py << 16 | px);
            ++count;
        }
    });
    if (count == 0) {
        band_pixels_.pop_back();
        return 0;
    }
    band_pixels_[at] = count;
    // Row by row (py << 16 | px ascending): a tile's pixel lists find their rows by bisection,
    // not by a scan of every band pixel of a long triangle for each tile it crosses.
    std::sort(band_pixels_.begin() + std::ptrdiff_t(at) + 1, band_pixels_.end());
    return uint32_t(at);
}

} // namespace vissort
