#pragma once
// VTK's cell type codes (vtkCellType.h) as vissort reads them: what both VTK readers (legacy .vtk
// and XML .vtu) share, so that a cell is kept, skipped or refused, and its problems worded, the
// same way in both. Internal to src/grid/.

#include <array>
#include <cstdint>
#include <string>
#include <utility>

#include "grid/raw_grid.h"

namespace vissort::detail {

/// VTK's name of a cell type code, as vtkCellType.h spells the type; "unknown" for codes it has
/// none for.
inline const char* vtkCellTypeName(int64_t code) {
    switch (code) {
    case 0:
        return "empty cell";
    case 1:
        return "vertex";
    case 2:
        return "poly-vertex";
    case 3:
        return "line";
    case 4:
        return "poly-line";
    case 5:
        return "triangle";
    case 6:
        return "triangle strip";
    case 7:
        return "polygon";
    case 8:
        return "pixel";
    case 9:
        return "quad";
    case 10:
        return "tetrahedron";
    case 11:
        return "voxel";
    case 12:
        return "hexahedron";
    case 13:
        return "wedge";
    case 14:
        return "pyramid";
    case 15:
        return "pentagonal prism";
    case 16:
        return "hexagonal prism";
    case 21:
        return "quadratic edge";
    case 22:
        return "quadratic triangle";
    case 23:
        return "quadratic quad";
    case 24:
        return "quadratic tetrahedron";
    case 25:
        return "quadratic hexahedron";
    case 26:
        return "quadratic wedge";
    case 27:
        return "quadratic pyramid";
    case 28:
        return "biquadratic quad";
    case 29:
        return "triquadratic hexahedron";
    case 30:
        return "quadratic-linear quad";
    case 31:
        return "quadratic-linear wedge";
    case 32:
        return "biquadratic-quadratic wedge";
    case 33:
        return "biquadratic-quadratic hexahedron";
    case 34:
        return "biquadratic triangle";
    case 35:
        return "cubic line";
    case 36:
        return "quadratic polygon";
    case 37:
        return "triquadratic pyramid";
    case 41:
        return "convex point set";
    case 42:
        return "polyhedron";
    case 51:
        return "parametric curve";
    case 52:
        return "parametric surface";
    case 53:
        return "parametric tri surface";
    case 54:
        return "parametric quad surface";
    case 55:
        return "parametric tetra region";
    case 56:
        return "parametric hex region";
    case 60:
        return "higher-order edge";
    case 61:
        return "higher-order triangle";
    case 62:
        return "higher-order quad";
    case 63:
        return "higher-order polygon";
    case 64:
        return "higher-order tetrahedron";
    case 65:
        return "higher-order wedge";
    case 66:
        return "higher-order pyramid";
    case 67:
        return "higher-order hexahedron";
    case 68:
        return "Lagrange curve";
    case 69:
        return "Lagrange triangle";
    case 70:
        return "Lagrange quadrilateral";
    case 71:
        return "Lagrange tetrahedron";
    case 72:
        return "Lagrange hexahedron";
    case 73:
        return "Lagrange wedge";
    case 74:
        return "Lagrange pyramid";
    case 75:
        return "Bezier curve";
    case 76:
        return "Bezier triangle";
    case 77:
        return "Bezier quadrilateral";
    case 78:
        return "Bezier tetrahedron";
    case 79:
        return "Bezier hexahedron";
    case 80:
        return "Bezier wedge";
    case 81:
        return "Bezier pyramid";
    default:
        return "unknown";
    }
}

/// Appends one VTK cell to grid, or says why it cannot be: cell (0-based, counted over the whole
/// file) of VTK type code with corner_count corners, whose point indices (relative to the piece's
/// first point) must lie in [0, point_count); point_base is added to each (the points of earlier
/// pieces). Linear tetrahedra, hexahedra, wedges and pyramids are kept as they are; voxels become
/// hexahedra; cells of lower dimension (codes 0 to 9) are counted in skipped_cells; the rest are
/// refused. Returns an empty string when the cell was kept or skipped.
inline std::string addVtkCell(RawGrid& grid, uint64_t cell, int64_t code, const int64_t* corners,
                              uint64_t corner_count, uint64_t point_base, uint64_t point_count) {
    // Indices are checked for every cell, skipped ones too: one out of range means a corrupt file.
    for (uint64_t i = 0; i < corner_count; ++i)
        if (corners[i] < 0 || uint64_t(corners[i]) >= point_count)
            return "cell " + std::to_string(cell) + " refers to point " +
                   std::to_string(corners[i]) + ", but " +
                   (point_count == 0
                        ? std::string("there are no points")
                        : "the points are numbered 0 to " + std::to_string(point_count - 1));
    if (code >= 0 && code <= 9) {
        ++grid.skipped_cells;
        return {};
    }
    CellType type;
    switch (code) {
    case 10:
        type = CellType::tetrahedron;
        break;
    case 11: // voxel: a hexahedron whose corners are ordered x fastest, then y, then z
    case 12:
        type = CellType::hexahedron;
        break;
    case 13:
        type = CellType::wedge;
        break;
    case 14:
        type = CellType::pyramid;
        break;
    default:
        return "cell " + std::to_string(cell) + " has VTK type " + std::to_string(code) + " (" +
               vtkCellTypeName(code) +
               "), which vissort does not read: only linear tetrahedra, hexahedra, wedges, "
               "pyramids and voxels";
    }
    if (corner_count != cornerCount(type))
        return "cell " + std::to_string(cell) + " (VTK type " + std::to_string(code) + ", " +
               vtkCellTypeName(code) + ") has " + std::to_string(corner_count) +
               " corners instead of " + std::to_string(cornerCount(type));
    std::array<uint32_t, 8> points{};
    for (uint64_t i = 0; i < corner_count; ++i)
        points[i] = uint32_t(point_base + corners[i]);
    if (code == 11) {
        // A voxel's 0-1-3-2 and 4-5-7-6 go round its two faces: a hexahedron's 0-1-2-3, 4-5-6-7.
        std::swap(points[2], points[3]);
        std::swap(points[6], points[7]);
    }
    grid.addCell(type, points.data());
    return {};
}

} // namespace vissort::detail
