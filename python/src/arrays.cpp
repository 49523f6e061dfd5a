#include "arrays.h"

#include <algorithm>
#include <cmath>
#include <span>
#include <sstream>

#include "vissort/image.h"
#include "vissort/vertex_positions.h"

namespace vissort::python {
namespace {

// Corner indices are 32-bit throughout the library.
constexpr uint64_t kMaxTriangles = (uint64_t(1) << 32) / 3 - 1;

std::string shapeText(const py::array& a) {
    std::ostringstream text;
    text << '(';
    for (py::ssize_t d = 0; d < a.ndim(); ++d)
        text << (d ? ", " : "") << a.shape(d);
    text << (a.ndim() == 1 ? ",)" : ")");
    return text.str();
}

std::string dtypeText(const py::array& a) {
    return py::str(a.dtype()).cast<std::string>();
}

py::array asArray(const py::handle& value, const std::string& what) {
    py::array a = py::array::ensure(value);
    if (!a)
        throw py::value_error(what + ": not an array of numbers");
    return a;
}

// float32 coordinates with x, y and z adjacent, at a row stride gatherPositions takes: the
// library reads such an array where it is.
bool gatherable(const py::array& a) {
    const py::ssize_t row = a.strides(a.ndim() == 3 ? 1 : 0);
    return a.dtype().is(py::dtype::of<float>()) && a.strides(a.ndim() - 1) == sizeof(float) &&
           row >= py::ssize_t(3 * sizeof(float)) && row % py::ssize_t(sizeof(float)) == 0 &&
           row <= 1024 && (a.ndim() == 2 || a.strides(0) == 3 * row);
}

// The corners of a gatherable array, gathered by the library (the one reading of positions: its
// checks and messages); its refusals as ValueErrors naming `what`.
void gatherArray(const py::array& a, const py::array_t<uint32_t>& index_array, uint64_t count,
                 TrianglePositions& out, const std::string& what) {
    const std::span<const uint32_t> indices =
        index_array.size() > 0
            ? std::span<const uint32_t>(index_array.data(), std::size_t(3 * count))
            : std::span<const uint32_t>();
    const py::ssize_t row = a.strides(a.ndim() == 3 ? 1 : 0);
    const std::size_t vertices = std::size_t(a.ndim() == 3 ? 3 * a.shape(0) : a.shape(0));
    const VertexPositionsView view{static_cast<const float*>(a.data()), vertices, std::size_t(row),
                                   indices};
    const Status gathered = gatherPositions(view, out);
    if (!gathered)
        throw py::value_error(what + ": " + gathered.error);
}

} // namespace

void readPositions(const py::handle& positions, const py::handle& triangles, TrianglePositions& out,
                   const std::string& what) {
    const py::array a = asArray(positions, what);
    const bool indexed = !triangles.is_none();
    if (!indexed && !(a.ndim() == 3 && a.shape(1) == 3 && a.shape(2) == 3))
        throw py::value_error(
            what +
            " must have shape (T, 3, 3) (triangles, corners, xyz), or (V, 3) with "
            "triangles=(T, 3) indices; got shape " +
            shapeText(a));
    if (indexed && !(a.ndim() == 2 && a.shape(1) == 3))
        throw py::value_error("with triangles given, " + what +
                              " must have shape (V, 3) (vertices, xyz); got shape " + shapeText(a));
    if (a.dtype().kind() != 'f')
        throw py::value_error(what +
                              " must hold floating-point coordinates (float32, or another "
                              "float type), got dtype " +
                              dtypeText(a));

    // Indices: uint32 in C order are the library's as they are; other integer types are checked
    // for what uint32 cannot hold (negative, 2^32 and above) and converted once.
    py::array_t<uint32_t> indices;
    if (indexed) {
        const py::array index_array = asArray(triangles, "triangles");
        if (!(index_array.ndim() == 2 && index_array.shape(1) == 3))
            throw py::value_error("triangles must have shape (T, 3) (vertex indices); got shape " +
                                  shapeText(index_array));
        const char kind = index_array.dtype().kind();
        if (kind != 'i' && kind != 'u')
            throw py::value_error("triangles must hold integer vertex indices, got dtype " +
                                  dtypeText(index_array));
        if (index_array.dtype().is(py::dtype::of<uint32_t>()) &&
            (index_array.flags() & py::array::c_style)) {
            indices = py::array_t<uint32_t>::ensure(index_array);
        } else {
            const auto wide = py::array_t<int64_t>::ensure(index_array);
            if (!wide)
                throw py::value_error("triangles: indices do not fit 64 bits");
            const auto ix = wide.unchecked<2>();
            indices = py::array_t<uint32_t>({ix.shape(0), py::ssize_t(3)});
            uint32_t* narrow = indices.mutable_data();
            for (py::ssize_t t = 0; t < ix.shape(0); ++t)
                for (int k = 0; k < 3; ++k) {
                    const int64_t v = ix(t, k);
                    if (v < 0 || v > int64_t(UINT32_MAX))
                        throw py::value_error("triangles: triangle " + std::to_string(t) +
                                              " names vertex " + std::to_string(v) +
                                              ", outside 0.." + std::to_string(a.shape(0) - 1) +
                                              " of " + what);
                    narrow[3 * t + k] = uint32_t(v);
                }
        }
    }
    const std::string counted = indexed ? "triangles" : what;
    const uint64_t count = uint64_t(indexed ? indices.shape(0) : a.shape(0));
    if (count == 0)
        throw py::value_error(counted + ": no triangles (an empty array)");
    if (count > kMaxTriangles)
        throw py::value_error(counted + ": " + std::to_string(count) +
                              " triangles, more than the " + std::to_string(kMaxTriangles) +
                              " that 32-bit corner indices address");
    if (gatherable(a)) {
        gatherArray(a, indices, count, out, what);
        return;
    }
    // Other layouts and float types (float64, half, long double): a C-ordered float32 copy first,
    // rounded as float(double) rounds (a value beyond float32's range becomes infinite, which the
    // gather refuses; numpy's own cast would also warn).
    const auto wide = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
    py::array_t<float> narrow(std::vector<py::ssize_t>(a.shape(), a.shape() + a.ndim()));
    std::transform(wide.data(), wide.data() + wide.size(), narrow.mutable_data(),
                   [](double v) { return float(v); });
    gatherArray(narrow, indices, count, out, what);
}

std::vector<PrimitiveRange> readObjects(const py::handle& objects, uint32_t triangle_count) {
    const py::array a = asArray(objects, "objects");
    const char kind = a.dtype().kind();
    const bool ranges = a.ndim() == 2 && a.shape(1) == 2;
    if (!(ranges || a.ndim() == 1) || (kind != 'i' && kind != 'u'))
        throw py::value_error("objects must be integer (first triangle, triangle count) pairs of "
                              "shape (K, 2), or triangle counts of shape (K,); got shape " +
                              shapeText(a) + ", dtype " + dtypeText(a));
    const auto values = py::array_t<int64_t>::ensure(a);
    const std::size_t count = std::size_t(a.shape(0));
    if (count == 0)
        throw py::value_error("objects: no objects (an empty array)");
    std::vector<PrimitiveRange> result(count);
    int64_t next = 0;
    for (std::size_t i = 0; i < count; ++i) {
        const int64_t first = ranges ? values.at(i, 0) : next;
        const int64_t size = ranges ? values.at(i, 1) : values.at(i);
        if (size < 1 || first < 0 || size > int64_t(triangle_count) ||
            first > int64_t(triangle_count) - size)
            throw py::value_error("objects: object " + std::to_string(i) + " (triangles " +
                                  std::to_string(first) + ", " + std::to_string(size) +
                                  " of them) is empty or outside the " +
                                  std::to_string(triangle_count) + " triangles given");
        result[i] = {uint32_t(first), uint32_t(size)};
        next = first + size;
    }
    return result;
}

py::array_t<float> cornersArray(PositionsView positions) {
    const py::ssize_t count = py::ssize_t(positions.triangleCount());
    py::array_t<float> corners({count, py::ssize_t(3), py::ssize_t(3)});
    auto c = corners.mutable_unchecked<3>();
    for (py::ssize_t t = 0; t < count; ++t)
        for (py::ssize_t k = 0; k < 3; ++k) {
            c(t, k, 0) = positions.x[3 * t + k];
            c(t, k, 1) = positions.y[3 * t + k];
            c(t, k, 2) = positions.z[3 * t + k];
        }
    return corners;
}

Vec3 readVec3(const py::handle& value, const std::string& what) {
    const py::array a = asArray(value, what);
    if (!(a.ndim() == 1 && a.shape(0) == 3) ||
        (a.dtype().kind() != 'f' && a.dtype().kind() != 'i' && a.dtype().kind() != 'u'))
        throw py::value_error(what + " must be three numbers (x, y, z)");
    const auto v = py::array_t<double>::ensure(a).unchecked<1>();
    const Vec3 result{v(0), v(1), v(2)};
    if (!std::isfinite(result.x) || !std::isfinite(result.y) || !std::isfinite(result.z))
        throw py::value_error(what + " must be finite");
    return result;
}

py::tuple vec3Tuple(const Vec3& v) {
    return py::make_tuple(v.x, v.y, v.z);
}

std::pair<uint32_t, uint32_t> readSize(const py::handle& size) {
    const std::string expected = "size must be (width, height), two positive integers";
    if (!py::isinstance<py::sequence>(size) || py::isinstance<py::str>(size) || py::len(size) != 2)
        throw py::value_error(expected);
    const py::sequence pair = py::reinterpret_borrow<py::sequence>(size);
    long long sides[2];
    for (int i = 0; i < 2; ++i) {
        const py::object side = pair[i];
        if (py::isinstance<py::bool_>(side) || !py::hasattr(side, "__index__"))
            throw py::value_error(expected);
        sides[i] = py::int_(side).cast<long long>();
        if (sides[i] < 0)
            throw py::value_error(expected);
    }
    if (Status valid = validateImageSize(uint64_t(sides[0]), uint64_t(sides[1])); !valid)
        throw py::value_error("size " + valid.error);
    return {uint32_t(sides[0]), uint32_t(sides[1])};
}

Rgba readColour(const py::handle& colour, const std::string& what) {
    const std::string expected = what + " must be (r, g, b) or (r, g, b, a), each in [0, 1]";
    const py::array array = py::array::ensure(colour);
    if (!array || array.ndim() != 1 || (array.shape(0) != 3 && array.shape(0) != 4))
        throw py::value_error(expected);
    const auto c = py::array_t<double>::ensure(array).unchecked<1>();
    for (py::ssize_t i = 0; i < array.shape(0); ++i)
        if (!(c(i) >= 0.0 && c(i) <= 1.0))
            throw py::value_error(expected);
    return {float(c(0)), float(c(1)), float(c(2)), array.shape(0) == 4 ? float(c(3)) : 1.0f};
}

py::tuple defaultBackground() {
    const auto rounded = [](float v) { return std::round(double(v) * 1e6) / 1e6; };
    const Rgba& c = kDefaultBackground;
    return py::make_tuple(rounded(c.r), rounded(c.g), rounded(c.b), rounded(c.a));
}

} // namespace vissort::python
