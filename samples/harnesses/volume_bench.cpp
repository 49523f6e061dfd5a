// runVolumeBench (volume_bench.h).

#include "harnesses/volume_bench.h"

#include <cmath>
#include <memory>
#include <stdexcept>

#include "harnesses/measurement.h"

namespace vissort::bench {

std::vector<std::string> volumeBenchGrids(uint64_t cells) {
    // Tetrahedra per lattice cell of n^3: the cube keeps all (6 each), the knot about 0.535 n^3
    // in all (measured at n = 40: 34,248).
    const auto n_for = [&](double per_cube) {
        return std::max(2, int(std::lround(std::cbrt(double(cells) / per_cube))));
    };
    return {"builtin:cube?n=" + std::to_string(n_for(6.0)),
            "builtin:knot?n=" + std::to_string(n_for(0.535))};
}

std::vector<VolumeBenchRow>
runVolumeBench(const VolumeBenchSettings& settings,
               const std::function<void(const std::string&)>& on_grid,
               const std::function<void(const VolumeBenchRow&)>& on_row) {
    Result<TransferFunction> tf = loadTransferFunction(settings.tf);
    if (!tf)
        throw std::runtime_error(tf.error);
    VolumeSettings volume;
    volume.transfer = *tf.value;
    volume.density = settings.density;
    std::vector<VolumeBenchRow> rows;
    for (const uint64_t cells : settings.cells)
        for (const std::string& spec : volumeBenchGrids(cells)) {
            if (on_grid)
                on_grid(spec);
            Result<TetGrid> grid = loadGrid(spec);
            if (!grid)
                throw std::runtime_error(grid.error);
            const Scene boundary = boundaryScene(*grid.value);
            const Bounds bounds = boundary.positions.bounds();
            const CameraSpec base = defaultCamera(bounds, double(settings.width) / settings.height);
            // raycast first: the reference of each frame.
            std::vector<VolumeMethod> methods;
            for (const auto& [method, name] : kVolumeMethodNames)
                if (method != VolumeMethod::raycast)
                    methods.push_back(method);
            methods.insert(methods.begin(), VolumeMethod::raycast);
            std::vector<std::unique_ptr<VolumeRenderer>> renderers;
            for (const VolumeMethod method : methods)
                renderers.push_back(
                    std::make_unique<VolumeRenderer>(*grid.value, method, settings.oracle));
            const std::size_t m = methods.size();
            std::vector<std::vector<double>> total(m), order(m), composite(m), queries(m);
            std::vector<VolumeBenchRow> grid_rows(m);
            for (int frame = 0; frame <= settings.frames; ++frame) {
                const ViewProjection view =
                    frameCamera(cameraOnPath(base, CameraPath::orbit, frame, bounds), bounds,
                                settings.width, settings.height);
                std::vector<uint8_t> reference;
                for (std::size_t k = 0; k < m; ++k) {
                    // raycast first, then the others in a rotating order.
                    const std::size_t i = k == 0 ? 0 : 1 + (k - 1 + std::size_t(frame)) % (m - 1);
                    const auto start = BenchClock::now();
                    Result<Image> image = renderers[i]->render(volume, view);
                    const double ms = secondsSince(start) * 1000;
                    if (!image)
                        throw std::runtime_error(image.error);
                    const std::vector<uint8_t> rgba = image.value->toRgba8();
                    if (i == 0)
                        reference = rgba;
                    const ImageError error = compareImages(rgba, reference);
                    VolumeBenchRow& row = grid_rows[i];
                    row.max_error = std::max(row.max_error, error.max_abs);
                    row.pixels_over_one = std::max(row.pixels_over_one, error.pixels_over_one);
                    const VolumeFrameStats& stats = renderers[i]->stats();
                    row.list_segments_per_cell =
                        std::max(row.list_segments_per_cell,
                                 double(stats.list_segments) / double(stats.cells));
                    if (frame == 0)
                        continue; // untimed: vissort's first order starts from depth
                    total[i].push_back(ms);
                    order[i].push_back(stats.order_ms);
                    composite[i].push_back(stats.composite_ms);
                    queries[i].push_back(double(stats.queries) / double(stats.cells));
                }
            }
            const GridFacts facts = describeGrid(*grid.value);
            for (std::size_t i = 0; i < m; ++i) {
                VolumeBenchRow& row = grid_rows[i];
                row.grid = spec;
                row.cells = grid.value->tets.size();
                row.convex = facts.convex;
                row.method = volumeMethodName(methods[i]);
                row.median_ms = median(total[i]);
                row.median_order_ms = median(order[i]);
                row.median_composite_ms = median(composite[i]);
                row.cells_per_second =
                    row.median_ms > 0 ? double(row.cells) / (row.median_ms / 1000) : 0;
                row.queries_per_cell = median(queries[i]);
                if (on_row)
                    on_row(row);
                rows.push_back(row);
            }
        }
    return rows;
}

} // namespace vissort::bench
