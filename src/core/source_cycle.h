#pragma once
// Finding a cycle that blocks Vis-sort: a source strongly connected component of the occlusion
// graph among the primitives that are stuck. Internal to the core.

#include <cstdint>
#include <span>
#include <vector>

#include "vissort/occlusion_oracle.h"
#include "vissort/vis_sort.h"

namespace vissort::detail {

/// `stuck` is the list I of an iteration that output nothing and in_monotone_run its M flags
/// after that iteration: a primitive in M is occluded by one before it in the list (pass 2 found
/// it behind those), any other by one after it (pass 1). The search uses that to halve its work.
///
/// Finds a set C of primitives from `stuck` that is strongly connected in the occlusion graph
/// (edge q -> p when q lies in front of p at some pixel) and that nothing else in `stuck`
/// occludes: a source component. Precondition: every primitive of `stuck` is occluded by another
/// one of `stuck` (Vis-sort made no progress), so C has two or more members.
/// Uses group tests only (draw a set, query members) and counts them in stats; scratch's
/// path_index must hold -1 for every primitive (it does again on return).
/// Returns C's members in the order they have in `stuck`.
std::vector<uint32_t> findSourceCycle(OcclusionOracle& oracle, std::span<const uint32_t> stuck,
                                      std::span<const uint8_t> in_monotone_run,
                                      VisSortStats& stats, VisSortWorkspace& scratch);

} // namespace vissort::detail
