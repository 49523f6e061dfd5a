// vissort.Scene, vissort.load and vissort.builtin: scenes as the command line reads them, their
// geometry as numpy arrays.

#include <cmath>
#include <memory>
#include <numeric>

#include <pybind11/stl.h>

#include "arrays.h"
#include "bindings.h"
#include "python_camera.h"
#include "scene_state.h"
#include "scenes/scene_library.h"

namespace vissort::python {
namespace {

// A scene made by `make` with the GIL released (a large file takes seconds); ValueError with
// the library's message when it fails.
template <class Make> std::shared_ptr<Scene> madeScene(const Make& make) {
    Result<Scene> scene;
    {
        py::gil_scoped_release unlocked;
        scene = make();
    }
    if (!scene)
        throw py::value_error(scene.error);
    return std::make_shared<Scene>(std::move(*scene.value));
}

// A keyword argument as a built-in scene's parameter value: numbers and strings as written,
// True/False as 1/0 (the scene parses and checks the value).
std::string parameterText(const std::string& key, const py::handle& value) {
    if (py::isinstance<py::bool_>(value))
        return value.cast<bool>() ? "1" : "0";
    if (py::isinstance<py::int_>(value) || py::isinstance<py::str>(value) ||
        py::isinstance<py::float_>(value))
        return py::str(value).cast<std::string>();
    throw py::value_error("builtin scene parameter " + key + " must be a number or a string, got " +
                          py::str(py::type::of(value).attr("__name__")).cast<std::string>());
}

py::array_t<uint32_t> objectRanges(const Scene& scene) {
    py::array_t<uint32_t> ranges({py::ssize_t(scene.objects.size()), py::ssize_t(2)});
    auto r = ranges.mutable_unchecked<2>();
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        r(i, 0) = scene.objects[i].first_triangle;
        r(i, 1) = scene.objects[i].triangle_count;
    }
    return ranges;
}

py::object cameraOrNone(const std::optional<CameraSpec>& camera) {
    return camera ? py::cast(PythonCamera{*camera, std::nullopt}) : py::none();
}

} // namespace

