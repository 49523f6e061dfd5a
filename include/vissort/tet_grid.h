#pragma once
// Unstructured grids for volume rendering: tetrahedra over points, with a scalar per point.
// Grid files of mixed cells (hexahedra, wedges, pyramids) become tetrahedra on loading, split
// consistently across shared faces (docs/volume.md, "Grids").
//
// Layer: vissort::grid (the package's `grid` component; docs/architecture.md).

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "vissort/geometry.h"
#include "vissort/result.h"

namespace vissort {

/// A tetrahedron's four point indices, positively oriented: p3 lies on the side of the plane
/// (p0, p1, p2) where (p1 - p0) x (p2 - p0) points.
using Tet = std::array<uint32_t, 4>;

/// A tetrahedral grid with one scalar per point (linear within each cell).
struct TetGrid {
    std::string name;
    std::vector<Vec3> points;
    std::vector<Tet> tets;
    /// One per point; empty when the file had none (volume rendering then refuses the grid).
    std::vector<double> scalars;
    std::string scalar_name;
    /// Per tetrahedron, the index of the file's cell it came from (a hexahedron gives 5 or 6).
    std::vector<uint32_t> source_cells;
    /// What the file held: its 3D cells, and the cells of lower dimension (vertices, lines,
    /// triangles, quads: boundary markers in many files) that were skipped.
    uint64_t file_cells = 0;
    uint64_t skipped_cells = 0;
};

/// The largest grid loaded or made: points and tetrahedra each (about 100 bytes of memory per
/// tetrahedron while loading, so 2.7 GB at the limit).
inline constexpr uint64_t kMaxGridPoints = uint64_t(1) << 26;
inline constexpr uint64_t kMaxGridTets = uint64_t(1) << 26;

/// Empty when grid is well formed, else a one-line problem: points finite, indices in range,
/// every tetrahedron of positive volume (relative to its size) with four distinct points, scalars
/// finite and one per point (or none), source_cells one per tetrahedron, and the cells
/// conforming: no triangle face shared by more than two tetrahedra, nor two that lie on the same
/// side of their shared face (overlapping cells).
Status validateGrid(const TetGrid& grid);

/// The tetrahedron across each face of a tetrahedron (face i is the one opposite corner i), or
/// kNoNeighbour on the boundary.
inline constexpr uint32_t kNoNeighbour = UINT32_MAX;
using TetNeighbours = std::array<uint32_t, 4>;

/// The corners of face i of a tetrahedron, ordered so that their normal by the right-hand rule
/// points into it (towards corner i) for a positively oriented tetrahedron.
inline constexpr std::array<std::array<uint8_t, 3>, 4> kTetFaceCorners{
    {{1, 3, 2}, {0, 2, 3}, {0, 3, 1}, {0, 1, 2}}};

/// Every tetrahedron's neighbours across its faces, or the problem that makes the grid
/// non-conforming (a face shared by three or more tetrahedra, or two that overlap). Expects
/// indices in range (validateGrid checks them first).
Result<std::vector<TetNeighbours>> faceNeighbours(const TetGrid& grid);

/// What `vissort info` says of a grid.
struct GridFacts {
    uint64_t points = 0, tets = 0, file_cells = 0, skipped_cells = 0;
    Bounds bounds;
    bool has_scalars = false;
    double scalar_min = 0, scalar_max = 0;
    uint64_t boundary_faces = 0; // triangle faces of one tetrahedron only
    /// Whether the boundary encloses a convex region: every boundary face's plane has every
    /// point on its inner side (within a relative 1e-9), and the boundary is one closed surface.
    bool convex = false;
};
GridFacts describeGrid(const TetGrid& grid);

/// Loads a grid from a file (by extension: .vtk legacy VTK, .vtu VTK XML, .node or .ele tetgen's
/// pair, .mesh Medit with an optional .sol beside it) or makes a built-in one
/// ("builtin:NAME?key=value&...": builtinGridNames()). Mixed cells are split into tetrahedra;
/// the result passes validateGrid. Errors name the file and the problem in one line.
Result<TetGrid> loadGrid(const std::string& spec);

/// The files loadGrid(spec) reads, without reading them: the grid file; tetgen's .node and .ele
/// (either named); Medit's .mesh and the .sol beside it when there is one; none for a built-in
/// grid. An output must be none of them (the command line refuses to overwrite an input).
std::vector<std::string> gridSourceFiles(const std::string& spec);

/// The linear 3D cells a grid can be made of, with their corners in VTK's order (docs/volume.md):
/// a tetrahedron's 4; a hexahedron's 8 (0-3 one quad face, 4-7 the opposite one, corner i + 4
/// joined to i); a wedge's 6 (triangles 0-1-2 and 3-4-5, i + 3 joined to i); a pyramid's 5 (quad
/// 0-1-2-3, apex 4).
enum class GridCellType : uint8_t { tetrahedron, hexahedron, wedge, pyramid };

/// A grid made of cells of one type: corners holds cornerCount(type) point indices per cell.
/// scalars: one per point, or empty. Split and validated as loadGrid does its files; errors name
/// the cell or point in one line.
Result<TetGrid> gridOfCells(std::vector<Vec3> points, GridCellType type,
                            std::span<const uint32_t> corners, std::vector<double> scalars,
                            std::string name);

/// Whether spec names a grid rather than a scene: a builtin:NAME of builtinGridNames(), or a
/// file whose extension is one of loadGrid's.
bool isGridSpec(const std::string& spec);

/// The built-in grids' names, each with a one-line description.
struct BuiltinGridInfo {
    const char* name;
    const char* description;
};
std::vector<BuiltinGridInfo> builtinGridNames();

} // namespace vissort
