// A tiled CPU depth rasterizer answering Vis-sort's occlusion queries (Govindaraju, Henson, Lin,
// Manocha, I3D 2005, section 4) with CpuReferenceOracle's answers, bit for bit.
// This work is based on: Juan Pineda. A Parallel Algorithm for Polygon Rasterization. 1988 (edge
// functions, evaluated incrementally and at tile corners); Ned Greene, Michael Kass, Gavin Miller.
// Hierarchical Z-Buffer Visibility. 1993 (per-tile depth bounds); Nicolas Capens. Advanced
// Rasterization. 2004 (8 x 8 blocks: trivial reject and full coverage from the block corners).
// This file holds its construction and interface; cpu_oracle_impl.h lists the files of the rest.
//
// Why every shortcut is exact:
//  - Edge functions are affine in the pixel indices and exact in int64_t, so over a rectangle of
//    pixel centres their minimum and maximum are at its corners: a tile is outside an edge when
//    the maximum of E + bias is <= 0, inside when the minimum is > 0 (the top-left rule is the
//    bias, so nothing changes there).
//  - A fragment's depth is float(v) with v = (d0 + ddx (cx - x0)) + ddy (cy - y0) rounded in
//    double. The exact affine value over a tile lies between its corner values, and v differs
//    from it by at most a few units in the last place of |d0| + |ddx (cx - x0)| + |ddy (cy - y0)|:
//    a margin of 2^-48 of that sum bounds v from both sides. Rounding to float is monotone, so
//    bounds on v bound the fragments, and comparisons against float depths stay exact.
//  - The exact rule's decisions (cpu_reference_oracle.h, rule 7) compare a fragment with the
//    stored depth within a band made of the fragment's error bound and one for every fragment drawn
//    into the tile since its clear (TileState::error, at least each pixel's): a wider band than the
//    reference's per-pixel one decides fewer fragments by floats and sends more to the exact model,
//    whose answers are the same.

#include "raster/cpu_oracle_impl.h"

#include <memory>

namespace vissort {

CpuOracle::Impl::Impl(const Options& options) {
    const detail::RowKernels kernels = detail::selectRowKernels(options.allow_simd, use_simd_);
    draw_tile_ = kernels.draw;
    query_tile_ = kernels.query;
    fill_tile_ = kernels.fill;
    draw_small_ = kernels.draw_small;
    query_small_ = kernels.query_small;
    if (use_simd_)
        setup_quad_ = detail::avx2SetupQuad(); // the same AVX2 check
    threads_ = options.threads == 0 ? std::thread::hardware_concurrency() : options.threads;
    if (options.pool != nullptr) {
        pool_ = options.pool;
        threads_ = pool_->threadCount();
    }
    threads_ = std::clamp<uint32_t>(threads_, 1, 256);
    parallel_threshold_ = options.parallel_threshold;
    image_min_triangles_ = options.image_min_triangles;
    image_budget_bytes_ = options.image_budget_bytes;
}

void CpuOracle::Impl::changeTolerance(float tolerance) {
    depth_tolerance_ = tolerance;
    near_images_.reset(uint32_t(imaged_.size()));
    far_images_.reset(uint32_t(imaged_.size()));
}

std::span<const float> CpuOracle::Impl::depthBuffer() const {
    for (std::size_t tile = 0; tile < tiles_.size(); ++tile)
        if (tiles_[tile].epoch != epoch_)
            clearTile(tile);
    row_major_.resize(std::size_t(width_) * height_);
    for (uint32_t y = 0; y < height_; ++y)
        for (uint32_t x = 0; x < width_; ++x)
            row_major_[std::size_t(y) * width_ + x] = *pixel(x, y);
    return row_major_;
}

void CpuOracle::Impl::draw(uint32_t primitive) {
    assert(primitive < primitive_count_);
    ++stats_.draws;
    stamp(primitive);
    makeImage<true>(primitive);
    drawIn(primitive, wholeScreen(), stats_);
}

bool CpuOracle::Impl::anyBehind(uint32_t primitive) {
    assert(primitive < primitive_count_);
    ++stats_.queries;
    makeImage<false>(primitive);
    QueryContext context{&undecided_, clock_};
    return queryIn(primitive, wholeScreen(), stats_, context);
}

// The interface: one call into Impl each.

CpuOracle::CpuOracle() : CpuOracle(Options{}) {}

CpuOracle::CpuOracle(const Options& options) : impl_(std::make_unique<Impl>(options)) {}

CpuOracle::~CpuOracle() = default;

void CpuOracle::bind(PositionsView positions, const ViewProjection& view,
                     std::span<const PrimitiveRange> primitives) {
    impl_->bind(positions, view, primitives);
}

void CpuOracle::rebind(PositionsView positions, const ViewProjection& view,
                       std::span<const PrimitiveRange> primitives) {
    impl_->rebind(positions, view, primitives);
}

uint32_t CpuOracle::primitiveCount() const {
    return impl_->primitive_count_;
}
void CpuOracle::clear() {
    impl_->clearBuffer();
}
std::span<const float> CpuOracle::depthBuffer() const {
    return impl_->depthBuffer();
}
bool CpuOracle::usesSimd() const {
    return impl_->use_simd_;
}
uint32_t CpuOracle::threadCount() const {
    return impl_->threads_;
}
uint32_t CpuOracle::width() const {
    return impl_->width_;
}
uint32_t CpuOracle::height() const {
    return impl_->height_;
}
const CpuOracleStats& CpuOracle::stats() const {
    return impl_->stats_;
}
void CpuOracle::resetStats() {
    impl_->stats_ = {};
}

void CpuOracle::draw(uint32_t primitive) {
    impl_->setTolerance(depth_tolerance_);
    impl_->draw(primitive);
}

bool CpuOracle::anyBehind(uint32_t primitive) {
    impl_->setTolerance(depth_tolerance_);
    return impl_->anyBehind(primitive);
}

void CpuOracle::backToFrontPass(std::span<const uint32_t> sequence, std::span<const uint8_t> query,
                                std::span<uint8_t> behind) {
    assert(query.size() == sequence.size() && behind.size() == sequence.size());
    const uint32_t bands = impl_->bandsFor(sequence.size());
    if (bands <= 1) {
        OcclusionOracle::backToFrontPass(sequence, query, behind);
        return;
    }
    impl_->setTolerance(depth_tolerance_);
    impl_->backToFrontPass(bands, sequence, query, behind);
}

void CpuOracle::queryAgainst(std::span<const uint32_t> occluders, std::span<const uint32_t> targets,
                             std::span<uint8_t> behind) {
    assert(behind.size() == targets.size());
    impl_->setTolerance(depth_tolerance_);
    impl_->queryAgainst(impl_->bandsFor(occluders.size() + targets.size()), occluders, targets,
                        behind);
}

bool CpuOracle::occlusionGraph(std::span<const uint32_t> members, std::vector<Occlusion>& edges) {
    impl_->setTolerance(depth_tolerance_);
    return impl_->occlusionGraph(members, edges);
}

} // namespace vissort