void bindScene(py::module_& m) {
    py::class_<SceneObject>(m, "SceneObject", "One object of a scene: a range of its triangles")
        .def_readonly("name", &SceneObject::name)
        .def_property_readonly("colour",
                               [](const SceneObject& o) {
                                   return py::make_tuple(o.colour.r, o.colour.g, o.colour.b,
                                                         o.colour.a);
                               })
        .def_readonly("transparent", &SceneObject::transparent)
        .def_readonly("first_triangle", &SceneObject::first_triangle)
        .def_readonly("triangle_count", &SceneObject::triangle_count)
        .def_property_readonly(
            "parts",
            [](const SceneObject& o) {
                py::list parts;
                for (const ObjectPart& p : o.parts)
                    parts.append(py::dict(py::arg("name") = p.name,
                                          py::arg("colour") = py::make_tuple(
                                              p.colour.r, p.colour.g, p.colour.b, p.colour.a),
                                          py::arg("first_triangle") = p.first_triangle,
                                          py::arg("triangle_count") = p.triangle_count));
                return parts;
            },
            "The meshes an object is made of (load(objects='node' or 'file')), each a dict of "
            "name, colour, first_triangle, triangle_count; empty for an object of one mesh")
        .def("__repr__", [](const SceneObject& o) {
            return "SceneObject(name='" + o.name + "', triangles " +
                   std::to_string(o.first_triangle) + ".." +
                   std::to_string(o.first_triangle + o.triangle_count) +
                   (o.transparent ? ", transparent)" : ")");
        });

    py::class_<Scene, std::shared_ptr<Scene>>(
        m, "Scene",
        "Objects made of triangles, with colours, transparency, cameras and, for a dynamic "
        "scene, motion; load() and builtin() make one, and Scene(positions, objects, ...) one "
        "from arrays. A static scene pickles as its arrays (to another process, a Dask worker)")
        .def(py::init([](const py::handle& positions, const py::handle& objects,
                         const py::handle& triangles, const py::handle& colours,
                         const py::handle& transparent, const py::handle& names,
                         const py::handle& camera, const std::string& name) {
                 return sceneFromArrays(positions, objects, triangles, colours, transparent, names,
                                        camera, name);
             }),
             py::arg("positions"), py::arg("objects") = py::none(), py::kw_only(),
             py::arg("triangles") = py::none(), py::arg("colours") = py::none(),
             py::arg("transparent") = py::none(), py::arg("names") = py::none(),
             py::arg("camera") = py::none(), py::arg("name") = "arrays",
             "A static scene from arrays: positions (T, 3, 3) or vertices (V, 3) with "
             "triangles=(T, 3); objects (K, 2) (first triangle, count) or (K,) counts tiling "
             "the triangles in order (None: one object); colours one (r, g, b[, a]) or (K, 3|4) "
             "in [0, 1]; transparent one bool or (K,) (None: alpha below 1); names K strings; "
             "camera the scene's own vissort.Camera. ValueError naming the problem")
        .def(py::pickle([](const Scene& s) { return sceneState(s); },
                        [](const py::dict& state) { return sceneFromState(state); }))
        .def_readonly("name", &Scene::name)
        .def_property_readonly("triangle_count", &Scene::triangleCount)
        .def_readonly("objects", &Scene::objects, "Every object, in object id order")
        .def_property_readonly("object_ranges", &objectRanges,
                               "(K, 2) uint32: each object's first triangle and triangle count")
        .def_property_readonly(
            "positions", [](const Scene& s) { return cornersArray(s.positions); },
            "(T, 3, 3) float32: the corners of every triangle at time 0 (a copy)")
        .def_property_readonly(
            "triangles",
            [](const Scene& s) {
                std::vector<uint32_t> indices(3 * s.triangleCount());
                std::iota(indices.begin(), indices.end(), 0u);
                return toArray(std::move(indices))
                    .reshape(std::vector<py::ssize_t>{py::ssize_t(s.triangleCount()), 3});
            },
            "(T, 3) uint32: each triangle's vertices in positions.reshape(-1, 3) (scenes keep "
            "every triangle's own corners)")
        .def_property_readonly("is_dynamic", &Scene::isDynamic)
        .def_property_readonly(
            "source_files", [](const Scene& s) { return s.source_files; },
            "Every file loading the scene read (a mesh file and what its reader opened beside "
            "it, a JSON scene and its meshes' files); empty for built-in scenes and arrays. "
            "vissort.batch refuses an output that is one of them")
        .def(
            "frame",
            [](const Scene& s, double t) {
                if (!std::isfinite(t))
                    throw py::value_error("time must be finite");
                TrianglePositions frame;
                {
                    py::gil_scoped_release unlocked;
                    s.frame(t, frame);
                }
                return cornersArray(frame);
            },
            py::arg("t"), "(T, 3, 3) float32: the corners at time t seconds (static scenes: t = 0)")
        .def_property_readonly(
            "bounds",
            [](const Scene& s) {
                const Bounds b = s.positions.bounds();
                return py::make_tuple(vec3Tuple(b.min), vec3Tuple(b.max));
            },
            "((min x, y, z), (max x, y, z)) at time 0")
        .def_property_readonly(
            "camera", [](const Scene& s) { return cameraOrNone(s.camera); },
            "The scene's own camera (a mesh file's first usable one), or None")
        .def_property_readonly(
            "cameras",
            [](const Scene& s) {
                py::list cameras;
                for (const StoredCamera& stored : s.cameras)
                    cameras.append(py::make_tuple(
                        stored.name,
                        stored.problem.empty() ? cameraOrNone(stored.camera) : py::none(),
                        stored.problem));
                return cameras;
            },
            "The cameras a mesh file stores: (name, Camera or None, problem) each")
        .def("__repr__", [](const Scene& s) {
            return "Scene('" + s.name + "', " + std::to_string(s.objects.size()) + " objects, " +
                   std::to_string(s.triangleCount()) + " triangles" +
                   (s.isDynamic() ? ", dynamic)" : ")");
        });

    m.def(
        "load",
        [](const py::object& path, const std::optional<std::string>& objects) {
            const py::object text = py::module_::import("os").attr("fspath")(path);
            if (!py::isinstance<py::str>(text))
                throw py::value_error("path must be a str or an os.PathLike of one");
            const std::string specification = text.cast<std::string>();
            std::optional<ObjectGrouping> grouping;
            if (objects) {
                const Result<ObjectGrouping> named =
                    parseEnum<ObjectGrouping>(kObjectGroupingNames, *objects, "grouping");
                if (!named)
                    throw py::value_error("objects: " + named.error);
                grouping = *named.value;
            }
            return madeScene([&] { return samples::loadScene(specification, grouping); });
        },
        py::arg("path"), py::kw_only(), py::arg("objects") = py::none(),
        "A scene from a mesh file (OBJ, PLY, STL, glTF, Collada, ... through assimp), a JSON "
        "scene, or a 'builtin:NAME?key=value' specification, as the command line reads it. "
        "objects: how a mesh file's meshes become objects, 'mesh' (one each, the default), "
        "'node' or 'file' (the command line's --objects). ValueError naming the problem when it "
        "cannot be read");
    m.def(
        "builtin",
        [](const std::string& name, const py::kwargs& parameters) {
            SceneParameters values;
            for (const auto& [key, value] : parameters) {
                const std::string k = py::str(key).cast<std::string>();
                values[k] = parameterText(k, value);
            }
            return madeScene([&] { return samples::makeBuiltinScene(name, values); });
        },
        py::arg("name"),
        "A built-in scene by name with its parameters: builtin('bunnies', n=18, seed=1); "
        "builtin_scenes() lists them");
    m.def(
        "builtin_scenes",
        [] {
            py::dict scenes;
            for (const samples::BuiltinSceneInfo& info : samples::builtinScenes())
                scenes[py::str(info.name)] = info.summary;
            return scenes;
        },
        "Every built-in scene's name and its one-line description");
}

} // namespace vissort::python
