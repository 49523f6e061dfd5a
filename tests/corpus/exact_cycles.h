#pragma once
// The exact oracle's occlusion graph, pair by pair, and its strongly connected components: the
// reference for the cycles an order reports. The graph holds a -> b when, at some pixel, a
// fragment of b lies behind a fragment of a by more than the tolerance (b's farthest hit exceeds
// a's nearest hit + tolerance): exactly what ExactOracle::anyBehind(b) answers after draw(a), so
// Vis-sort over the exact oracle must report these components and nothing else.

#include <cstdint>
#include <span>
#include <vector>

#include "vissort/camera.h"
#include "vissort/geometry.h"
#include "vissort/geometry_oracle.h"

namespace vissort::test {

/// graph[a] lists, ascending, every b that a occludes somewhere (ids of primitives).
std::vector<std::vector<uint32_t>> exactOcclusionGraph(PositionsView positions,
                                                       const ViewProjection& view,
                                                       std::span<const PrimitiveRange> primitives,
                                                       float tolerance = kDepthTolerance);

/// The components of two or more primitives of exactOcclusionGraph, each ascending, sorted.
std::vector<std::vector<uint32_t>> exactCycles(PositionsView positions, const ViewProjection& view,
                                               std::span<const PrimitiveRange> primitives,
                                               float tolerance = kDepthTolerance);

} // namespace vissort::test
