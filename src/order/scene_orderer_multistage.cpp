// The multi-stage scheme of Govindaraju et al. (I3D 2005, section 5): order objects, then re-sort
// triangles only within each object or object cycle (a group), each group from its triangles'
// order in the last frame.

#include "order/scene_orderer_sort.h"

namespace vissort {

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
