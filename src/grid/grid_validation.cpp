// Checks a tetrahedral grid (validateGrid), finds the neighbours across faces (faceNeighbours) and
// describes the grid (describeGrid). Faces are matched by sorting their corner triples: memory
// and time are those of one sort of 4 records per tetrahedron, whatever the grid's shape.
#include <algorithm>
#include <cmath>
#include <numeric>

#include "grid/tet_measures.h"
#include "vissort/tet_grid.h"

namespace vissort {
namespace {

using detail::kFlatVolumeRatio;
using detail::longestEdge;
using detail::orient;

// A face of a tetrahedron, keyed by its sorted corners.
struct FaceRecord {
    std::array<uint32_t, 3> key;
    uint32_t tet;
    uint8_t face;
};

std::array<uint32_t, 3> faceOf(const Tet& tet, int face) {
    return {tet[kTetFaceCorners[face][0]], tet[kTetFaceCorners[face][1]],
            tet[kTetFaceCorners[face][2]]};
}

std::string tetName(uint32_t t) {
    return "tetrahedron " + std::to_string(t);
}

} // namespace

Result<std::vector<TetNeighbours>> faceNeighbours(const TetGrid& grid) {
    using R = Result<std::vector<TetNeighbours>>;
    std::vector<FaceRecord> faces;
    faces.reserve(grid.tets.size() * 4);
    for (uint32_t t = 0; t < grid.tets.size(); ++t)
        for (uint8_t f = 0; f < 4; ++f) {
            std::array<uint32_t, 3> key = faceOf(grid.tets[t], f);
            std::sort(key.begin(), key.end());
            faces.push_back({key, t, f});
        }
    std::sort(faces.begin(), faces.end(), [](const FaceRecord& a, const FaceRecord& b) {
        return a.key != b.key ? a.key < b.key : a.tet < b.tet;
    });
    std::vector<TetNeighbours> neighbours(grid.tets.size());
    for (TetNeighbours& n : neighbours)
        n.fill(kNoNeighbour);
    for (std::size_t i = 0; i < faces.size();) {
        std::size_t end = i + 1;
        while (end < faces.size() && faces[end].key == faces[i].key)
            ++end;
        const auto corners = [&] {
            return std::to_string(faces[i].key[0]) + ", " + std::to_string(faces[i].key[1]) +
                   " and " + std::to_string(faces[i].key[2]);
        };
        if (end - i > 2)
            return R::failure(
                "the grid is not conforming: the face of points " + corners() + " belongs to " +
                std::to_string(end - i) + " tetrahedra (" + std::to_string(faces[i].tet) + ", " +
                std::to_string(faces[i + 1].tet) + ", " + std::to_string(faces[i + 2].tet) + ")");
        if (end - i == 2) {
            const FaceRecord& a = faces[i];
            const FaceRecord& b = faces[i + 1];
            const Tet& ta = grid.tets[a.tet];
            const std::array<uint32_t, 3> fa = faceOf(ta, a.face);
            // b's far corner must lie on the other side of the shared face than a's.
            const Vec3& far_b = grid.points[grid.tets[b.tet][b.face]];
            const double side =
                orient(grid.points[fa[0]], grid.points[fa[1]], grid.points[fa[2]], far_b);
            const double edge =
                std::max(longestEdge(grid.points, ta), longestEdge(grid.points, grid.tets[b.tet]));
            if (side > kFlatVolumeRatio * edge * edge * edge)
                return R::failure("the grid is not conforming: tetrahedra " +
                                  std::to_string(a.tet) + " and " + std::to_string(b.tet) +
                                  " overlap (both lie on the same side "
                                  "of their face of points " +
                                  corners() + ")");
            neighbours[a.tet][a.face] = b.tet;
            neighbours[b.tet][b.face] = a.tet;
        }
        i = end;
    }
    return R{std::move(neighbours), {}};
}

Status validateGrid(const TetGrid& grid) {
    if (grid.tets.empty())
        return Status::failure("the grid has no tetrahedra");
    if (grid.points.size() > kMaxGridPoints || grid.tets.size() > kMaxGridTets)
        return Status::failure(
            std::to_string(grid.points.size()) + " points and " + std::to_string(grid.tets.size()) +
            " tetrahedra: more than a grid may have (" + std::to_string(kMaxGridTets) + " each)");
    for (std::size_t p = 0; p < grid.points.size(); ++p) {
        const Vec3& v = grid.points[p];
        if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
            return Status::failure("point " + std::to_string(p) +
                                   " has a coordinate that is not finite");
    }
    if (!grid.scalars.empty()) {
        if (grid.scalars.size() != grid.points.size())
            return Status::failure(std::to_string(grid.scalars.size()) + " scalars for " +
                                   std::to_string(grid.points.size()) + " points");
        for (std::size_t p = 0; p < grid.scalars.size(); ++p)
            if (!std::isfinite(grid.scalars[p]))
                return Status::failure("the scalar of point " + std::to_string(p) +
                                       " is not finite");
    }
    if (grid.source_cells.size() != grid.tets.size())
        return Status::failure(std::to_string(grid.source_cells.size()) + " source cells for " +
                               std::to_string(grid.tets.size()) + " tetrahedra");
    for (uint32_t t = 0; t < grid.tets.size(); ++t) {
        const Tet& tet = grid.tets[t];
        for (const uint32_t p : tet)
            if (p >= grid.points.size())
                return Status::failure(tetName(t) + " names point " + std::to_string(p) + " of " +
                                       std::to_string(grid.points.size()));
        if (detail::hasRepeatedCorner(tet))
            return Status::failure(tetName(t) + " repeats a point");
        const double volume6 = detail::signedVolume6(grid.points, tet);
        if (volume6 < 0 || detail::isFlat(volume6, longestEdge(grid.points, tet)))
            return Status::failure(tetName(t) + (volume6 < 0 ? " is inverted (negative volume)"
                                                             : " is degenerate (no volume)"));
    }
    Result<std::vector<TetNeighbours>> neighbours = faceNeighbours(grid);
    if (!neighbours)
        return Status::failure(neighbours.error);
    return Status::ok();
}

GridFacts describeGrid(const TetGrid& grid) {
    GridFacts facts;
    facts.points = grid.points.size();
    facts.tets = grid.tets.size();
    facts.file_cells = grid.file_cells;
    facts.skipped_cells = grid.skipped_cells;
    for (const Vec3& p : grid.points)
        facts.bounds.add(p);
    facts.has_scalars = !grid.scalars.empty();
    if (facts.has_scalars) {
        const auto [low, high] = std::minmax_element(grid.scalars.begin(), grid.scalars.end());
        facts.scalar_min = *low;
        facts.scalar_max = *high;
    }
    Result<std::vector<TetNeighbours>> neighbours = faceNeighbours(grid);
    if (!neighbours)
        return facts;

    // The boundary: faces with no neighbour, oriented into their tetrahedron.
    std::vector<std::array<uint32_t, 3>> boundary;
    for (uint32_t t = 0; t < grid.tets.size(); ++t)
        for (int f = 0; f < 4; ++f)
            if ((*neighbours.value)[t][f] == kNoNeighbour)
                boundary.push_back(faceOf(grid.tets[t], f));
    facts.boundary_faces = boundary.size();

    // Convex when the boundary is one closed surface (every edge in exactly two boundary faces,
    // all connected) that is locally convex at every edge: for a closed connected surface, local
    // convexity everywhere is convexity.
    struct EdgeRecord {
        uint32_t low, high, face, opposite;
    };
    std::vector<EdgeRecord> edges;
    edges.reserve(boundary.size() * 3);
    for (uint32_t f = 0; f < boundary.size(); ++f)
        for (int e = 0; e < 3; ++e) {
            const uint32_t a = boundary[f][e], b = boundary[f][(e + 1) % 3];
            edges.push_back({std::min(a, b), std::max(a, b), f, boundary[f][(e + 2) % 3]});
        }
    std::sort(edges.begin(), edges.end(), [](const EdgeRecord& x, const EdgeRecord& y) {
        return x.low != y.low ? x.low < y.low : x.high < y.high;
    });
    std::vector<uint32_t> parent(boundary.size());
    std::iota(parent.begin(), parent.end(), 0u);
    const auto root = [&](uint32_t f) {
        while (parent[f] != f)
            f = parent[f] = parent[parent[f]];
        return f;
    };
    const double scale = facts.bounds.radius();
    bool convex = !boundary.empty();
    for (std::size_t i = 0; i < edges.size() && convex; i += 2) {
        if (i + 1 >= edges.size() || edges[i + 1].low != edges[i].low ||
            edges[i + 1].high != edges[i].high ||
            (i + 2 < edges.size() && edges[i + 2].low == edges[i].low &&
             edges[i + 2].high == edges[i].high)) {
            convex = false;
            break;
        }
        for (int k = 0; k < 2; ++k) {
            const EdgeRecord& mine = edges[i + k];
            const EdgeRecord& other = edges[i + 1 - k];
            const auto& face = boundary[mine.face];
            // The other face's far corner must not lie outside this face's plane.
            const Vec3 normal = cross(grid.points[face[1]] - grid.points[face[0]],
                                      grid.points[face[2]] - grid.points[face[0]]);
            const double side = dot(normal, grid.points[other.opposite] - grid.points[face[0]]);
            if (side < -1e-9 * length(normal) * scale)
                convex = false;
        }
        parent[root(edges[i].face)] = root(edges[i + 1].face);
    }
    if (convex)
        for (uint32_t f = 0; f < boundary.size(); ++f)
            if (root(f) != root(0))
                convex = false;
    facts.convex = convex;
    return facts;
}

} // namespace vissort
