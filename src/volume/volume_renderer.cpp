// VolumeRenderer: one method's frames of one grid. The ordering methods put the cells in order
// (cell_orders.h) and composite them (cell_compositor.h); lists and raycast need no order.
#include <chrono>
#include <optional>
#include <thread>

#include "vissort/volume.h"
#include "volume/cell_compositor.h"
#include "volume/cell_orders.h"
#include "volume/cell_walk_ray_caster.h"
#include "volume/volume_law.h"

namespace vissort {

struct VolumeRenderer::State {
    const TetGrid& grid;
    VolumeMethod method;
    OracleKind oracle;
    unsigned threads;
    detail::GridMeasures measures; // what the law needs of the grid, once
    detail::PixelRayTable rays;    // this frame's rays; its memory kept for the next
    std::optional<std::vector<TetNeighbours>> neighbours;    // mpvo's, made on its first frame
    std::unique_ptr<detail::VisibilityCellOrder> visibility; // vissort's, kept for coherence
    std::unique_ptr<detail::CellWalkCaster> caster;          // raycast's neighbours and tree
    std::vector<uint32_t> order;                             // centroid's and mpvo's
    VolumeFrameStats stats;
};

VolumeRenderer::VolumeRenderer(const TetGrid& grid, VolumeMethod method, OracleKind oracle,
                               unsigned thread_count)
    : state_(new State{grid,
                       method,
                       oracle,
                       thread_count == 0 ? std::max(1u, std::thread::hardware_concurrency())
                                         : thread_count,
                       detail::GridMeasures(grid),
                       {},
                       std::nullopt,
                       nullptr,
                       nullptr,
                       {},
                       {}}) {}

VolumeRenderer::~VolumeRenderer() = default;

const VolumeFrameStats& VolumeRenderer::stats() const {
    return state_->stats;
}

Result<Image> VolumeRenderer::render(const VolumeSettings& settings, const ViewProjection& view) {
    using R = Result<Image>;
    using Clock = std::chrono::steady_clock;
    const auto ms = [](Clock::time_point since) {
        return std::chrono::duration<double, std::milli>(Clock::now() - since).count();
    };
    State& s = *state_;
    s.stats = {};
    s.stats.cells = s.grid.tets.size();
    if (Status valid = validateVolumeSettings(s.grid, settings); !valid)
        return R::failure(valid.error);
    if (s.method == VolumeMethod::raycast) {
        const auto start = Clock::now();
        if (!s.caster) {
            Result<std::unique_ptr<detail::CellWalkCaster>> made =
                detail::CellWalkCaster::make(s.grid);
            if (!made)
                return R::failure(made.error);
            s.caster = std::move(*made.value);
        }
        s.rays.fill(view);
        Image image = s.caster->render(detail::VolumeLaw(s.measures, settings), settings.background,
                                       s.rays, s.threads, s.stats.segments);
        s.stats.composite_ms = ms(start);
        return R{std::move(image), {}};
    }

    const auto order_start = Clock::now();
    std::span<const uint32_t> order;
    std::span<const std::vector<uint32_t>> cycles;
    switch (s.method) {
    case VolumeMethod::centroid:
        s.order = detail::centroidOrder(s.grid, view);
        order = s.order;
        break;
    case VolumeMethod::mpvo: {
        if (!s.neighbours) {
            Result<std::vector<TetNeighbours>> neighbours = faceNeighbours(s.grid);
            if (!neighbours)
                return R::failure(neighbours.error);
            s.neighbours = std::move(*neighbours.value);
        }
        detail::MpvoOrder mpvo = detail::mpvoOrder(s.grid, *s.neighbours, view);
        s.order = std::move(mpvo.order);
        order = s.order;
        s.stats.cycles = mpvo.broken_cycles;
        break;
    }
    case VolumeMethod::vissort: {
        if (!s.visibility) {
            Result<std::unique_ptr<detail::VisibilityCellOrder>> made =
                detail::VisibilityCellOrder::make(s.grid, s.oracle);
            if (!made)
                return R::failure(made.error);
            s.visibility = std::move(*made.value);
        }
        const FrameOrder& frame = s.visibility->order(view);
        order = frame.order;
        cycles = frame.cycles;
        s.stats.queries = frame.stats.queries;
        s.stats.cycles = frame.cycles.size();
        for (const std::vector<uint32_t>& cycle : frame.cycles)
            s.stats.cells_in_cycles += cycle.size();
        break;
    }
    case VolumeMethod::lists:
    case VolumeMethod::raycast:
        break;
    }
    s.stats.order_ms = ms(order_start);

    const auto composite_start = Clock::now();
    const detail::VolumeLaw law(s.measures, settings);
    s.rays.fill(view);
    const detail::CompositeJob job{s.grid, law, s.rays, view, settings.background, s.threads};
    Image image = s.method == VolumeMethod::lists
                      ? detail::compositeLists(job, s.stats)
                      : detail::compositeInOrder(job, order, cycles, s.stats);
    s.stats.composite_ms = ms(composite_start);
    return R{std::move(image), {}};
}

} // namespace vissort
