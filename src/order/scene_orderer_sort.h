#pragma once
// SceneOrderer::sortFrom, which both stages call (scene_orderer_coherence.cpp,
// scene_orderer_multistage.cpp): a template over how an id becomes a primitive, so that stage 1
// at triangle level makes each triangle's range as needed instead of keeping a list of them.
// Internal to src/order/.

#include <algorithm>
#include <numeric>

#include "vissort/scene_orderer.h"

namespace vissort {

// Why bind in start order: Vis-sort visits primitives in list order, the list stays close to the
// start (coherence), and a fast oracle lays out each primitive's set-up in bind order, so the
// visits read memory forward instead of jumping across megabytes of set-ups. The relabelling
// changes nothing else: Vis-sort depends on list positions and answers, never on id values.
template <class PrimitiveAt>
inline void SceneOrderer::sortFrom(PositionsView positions, const ViewProjection& view,
                                   std::size_t n, const PrimitiveAt& primitive,
                                   std::span<const uint32_t> start, VisibilityOrder& into, Bind how,
                                   CycleHints hints) {
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

} // namespace vissort
