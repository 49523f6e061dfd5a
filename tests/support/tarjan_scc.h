#pragma once
// Strongly connected components (Tarjan, "Depth-first search and linear graph algorithms",
// SIAM J. Computing 1972): the test-side reference for the cycles Vis-sort reports.

#include <cstdint>
#include <vector>

namespace vissort::test {

/// Every strongly connected component of graph (graph[a] lists the b of the edges a -> b, each
/// below graph.size()). Each component ascending; components sorted by their first id.
std::vector<std::vector<uint32_t>>
stronglyConnectedComponents(const std::vector<std::vector<uint32_t>>& graph);

/// The components of two or more vertices: the cycles, in the form VisibilityOrder reports them.
std::vector<std::vector<uint32_t>>
cyclicComponents(const std::vector<std::vector<uint32_t>>& graph);

} // namespace vissort::test
