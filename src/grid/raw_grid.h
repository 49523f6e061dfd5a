#pragma once
// What a grid file holds before its cells become tetrahedra: points, cells of the four linear
// 3D kinds in VTK's point order, and a scalar per point. Every reader of src/grid/ produces one;
// tetrahedralize() (cell_split.h) turns it into a TetGrid. Internal to src/grid/.

#include <cstdint>
#include <string>
#include <vector>

#include "vissort/geometry.h"
#include "vissort/result.h"
#include "vissort/tet_grid.h"

namespace vissort::detail {

/// The linear 3D cells in VTK's corner order (VTK_TETRA 10, VTK_HEXAHEDRON 12, VTK_WEDGE 13,
/// VTK_PYRAMID 14): GridCellType (tet_grid.h) says the orders.
using CellType = GridCellType;

/// Corners of a cell type: 4, 8, 6 or 5.
inline uint32_t cornerCount(CellType type) {
    switch (type) {
    case CellType::tetrahedron:
        return 4;
    case CellType::hexahedron:
        return 8;
    case CellType::wedge:
        return 6;
    case CellType::pyramid:
        return 5;
    }
    return 0;
}

struct RawGrid {
    std::vector<Vec3> points;
    std::vector<CellType> cell_types;
    /// Cell c's corners are cell_points[cell_offsets[c] .. cell_offsets[c + 1]): cell_types.size()
    /// + 1 offsets, starting at 0, each span cornerCount(cell_types[c]) long.
    std::vector<uint64_t> cell_offsets{0};
    std::vector<uint32_t> cell_points;
    /// One per point, or empty when the file has none.
    std::vector<double> scalars;
    std::string scalar_name;
    /// Cells of lower dimension the reader skipped (vertices, lines, polygons).
    uint64_t skipped_cells = 0;

    void addCell(CellType type, const uint32_t* corners) {
        cell_types.push_back(type);
        cell_points.insert(cell_points.end(), corners, corners + cornerCount(type));
        cell_offsets.push_back(cell_points.size());
    }
};

// The readers. Each parses a whole file held in memory and returns the grid or a one-line problem
// without the file's name (loadGrid adds it). Each refuses, before allocating, any count that the
// bytes given cannot hold (bounded memory on hostile headers), and any count beyond
// kMaxGridPoints / kMaxGridTets. Indices are checked against the points (0-based after a reader's
// own base), coordinates and scalars for being finite, by the readers or by tetrahedralize().

/// Legacy VTK (.vtk): ASCII or BINARY, DATASET UNSTRUCTURED_GRID, POINT_DATA SCALARS (the first
/// scalar array, or the one named `scalar_name` when not empty).
Result<RawGrid> readVtkLegacy(const std::string& bytes, const std::string& scalar_name = {});

/// VTK XML unstructured grid (.vtu): ascii, base64 binary (header UInt32 or UInt64, zlib
/// compressed or not) and appended raw or base64 data; PointData's first scalar array (or the one
/// named).
Result<RawGrid> readVtu(const std::string& bytes, const std::string& scalar_name = {});

/// tetgen's .node (points; the first point attribute, if any, is the scalar) and .ele
/// (tetrahedra of 4 corners; 10-corner ones use their first 4), with their first index 0 or 1
/// as the .node file says.
Result<RawGrid> readTetgen(const std::string& node_bytes, const std::string& ele_bytes);

/// Medit .mesh (ASCII, MeshVersionFormatted 1 or 2, Dimension 3): Vertices, Tetrahedra,
/// Hexahedra, Prisms, Pyramids (Triangles, Quadrilaterals, Edges and the rest skipped), with the
/// scalar of an optional .sol (SolAtVertices, one scalar field).
Result<RawGrid> readMedit(const std::string& mesh_bytes, const std::string* sol_bytes = nullptr);

/// Splits every cell into positively oriented tetrahedra, consistently across shared faces, and
/// validates the result (validateGrid). The problems name the cell: "cell 12 (hexahedron) is
/// inverted".
Result<TetGrid> tetrahedralize(RawGrid raw, std::string name);

} // namespace vissort::detail
