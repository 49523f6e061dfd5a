// Splits hexahedra, wedges and pyramids into tetrahedra consistently across shared faces, by the
// rule of Dompierre, Labbé, Vallet and Camarero ("How to Subdivide Pyramids, Prisms and
// Hexahedra into Tetrahedra", IMR 1999): every quadrilateral face is cut by its diagonal through
// its corner of smallest global point index. Two cells sharing a face see the same indices, so
// they cut it the same way and the tetrahedra meet face to face (a cut chosen per cell, by its
// local corner numbers, leaves cracks a ray passes through).
//
// A cell is split as a cone from its corner v of smallest index over the faces that do not
// contain v: each triangle of those faces with v makes a tetrahedron. The faces that contain v
// are then cut by diagonals through v, which is their smallest corner too, so the cone obeys the
// rule on every face (a hexahedron gives 6 tetrahedra, a wedge 3, a pyramid 2). Corners repeated
// in a cell (a hexahedron collapsed to a wedge, as some writers store them) make tetrahedra with
// a repeated corner, which are left out.
#include <algorithm>
#include <array>
#include <cmath>
#include <span>

#include "grid/raw_grid.h"
#include "grid/tet_measures.h"

namespace vissort::detail {
namespace {

// Faces of each cell type in VTK's corner order, each listed so that the right-hand rule gives a
// normal pointing into the cell when the cell is oriented as VTK documents its type: the bottom
// quad of a hexahedron points towards the top, a wedge's first triangle points away from the
// second (vtkWedge's documented convention, the opposite of the others), a pyramid's base towards
// its apex, a tetrahedron's first three corners towards the fourth.
struct CellFace {
    uint8_t count; // 3 or 4 corners
    std::array<uint8_t, 4> corners;
};
constexpr std::array<CellFace, 6> kHexahedronFaces{{{4, {0, 1, 2, 3}},
                                                    {4, {4, 7, 6, 5}},
                                                    {4, {0, 4, 5, 1}},
                                                    {4, {1, 5, 6, 2}},
                                                    {4, {2, 6, 7, 3}},
                                                    {4, {3, 7, 4, 0}}}};
constexpr std::array<CellFace, 5> kWedgeFaces{{{3, {0, 2, 1, 0}},
                                               {3, {3, 4, 5, 0}},
                                               {4, {0, 1, 4, 3}},
                                               {4, {1, 2, 5, 4}},
                                               {4, {2, 0, 3, 5}}}};
constexpr std::array<CellFace, 5> kPyramidFaces{{{4, {0, 1, 2, 3}},
                                                 {3, {0, 4, 1, 0}},
                                                 {3, {1, 4, 2, 0}},
                                                 {3, {2, 4, 3, 0}},
                                                 {3, {3, 4, 0, 0}}}};

std::span<const CellFace> facesOf(CellType type) {
    switch (type) {
    case CellType::hexahedron:
        return kHexahedronFaces;
    case CellType::wedge:
        return kWedgeFaces;
    case CellType::pyramid:
        return kPyramidFaces;
    case CellType::tetrahedron:
        break;
    }
    return {};
}

const char* cellTypeName(CellType type) {
    switch (type) {
    case CellType::tetrahedron:
        return "tetrahedron";
    case CellType::hexahedron:
        return "hexahedron";
    case CellType::wedge:
        return "wedge";
    case CellType::pyramid:
        return "pyramid";
    }
    return "cell";
}

// The tetrahedra of one cell, oriented as the cell is (positive for a cell oriented as VTK
// documents), without those with a repeated corner.
void splitCell(CellType type, std::span<const uint32_t> corners, std::vector<Tet>& out) {
    if (type == CellType::tetrahedron) {
        out.push_back({corners[0], corners[1], corners[2], corners[3]});
        std::erase_if(out, hasRepeatedCorner);
        return;
    }
    const uint32_t apex = *std::min_element(corners.begin(), corners.end());
    for (const CellFace& face : facesOf(type)) {
        std::array<uint32_t, 4> f{};
        bool contains_apex = false;
        for (uint32_t i = 0; i < face.count; ++i) {
            f[i] = corners[face.corners[i]];
            contains_apex = contains_apex || f[i] == apex;
        }
        if (contains_apex)
            continue;
        if (face.count == 3) {
            out.push_back({f[0], f[1], f[2], apex});
            continue;
        }
        // The diagonal through the face's smallest corner: 0-2 or 1-3.
        const uint32_t smallest = *std::min_element(f.begin(), f.end());
        if (smallest == f[0] || smallest == f[2]) {
            out.push_back({f[0], f[1], f[2], apex});
            out.push_back({f[0], f[2], f[3], apex});
        } else {
            out.push_back({f[0], f[1], f[3], apex});
            out.push_back({f[1], f[2], f[3], apex});
        }
    }
    std::erase_if(out, hasRepeatedCorner);
}

} // namespace

Result<TetGrid> tetrahedralize(RawGrid raw, std::string name) {
    using R = Result<TetGrid>;
    const std::size_t cell_count = raw.cell_types.size();
    if (raw.cell_offsets.size() != cell_count + 1 ||
        raw.cell_offsets.back() != raw.cell_points.size())
        return R::failure("the cells' corner lists do not match their count");
    if (cell_count == 0)
        return R::failure("no 3D cells (tetrahedra, hexahedra, wedges, pyramids)");
    if (raw.points.size() > kMaxGridPoints)
        return R::failure(std::to_string(raw.points.size()) + " points, more than the " +
                          std::to_string(kMaxGridPoints) + " a grid may have");
    for (std::size_t p = 0; p < raw.points.size(); ++p) {
        const Vec3& v = raw.points[p];
        if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
            return R::failure("point " + std::to_string(p) +
                              " has a coordinate that is not finite");
    }
    if (!raw.scalars.empty() && raw.scalars.size() != raw.points.size())
        return R::failure(std::to_string(raw.scalars.size()) + " scalars for " +
                          std::to_string(raw.points.size()) + " points");

    TetGrid grid;
    grid.name = std::move(name);
    grid.file_cells = cell_count;
    grid.skipped_cells = raw.skipped_cells;
    grid.tets.reserve(cell_count);
    grid.source_cells.reserve(cell_count);
    // Tetrahedra may come in either orientation (writers differ, and a tetrahedron's corner order
    // has no other meaning): each is turned positive. The other cells' orientation is their
    // corner order's, documented by VTK; a file may use the mirror convention throughout, but a
    // cell oriented against the file's first cell of its type is inverted. (Per type: writers agree
    // on hexahedra but not on wedges, whose first triangle VTK winds outwards and Gmsh inwards.)
    std::array<int, 4> file_orientation{}; // per type, of its first cell: +1 or -1
    std::vector<Tet> pieces;
    for (std::size_t c = 0; c < cell_count; ++c) {
        const CellType type = raw.cell_types[c];
        const std::span<const uint32_t> corners(raw.cell_points.data() + raw.cell_offsets[c],
                                                raw.cell_offsets[c + 1] - raw.cell_offsets[c]);
        const auto describe = [&] {
            return "cell " + std::to_string(c) + " (" + cellTypeName(type) + ")";
        };
        if (corners.size() != cornerCount(type))
            return R::failure(describe() + " has " + std::to_string(corners.size()) +
                              " corners, not " + std::to_string(cornerCount(type)));
        for (const uint32_t p : corners)
            if (p >= raw.points.size())
                return R::failure(describe() + " names point " + std::to_string(p) + " of " +
                                  std::to_string(raw.points.size()));
        pieces.clear();
        splitCell(type, corners, pieces);
        if (pieces.empty())
            return R::failure(describe() +
                              " is degenerate: it repeats corners until it has no volume");
        int cell_orientation = 0;
        for (Tet& tet : pieces) {
            const double volume = signedVolume6(raw.points, tet);
            if (isFlat(volume, longestEdge(raw.points, tet)))
                return R::failure(describe() + " is degenerate: it has no volume (corners " +
                                  std::to_string(tet[0]) + ", " + std::to_string(tet[1]) + ", " +
                                  std::to_string(tet[2]) + " and " + std::to_string(tet[3]) +
                                  " are coplanar)");
            const int sign = volume > 0 ? 1 : -1;
            if (type == CellType::tetrahedron) {
                if (sign < 0)
                    std::swap(tet[2], tet[3]);
                continue;
            }
            if (cell_orientation == 0)
                cell_orientation = sign;
            if (sign != cell_orientation)
                return R::failure(describe() + " is tangled or far from convex: its split into "
                                               "tetrahedra has pieces of both orientations");
            if (sign < 0)
                std::swap(tet[2], tet[3]);
        }
        if (cell_orientation != 0) {
            int& type_orientation = file_orientation[std::size_t(type)];
            if (type_orientation == 0)
                type_orientation = cell_orientation;
            if (cell_orientation != type_orientation)
                return R::failure(describe() +
                                  " is inverted: its corners are ordered against the "
                                  "orientation of the file's earlier " +
                                  cellTypeName(type) + " cells");
        }
        if (grid.tets.size() + pieces.size() > kMaxGridTets)
            return R::failure("more than " + std::to_string(kMaxGridTets) +
                              " tetrahedra after splitting the cells");
        grid.tets.insert(grid.tets.end(), pieces.begin(), pieces.end());
        grid.source_cells.insert(grid.source_cells.end(), pieces.size(), uint32_t(c));
    }
    grid.points = std::move(raw.points);
    grid.scalars = std::move(raw.scalars);
    grid.scalar_name = std::move(raw.scalar_name);
    if (Status valid = validateGrid(grid); !valid)
        return R::failure(valid.error);
    return R{std::move(grid), {}};
}

} // namespace vissort::detail

