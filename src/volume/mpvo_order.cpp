// mpvoOrder: Williams' MPVO (ACM TOG 11(2), 1992) over the grid's face adjacency.
#include <queue>

#include "volume/cell_orders.h"

namespace vissort::detail {

MpvoOrder mpvoOrder(const TetGrid& grid, const std::vector<TetNeighbours>& neighbours,
                    const ViewProjection& view) {
    const std::size_t n = grid.tets.size();
    const bool perspective = view.projection == Projection::perspective;
    // Each shared face once (from the lower id): an edge from the cell on the eye's side to the
    // other. in_front[c] counts the cells that must come before c.
    std::vector<uint32_t> in_front(n, 0);
    std::vector<std::array<uint32_t, 4>> behind(n);
    std::vector<uint8_t> behind_count(n, 0);
    for (uint32_t t = 0; t < n; ++t)
        for (int f = 0; f < 4; ++f) {
            const uint32_t other = neighbours[t][f];
            if (other == kNoNeighbour || other < t)
                continue;
            const Tet& tet = grid.tets[t];
            const Vec3& a = grid.points[tet[kTetFaceCorners[f][0]]];
            const Vec3 normal = cross(grid.points[tet[kTetFaceCorners[f][1]]] - a,
                                      grid.points[tet[kTetFaceCorners[f][2]]] - a);
            // The normal points into t: the eye on that side sees t first.
            const double eye_side =
                perspective ? dot(normal, view.eye_position - a) : -dot(normal, view.forward);
            if (eye_side == 0)
                continue;
            const uint32_t front = eye_side > 0 ? t : other, back = eye_side > 0 ? other : t;
            behind[front][behind_count[front]++] = back;
            ++in_front[back];
        }
    // Kahn's sort with the ready cells first in, first out, as Williams's algorithm takes them
    // (in no order of depth: what it knows of depth is the shared faces alone).
    std::queue<uint32_t> ready;
    for (uint32_t t = 0; t < n; ++t)
        if (in_front[t] == 0)
            ready.push(t);
    MpvoOrder result;
    result.order.reserve(n);
    std::vector<uint8_t> done(n, 0);
    uint32_t next_unordered = 0;
    while (result.order.size() < n) {
        if (ready.empty()) {
            // A cycle: take the first cell not yet output.
            while (done[next_unordered])
                ++next_unordered;
            ready.push(next_unordered);
            ++result.broken_cycles;
        }
        const uint32_t t = ready.front();
        ready.pop();
        if (done[t])
            continue;
        done[t] = 1;
        result.order.push_back(t);
        for (uint8_t k = 0; k < behind_count[t]; ++k)
            if (--in_front[behind[t][k]] == 0 && !done[behind[t][k]])
                ready.push(behind[t][k]);
    }
    return result;
}

} // namespace vissort::detail
