// vissort.order and vissort.Orderer: visibility orders of numpy triangles or of scenes, with
// the command line's levels, oracles and default camera.

#include <memory>
#include <mutex>

#include <pybind11/stl.h>

#include "arrays.h"
#include "bindings.h"
#include "frame_input.h"
#include "gl_turn.h"
#include "python_camera.h"
#include "stats_dict.h"
#include "vissort/oracles.h"
#include "vissort/scene_orderer.h"

namespace vissort::python {
namespace {

struct OrderResult {
    py::array_t<uint32_t> order;
    py::list cycles;
    py::dict stats;
    std::string level;
    PythonCamera camera;
};

OrderResult resultOf(FrameOrder&& frame, const PythonCamera& camera) {
    OrderResult result;
    result.order = toArray(std::move(frame.order));
    for (std::vector<uint32_t>& cycle : frame.cycles)
        result.cycles.append(toArray(std::move(cycle)));
    addStats(result.stats, frame.stats);
    result.stats["ms"] = frame.milliseconds;
    result.level = orderLevelName(frame.level);
    result.camera = camera;
    return result;
}

// Orders successive frames of one set of objects (SceneOrderer): each starts from the last
// one's order. One call at a time: a second thread waits for the first.
class Orderer {
public:
    Orderer(const py::object& objects, const std::string& level, const std::string& oracle,
            uint32_t threads) {
        const Result<OrderLevel> parsed_level = parseOrderLevel(level);
        if (!parsed_level)
            throw py::value_error(parsed_level.error);
        level_ = *parsed_level.value;
        const Result<OracleKind> kind = parseOracleKind(oracle);
        if (!kind)
            throw py::value_error(kind.error);
        if (py::isinstance<Scene>(objects)) {
            scene_ = objects.cast<std::shared_ptr<Scene>>();
            objects_ = scene_->objectPrimitives();
            triangle_count_ = uint32_t(scene_->triangleCount());
        } else if (!objects.is_none()) {
            objects_arg_ = objects; // read against the first frame's triangle count
        }
        Result<std::unique_ptr<GeometryOracle>> made;
        {
            py::gil_scoped_release unlocked;
#if VISSORT_WITH_GL
            if (*kind.value == OracleKind::gl) {
                Result<std::shared_ptr<GlContext>> context = sharedGlContext();
                if (context)
                    gl_ = *context.value;
            }
            GlTurn turn(gl_);
#endif
            OracleOptions options;
            options.threads = threads;
            made = makeOracle(*kind.value, options);
        }
        if (!made)
            throw std::runtime_error(made.error);
        oracle_ = std::move(*made.value);
    }

    ~Orderer() {
#if VISSORT_WITH_GL
        GlTurn turn(gl_); // the gl oracle deletes its queries in the context
#endif
        orderer_.reset();
        oracle_.reset();
    }

