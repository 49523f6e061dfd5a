// vissort.collide and vissort.CollisionDetector: every intersecting pair of triangles of
// different objects, as a (K, 2) uint32 array, with the command line's methods.

#include <memory>
#include <mutex>

#include <pybind11/stl.h>

#include "arrays.h"
#include "bindings.h"
#include "frame_input.h"
#include "stats_dict.h"
#include "vissort/collision.h"
#include "vissort/collision_peers.h"

namespace vissort::python {
namespace {

py::dict statsDict(const CollisionStats& s) {
    py::dict d;
    addStats(d, s);
    return d;
}

// Pairs as a (K, 2) uint32 array over their own memory (a TrianglePair or an ObjectPair is two
// uint32s).
template <class Pair> py::array_t<uint32_t> pairsArray(std::vector<Pair>&& pairs) {
    static_assert(sizeof(Pair) == 2 * sizeof(uint32_t));
    const py::ssize_t count = py::ssize_t(pairs.size());
    return ownedArray<uint32_t>(std::move(pairs), {count, 2},
                                {py::ssize_t(sizeof(Pair)), py::ssize_t(sizeof(uint32_t))});
}

// A CollisionDetector of one set of objects: successive frames reuse what the last one learnt.
class Detector {
public:
    Detector(const py::object& objects, const std::string& method, uint32_t threads,
             const py::object& size, double min_cull, const std::string& object_stage) {
        const Result<CollisionMethod> parsed = parseCollisionMethod(method);
        if (!parsed)
            throw py::value_error(parsed.error);
        settings_.method = *parsed.value;
        settings_.threads = threads;
        const auto [width, height] = readSize(size);
        settings_.width = width;
        settings_.height = height;
        settings_.min_cull_fraction = float(min_cull);
        const Result<ObjectStage> stage = parseObjectStage(object_stage);
        if (!stage)
            throw py::value_error(stage.error);
        settings_.object_stage = *stage.value;
        if (Status valid = validateCollisionSettings(settings_); !valid)
            throw py::value_error(valid.error);
        if (py::isinstance<Scene>(objects)) {
            scene_ = objects.cast<std::shared_ptr<Scene>>();
            objects_ = scene_->objectPrimitives();
            detector_ = std::make_unique<CollisionDetector>(objects_, settings_);
        } else if (objects.is_none()) {
            throw py::value_error("collide needs objects: a Scene, or integer (first, count) "
                                  "ranges (K, 2) or counts (K,) of the triangles (pairs within "
                                  "one object are not collisions)");
        } else {
            objects_arg_ = objects; // read against the first frame's triangle count
        }
    }

    py::array_t<uint32_t> collide(const py::object& positions, const py::object& triangles,
                                  const py::object& time) {
        const std::unique_lock<std::mutex> lock = lockWithoutGil(mutex_);
        std::shared_ptr<Scene> used_scene;
        const PositionsView frame =
            readFrame(positions, triangles, time, scene_, buffer_, used_scene);
        if (!detector_) {
            objects_ = readObjects(objects_arg_, uint32_t(frame.triangleCount()));
            detector_ = std::make_unique<CollisionDetector>(objects_, settings_);
        }
        {
            py::gil_scoped_release unlocked;
            detector_->collide(frame, result_);
        }
        stats_ = statsDict(result_.stats);
        object_pairs_ = pairsArray(std::move(result_.object_pairs));
        return pairsArray(std::move(result_.pairs));
    }

    py::dict stats() const { return stats_; }
    py::object objectPairs() const { return object_pairs_; }

private:
    std::shared_ptr<Scene> scene_; // kept alive while the detector is
    py::object objects_arg_ = py::none();
    std::vector<PrimitiveRange> objects_;
    CollisionSettings settings_;
    std::unique_ptr<CollisionDetector> detector_;
    CollisionResult result_;
    TrianglePositions buffer_;
    py::dict stats_;
    py::object object_pairs_ = py::none();
    std::mutex mutex_;
};

constexpr const char* kDetectorDoc =
    "objects: a Scene (kept alive by the detector), or integer (first, count) ranges (K, 2) or "
    "counts (K,). method: vissort, brute, bullet or fcl. The settings, as the command line's "
    "collide options: threads (vissort and bullet; the calling one included; 0: one per core), "
    "and vissort's size (each object-stage view, pixels) and min_cull (the next direction only "
    "while the last culled at "
    "least this fraction of its object pairs) and object_stage (adaptive, always or never: when "
    "the "
    "object stage runs). The pairs never depend on them.";

constexpr const char* kCollideDoc =
    "Every pair of intersecting triangles of different objects (touching counts), as a (K, 2) "
    "uint32 array of triangle ids, first < second, ascending. positions: a Scene (at time, "
    "default 0) or corners (T, 3, 3), or (V, 3) with triangles=(T, 3). Releases the GIL.";

} // namespace

void bindCollide(py::module_& m) {
    // method="bullet" and "fcl", as on the command line.
    registerPeerColliders();
    py::class_<Detector>(m, "CollisionDetector",
                         "Finds the intersecting triangle pairs of the same objects frame after "
                         "frame, reusing what each frame learnt")
        .def(py::init<const py::object&, const std::string&, uint32_t, const py::object&, double,
                      const std::string&>(),
             py::arg("objects"), py::kw_only(), py::arg("method") = "vissort",
             py::arg("threads") = 1, py::arg("size") = py::make_tuple(64, 64),
             py::arg("min_cull") = 0.25, py::arg("object_stage") = "adaptive", kDetectorDoc)
        .def("collide", &Detector::collide, py::arg("positions") = py::none(),
             py::arg("triangles") = py::none(), py::kw_only(), py::arg("time") = py::none(),
             kCollideDoc)
        .def_property_readonly("stats", &Detector::stats, "The last frame's costs and culling")
        .def_property_readonly("object_pairs", &Detector::objectPairs,
                               "The last frame's colliding objects: a (M, 2) uint32 array of "
                               "object indices (first < second, ascending) with some "
                               "intersecting triangle pair between them; None before a frame");
    m.def(
        "collide",
        [](const py::object& positions, const py::object& objects, const std::string& method,
           const py::object& triangles, const py::object& time, uint32_t threads,
           const py::object& size, double min_cull, const std::string& object_stage) {
            const bool scene = py::isinstance<Scene>(positions);
            if (scene && !objects.is_none())
                throw py::value_error("a Scene brings its own objects: objects must be None");
            Detector detector(scene ? positions : objects, method, threads, size, min_cull,
                              object_stage);
            return detector.collide(positions, triangles, time);
        },
        py::arg("positions"), py::arg("objects") = py::none(), py::arg("method") = "vissort",
        py::kw_only(), py::arg("triangles") = py::none(), py::arg("time") = py::none(),
        py::arg("threads") = 1, py::arg("size") = py::make_tuple(64, 64),
        py::arg("min_cull") = 0.25, py::arg("object_stage") = "adaptive",
        ("One frame's pairs (CollisionDetector follows frames). objects as "
         "CollisionDetector's. " +
         std::string(kCollideDoc))
            .c_str());
}

} // namespace vissort::python
