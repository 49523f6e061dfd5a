// mpvoOrder: Williams' MPVO (ACM TOG 11(2), 1992) over the grid's face adjacency, and the same
// sort taking ready cells by a preferred order (vissort's start list).
#include <functional>
#include <queue>

#include "volume/cell_orders.h"

namespace vissort::detail {
namespace {

// The shared faces as edges, from the cell on the eye's side to the other: behind[c] (count
// behind_count[c]) are the cells c must come before; in_front[c] counts those before c.
struct FaceEdges {
    std::vector<uint32_t> in_front;
    std::vector<std::array<uint32_t, 4>> behind;
    std::vector<uint8_t> behind_count;

    FaceEdges(const TetGrid& grid, const std::vector<TetNeighbours>& neighbours,
              const ViewProjection& view)
        : in_front(grid.tets.size(), 0), behind(grid.tets.size()),
          behind_count(grid.tets.size(), 0) {
        const bool perspective = view.projection == Projection::perspective;
        // Each shared face once (from the lower id).
        for (uint32_t t = 0; t < grid.tets.size(); ++t)
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
    }
};

// Kahn's sort of the edges: take() gives the next ready cell (Ready: push, pop, empty, next);
// when none is ready (a cycle), stuck() names the cell to take.
template <class Ready, class Stuck> MpvoOrder kahn(FaceEdges& edges, Ready& ready, Stuck&& stuck) {
    const std::size_t n = edges.in_front.size();
    for (uint32_t t = 0; t < n; ++t)
        if (edges.in_front[t] == 0)
            ready.push(t);
    MpvoOrder result;
    result.order.reserve(n);
    std::vector<uint8_t> done(n, 0);
    while (result.order.size() < n) {
        if (ready.empty()) {
            ready.push(stuck(done));
            ++result.broken_cycles;
        }
        const uint32_t t = ready.next();
        ready.pop();
        if (done[t])
            continue;
        done[t] = 1;
        result.order.push_back(t);
        for (uint8_t k = 0; k < edges.behind_count[t]; ++k) {
            const uint32_t back = edges.behind[t][k];
            if (--edges.in_front[back] == 0 && !done[back])
                ready.push(back);
        }
    }
    return result;
}

// First in, first out, as Williams's algorithm takes them (in no order of depth: what it knows
// of depth is the shared faces alone).
struct Fifo : std::queue<uint32_t> {
    uint32_t next() const { return front(); }
};

// The ready cell earliest in the preferred order: a heap of (rank, cell), least rank on top.
struct Preferred {
    const std::vector<uint32_t>& rank;
    std::priority_queue<uint64_t, std::vector<uint64_t>, std::greater<>> heap;
    void push(uint32_t t) { heap.push(uint64_t(rank[t]) << 32 | t); }
    void pop() { heap.pop(); }
    bool empty() const { return heap.empty(); }
    uint32_t next() const { return uint32_t(heap.top()); }
};

} // namespace

MpvoOrder mpvoOrder(const TetGrid& grid, const std::vector<TetNeighbours>& neighbours,
                    const ViewProjection& view) {
    FaceEdges edges(grid, neighbours, view);
    Fifo ready;
    uint32_t next_unordered = 0;
    return kahn(edges, ready, [&](const std::vector<uint8_t>& done) {
        while (done[next_unordered]) // a cycle: the first cell not yet output
            ++next_unordered;
        return next_unordered;
    });
}

MpvoOrder faceConsistentOrder(const TetGrid& grid, const std::vector<TetNeighbours>& neighbours,
                              const ViewProjection& view, std::span<const uint32_t> preferred) {
    std::vector<uint32_t> rank(grid.tets.size());
    for (uint32_t i = 0; i < preferred.size(); ++i)
        rank[preferred[i]] = i;
    FaceEdges edges(grid, neighbours, view);
    Preferred ready{rank};
    std::size_t next_preferred = 0;
    return kahn(edges, ready, [&](const std::vector<uint8_t>& done) {
        while (done[preferred[next_preferred]]) // a cycle: the earliest preferred not yet output
            ++next_preferred;
        return preferred[next_preferred];
    });
}

} // namespace vissort::detail