    OrderResult order(const py::object& positions, const py::object& triangles,
                      const py::object& camera, const py::object& size, const py::object& time) {
        const auto [width, height] = readSize(size);
        const std::unique_lock<std::mutex> lock = lockWithoutGil(mutex_);
        std::shared_ptr<Scene> used_scene;
        const PositionsView view_positions =
            readFrame(positions, triangles, time, scene_, buffer_, used_scene);
        const uint32_t triangle_count = uint32_t(view_positions.triangleCount());
        if (!orderer_) {
            // The objects given, else those of the scene ordered, else one a triangle.
            if (objects_.empty())
                objects_ = !objects_arg_.is_none() ? readObjects(objects_arg_, triangle_count)
                           : used_scene            ? used_scene->objectPrimitives()
                                        : levelPrimitives({}, triangle_count, OrderLevel::triangle);
            if (!scene_)
                triangle_count_ = triangle_count;
            orderer_ = std::make_unique<SceneOrderer>(objects_, triangle_count_, level_, *oracle_);
        }
        if (triangle_count != triangle_count_)
            throw py::value_error("this orderer orders " + std::to_string(triangle_count_) +
                                  " triangles; got " + std::to_string(triangle_count));
        const PythonCamera used_camera = cameras_.choose(camera, used_scene ? used_scene : scene_,
                                                         view_positions, width, height);
        FrameOrder frame;
        {
            py::gil_scoped_release unlocked;
#if VISSORT_WITH_GL
            GlTurn turn(gl_);
#endif
            const ViewProjection view = viewOf(used_camera, view_positions, width, height);
            orderer_->orderFrame(view_positions, view, frame);
        }
        return resultOf(std::move(frame), used_camera);
    }

private:
    std::shared_ptr<Scene> scene_; // kept alive while the orderer is
    CameraChoice cameras_;
    py::object objects_arg_ = py::none();
    std::vector<PrimitiveRange> objects_;
    uint32_t triangle_count_ = 0;
    OrderLevel level_ = OrderLevel::object;
#if VISSORT_WITH_GL
    std::shared_ptr<GlContext> gl_;
#endif
    std::unique_ptr<GeometryOracle> oracle_;
    std::unique_ptr<SceneOrderer> orderer_;
    TrianglePositions buffer_;
    std::mutex mutex_;
};

constexpr const char* kOrderDoc =
    "Orders positions front to back. positions: a Scene (at time, default 0) or triangle "
    "corners, float (T, 3, 3) or (V, 3) with triangles=(T, 3) indices. camera: a Camera; "
    "default the command line's (a scene's own, else the geometry framed). size: (width, "
    "height) of the oracle's image. Releases the GIL.";

} // namespace

void bindOrder(py::module_& m) {
    py::class_<OrderResult>(m, "OrderResult", "A visibility order and what it cost")
        .def_readonly("order", &OrderResult::order,
                      "uint32 ids front to back: objects at object level, else triangles")
        .def_readonly("cycles", &OrderResult::cycles,
                      "Each cycle the order met: its ids, ascending (uint32 arrays)")
        .def_readonly("stats", &OrderResult::stats,
                      "queries, draws, clears, iterations, stuck_iterations, cycle_queries, "
                      "cycle_draws, hinted_cycles, graph_passes, ms: as the command line's --json")
        .def_readonly("level", &OrderResult::level)
        .def_readonly("camera", &OrderResult::camera, "The camera the order was computed for")
        .def("__repr__", [](const OrderResult& r) {
            return "OrderResult(" + std::to_string(r.order.size()) + " ids, " +
                   std::to_string(r.cycles.size()) + " cycles, " + r.level + " level)";
        });

    py::class_<Orderer>(m, "Orderer",
                        "Orders successive frames of the same objects, each frame starting from "
                        "the last one's order: about linear work on coherent frames")
        .def(py::init<const py::object&, const std::string&, const std::string&, uint32_t>(),
             py::arg("objects") = py::none(), py::kw_only(), py::arg("level") = "object",
             py::arg("oracle") = "cpu", py::arg("threads") = 1u,
             "objects: a Scene (kept alive by the orderer), integer (first, count) ranges (K, 2) "
             "or counts (K,), or None: every triangle its own object. level: object, triangle or "
             "multistage. oracle: cpu, cpu-reference, exact or gl. threads: the cpu oracle's, the "
             "calling one included (default 1; 0: one per core; the order never depends on it)")
        .def(
            "order",
            [](Orderer& orderer, const py::object& positions, const py::object& camera,
               const py::object& size, const py::object& triangles, const py::object& time) {
                return orderer.order(positions, triangles, camera, size, time);
            },
            py::arg("positions") = py::none(), py::arg("camera") = py::none(),
            py::arg("size") = py::make_tuple(1024, 1024), py::kw_only(),
            py::arg("triangles") = py::none(), py::arg("time") = py::none(), kOrderDoc);

    m.def(
        "order",
        [](const py::object& positions, const py::object& objects, const py::object& camera,
           const py::object& size, const std::string& level, const std::string& oracle,
           const py::object& triangles, const py::object& time, uint32_t threads) {
            const bool scene = py::isinstance<Scene>(positions);
            if (scene && !objects.is_none())
                throw py::value_error("a Scene brings its own objects: objects must be None");
            Orderer orderer(scene ? positions : objects, level, oracle, threads);
            return orderer.order(positions, triangles, camera, size, time);
        },
        py::arg("positions"), py::arg("objects") = py::none(), py::arg("camera") = py::none(),
        py::arg("size") = py::make_tuple(1024, 1024), py::arg("level") = "object",
        py::arg("oracle") = "cpu", py::kw_only(), py::arg("triangles") = py::none(),
        py::arg("time") = py::none(), py::arg("threads") = 1u,
        ("One frame's order (Orderer keeps it for the next). objects as Orderer's. " +
         std::string(kOrderDoc))
            .c_str());
}

} // namespace vissort::python
