// vissort.Grid, vissort.load_grid, vissort.render_volume and vissort.VolumeRenderer: tetrahedral
// grids from files or numpy arrays, rendered by emission and absorption (docs/volume.md) into
// (H, W, 4) uint8 images. The renderers run on the CPU with the GIL released.

#include <memory>

#include <pybind11/stl.h>

#include "arrays.h"
#include "bindings.h"
#include "python_camera.h"
#include "vissort/volume.h"

namespace vissort::python {
namespace {

// A grid and, made on first use, its boundary as a scene: what frames its default camera.
struct PythonGrid {
    std::shared_ptr<const TetGrid> grid;
    std::shared_ptr<Scene> boundary;

    const Scene& boundaryScene() {
        if (!boundary)
            boundary = std::make_shared<Scene>(vissort::boundaryScene(*grid));
        return *boundary;
    }
};

PythonGrid madeGrid(Result<TetGrid> grid) {
    if (!grid)
        throw py::value_error(grid.error);
    return {std::make_shared<const TetGrid>(std::move(*grid.value)), nullptr};
}

GridCellType cellTypeOfWidth(py::ssize_t width) {
    switch (width) {
    case 4:
        return GridCellType::tetrahedron;
    case 5:
        return GridCellType::pyramid;
    case 6:
        return GridCellType::wedge;
    case 8:
        return GridCellType::hexahedron;
    default:
        throw py::value_error(
            "cells must have shape (M, 4) tetrahedra, (M, 5) pyramids, (M, 6) wedges or (M, 8) "
            "hexahedra, got width " +
            std::to_string(width));
    }
}

PythonGrid gridOfArrays(const py::handle& points, const py::handle& cells,
                        const py::handle& scalars, const std::string& name) {
    const auto p = py::array_t<double, py::array::forcecast>::ensure(points);
    if (!p || p.ndim() != 2 || p.shape(1) != 3)
        throw py::value_error("points must have shape (N, 3)");
    const py::array cell_array = py::array::ensure(cells);
    if (!cell_array || cell_array.ndim() != 2 ||
        (cell_array.dtype().kind() != 'i' && cell_array.dtype().kind() != 'u'))
        throw py::value_error(
            "cells must be an integer array of shape (M, 4), (M, 5), (M, 6) or (M, 8)");
    const GridCellType type = cellTypeOfWidth(cell_array.shape(1));
    const auto c = py::array_t<int64_t, py::array::forcecast>::ensure(cell_array);
    std::vector<Vec3> point_list(std::size_t(p.shape(0)));
    const auto pv = p.unchecked<2>();
    for (py::ssize_t i = 0; i < p.shape(0); ++i)
        point_list[std::size_t(i)] = {pv(i, 0), pv(i, 1), pv(i, 2)};
    std::vector<uint32_t> corners;
    corners.reserve(std::size_t(c.size()));
    const auto cv = c.unchecked<2>();
    for (py::ssize_t i = 0; i < c.shape(0); ++i)
        for (py::ssize_t k = 0; k < c.shape(1); ++k) {
            if (cv(i, k) < 0 || cv(i, k) >= p.shape(0))
                throw py::value_error("cell " + std::to_string(i) + " names point " +
                                      std::to_string(cv(i, k)) + " of " +
                                      std::to_string(p.shape(0)));
            corners.push_back(uint32_t(cv(i, k)));
        }
    std::vector<double> scalar_list;
    if (!scalars.is_none()) {
        const auto s = py::array_t<double, py::array::forcecast>::ensure(scalars);
        if (!s || s.ndim() != 1 || s.shape(0) != p.shape(0))
            throw py::value_error("scalars must have shape (N,): one per point");
        scalar_list.assign(s.data(), s.data() + s.shape(0));
    }
    Result<TetGrid> grid;
    {
        py::gil_scoped_release unlocked;
        grid = gridOfCells(std::move(point_list), type, corners, std::move(scalar_list), name);
    }
    return madeGrid(std::move(grid));
}

// A transfer function: a preset's name or a JSON file's path, or rows (scalar, r, g, b,
// extinction) over the normalized or absolute scalar.
TransferFunction readTransfer(const py::handle& tf, const std::string& range) {
    if (range != "normalized" && range != "absolute")
        throw py::value_error("tf_range must be 'normalized' or 'absolute', not '" + range + "'");
    if (py::isinstance<py::str>(tf)) {
        Result<TransferFunction> loaded = loadTransferFunction(tf.cast<std::string>());
        if (!loaded)
            throw py::value_error("tf: " + loaded.error);
        return *loaded.value;
    }
    const auto rows = py::array_t<double, py::array::forcecast>::ensure(tf);
    if (!rows || rows.ndim() != 2 || rows.shape(1) != 5)
        throw py::value_error(
            "tf must be a preset's name, a JSON file, or rows (scalar, r, g, b, extinction)");
    TransferFunction function;
    function.normalized = range == "normalized";
    const auto r = rows.unchecked<2>();
    for (py::ssize_t i = 0; i < rows.shape(0); ++i)
        function.points.push_back({r(i, 0), r(i, 1), r(i, 2), r(i, 3), r(i, 4)});
    if (Status valid = validateTransferFunction(function); !valid)
        throw py::value_error("tf: " + valid.error);
    return function;
}

VolumeSettings readSettings(const py::handle& tf, const std::string& tf_range, double density,
                            const py::handle& background) {
    VolumeSettings settings;
    settings.transfer = readTransfer(tf, tf_range);
    if (!std::isfinite(density) || density < 0)
        throw py::value_error("density must be a finite number >= 0");
    settings.density = density;
    settings.background = readColour(background, "background");
    return settings;
}

// One renderer per grid and method: a Python VolumeRenderer keeps its grid alive.
class PythonVolumeRenderer {
public:
    PythonVolumeRenderer(PythonGrid grid, const std::string& method, const std::string& oracle,
                         unsigned threads)
        : grid_(std::move(grid)) {
        const Result<VolumeMethod> parsed = parseVolumeMethod(method);
        if (!parsed)
            throw py::value_error(parsed.error);
        const Result<OracleKind> kind = parseOracleKind(oracle);
        if (!kind)
            throw py::value_error(kind.error);
        renderer_ =
            std::make_unique<VolumeRenderer>(*grid_.grid, *parsed.value, *kind.value, threads);
    }

