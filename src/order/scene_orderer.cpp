// Ordering scenes at a level, with the multi-stage scheme of Govindaraju et al. (I3D 2005,
// section 5): order objects, then re-sort triangles only within each object or object cycle.

#include "vissort/scene_orderer.h"

#include <algorithm>
#include <cassert>
#include <chrono>
#include <numeric>

namespace vissort {

std::vector<PrimitiveRange> levelPrimitives(std::span<const PrimitiveRange> objects,
                                            uint32_t triangle_count, OrderLevel level) {
    if (level == OrderLevel::object)
        return {objects.begin(), objects.end()};
    std::vector<PrimitiveRange> triangles(triangle_count);
    for (uint32_t t = 0; t < triangle_count; ++t)
        triangles[t] = {t, 1};
    return triangles;
}

SceneOrderer::SceneOrderer(std::span<const PrimitiveRange> objects, uint32_t triangle_count,
                           OrderLevel level, GeometryOracle& oracle)
    : objects_(objects.begin(), objects.end()), triangle_count_(triangle_count), level_(level),
      oracle_(oracle) {
    if (level_ != OrderLevel::multistage)
        return;
    object_of_triangle_.assign(triangle_count_, kNoObject);
    for (uint32_t o = 0; o < objects_.size(); ++o)
        for (uint32_t t = objects_[o].first_triangle;
             t < objects_[o].first_triangle + objects_[o].triangle_count; ++t) {
            if (object_of_triangle_[t] != kNoObject) {
                // Objects sharing triangles: a triangle has no single group to be dealt to;
                // every frame starts from the depth-key order (buildGroupStarts).
                object_of_triangle_.clear();
                return;
            }
            object_of_triangle_[t] = o;
        }
}

void SceneOrderer::sortStage1(PositionsView positions, const ViewProjection& view) {
    // Stage 1's primitives: every triangle at triangle level (made as needed: a list of them
    // would cost 8 bytes a triangle), else the objects.
    const bool triangles = level_ == OrderLevel::triangle;
    const std::size_t n = triangles ? triangle_count_ : objects_.size();
    progress_base_ = 0;
    progress_total_ = level_ == OrderLevel::multistage ? 0 : n; // multistage: its triangle stage
    const auto primitive = [&](uint32_t i) {
        return triangles ? PrimitiveRange{i, 1} : objects_[i];
    };
    if (previous_order_.size() == n) {
        // Last frame's cycles (still in sorted_: stage 2 sorts into group_sorted_), as hints in
        // this frame's bound ids (positions in its order). Not triangles': on the deforming
        // bunnies 1 to 3 of their 45 to 70 cycles a frame survive to the next, and confirming the
        // rest cost 4 to 7% of the frame (docs/benchmarks.md). A frame after one without cycles
        // holds no map.
        const std::size_t hints = triangles ? 0 : sorted_.cycles.size();
        if (hints != 0) {
            bound_id_.resize(n);
            for (uint32_t i = 0; i < n; ++i)
                bound_id_[previous_order_[i]] = i;
        }
        hint_cycles_.resize(hints);
        hint_witnesses_.resize(hints);
        for (std::size_t c = 0; c < hints; ++c) {
            hint_cycles_[c].clear();
            for (uint32_t p : sorted_.cycles[c])
                hint_cycles_[c].push_back(bound_id_[p]);
            hint_witnesses_[c].clear();
            for (const Occlusion& o : sorted_.cycle_witnesses[c])
                hint_witnesses_[c].push_back({bound_id_[o.front], bound_id_[o.back]});
        }
        sortFrom(positions, view, n, primitive, previous_order_, sorted_, Bind::new_frame,
                 {hint_cycles_, hint_witnesses_});
    } else {
        std::span<const PrimitiveRange> primitives = objects_;
        if (triangles) { // bound_ as scratch: sortFrom overwrites it
            bound_.resize(n);
            for (uint32_t t = 0; t < n; ++t)
                bound_[t] = {t, 1};
            primitives = bound_;
        }
        const std::vector<uint32_t> start = depthKeyOrder(positions, view, primitives);
        sortFrom(positions, view, n, primitive, start, sorted_);
    }
    // The order becomes the previous one; sorted_ keeps the old buffer for the next frame.
    std::swap(previous_order_, sorted_.order);
}

// Why bind in start order: Vis-sort visits primitives in list order, the list stays close to the
// start (coherence), and a fast oracle lays out each primitive's set-up in bind order, so the
// visits read memory forward instead of jumping across megabytes of set-ups. The relabelling
// changes nothing else: Vis-sort depends on list positions and answers, never on id values.
template <class PrimitiveAt>
void SceneOrderer::sortFrom(PositionsView positions, const ViewProjection& view, std::size_t n,
                            const PrimitiveAt& primitive, std::span<const uint32_t> start,
                            VisibilityOrder& into, Bind how, CycleHints hints) {
    bound_.resize(n);
    for (std::size_t i = 0; i < n; ++i)
        bound_[i] = primitive(start[i]);
    if (identity_.size() != n) {
        identity_.resize(n);
        std::iota(identity_.begin(), identity_.end(), 0u);
    }
    if (how == Bind::same_frame)
        oracle_.rebind(positions, view, bound_);
    else
        oracle_.bind(positions, view, bound_);
    if (progress_ && progress_total_ > 0)
        workspace_.on_iteration = [this](std::size_t sorted, std::size_t) {
            progress_(double(progress_base_ + sorted) / double(progress_total_));
        };
    else
        workspace_.on_iteration = nullptr;
    visSort(oracle_, identity_, into, workspace_, hints);
    for (uint32_t& p : into.order)
        p = start[p];
    for (std::vector<uint32_t>& cycle : into.cycles) {
        for (uint32_t& p : cycle)
            p = start[p];
        std::sort(cycle.begin(), cycle.end());
    }
    for (std::vector<Occlusion>& witness : into.cycle_witnesses)
        for (Occlusion& o : witness)
            o = {start[o.front], start[o.back]};
}

void SceneOrderer::orderFrame(PositionsView positions, const ViewProjection& view,
                              FrameOrder& out) {
    assert(positions.triangleCount() == triangle_count_);
    const auto start = std::chrono::steady_clock::now();
    out.level = level_;
    out.stats = {};
    if (level_ == OrderLevel::multistage) {
        orderMultistage(positions, view, out);
    } else {
        sortStage1(positions, view);
        out.order = previous_order_; // copy-assignments: the vectors keep their capacity
        out.cycles = sorted_.cycles;
        out.stats = sorted_.stats;
    }
    out.milliseconds =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

FrameOrder SceneOrderer::orderFrame(PositionsView positions, const ViewProjection& view) {
    FrameOrder frame;
    orderFrame(positions, view, frame);
    return frame;
}

void SceneOrderer::orderMultistage(PositionsView positions, const ViewProjection& view,
                                   FrameOrder& frame) {
    frame.order.clear();
    frame.cycles.clear();
    // Stage 1: objects.
    sortStage1(positions, view);
    const VisibilityOrder& objects = sorted_; // its order is in previous_order_
    const std::vector<uint32_t>& object_order = previous_order_;
    frame.stats += objects.stats;

    // Stage 2: a group is one object, or all objects of one cycle; groups come out whole and in
    // object order (a cycle's members are contiguous in it), and no triangle of a later group
    // occludes one of an earlier group, so ordering triangles within groups orders them all.
    std::vector<int32_t>& cycle_of = cycle_of_;
    cycle_of.assign(objects_.size(), -1);
    for (std::size_t c = 0; c < objects.cycles.size(); ++c)
        for (uint32_t object : objects.cycles[c])
            cycle_of[object] = int32_t(c);

    const bool coherent = buildGroupStarts(object_order);

    std::vector<PrimitiveRange>& group = group_;
    std::vector<uint32_t>& group_start = group_start_;
    frame.order.reserve(triangle_count_);
    for (std::size_t first = 0, g = 0; first < object_order.size(); ++g) {
        const std::size_t end = groupEnd(object_order, first);
        group.clear();
        for (std::size_t k = first; k < end; ++k) {
            const PrimitiveRange& object = objects_[object_order[k]];
            for (uint32_t t = 0; t < object.triangle_count; ++t)
                group.push_back({object.first_triangle + t, 1});
        }
        std::span<const uint32_t> start;
        if (coherent) { // the group's triangles in last frame's order
            start = std::span(starts_).subspan(group_starts_at_[g], group.size());
        } else {
            group_start = depthKeyOrder(positions, view, group);
            start = group_start;
        }
        VisibilityOrder& triangles = group_sorted_;
        progress_base_ = frame.order.size();
        progress_total_ = triangle_count_;
        // The objects' bind set up every triangle of this frame: a group reuses its set-ups.
        sortFrom(
            positions, view, group.size(), [&](uint32_t i) { return group[i]; }, start, triangles,
            Bind::same_frame);
        frame.stats += triangles.stats;
        for (uint32_t local : triangles.order)
            frame.order.push_back(group[local].first_triangle);
        for (auto& cycle : triangles.cycles) {
            for (uint32_t& local : cycle)
                local = group[local].first_triangle;
            std::sort(cycle.begin(), cycle.end());
            frame.cycles.push_back(std::move(cycle));
        }
        first = end;
    }
    previous_triangle_order_.assign(frame.order.begin(), frame.order.end());
}

void SceneOrderer::setProgress(std::function<void(double fraction)> report) {
    progress_ = std::move(report);
}

std::size_t SceneOrderer::groupEnd(std::span<const uint32_t> object_order,
                                   std::size_t first) const {
    std::size_t end = first + 1;
    if (cycle_of_[object_order[first]] >= 0)
        while (end < object_order.size() &&
               cycle_of_[object_order[end]] == cycle_of_[object_order[first]])
            ++end;
    return end;
}

bool SceneOrderer::buildGroupStarts(std::span<const uint32_t> object_order) {
    // The first frame has no last order to keep; objects sharing triangles have no map.
    if (previous_triangle_order_.empty() || object_of_triangle_.empty())
        return false;
    // Each group's triangles numbered from 0 in object order (the ids sortFrom sees); where its
    // start list ends in starts_.
    group_of_object_.resize(objects_.size());
    first_local_.resize(objects_.size());
    group_starts_at_.clear();
    group_starts_at_.reserve(objects_.size()); // at most a group an object, no slack
    uint32_t total = 0;
    for (std::size_t first = 0; first < object_order.size();) {
        const std::size_t end = groupEnd(object_order, first);
        uint32_t local = 0;
        for (std::size_t k = first; k < end; ++k) {
            const uint32_t object = object_order[k];
            group_of_object_[object] = uint32_t(group_starts_at_.size());
            first_local_[object] = local;
            local += objects_[object].triangle_count;
        }
        total += local;
        group_starts_at_.push_back(total);
        first = end;
    }
    // One pass over last frame's order, from its end, deals each triangle to its group, in that
    // order (a sort of each group by last frame's positions took 8% of the bunnies' multistage
    // frame); each group's end moves back to its start.
    starts_.resize(total);
    for (std::size_t i = previous_triangle_order_.size(); i-- > 0;) {
        const uint32_t t = previous_triangle_order_[i];
        const uint32_t object = object_of_triangle_[t];
        starts_[--group_starts_at_[group_of_object_[object]]] =
            first_local_[object] + (t - objects_[object].first_triangle);
    }
    return true;
}

} // namespace vissort
