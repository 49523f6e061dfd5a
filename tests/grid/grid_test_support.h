#pragma once
// Helpers of the grid tests: volumes and unit cells in VTK's corner order.

#include <random>

#include "grid/raw_grid.h"

namespace vissort::test {

inline double tetVolume(const TetGrid& grid, const Tet& t) {
    const Vec3& a = grid.points[t[0]];
    return dot(cross(grid.points[t[1]] - a, grid.points[t[2]] - a), grid.points[t[3]] - a) / 6;
}

inline double totalVolume(const TetGrid& grid) {
    double sum = 0;
    for (const Tet& t : grid.tets)
        sum += tetVolume(grid, t);
    return sum;
}

inline std::vector<Vec3> unitCubeCorners() {
    return {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
}

} // namespace vissort::test
