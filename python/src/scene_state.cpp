// Scenes from arrays and scenes as pickle's state (scene_state.h).

#include "scene_state.h"

#include <cmath>
#include <utility>
#include <vector>

#include <pybind11/numpy.h>

#include "arrays.h"
#include "python_camera.h"

namespace vissort::python {
namespace {

// Bumped when the state's layout changes, so that an old pickle is refused by name rather than
// misread.
constexpr int kStateVersion = 1;

py::tuple colourTuple(const Rgba& c) {
    return py::make_tuple(c.r, c.g, c.b, c.a);
}

py::tuple cameraState(const CameraSpec& c) {
    return py::make_tuple(c.projection == Projection::orthographic ? "orthographic" : "perspective",
                          vec3Tuple(c.eye), vec3Tuple(c.target), vec3Tuple(c.up), c.fov_degrees,
                          vec3Tuple(c.ortho_direction));
}

CameraSpec cameraFromState(const py::handle& state, const std::string& what) {
    const auto fields = py::reinterpret_borrow<py::tuple>(state);
    if (!py::isinstance<py::tuple>(state) || fields.size() != 6)
        throw py::value_error(what + " must be a camera's 6 fields");
    CameraSpec c;
    const std::string projection = py::str(fields[0]);
    if (projection != "perspective" && projection != "orthographic")
        throw py::value_error(what + ": unknown projection '" + projection + "'");
    c.projection =
        projection == "orthographic" ? Projection::orthographic : Projection::perspective;
    c.eye = readVec3(fields[1], what + " eye");
    c.target = readVec3(fields[2], what + " target");
    c.up = readVec3(fields[3], what + " up");
    c.fov_degrees = fields[4].cast<double>();
    c.ortho_direction = readVec3(fields[5], what + " direction");
    return c;
}

// colours as sceneFromArrays takes them, one Rgba per object.
std::vector<Rgba> objectColours(const py::handle& colours, std::size_t count) {
    if (colours.is_none())
        return std::vector<Rgba>(count);
    // One colour is a flat run of 3 or 4 numbers; anything else is one colour per object (rows
    // of an array, or a list of tuples of either length).
    const py::array flat = py::array_t<double>::ensure(colours);
    if (flat && flat.ndim() == 1)
        return std::vector<Rgba>(count, readColour(flat, "colours"));
    if (!py::isinstance<py::sequence>(colours) && !py::isinstance<py::array>(colours))
        throw py::value_error("colours must be one (r, g, b[, a]) or one per object");
    const py::sequence rows = py::reinterpret_borrow<py::sequence>(colours);
    if (std::size_t(py::len(rows)) != count)
        throw py::value_error("colours must be one (r, g, b[, a]) or one per object (" +
                              std::to_string(count) + "), got " + std::to_string(py::len(rows)));
    std::vector<Rgba> out;
    for (std::size_t i = 0; i < count; ++i)
        out.push_back(readColour(rows[i], "colours[" + std::to_string(i) + "]"));
    return out;
}

// transparent as sceneFromArrays takes it; -1 where alpha decides.
std::vector<int> objectTransparency(const py::handle& transparent, std::size_t count) {
    if (transparent.is_none())
        return std::vector<int>(count, -1);
    const py::array a = py::array::ensure(transparent);
    const bool one = a && a.ndim() == 0,
               each = a && a.ndim() == 1 && std::size_t(a.size()) == count;
    if (!(one || each) || a.dtype().kind() != 'b')
        throw py::value_error("transparent must be one bool or one bool per object (" +
                              std::to_string(count) + ")");
    const auto values = py::array_t<bool>::ensure(a);
    std::vector<int> out(count);
    for (std::size_t i = 0; i < count; ++i)
        out[i] = values.data()[one ? 0 : i] ? 1 : 0;
    return out;
}

std::vector<std::string> objectNames(const py::handle& names, std::size_t count) {
    std::vector<std::string> out;
    if (names.is_none()) {
        for (std::size_t i = 0; i < count; ++i)
            out.push_back("object " + std::to_string(i));
        return out;
    }
    if (py::isinstance<py::str>(names) || !py::isinstance<py::sequence>(names) ||
        py::len(names) != count)
        throw py::value_error("names must be one string per object (" + std::to_string(count) +
                              ")");
    for (const py::handle name : names) {
        if (!py::isinstance<py::str>(name))
            throw py::value_error("names must be one string per object (" + std::to_string(count) +
                                  ")");
        out.push_back(name.cast<std::string>());
    }
    return out;
}

} // namespace

std::shared_ptr<Scene> sceneFromArrays(const py::handle& positions, const py::handle& objects,
                                       const py::handle& triangles, const py::handle& colours,
                                       const py::handle& transparent, const py::handle& names,
                                       const py::handle& camera, const std::string& name) {
    auto scene = std::make_shared<Scene>();
    scene->name = name;
    readPositions(positions, triangles, scene->positions);
    const uint32_t triangle_count = uint32_t(scene->positions.triangleCount());
    const std::vector<PrimitiveRange> ranges =
        objects.is_none() ? std::vector<PrimitiveRange>{{0, triangle_count}}
                          : readObjects(objects, triangle_count);
    const std::vector<Rgba> colour = objectColours(colours, ranges.size());
    const std::vector<int> transparency = objectTransparency(transparent, ranges.size());
    const std::vector<std::string> name_of = objectNames(names, ranges.size());
    for (std::size_t i = 0; i < ranges.size(); ++i) {
        SceneObject object;
        object.name = name_of[i];
        object.colour = colour[i];
        object.transparent = transparency[i] < 0 ? colour[i].a < 1.0f : transparency[i] == 1;
        object.first_triangle = ranges[i].first_triangle;
        object.triangle_count = ranges[i].triangle_count;
        scene->objects.push_back(std::move(object));
    }
    if (!camera.is_none()) {
        if (!py::isinstance<PythonCamera>(camera))
            throw py::value_error("camera must be a vissort.Camera or None");
        scene->camera = camera.cast<const PythonCamera&>().spec;
    }
    if (const Status valid = validateScene(*scene); !valid)
        throw py::value_error(valid.error);
    return scene;
}

py::dict sceneState(const Scene& scene) {
    if (scene.isDynamic())
        throw py::type_error("cannot pickle the dynamic scene '" + scene.name +
                             "': its motion is code, not arrays; give other processes its "
                             "builtin specification or file path instead");
    py::list objects;
    for (const SceneObject& o : scene.objects) {
        py::list parts;
        for (const ObjectPart& p : o.parts)
            parts.append(
                py::make_tuple(p.name, colourTuple(p.colour), p.first_triangle, p.triangle_count));
        objects.append(py::make_tuple(o.name, colourTuple(o.colour), o.transparent,
                                      o.first_triangle, o.triangle_count, parts));
    }
    py::list cameras, path;
    for (const StoredCamera& c : scene.cameras)
        cameras.append(py::make_tuple(c.name, cameraState(c.camera), c.problem));
    for (const CameraKey& key : scene.camera_path)
        path.append(py::make_tuple(key.time, cameraState(key.camera)));
    py::dict state;
    state["version"] = kStateVersion;
    state["name"] = scene.name;
    state["positions"] = cornersArray(scene.positions);
    state["objects"] = objects;
    state["camera"] = scene.camera ? py::object(cameraState(*scene.camera)) : py::none();
    state["cameras"] = cameras;
    state["camera_path"] = path;
    return state;
}

std::shared_ptr<Scene> sceneFromState(const py::dict& state) {
    try {
        if (!state.contains("version") || state["version"].cast<int>() != kStateVersion)
            throw py::value_error("not a vissort.Scene state of version " +
                                  std::to_string(kStateVersion));
        auto scene = std::make_shared<Scene>();
        scene->name = state["name"].cast<std::string>();
        readPositions(state["positions"], py::none(), scene->positions, "scene state positions");
        for (const py::handle o : state["objects"]) {
            const auto fields = o.cast<py::tuple>();
            SceneObject object;
            object.name = fields[0].cast<std::string>();
            object.colour = readColour(fields[1], "scene state colour");
            object.transparent = fields[2].cast<bool>();
            object.first_triangle = fields[3].cast<uint32_t>();
            object.triangle_count = fields[4].cast<uint32_t>();
            for (const py::handle p : fields[5]) {
                const auto part = p.cast<py::tuple>();
                object.parts.push_back({part[0].cast<std::string>(),
                                        readColour(part[1], "scene state part colour"),
                                        part[2].cast<uint32_t>(), part[3].cast<uint32_t>()});
            }
            scene->objects.push_back(std::move(object));
        }
        if (!state["camera"].is_none())
            scene->camera = cameraFromState(state["camera"], "scene state camera");
        for (const py::handle c : state["cameras"]) {
            const auto fields = c.cast<py::tuple>();
            scene->cameras.push_back({fields[0].cast<std::string>(),
                                      cameraFromState(fields[1], "scene state camera"),
                                      fields[2].cast<std::string>()});
        }
        for (const py::handle k : state["camera_path"]) {
            const auto fields = k.cast<py::tuple>();
            scene->camera_path.push_back(
                {fields[0].cast<double>(), cameraFromState(fields[1], "scene state path")});
        }
        if (const Status valid = validateScene(*scene); !valid)
            throw py::value_error(valid.error);
        return scene;
    } catch (const py::cast_error&) {
        throw py::value_error("not a vissort.Scene state: a field has the wrong type");
    } catch (const py::error_already_set& e) {
        if (e.matches(PyExc_ValueError))
            throw;
        throw py::value_error("not a vissort.Scene state: " + std::string(e.what()));
    }
}

} // namespace vissort::python
