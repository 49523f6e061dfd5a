#pragma once
// What a call orders, renders or collides: a Scene at a time (its own arrays, or a frame of its
// motion), or the caller's numpy corners.

#include <memory>
#include <mutex>
#include <string>

#include <pybind11/pybind11.h>

#include "vissort/scene.h"

namespace vissort::python {

namespace py = pybind11;

/// Locks mutex (one call at a time on an object), waiting with the GIL released so that the
/// call holding it can take the GIL back. Needs the GIL.
std::unique_lock<std::mutex> lockWithoutGil(std::mutex& mutex);

/// The positions of one call. `source` is a Scene (at `time`, default 0), a corners array
/// ((T, 3, 3), or (V, 3) with `triangles`), or None for `scene` at `time`. Arrays and dynamic
/// scenes' frames are read into `buffer`; a static scene is read in place. Sets `used_scene` to
/// the scene read, or null. ValueError for bad input (see readPositions), a time that is not
/// finite, or None without a scene. Needs the GIL.
PositionsView readFrame(const py::handle& source, const py::handle& triangles,
                        const py::handle& time, const std::shared_ptr<Scene>& scene,
                        TrianglePositions& buffer, std::shared_ptr<Scene>& used_scene);

} // namespace vissort::python
