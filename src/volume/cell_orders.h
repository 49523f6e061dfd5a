#pragma once
// The orders in which the rasterizing methods composite cells, front to back: by centres
// (centroid), by face adjacency (mpvo) and by occlusion queries (vissort). Internal to
// src/volume/.

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "vissort/camera.h"
#include "vissort/oracles.h"
#include "vissort/scene_orderer.h"
#include "vissort/tet_grid.h"
#include "volume/convex_facing_oracle.h"

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

/// The same topological sort of the shared faces, taking among the ready cells the one earliest
/// in `preferred` (a permutation of the cells), and breaking a cycle at the earliest preferred
/// cell left: an order every shared face agrees with, otherwise as close to `preferred` as the
/// faces allow. Vissort's start list: last frame's order (or the centres') for the cells that
/// share no face, the faces for those that do.
MpvoOrder faceConsistentOrder(const TetGrid& grid, const std::vector<TetNeighbours>& neighbours,
                              const ViewProjection& view, std::span<const uint32_t> preferred);

/// The cells' faces as triangles, four a cell (cell c's are triangles 4c to 4c + 3, face f
/// opposite corner f, corners in kTetFaceCorners' order), and each cell's range of them: the
/// primitives of the cell order.
TrianglePositions cellFaces(const TetGrid& grid);
std::vector<PrimitiveRange> cellRanges(std::size_t cells);

/// Vis-sort at cell level: each cell one primitive of its four faces (drawn by its front faces,
/// queried by its back ones: ConvexFacingOracle), ordered by SceneOrderer with the given oracle
/// from a start list every shared face agrees with, otherwise in last frame's order (the first
/// frame's: the centroid order): faceConsistentOrder.
class VisibilityCellOrder {
public:
    /// Fails (one line) when the oracle cannot be made or the grid is not conforming.
    static Result<std::unique_ptr<VisibilityCellOrder>> make(const TetGrid& grid,
                                                             OracleKind oracle);

    /// This frame's order and cycles (cell ids).
    const FrameOrder& order(const ViewProjection& view);

private:
    VisibilityCellOrder(const TetGrid& grid, std::vector<TetNeighbours> neighbours,
                        std::unique_ptr<GeometryOracle> oracle);

    const TetGrid& grid_;
    std::vector<TetNeighbours> neighbours_; // for the start list (faceConsistentOrder)
    TrianglePositions faces_;
    std::vector<PrimitiveRange> cells_;
    std::unique_ptr<GeometryOracle> oracle_;
    ConvexFacingOracle facing_; // over oracle_: fronts drawn, backs queried
    SceneOrderer orderer_;
    FrameOrder frame_;
    std::vector<uint32_t> preferred_; // last frame's order, or the centres' on the first
    bool first_frame_ = true;
};

} // namespace vissort::detail
