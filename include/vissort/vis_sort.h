#pragma once
// Vis-sort in 3D (Govindaraju, Henson, Lin, Manocha, I3D 2005, section 4): a front-to-back
// visibility order of primitives computed with occlusion queries only, and the cycles that make
// a strict order impossible. Depends on nothing but the standard library.
//
// Layer: vissort::core (the package's `order` component; docs/architecture.md).

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
    uint32_t hinted_cycles = 0;    // cycles confirmed from CycleHints instead of searched for
    uint32_t graph_passes = 0;     // stuck sets ordered from the oracle's occlusion graph

    /// Adds every count of `part` (a stage's or a step's) to these.
    VisSortStats& operator+=(const VisSortStats& part) {
        queries += part.queries;
        draws += part.draws;
        clears += part.clears;
        iterations += part.iterations;
        stuck_iterations += part.stuck_iterations;
        cycle_queries += part.cycle_queries;
        cycle_draws += part.cycle_draws;
        hinted_cycles += part.hinted_cycles;
        graph_passes += part.graph_passes;
        return *this;
    }
};

/// Every count of VisSortStats by name, in one list: the command line's JSON and CSV and the
/// Python module's dicts are written from it, so a count added here reaches each of them (as the
/// tables of enum_names.h do for enums). Calls visit(name, value) per field, in this order.
template <class Visit> void forEachStat(const VisSortStats& s, Visit&& visit) {
    visit("queries", s.queries);
    visit("draws", s.draws);
    visit("clears", s.clears);
    visit("iterations", s.iterations);
    visit("stuck_iterations", s.stuck_iterations);
    visit("cycle_queries", s.cycle_queries);
    visit("cycle_draws", s.cycle_draws);
    visit("hinted_cycles", s.hinted_cycles);
    visit("graph_passes", s.graph_passes);
}

struct VisibilityOrder {
    /// Primitive ids front to back: a permutation of 0..n-1.
    std::vector<uint32_t> order;
    /// Each cycle: the primitives of one strongly connected component (of two or more) of the
    /// occlusion graph among primitives that could not be ordered, ascending ids.
    std::vector<std::vector<uint32_t>> cycles;
    /// Per cycle (parallel to cycles), occlusions among its members that the oracle confirmed and
    /// that make it strongly connected: what a later frame re-checks, one small test each, to
    /// confirm the same cycle instead of searching for it again (CycleHints).
    std::vector<std::vector<Occlusion>> cycle_witnesses;
    VisSortStats stats;
};

/// Scratch memory for visSort, owned by the caller and reused across frames, so that a frame
/// allocates nothing in steady state unless it meets a cycle (the cycle search and
/// VisibilityOrder::cycles allocate a few small vectors per cycle). Contents between calls are
/// unspecified.
/// A strongly connected set of primitives on the cycle search's path (src/core/source_cycle.h):
/// its members, the occlusions among them that make it so, and the occlusion that links it to
/// the set below it on the path (an occluder of one of that set's members).
struct CycleSearchStep {
    std::vector<uint32_t> members;
    std::vector<Occlusion> witness;
    Occlusion link;
};

struct VisSortWorkspace {
    std::vector<uint32_t> unsorted, outside, candidates, targets, position;
    std::vector<uint8_t> in_monotone_run, query, behind, in_cycle, walk_state;
    std::vector<int32_t> path_index;
    // The cycle search's coverage: per primitive, the list positions [first, last] whose other
    // primitives it was tested behind, in the current call (src/core/source_cycle.cpp).
    std::vector<uint32_t> covered_first, covered_last;
    // The cycle search's path below the last source it found, resumed at the next stuck
    // iteration of the same visSort call (src/core/source_cycle.h).
    std::vector<CycleSearchStep> pending_path;
    std::vector<uint8_t> seen; // the precondition check's, in builds with assertions
    /// Called after each iteration with the primitives output so far and their total, when set:
    /// what a progress display of a long order reads. Not scratch: visSort leaves it as it is.
    std::function<void(std::size_t sorted, std::size_t total)> on_iteration;
};

/// Cycles expected from an earlier frame, each given by its members and a witness: occlusions
/// among them that made it strongly connected then (VisibilityOrder::cycles and
/// cycle_witnesses of the last frame, in this call's ids). When Vis-sort is stuck it first
/// re-checks the hints: each occlusion of a witness once per call (one small test per occluder),
/// keeping of each hint its members still unsorted that the confirmed occlusions connect; a part
/// that no other unsorted primitive occludes is a source component and is reported as a cycle
/// without a search. The other parts are where the search starts its walks. Hints change how
/// many queries a frame takes, never its order's validity: nothing becomes a cycle unless this
/// frame's oracle confirms it, and a witness that names other primitives or does not connect its
/// members only shrinks its hint.
struct CycleHints {
    std::span<const std::vector<uint32_t>> cycles;
    std::span<const std::vector<Occlusion>> witnesses; // parallel to cycles
};

/// Orders the oracle's primitives front to back.
/// initial_order is the list I to start from (a permutation of 0..n-1): the previous frame's
/// order for coherence, or a depth-key order; the closer to a visibility order, the fewer
/// queries. On return order is complete even when there are cycles: see docs/algorithm.md for
/// how cycles are found and broken.
VisibilityOrder visSort(OcclusionOracle& oracle, std::span<const uint32_t> initial_order);

/// The same, writing into result (its vectors keep their capacity) with the caller's scratch.
/// hints: cycles the last frame found (see CycleHints); none by default.
void visSort(OcclusionOracle& oracle, std::span<const uint32_t> initial_order,
             VisibilityOrder& result, VisSortWorkspace& workspace, CycleHints hints = {});

} // namespace vissort
