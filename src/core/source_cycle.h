#pragma once
// Finding a cycle that blocks Vis-sort: a source strongly connected component of the occlusion
// graph among the primitives that are stuck. Internal to the core.

#include <cstdint>
#include <span>
#include <vector>

#include "vissort/occlusion_oracle.h"
#include "vissort/vis_sort.h"

namespace vissort::detail {

/// A source strongly connected component: its members and the occlusions among them, found by
/// the search, that make it strongly connected (empty for a source of one).
struct SourceComponent {
    std::vector<uint32_t> members;
    std::vector<Occlusion> witness;
};

/// One group test (OcclusionOracle::queryAgainst), counted in stats as a cycle search's.
void groupTest(OcclusionOracle& oracle, std::span<const uint32_t> occluders,
               std::span<const uint32_t> targets, std::span<uint8_t> behind, VisSortStats& stats);

/// An occluder of target among candidates (which do not hold it), by one group test of them all
/// and then halving; false when none occludes it.
bool findOccluderAmong(OcclusionOracle& oracle, std::span<const uint32_t> candidates,
                       uint32_t target, VisSortStats& stats, uint32_t& occluder);

/// `stuck` is the list I of an iteration that output nothing and in_monotone_run its M flags
/// after that iteration: a primitive in M is occluded by one before it in the list (pass 2 found
/// it behind those), any other by one after it (pass 1). The search uses that to halve its work.
///
/// Finds sets of primitives from `stuck` that are strongly connected in the occlusion graph
/// (edge q -> p when q lies in front of p at some pixel) and that nothing else in `stuck`
/// occludes: source components. Precondition: every primitive of `stuck` is occluded by another
/// one of `stuck` (Vis-sort made no progress), so each has two or more members, and there is at
/// least one. Up to max_walks walks, each from the front-most primitive not yet known to be in a
/// source or behind one; a walk that reaches such a primitive ends without a new source.
/// Uses group tests only (draw a set, query members) and counts them in stats. Each source lists
/// its members in the order they have in `stuck`, and the occlusions it found among them that
/// make them strongly connected.
std::vector<SourceComponent> findSourceCycles(OcclusionOracle& oracle,
                                              std::span<const uint32_t> stuck,
                                              std::span<const uint8_t> in_monotone_run,
                                              uint32_t max_walks, VisSortStats& stats,
                                              VisSortWorkspace& scratch);

} // namespace vissort::detail
