#pragma once
// numpy arrays in and out: triangle corners read into the library's structure of arrays, with
// every problem (shape, dtype, NaN, indices out of range, no triangles) a ValueError in one line;
// results handed to numpy without a copy.

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "vissort/camera.h"
#include "vissort/geometry.h"

namespace vissort::python {

namespace py = pybind11;

/// Reads triangle corners into out (resized; its memory reused from call to call): `positions`
/// of shape (T, 3, 3) (triangle, corner, xyz), or (V, 3) vertices with `triangles` (T, 3)
/// integer indices into them. float32 and float64 with any strides are read where they are
/// (the one copy is into out), other float types converted to float32 first; other dtypes,
/// shapes, values not finite as float32, indices out of range and empty input raise ValueError
/// naming `what` and the problem. Needs the GIL.
void readPositions(const py::handle& positions, const py::handle& triangles, TrianglePositions& out,
                   const std::string& what = "positions");

/// Objects as triangle ranges over `triangle_count` triangles: an integer array of shape (K, 2)
/// (first triangle, triangle count), or of shape (K,) (counts of consecutive ranges from
/// triangle 0). Every range must hold at least one triangle, all within the triangles; else
/// ValueError naming the object. Ranges may share triangles where the library allows it (the
/// orderer does; the collision detector refuses). Needs the GIL.
std::vector<PrimitiveRange> readObjects(const py::handle& objects, uint32_t triangle_count);

/// Corners as an array of shape (T, 3, 3), float32 (a copy: the library keeps x, y and z apart).
py::array_t<float> cornersArray(PositionsView positions);

/// A vector handed to numpy without a copy, seen as Element of that shape and those strides
/// (bytes) over its memory: the array owns it from then on.
template <class Element, class T>
py::array_t<Element> ownedArray(std::vector<T>&& values, std::vector<py::ssize_t> shape,
                                std::vector<py::ssize_t> strides) {
    auto* owned = new std::vector<T>(std::move(values));
    py::capsule free_when_done(owned, [](void* p) { delete static_cast<std::vector<T>*>(p); });
    return py::array_t<Element>(std::move(shape), std::move(strides),
                                reinterpret_cast<const Element*>(owned->data()), free_when_done);
}

/// A vector handed to numpy as a 1-D array, without a copy.
template <class T> py::array_t<T> toArray(std::vector<T>&& values) {
    const py::ssize_t size = py::ssize_t(values.size());
    return ownedArray<T>(std::move(values), {size}, {py::ssize_t(sizeof(T))});
}

/// A 3-vector from any sequence of three finite numbers; ValueError naming `what` otherwise.
Vec3 readVec3(const py::handle& value, const std::string& what);
py::tuple vec3Tuple(const Vec3& v);

/// An image size (width, height) within validateImageSize's limits (the command line's --size);
/// ValueError otherwise.
std::pair<uint32_t, uint32_t> readSize(const py::handle& size);

/// A colour (r, g, b) or (r, g, b, a), each in [0, 1] (alpha 1 when left out); else ValueError:
/// "WHAT must be (r, g, b) or (r, g, b, a), each in [0, 1]". Needs the GIL.
Rgba readColour(const py::handle& colour, const std::string& what);

/// The library's default background as Python writes it: (0.3, 0.32, 0.36, 1.0), not the floats'
/// 0.30000001192092896.
py::tuple defaultBackground();

} // namespace vissort::python
