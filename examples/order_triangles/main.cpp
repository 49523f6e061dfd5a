// Orders the caller's own triangles, without a Scene: positions in a structure of arrays, one
// primitive per triangle, the CPU oracle and Vis-sort (vis_sort.h) over it.
// Five triangles facing the camera at the depths below, overlapping in the image: the order
// printed is nearest first, 1 3 0 2 4.

#include <array>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <numeric>
#include <vector>

#include <vissort/camera.h>
#include <vissort/geometry.h>
#include <vissort/oracles.h>
#include <vissort/vis_sort.h>

int main() {
    const std::array<float, 5> depths = {-2.0f, 0.0f, -3.0f, -1.0f, -4.0f}; // z of each triangle
    vissort::TrianglePositions positions;
    for (std::size_t i = 0; i < depths.size(); ++i) {
        const float shift = 0.2f * static_cast<float>(i); // overlapping, not identical
        positions.x.insert(positions.x.end(), {-1.0f + shift, 1.0f + shift, shift});
        positions.y.insert(positions.y.end(), {-1.0f, -1.0f, 1.0f});
        positions.z.insert(positions.z.end(), {depths[i], depths[i], depths[i]});
    }
    std::vector<vissort::PrimitiveRange> primitives;
    for (uint32_t t = 0; t < positions.triangleCount(); ++t)
        primitives.push_back({t, 1});

    vissort::Result<std::unique_ptr<vissort::GeometryOracle>> made =
        vissort::makeOracle(vissort::OracleKind::cpu);
    if (!made) {
        std::fprintf(stderr, "order_triangles: %s\n", made.error.c_str());
        return 1;
    }
    vissort::GeometryOracle& oracle = **made.value;

    vissort::CameraSpec camera; // at (0, 0, 5), looking down -z at the origin
    const vissort::ViewProjection view = vissort::frameCamera(camera, positions.bounds(), 256, 256);
    oracle.bind(positions, view, primitives);
    std::vector<uint32_t> initial_order(primitives.size()); // any permutation; ids ascending
    std::iota(initial_order.begin(), initial_order.end(), 0u);
    const vissort::VisibilityOrder sorted = vissort::visSort(oracle, initial_order);

    std::printf("order:");
    for (uint32_t id : sorted.order)
        std::printf(" %u", id);
    std::printf("\ncycles: %zu, queries: %llu\n", sorted.cycles.size(),
                static_cast<unsigned long long>(sorted.stats.queries));
    return 0;
}
