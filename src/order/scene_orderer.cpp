// Ordering scenes at a level, with the multi-stage scheme of Govindaraju et al. (I3D 2005,
// section 5): order objects, then re-sort triangles only within each object or object cycle.

#include "vissort/scene_orderer.h"

#include <algorithm>
#include <chrono>
#include <numeric>

namespace vissort {
namespace {

void addStats(VisSortStats& total, const VisSortStats& part) {
    total.queries += part.queries;
    total.draws += part.draws;
    total.clears += part.clears;
    total.iterations += part.iterations;
    total.stuck_iterations += part.stuck_iterations;
    total.cycle_queries += part.cycle_queries;
    total.cycle_draws += part.cycle_draws;
}

} // namespace

std::vector<PrimitiveRange> primitivesOf(const Scene& scene, OrderLevel level) {
    return level == OrderLevel::object ? scene.objectPrimitives() : scene.trianglePrimitives();
}

SceneOrderer::SceneOrderer(const Scene& scene, OrderLevel level, GeometryOracle& oracle)
    : scene_(scene), level_(level), oracle_(oracle),
      primitives_(level == OrderLevel::triangle ? scene.trianglePrimitives()
                                                : scene.objectPrimitives()) {}

void SceneOrderer::sortPrimitives(PositionsView positions, const ViewProjection& view,
                                  std::span<const PrimitiveRange> primitives,
                                  std::span<const uint32_t> previous_order, VisibilityOrder& into) {
    if (previous_order.size() == primitives.size()) {
        sortFrom(positions, view, primitives, previous_order, into);
        return;
    }
    const std::vector<uint32_t> start = depthKeyOrder(positions, view, primitives);
    sortFrom(positions, view, primitives, start, into);
}

// Why bind in start order: Vis-sort visits primitives in list order, the list stays close to the
// start (coherence), and a fast oracle lays out each primitive's set-up in bind order, so the
// visits read memory forward instead of jumping across megabytes of set-ups. The relabelling
// changes nothing else: Vis-sort depends on list positions and answers, never on id values.
void SceneOrderer::sortFrom(PositionsView positions, const ViewProjection& view,
                            std::span<const PrimitiveRange> primitives,
                            std::span<const uint32_t> start, VisibilityOrder& into) {
    const std::size_t n = primitives.size();
    bound_.resize(n);
    for (std::size_t i = 0; i < n; ++i) bound_[i] = primitives[start[i]];
    if (identity_.size() != n) {
        identity_.resize(n);
        std::iota(identity_.begin(), identity_.end(), 0u);
    }
    oracle_.bind(positions, view, bound_);
    visSort(oracle_, identity_, into, workspace_);
    for (uint32_t& p : into.order) p = start[p];
    for (std::vector<uint32_t>& cycle : into.cycles) {
        for (uint32_t& p : cycle) p = start[p];
        std::sort(cycle.begin(), cycle.end());
    }
}

FrameOrder SceneOrderer::orderFrame(PositionsView positions, const ViewProjection& view) {
    const auto start = std::chrono::steady_clock::now();
    FrameOrder frame;
    if (level_ == OrderLevel::multistage) {
        frame = orderMultistage(positions, view);
    } else {
        sortPrimitives(positions, view, primitives_, previous_order_, sorted_);
        previous_order_ = sorted_.order;
        frame.level = level_;
        frame.order = sorted_.order;
        frame.cycles = sorted_.cycles;
        frame.stats = sorted_.stats;
    }
    frame.milliseconds =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return frame;
}

FrameOrder SceneOrderer::orderMultistage(PositionsView positions,
                                         const ViewProjection& view) {
    FrameOrder frame;
    frame.level = OrderLevel::multistage;
    // Stage 1: objects.
    sortPrimitives(positions, view, primitives_, previous_order_, sorted_);
    const VisibilityOrder& objects = sorted_;
    previous_order_ = objects.order;
    addStats(frame.stats, objects.stats);

    // Stage 2: a group is one object, or all objects of one cycle; groups come out whole and in
    // object order (a cycle's members are contiguous in it), and no triangle of a later group
    // occludes one of an earlier group, so ordering triangles within groups orders them all.
    std::vector<int32_t> cycle_of(scene_.objects.size(), -1);
    for (std::size_t c = 0; c < objects.cycles.size(); ++c)
        for (uint32_t object : objects.cycles[c]) cycle_of[object] = int32_t(c);

    const std::size_t triangle_count = positions.triangleCount();
    const bool have_ranks = previous_triangle_rank_.size() == triangle_count;
    std::vector<uint32_t> rank(triangle_count, 0);
    std::vector<PrimitiveRange>& group = group_;
    std::vector<uint32_t>& group_start = group_start_;
    frame.order.reserve(triangle_count);
    for (std::size_t i = 0; i < objects.order.size();) {
        std::size_t end = i + 1;
        if (cycle_of[objects.order[i]] >= 0)
            while (end < objects.order.size() &&
                   cycle_of[objects.order[end]] == cycle_of[objects.order[i]])
                ++end;
        group.clear();
        for (std::size_t k = i; k < end; ++k) {
            const SceneObject& object = scene_.objects[objects.order[k]];
            for (uint32_t t = 0; t < object.triangle_count; ++t)
                group.push_back({object.first_triangle + t, 1});
        }
        if (have_ranks) {
            // Coherence: the group's triangles in last frame's order.
            group_start.resize(group.size());
            std::iota(group_start.begin(), group_start.end(), 0u);
            std::sort(group_start.begin(), group_start.end(), [&](uint32_t a, uint32_t b) {
                return previous_triangle_rank_[group[a].first_triangle] <
                       previous_triangle_rank_[group[b].first_triangle];
            });
        } else {
            group_start = depthKeyOrder(positions, view, group);
        }
        VisibilityOrder& triangles = group_sorted_;
        sortFrom(positions, view, group, group_start, triangles);
        addStats(frame.stats, triangles.stats);
        for (uint32_t local : triangles.order) {
            rank[group[local].first_triangle] = uint32_t(frame.order.size());
            frame.order.push_back(group[local].first_triangle);
        }
        for (auto& cycle : triangles.cycles) {
            for (uint32_t& local : cycle) local = group[local].first_triangle;
            std::sort(cycle.begin(), cycle.end());
            frame.cycles.push_back(std::move(cycle));
        }
        i = end;
    }
    previous_triangle_rank_ = std::move(rank);
    return frame;
}

} // namespace vissort
