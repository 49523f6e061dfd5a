#pragma once
// Vis-sort with the last frame's cycles contracted: each part of a hint that this frame's oracle
// confirms strongly connected (hinted_cycles.h) is ordered as one primitive, so the frame neither
// gets stuck on it nor searches for it again. Internal to the core.

#include <cstdint>
#include <span>

#include "vissort/occlusion_oracle.h"
#include "vissort/vis_sort.h"

namespace vissort::detail {

/// visSort with hints (vis_sort.h). Why the answer is the same as without them: a confirmed group
/// is strongly connected, so it lies within one strongly connected component of the occlusion
/// graph; contracting it changes no other component, and a component of the contracted graph
/// expands into a component of the graph (a path leaving a group and coming back would be a cycle
/// through it). A group that is no cycle of the contracted order is a component by itself.
void contractedVisSort(OcclusionOracle& oracle, std::span<const uint32_t> initial_order,
                       const CycleHints& hints, VisibilityOrder& result,
                       VisSortWorkspace& workspace);

} // namespace vissort::detail
