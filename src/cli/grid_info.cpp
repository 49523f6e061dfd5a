// vissort info GRID: what a grid file or built-in grid holds (describeGrid).
#include <iostream>

#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "cli/json_output.h"
#include "cli/text_output.h"
#include "vissort/volume.h"

namespace vissort::cli {

int runGridInfo(const InfoOptions& options) {
    if (!options.objects.empty())
        return fail(kExitUsage, "--objects is for mesh files; " + options.scene + " is a grid");
    Result<TetGrid> grid = loadGrid(options.scene);
    if (!grid)
        return fail(kExitInput, grid.error);
    const Scene boundary = boundaryScene(*grid.value);
    ChosenView view;
    if (const std::string error = resolveView(options.view, boundary, view); !error.empty())
        return fail(kExitUsage, error);
    const GridFacts facts = describeGrid(*grid.value);
    const Bounds& b = facts.bounds;
    std::cout << "grid: " << grid.value->name << '\n'
              << "cells: " << facts.file_cells << " in the file"
              << (facts.skipped_cells
                      ? " (and " + counted(facts.skipped_cells, "lower-dimensional cell") +
                            " skipped)"
                      : "")
              << ", " << counted(facts.tets, "tetrahedron", "tetrahedra") << '\n'
              << "points: " << facts.points << '\n';
    if (facts.has_scalars)
        std::cout << "scalars: '" << grid.value->scalar_name << "' from " << facts.scalar_min
                  << " to " << facts.scalar_max << '\n';
    else
        std::cout << "scalars: none (vissort volume needs a scalar per point)\n";
    std::cout << "bounds: [" << b.min.x << ", " << b.min.y << ", " << b.min.z << "] to [" << b.max.x
              << ", " << b.max.y << ", " << b.max.z << "], radius " << b.radius() << '\n'
              << "boundary: " << counted(facts.boundary_faces, "triangle") << ", "
              << (facts.convex ? "convex" : "not convex") << '\n'
              << cameraLine(view) << '\n';
    if (options.json.path.empty())
        return kExitOk;
    nlohmann::json scalars = nullptr;
    if (facts.has_scalars)
        scalars = {{"name", grid.value->scalar_name},
                   {"min", facts.scalar_min},
                   {"max", facts.scalar_max}};
    const nlohmann::json document = {
        {"grid", grid.value->name},
        {"file_cells", facts.file_cells},
        {"skipped_cells", facts.skipped_cells},
        {"tetrahedra", facts.tets},
        {"points", facts.points},
        {"scalars", scalars},
        {"bounds", {{"min", vec3Json(b.min)}, {"max", vec3Json(b.max)}, {"radius", b.radius()}}},
        {"boundary_faces", facts.boundary_faces},
        {"convex", facts.convex},
        {"camera", cameraJson(view.camera)}};
    return writeJsonFile(options.json, document);
}

} // namespace vissort::cli
