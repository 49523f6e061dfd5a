#pragma once
// The orders in which the rasterizing methods composite cells, front to back: by centres
// (centroid), by face adjacency (mpvo) and by occlusion queries (vissort). Internal to
// src/volume/.

#include <cstdint>
#include <memory>
#include <vector>

#include "vissort/camera.h"
#include "vissort/oracles.h"
#include "vissort/scene_orderer.h"
#include "vissort/tet_grid.h"

namespace vissort::detail {

/// Cells sorted by their centres' depth along the view direction, nearest first (ties by id):
/// the rule of VTK's vtkCellCenterDepthSort.
std::vector<uint32_t> centroidOrder(const TetGrid& grid, const ViewProjection& view);

/// Williams' Meshed Polyhedra Visibility Ordering ("Visibility ordering meshed polyhedra", ACM
/// TOG 1992): every face two cells share orders them by the side of its plane the eye is on; a
/// topological sort of those edges (Kahn's, ready cells first in, first out). The boundary gives
/// no edges, so on a non-convex grid cells that hide each other across a gap are not ordered: the
/// method's known failure. A cycle (possible in non-Delaunay grids) is broken by taking the
/// remaining cell of lowest id; broken_cycles counts those.
struct MpvoOrder {
    std::vector<uint32_t> order;
    uint64_t broken_cycles = 0;
};
MpvoOrder mpvoOrder(const TetGrid& grid, const std::vector<TetNeighbours>& neighbours,
                    const ViewProjection& view);

/// Vis-sort at cell level: each cell one primitive of its four faces, ordered by SceneOrderer
/// (coherence from the last frame's order and cycles; the first frame from the centroid order)
/// with the given oracle.
class VisibilityCellOrder {
public:
    /// Fails (one line) when the oracle cannot be made.
    static Result<std::unique_ptr<VisibilityCellOrder>> make(const TetGrid& grid,
                                                             OracleKind oracle);

    /// This frame's order and cycles (cell ids).
    const FrameOrder& order(const ViewProjection& view);

private:
    VisibilityCellOrder(const TetGrid& grid, std::unique_ptr<GeometryOracle> oracle);

    const TetGrid& grid_;
    TrianglePositions faces_;
    std::vector<PrimitiveRange> cells_;
    std::unique_ptr<GeometryOracle> oracle_;
    SceneOrderer orderer_;
    FrameOrder frame_;
    bool first_frame_ = true;
};

} // namespace vissort::detail
