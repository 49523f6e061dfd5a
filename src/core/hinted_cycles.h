#pragma once
// Confirming the cycles an earlier frame found, instead of searching for them again: cycles are
// as coherent as orders (the pipe runs that crossed last frame cross this frame). Internal to the
// core.

#include <cstdint>
#include <span>
#include <vector>

#include "source_cycle.h"
#include "vissort/occlusion_oracle.h"
#include "vissort/vis_sort.h"

namespace vissort::detail {

/// The sets of two or more of `members` that the occlusions of `witness` between members make
/// strongly connected (the components of that graph), each ascending. Occlusions with an end
/// outside members are ignored.
std::vector<std::vector<uint32_t>> connectedParts(std::span<const uint32_t> members,
                                                  std::span<const Occlusion> witness);

/// Whether `witness` makes all of `members` (two or more, no repeats) strongly connected.
bool witnessConnects(std::span<const uint32_t> members, std::span<const Occlusion> witness);

/// The occlusions of `witness` with both ends in `part` (ascending).
std::vector<Occlusion> witnessWithin(std::span<const uint32_t> part,
                                     std::span<const Occlusion> witness);

/// A set of primitives this frame's oracle proved strongly connected, and the proof.
struct ConfirmedGroup {
    std::vector<uint32_t> members; // ascending
    std::vector<Occlusion> witness;
};

/// Tests every occlusion of every hint's witness (one group test per occluder, counted in stats
/// as the cycle search's) and returns the parts of each hint that the confirmed ones make
/// strongly connected: disjoint, so that a caller's overlapping hints cannot put a primitive in
/// two groups. Ids out of range are ignored.
std::vector<ConfirmedGroup> confirmHints(OcclusionOracle& oracle, const CycleHints& hints,
                                         VisSortStats& stats);

} // namespace vissort::detail