    py::array_t<uint8_t> render(const py::handle& camera, const py::handle& size,
                                const py::handle& tf, const std::string& tf_range, double density,
                                const py::handle& background) {
        const VolumeSettings settings = readSettings(tf, tf_range, density, background);
        const auto [width, height] = readSize(size);
        // The grid's boundary frames the default camera, chosen once per size (CameraChoice).
        const Scene& boundary = grid_.boundaryScene();
        const PythonCamera chosen =
            choice_.choose(camera, grid_.boundary, boundary.positions, width, height);
        const ViewProjection view = viewOf(chosen, boundary.positions, width, height);
        Result<Image> image;
        {
            py::gil_scoped_release unlocked;
            image = renderer_->render(settings, view);
        }
        if (!image)
            throw py::value_error(image.error);
        return ownedArray<uint8_t>(image.value->toRgba8(),
                                   {py::ssize_t(height), py::ssize_t(width), 4},
                                   {py::ssize_t(width) * 4, 4, 1});
    }

    py::dict stats() const {
        const VolumeFrameStats& s = renderer_->stats();
        py::dict d;
        d["order_ms"] = s.order_ms;
        d["composite_ms"] = s.composite_ms;
        d["cells"] = s.cells;
        d["queries"] = s.queries;
        d["cycles"] = s.cycles;
        d["cells_in_cycles"] = s.cells_in_cycles;
        d["segments"] = s.segments;
        d["list_segments"] = s.list_segments;
        return d;
    }

private:
    PythonGrid grid_;
    std::unique_ptr<VolumeRenderer> renderer_;
    CameraChoice choice_;
};

py::dict factsDict(const PythonGrid& grid) {
    const GridFacts facts = describeGrid(*grid.grid);
    py::dict d;
    d["points"] = facts.points;
    d["tetrahedra"] = facts.tets;
    d["file_cells"] = facts.file_cells;
    d["skipped_cells"] = facts.skipped_cells;
    d["bounds"] = py::make_tuple(vec3Tuple(facts.bounds.min), vec3Tuple(facts.bounds.max));
    d["scalar_range"] = facts.has_scalars
                            ? py::object(py::make_tuple(facts.scalar_min, facts.scalar_max))
                            : py::none();
    d["boundary_faces"] = facts.boundary_faces;
    d["convex"] = facts.convex;
    return d;
}

constexpr const char* kRenderDoc =
    "The grid's picture as (H, W, 4) uint8: camera a vissort.Camera or None (the grid framed), "
    "size "
    "(width, height), tf a preset ('cool-warm', 'fire', 'grey', 'bands'), a JSON file or rows "
    "(scalar, r, g, "
    "b, extinction), tf_range 'normalized' or 'absolute', density scaling every extinction, "
    "background (r, g, "
    "b[, a]). Releases the GIL. docs/volume.md has the rendering law.";

} // namespace

void bindVolume(py::module_& m) {
    py::class_<PythonGrid>(
        m, "Grid",
        "A tetrahedral grid with a scalar per point: load_grid(path) or Grid(points, cells, "
        "scalars); hexahedra, wedges and pyramids are split into tetrahedra")
        .def(py::init([](const py::handle& points, const py::handle& cells,
                         const py::handle& scalars, const std::string& name) {
                 return gridOfArrays(points, cells, scalars, name);
             }),
             py::arg("points"), py::arg("cells"), py::arg("scalars") = py::none(),
             py::arg("name") = "grid",
             "points (N, 3); cells (M, 4) tetrahedra, (M, 5) pyramids, (M, 6) wedges or (M, 8) "
             "hexahedra, corners in "
             "VTK's order; scalars (N,) or None. ValueError naming the problem.")
        .def_property_readonly("name", [](const PythonGrid& g) { return g.grid->name; })
        .def_property_readonly("scalar_name",
                               [](const PythonGrid& g) { return g.grid->scalar_name; })
        .def_property_readonly("points",
                               [](const PythonGrid& g) {
                                   std::vector<double> xyz;
                                   xyz.reserve(g.grid->points.size() * 3);
                                   for (const Vec3& p : g.grid->points)
                                       xyz.insert(xyz.end(), {p.x, p.y, p.z});
                                   return ownedArray<double>(
                                       std::move(xyz), {py::ssize_t(g.grid->points.size()), 3},
                                       {24, 8});
                               })
        .def_property_readonly("tets",
                               [](const PythonGrid& g) {
                                   std::vector<uint32_t> corners;
                                   corners.reserve(g.grid->tets.size() * 4);
                                   for (const Tet& t : g.grid->tets)
                                       corners.insert(corners.end(), t.begin(), t.end());
                                   return ownedArray<uint32_t>(
                                       std::move(corners), {py::ssize_t(g.grid->tets.size()), 4},
                                       {16, 4});
                               })
        .def_property_readonly("scalars",
                               [](const PythonGrid& g) -> py::object {
                                   if (g.grid->scalars.empty())
                                       return py::none();
                                   std::vector<double> copy = g.grid->scalars;
                                   const py::ssize_t n = py::ssize_t(copy.size());
                                   return ownedArray<double>(std::move(copy), {n}, {8});
                               })
        .def("facts", &factsDict,
             "A dict: points, tetrahedra, file_cells, skipped_cells, bounds, scalar_range (or "
             "None), "
             "boundary_faces, convex")
        .def("__repr__", [](const PythonGrid& g) {
            return "Grid('" + g.grid->name + "', " + std::to_string(g.grid->tets.size()) +
                   " tetrahedra, " + std::to_string(g.grid->points.size()) + " points)";
        });

    m.def(
        "load_grid",
        [](const std::string& spec) {
            Result<TetGrid> grid;
            {
                py::gil_scoped_release unlocked;
                grid = loadGrid(spec);
            }
            return madeGrid(std::move(grid));
        },
        py::arg("spec"),
        "A grid from a file (.vtk, .vtu, tetgen .node/.ele, Medit .mesh) or "
        "builtin:cube|torus|knot?n=CELLS; "
        "ValueError with the loader's one-line message");

    py::class_<PythonVolumeRenderer>(m, "VolumeRenderer",
                                     "Frames of one grid by one method (vissort, centroid, mpvo, "
                                     "lists, raycast), keeping vissort's last order "
                                     "for the next frame")
        .def(py::init<PythonGrid, const std::string&, const std::string&, unsigned>(),
             py::arg("grid"), py::arg("method") = "vissort", py::kw_only(),
             py::arg("oracle") = "cpu", py::arg("threads") = 0u)
        .def("render", &PythonVolumeRenderer::render, py::arg("camera") = py::none(), py::kw_only(),
             py::arg("size") = py::make_tuple(512, 512), py::arg("tf") = "cool-warm",
             py::arg("tf_range") = "normalized", py::arg("density") = 4.0,
             py::arg("background") = defaultBackground(), kRenderDoc)
        .def_property_readonly(
            "stats", &PythonVolumeRenderer::stats,
            "The last frame's costs: order_ms, composite_ms, cells, queries, cycles, "
            "cells_in_cycles, segments, list_segments");

    m.def(
        "render_volume",
        [](const PythonGrid& grid, const py::handle& camera, const py::handle& size,
           const std::string& method, const py::handle& tf, const std::string& tf_range,
           double density, const py::handle& background, const std::string& oracle) {
            PythonVolumeRenderer renderer(grid, method, oracle, 0);
            return renderer.render(camera, size, tf, tf_range, density, background);
        },
        py::arg("grid"), py::arg("camera") = py::none(), py::kw_only(),
        py::arg("size") = py::make_tuple(512, 512), py::arg("method") = "vissort",
        py::arg("tf") = "cool-warm", py::arg("tf_range") = "normalized", py::arg("density") = 4.0,
        py::arg("background") = defaultBackground(), py::arg("oracle") = "cpu", kRenderDoc);
}

} // namespace vissort::python
