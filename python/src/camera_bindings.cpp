// vissort.Camera: perspective and orthographic cameras with the command line's conventions
// (--eye/--target/--up/--fov and --ortho-dir).

#include <tuple>

#include <pybind11/stl.h>

#include "arrays.h"
#include "bindings.h"
#include "python_camera.h"
#include "vissort/camera_path.h"
#include "vissort/view_choice.h"

namespace vissort::python {

PythonCamera cameraOfScene(const Scene& scene, const ViewDef& def) {
    Result<ChosenView> chosen = chooseView(def, scene);
    if (!chosen)
        throw py::value_error(chosen.error);
    // Framing each call's positions, as the command line frames each frame's.
    return {chosen.value->camera, std::nullopt};
}

PythonCamera defaultCameraOf(const Scene& scene, uint32_t width, uint32_t height, int frames) {
    ViewDef def;
    def.width = width;
    def.height = height;
    def.frames = frames;
    def.names = OptionNames::python;
    return cameraOfScene(scene, def);
}

ViewProjection viewOf(const PythonCamera& camera, PositionsView positions, uint32_t width,
                      uint32_t height) {
    return frameCamera(camera.spec, camera.framed_bounds.value_or(positions.bounds()), width,
                       height);
}

PythonCamera CameraChoice::choose(const py::handle& camera, const std::shared_ptr<Scene>& scene,
                                  PositionsView positions, uint32_t width, uint32_t height) {
    if (!camera.is_none()) {
        if (!py::isinstance<PythonCamera>(camera))
            throw py::value_error("camera must be a vissort.Camera (Camera.perspective, "
                                  "Camera.orthographic or Camera.default), or None");
        return camera.cast<PythonCamera>();
    }
    if (!scene)
        return {framingCamera(positions, double(width) / height), std::nullopt};
    if (scene != scene_ || std::pair(width, height) != size_) {
        // Calls run on, frame after frame: a dynamic scene is framed over its first 10 s, as
        // `vissort view` frames it without --frames.
        constexpr int kOpenEndedFrames = 300;
        camera_ = defaultCameraOf(*scene, width, height, kOpenEndedFrames);
        scene_ = scene;
        size_ = {width, height};
    }
    return camera_;
}

namespace {

PythonCamera checked(PythonCamera camera, const char* what) {
    if (Status valid = validateCamera(camera.spec); !valid)
        throw py::value_error(std::string(what) + ": " + valid.error);
    return camera;
}

py::object perspectiveOnly(const PythonCamera& camera, py::object value) {
    return camera.spec.projection == Projection::perspective ? value : py::none();
}

std::string describe(const PythonCamera& camera) {
    return "Camera(" + describeCamera(camera.spec) +
           (camera.framed_bounds ? ", framing a scene's bounds at time 0)" : ")");
}

} // namespace

void bindCamera(py::module_& m) {
    py::class_<PythonCamera>(m, "Camera",
                             "A camera: perspective (eye, target, up, vertical field of view) or "
                             "orthographic along a direction, framing the geometry's bounding "
                             "sphere; the command line's --eye/--target/--up/--fov and --ortho-dir")
        .def_static(
            "perspective",
            [](const py::handle& eye, const py::handle& target, const py::handle& up,
               double fov_deg) {
                PythonCamera camera;
                camera.spec.projection = Projection::perspective;
                camera.spec.eye = readVec3(eye, "eye");
                camera.spec.target = readVec3(target, "target");
                camera.spec.up = readVec3(up, "up");
                camera.spec.fov_degrees = fov_deg;
                return checked(camera, "Camera.perspective");
            },
            py::arg("eye"), py::arg("target"), py::arg("up") = py::make_tuple(0, 1, 0),
            py::arg("fov_deg") = 45.0,
            "Looks from eye at target; fov_deg is the vertical field of view in (0, 180)")
        .def_static(
            "orthographic",
            [](const py::handle& direction, const py::object& scene) {
                PythonCamera camera;
                camera.spec.projection = Projection::orthographic;
                camera.spec.ortho_direction = readVec3(direction, "direction");
                if (!scene.is_none()) {
                    if (!py::isinstance<Scene>(scene))
                        throw py::value_error("scene must be a vissort.Scene or None");
                    camera.framed_bounds = scene.cast<const Scene&>().positions.bounds();
                }
                return checked(camera, "Camera.orthographic");
            },
            py::arg("direction"), py::arg("scene") = py::none(),
            "Looks along direction, framing the bounding sphere of the geometry each call is "
            "given (as the command line does, frame by frame), or of scene at time 0 if given")
        .def_static(
            "default",
            [](const Scene& scene, const py::handle& size, int frames) {
                const auto [width, height] = readSize(size);
                return defaultCameraOf(scene, width, height, frames);
            },
            py::arg("scene"), py::arg("size") = py::make_tuple(1024, 1024), py::arg("frames") = 1,
            "The command line's camera when none is given: the scene's own, else its geometry "
            "framed for an image of that size (a dynamic scene over its first `frames` frames, "
            "as the command line's --frames N)")
        .def_static(
            "of_scene",
            [](const Scene& scene, const py::object& camera, const py::object& eye,
               const py::object& target, const py::object& up, std::optional<double> fov_deg,
               const py::object& ortho_dir, std::optional<double> azimuth,
               std::optional<double> elevation, std::optional<double> distance,
               const py::handle& size, int frames) {
                ViewDef def;
                def.names = OptionNames::python;
                std::tie(def.width, def.height) = readSize(size);
                def.frames = frames;
                const std::pair<const py::object*, std::optional<Vec3>*> vectors[] = {
                    {&eye, &def.eye},
                    {&target, &def.target},
                    {&up, &def.up},
                    {&ortho_dir, &def.ortho_direction}};
                const char* names[] = {"eye", "target", "up", "ortho_dir"};
                for (std::size_t i = 0; i < std::size(vectors); ++i)
                    if (!vectors[i].first->is_none())
                        *vectors[i].second = readVec3(*vectors[i].first, names[i]);
                if (!camera.is_none()) {
                    if (!py::isinstance<py::str>(camera) && !py::isinstance<py::int_>(camera))
                        throw py::value_error("camera must be a stored camera's name or index");
                    def.stored_camera = py::str(camera);
                }
                def.fov_degrees = fov_deg;
                def.azimuth_degrees = azimuth;
                def.elevation_degrees = elevation;
                def.distance = distance;
                return cameraOfScene(scene, def);
            },
            py::arg("scene"), py::kw_only(), py::arg("camera") = py::none(),
            py::arg("eye") = py::none(), py::arg("target") = py::none(), py::arg("up") = py::none(),
            py::arg("fov_deg") = py::none(), py::arg("ortho_dir") = py::none(),
            py::arg("azimuth") = py::none(), py::arg("elevation") = py::none(),
            py::arg("distance") = py::none(), py::arg("size") = py::make_tuple(1024, 1024),
            py::arg("frames") = 1,
            "The camera the command line chooses for these options (--camera, --eye, --target, "
            "--up, --fov, --ortho-dir, --azimuth, --elevation, --distance, --size, --frames): "
            "the same policy and the same errors, named as these keywords. camera: a camera "
            "the file stores, by name or index (Scene.cameras)")
        .def(
            "on_path",
            [](const PythonCamera& base, const Scene& scene, const std::string& path, int frame) {
                const Result<CameraPath> parsed = parseCameraPath(path);
                if (!parsed)
                    throw py::value_error(parsed.error);
                if (frame < 0)
                    throw py::value_error("frame must be at least 0, got " + std::to_string(frame));
                // As every command's frames (FrameDriver): the path turns about the scene's
                // bounds at time 0.
                PythonCamera moved = base;
                moved.spec = cameraOnPath(base.spec, *parsed.value, frame, scene.positions.bounds(),
                                          scene.camera_path);
                if (Status usable = validateCamera(moved.spec); !usable)
                    throw py::value_error("camera of frame " + std::to_string(frame) +
                                          " on path '" + path + "': " + usable.error);
                return moved;
            },
            py::arg("scene"), py::arg("path"), py::arg("frame"),
            "This camera moved to frame `frame` of a camera path over scene, as the command "
            "line's --path with --frames: static, orbit, flythrough or scene (the scene's own "
            "key frames)")
        .def_property_readonly("projection",
                               [](const PythonCamera& c) {
                                   return c.spec.projection == Projection::perspective
                                              ? "perspective"
                                              : "orthographic";
                               })
        .def_property_readonly(
            "eye", [](const PythonCamera& c) { return perspectiveOnly(c, vec3Tuple(c.spec.eye)); },
            "None for an orthographic camera")
        .def_property_readonly(
            "target",
            [](const PythonCamera& c) { return perspectiveOnly(c, vec3Tuple(c.spec.target)); },
            "None for an orthographic camera")
        .def_property_readonly(
            "up", [](const PythonCamera& c) { return perspectiveOnly(c, vec3Tuple(c.spec.up)); },
            "None for an orthographic camera")
        .def_property_readonly(
            "fov_deg",
            [](const PythonCamera& c) {
                return perspectiveOnly(c, py::float_(c.spec.fov_degrees));
            },
            "None for an orthographic camera")
        .def_property_readonly(
            "direction",
            [](const PythonCamera& c) {
                return vec3Tuple(c.spec.projection == Projection::orthographic
                                     ? c.spec.ortho_direction
                                     : normalized(c.spec.target - c.spec.eye));
            },
            "The view direction")
        .def("__repr__", &describe);
}

} // namespace vissort::python
