#pragma once
// Scenes made from numpy arrays, and scenes as plain data (pickle's state): what lets a static
// scene travel to another process (a Dask worker, multiprocessing) as its arrays.

#include <memory>
#include <string>

#include <pybind11/pybind11.h>

#include "vissort/scene.h"

namespace vissort::python {

namespace py = pybind11;

/// A static scene from arrays: positions (and triangles) as readPositions reads them; objects as
/// readObjects reads them (None: one object of every triangle), tiling the triangles in order;
/// colours None (the library's grey), one colour or one per object, (r, g, b[, a]) in [0, 1];
/// transparent None (an object is transparent when its alpha is below 1), one bool or one per
/// object; names None ("object 0", ...) or one string per object; camera None or the
/// vissort.Camera that frames the scene by default. ValueError naming the problem.
std::shared_ptr<Scene> sceneFromArrays(const py::handle& positions, const py::handle& objects,
                                       const py::handle& triangles, const py::handle& colours,
                                       const py::handle& transparent, const py::handle& names,
                                       const py::handle& camera, const std::string& name);

/// A static scene as plain data (a dict of strings, numbers, tuples and one float32 array):
/// its name, positions, objects with their parts, cameras and camera path. A dynamic scene has
/// none (its motion is code): TypeError saying to pass its specification instead.
py::dict sceneState(const Scene& scene);

/// The scene sceneState gave, checked as a loaded scene is (validateScene); ValueError naming
/// the problem for a state that is not one.
std::shared_ptr<Scene> sceneFromState(const py::dict& state);

} // namespace vissort::python
