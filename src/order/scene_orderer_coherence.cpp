// Coherence (Govindaraju et al., I3D 2005): stage 1 of a frame starts from last
// frame's order, with last frame's cycles as hints to confirm (hinted_cycles.h); the first frame,
// or one whose primitives changed, starts from the depth-key order.

#include <algorithm>
#include <stdexcept>
#include <string>

#include "order/scene_orderer_sort.h"

namespace vissort {

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
    // Objects without triangles (out of view, setObjects) neither occlude nor are occluded:
    // they go to the end of the order, in last frame's order, without a query, and Vis-sort
    // sorts the rest. The ids it binds are then positions in that list (sortFrom's start).
    const auto empty = [&](uint32_t i) { return !triangles && objects_[i].triangle_count == 0; };
    bool any_empty = false;
    for (std::size_t i = 0; !triangles && !any_empty && i < n; ++i)
        any_empty = empty(uint32_t(i));
    std::span<const uint32_t> start;
    std::vector<uint32_t> depth_start; // the first frame's: freed with the frame
    const bool coherent = previous_order_.size() == n;
    if (coherent) {
        start = previous_order_;
    } else {
        std::span<const PrimitiveRange> primitives = objects_;
        if (triangles) { // bound_ as scratch: sortFrom overwrites it
            bound_.resize(n);
            for (uint32_t t = 0; t < n; ++t)
                bound_[t] = {t, 1};
            primitives = bound_;
        }
        depth_start = depthKeyOrder(positions, view, primitives);
        start = depth_start;
    }
    empty_.clear();
    if (any_empty) {
        visible_.clear();
        for (uint32_t p : start)
            (empty(p) ? empty_ : visible_).push_back(p);
        start = visible_;
    }
    if (coherent) {
        // Last frame's cycles (still in sorted_: stage 2 sorts into group_sorted_), as hints in
        // this frame's bound ids (positions in its start list). Not triangles': on the deforming
        // bunnies 1 to 3 of their 45 to 70 cycles a frame survive to the next, and confirming the
        // rest cost 4 to 7% of the frame (docs/benchmarks.md). A frame after one without cycles
        // holds no map. A cycle with a member now empty is no cycle: it is no hint.
        std::size_t hints = triangles ? 0 : sorted_.cycles.size();
        if (hints != 0) {
            bound_id_.assign(n, kNoObject);
            for (uint32_t i = 0; i < start.size(); ++i)
                bound_id_[start[i]] = i;
        }
        // The hints' vectors keep their capacity from frame to frame.
        std::size_t kept = 0;
        for (std::size_t c = 0; c < hints; ++c) {
            const auto gone = [&](uint32_t p) { return bound_id_[p] == kNoObject; };
            if (std::any_of(sorted_.cycles[c].begin(), sorted_.cycles[c].end(), gone))
                continue;
            if (hint_cycles_.size() <= kept) {
                hint_cycles_.emplace_back();
                hint_witnesses_.emplace_back();
            }
            hint_cycles_[kept].clear();
            for (uint32_t p : sorted_.cycles[c])
                hint_cycles_[kept].push_back(bound_id_[p]);
            hint_witnesses_[kept].clear();
            for (const Occlusion& o : sorted_.cycle_witnesses[c])
                hint_witnesses_[kept].push_back({bound_id_[o.front], bound_id_[o.back]});
            ++kept;
        }
        hint_cycles_.resize(kept);
        hint_witnesses_.resize(kept);
        sortFrom(positions, view, start.size(), primitive, start, sorted_, Bind::new_frame,
                 {hint_cycles_, hint_witnesses_});
    } else {
        sortFrom(positions, view, start.size(), primitive, start, sorted_);
    }
    sorted_.order.insert(sorted_.order.end(), empty_.begin(), empty_.end());
    // The order becomes the previous one; sorted_ keeps the old buffer for the next frame.
    std::swap(previous_order_, sorted_.order);
}

void SceneOrderer::seed(std::span<const uint32_t> start) {
    const std::size_t n = level_ == OrderLevel::triangle ? triangle_count_ : objects_.size();
    std::vector<uint8_t> seen(n, 0);
    bool permutation = start.size() == n;
    for (std::size_t i = 0; permutation && i < start.size(); ++i) {
        permutation = start[i] < n && !seen[start[i]];
        if (permutation)
            seen[start[i]] = 1;
    }
    if (!permutation)
        throw std::invalid_argument(
            "SceneOrderer::seed: the start list must be a permutation of the " + std::to_string(n) +
            " primitives of the orderer's first stage");
    previous_order_.assign(start.begin(), start.end());
    sorted_.cycles.clear(); // no hints: the cycles were of another order's ids
    sorted_.cycle_witnesses.clear();
    previous_triangle_order_.clear();
}

} // namespace vissort
