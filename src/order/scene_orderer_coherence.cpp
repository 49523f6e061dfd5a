// Coherence (Govindaraju et al., I3D 2005): stage 1 of a frame starts from last
// frame's order, with last frame's cycles as hints to confirm (hinted_cycles.h); the first frame,
// or one whose primitives changed, starts from the depth-key order.

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
