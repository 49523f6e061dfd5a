#pragma once
// Plain geometric value types shared by scenes, cameras and oracles. No external types here.
//
// Layer: vissort::geometry (the package's `order` component; docs/architecture.md).

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace vissort {

struct Vec3 {
    double x = 0, y = 0, z = 0;
};

inline Vec3 operator+(const Vec3& a, const Vec3& b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
inline Vec3 operator-(const Vec3& a, const Vec3& b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
inline Vec3 operator-(const Vec3& a) {
    return {-a.x, -a.y, -a.z};
}
inline Vec3 operator*(const Vec3& a, double s) {
    return {a.x * s, a.y * s, a.z * s};
}
inline Vec3 operator*(double s, const Vec3& a) {
    return a * s;
}
inline Vec3 operator/(const Vec3& a, double s) {
    return {a.x / s, a.y / s, a.z / s};
}
inline bool operator==(const Vec3& a, const Vec3& b) {
    return a.x == b.x && a.y == b.y && a.z == b.z;
}
inline double dot(const Vec3& a, const Vec3& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double length(const Vec3& a) {
    return std::sqrt(dot(a, a));
}
/// a scaled to length 1; a zero vector stays zero.
inline Vec3 normalized(const Vec3& a) {
    const double l = length(a);
    return l > 0 ? a / l : a;
}

struct Rgba {
    float r = 0.8f, g = 0.8f, b = 0.8f, a = 1.0f;

    friend bool operator==(const Rgba&, const Rgba&) = default;
};

/// Axis-aligned box; `isEmpty()` until a point is added.
struct Bounds {
    Vec3 min{1e300, 1e300, 1e300};
    Vec3 max{-1e300, -1e300, -1e300};

    bool isEmpty() const { return min.x > max.x; }
    void add(const Vec3& p);
    Vec3 centre() const;
    /// Half the diagonal: the radius of the bounding sphere the cameras frame.
    double radius() const;
    /// Corner i (0 to 7) of a box that is not empty: bit 0 of i picks max.x over min.x, bit 1
    /// max.y, bit 2 max.z.
    Vec3 corner(unsigned i) const {
        return {i & 1 ? max.x : min.x, i & 2 ? max.y : min.y, i & 4 ? max.z : min.z};
    }
};

/// World-space triangle corners as a structure of arrays, seen, not owned: what every oracle,
/// the orderer, the renderer and the collision detector read, so that a caller's own buffers
/// (a numpy array, a viewer's vertex arrays) are used without a copy. Triangle t has its corners
/// at indices 3t, 3t+1, 3t+2 of x, y and z, which have the same size, a multiple of 3. Vertex
/// buffers (a byte stride, interleaved attributes, indices) are gathered into this form by
/// gatherPositions (vertex_positions.h).
struct PositionsView {
    std::span<const float> x, y, z;

    std::size_t triangleCount() const { return x.size() / 3; }
    Vec3 corner(std::size_t index) const { return {x[index], y[index], z[index]}; }
    Bounds bounds() const;
};

/// World-space triangle corners as a structure of arrays, owned: the convenience type of scenes
/// and frames. Converts to a PositionsView wherever one is expected.
struct TrianglePositions {
    std::vector<float> x, y, z;

    std::size_t triangleCount() const { return x.size() / 3; }
    Vec3 corner(std::size_t index) const { return {x[index], y[index], z[index]}; }
    void resize(std::size_t triangles);
    Bounds bounds() const { return view().bounds(); }
    PositionsView view() const { return {x, y, z}; }
    operator PositionsView() const { return view(); }
};

/// A primitive of the ordering: a contiguous range of triangles (one object, or one triangle).
struct PrimitiveRange {
    uint32_t first_triangle = 0;
    uint32_t triangle_count = 0;
};

} // namespace vissort
