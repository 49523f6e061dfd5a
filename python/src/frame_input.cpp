#include "frame_input.h"

#include <cmath>

#include "arrays.h"

namespace vissort::python {

std::unique_lock<std::mutex> lockWithoutGil(std::mutex& mutex) {
    py::gil_scoped_release unlocked;
    return std::unique_lock<std::mutex>(mutex);
}

PositionsView readFrame(const py::handle& source, const py::handle& triangles,
                        const py::handle& time, const std::shared_ptr<Scene>& scene,
                        TrianglePositions& buffer, std::shared_ptr<Scene>& used_scene) {
    used_scene = nullptr;
    if (source.is_none() || py::isinstance<Scene>(source)) {
        used_scene = source.is_none() ? scene : source.cast<std::shared_ptr<Scene>>();
        if (!used_scene)
            throw py::value_error("no positions given, and no scene to take them from");
        if (!triangles.is_none())
            throw py::value_error("triangles index positions arrays: not with a Scene");
        if (!time.is_none() && !py::hasattr(time, "__float__") && !py::hasattr(time, "__index__"))
            throw py::value_error("time must be a number of seconds");
        const double t = time.is_none()
                             ? 0.0
                             : py::float_(py::reinterpret_borrow<py::object>(time)).cast<double>();
        if (!std::isfinite(t))
            throw py::value_error("time must be finite");
        if (!used_scene->isDynamic())
            return used_scene->positions.view();
        py::gil_scoped_release unlocked;
        used_scene->frame(t, buffer);
        return buffer.view();
    }
    if (!time.is_none())
        throw py::value_error("time picks a frame of a Scene: not with positions arrays");
    readPositions(source, triangles, buffer);
    return buffer.view();
}

} // namespace vissort::python
