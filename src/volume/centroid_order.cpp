// centroidOrder: cells by the depth of their centres along the view direction, the approximate
// order of VTK's projected-tetrahedra mapper (vtkCellCenterDepthSort).
#include <algorithm>
#include <numeric>

#include "volume/cell_orders.h"

namespace vissort::detail {

std::vector<uint32_t> centroidOrder(const TetGrid& grid, const ViewProjection& view) {
    std::vector<double> depth(grid.tets.size());
    for (std::size_t t = 0; t < grid.tets.size(); ++t) {
        Vec3 centre{0, 0, 0};
        for (const uint32_t p : grid.tets[t])
            centre = centre + grid.points[p];
        depth[t] = dot(centre * 0.25 - view.eye_position, view.forward);
    }
    std::vector<uint32_t> order(grid.tets.size());
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(),
                     [&](uint32_t a, uint32_t b) { return depth[a] < depth[b]; });
    return order;
}

} // namespace vissort::detail