namespace vissort {

Result<TetGrid> gridOfCells(std::vector<Vec3> points, GridCellType type,
                            std::span<const uint32_t> corners, std::vector<double> scalars,
                            std::string name) {
    using detail::RawGrid;
    const uint32_t per_cell = detail::cornerCount(type);
    if (corners.size() % per_cell != 0)
        return Result<TetGrid>::failure(std::to_string(corners.size()) +
                                        " corner indices: not a whole number of cells of " +
                                        std::to_string(per_cell));
    if (corners.size() / per_cell > kMaxGridTets)
        return Result<TetGrid>::failure(std::to_string(corners.size() / per_cell) +
                                        " cells, more than the " + std::to_string(kMaxGridTets) +
                                        " a grid may have");
    RawGrid raw;
    raw.points = std::move(points);
    raw.scalars = std::move(scalars);
    raw.scalar_name = raw.scalars.empty() ? "" : "scalars";
    raw.cell_types.assign(corners.size() / per_cell, type);
    raw.cell_points.assign(corners.begin(), corners.end());
    raw.cell_offsets.resize(raw.cell_types.size() + 1);
    for (std::size_t c = 0; c < raw.cell_offsets.size(); ++c)
        raw.cell_offsets[c] = c * per_cell;
    return detail::tetrahedralize(std::move(raw), std::move(name));
}

} // namespace vissort
