#pragma once
// Vis-sort in 3D (Govindaraju, Henson, Lin, Manocha, I3D 2005, section 4): a front-to-back
// visibility order of primitives computed with occlusion queries only, and the cycles that make
// a strict order impossible. Depends on nothing but the standard library.

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "vissort/occlusion_oracle.h"

namespace vissort {

/// What one ordering cost, counted in oracle operations.
struct VisSortStats {
    uint64_t queries = 0;          // anyBehind answers asked for
    uint64_t draws = 0;            // primitives drawn into the depth buffer
    uint64_t clears = 0;           // depth buffer clears (one per pass or group test)
    uint32_t iterations = 0;       // Vis-sort iterations (pass 1 + pass 2)
    uint32_t stuck_iterations = 0; // iterations that output nothing (a cycle was met)
    uint64_t cycle_queries = 0;    // of queries, those spent finding cycles
    uint64_t cycle_draws = 0;      // of draws, those spent finding cycles
};

struct VisibilityOrder {
    /// Primitive ids front to back: a permutation of 0..n-1.
    std::vector<uint32_t> order;
    /// Each cycle: the primitives of one strongly connected component (of two or more) of the
    /// occlusion graph among primitives that could not be ordered, ascending ids.
    std::vector<std::vector<uint32_t>> cycles;
    VisSortStats stats;
};

/// Scratch memory for visSort, owned by the caller and reused across frames, so that a frame
/// allocates nothing in steady state unless it meets a cycle (the cycle search and
/// VisibilityOrder::cycles allocate a few small vectors per cycle). Contents between calls are
/// unspecified.
struct VisSortWorkspace {
    std::vector<uint32_t> unsorted, outside, candidates, targets, position;
    std::vector<uint8_t> in_monotone_run, query, behind, in_cycle, walk_state;
    std::vector<int32_t> path_index;
    // The cycle search's path below the last source it found, resumed at the next stuck
    // iteration of the same visSort call (src/core/source_cycle.h).
    std::vector<std::vector<uint32_t>> pending_path;
    std::vector<uint8_t> seen; // the precondition check's, in builds with assertions
    /// Called after each iteration with the primitives output so far and their total, when set:
    /// what a progress display of a long order reads. Not scratch: visSort leaves it as it is.
    std::function<void(std::size_t sorted, std::size_t total)> on_iteration;
};

/// Orders the oracle's primitives front to back.
/// initial_order is the list I to start from (a permutation of 0..n-1): the previous frame's
/// order for coherence, or a depth-key order; the closer to a visibility order, the fewer
/// queries. On return order is complete even when there are cycles: see docs/algorithm.md for
/// how cycles are found and broken.
VisibilityOrder visSort(OcclusionOracle& oracle, std::span<const uint32_t> initial_order);

/// The same, writing into result (its vectors keep their capacity) with the caller's scratch.
void visSort(OcclusionOracle& oracle, std::span<const uint32_t> initial_order,
             VisibilityOrder& result, VisSortWorkspace& workspace);

} // namespace vissort
