#pragma once
// Ordering a stuck set from its occlusion graph in one pass (OcclusionOracle::occlusionGraph):
// the strongly connected components of a graph given as edges, in topological order, each with
// a witness. Internal to the core.

#include <cstdint>
#include <span>
#include <vector>

#include "source_cycle.h"
#include "vissort/occlusion_oracle.h"

namespace vissort::detail {

/// The strongly connected components of the graph on nodes 0..n-1 with `edges` (Tarjan's
/// algorithm, without recursion), in topological order: a component comes before every one its
/// members have an edge to. Each lists its members ascending; a component of two or more also
/// gets a witness, 2 (k - 1) of the edges that make it strongly connected (a breadth-first tree
/// out of its first member and one into it). Repeated edges and self-edges are allowed.
std::vector<SourceComponent> graphComponents(uint32_t n, std::span<const Occlusion> edges);

} // namespace vissort::detail
