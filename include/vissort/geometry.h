#pragma once
// Plain geometric value types shared by scenes, cameras and oracles. No external types here.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace vissort {

struct Vec3 {
    double x = 0, y = 0, z = 0;
};

struct Rgba {
    float r = 0.8f, g = 0.8f, b = 0.8f, a = 1.0f;
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
};

/// World-space triangle corners as a structure of arrays, ready for a rasterizer:
/// triangle t has its corners at indices 3t, 3t+1, 3t+2 of x, y and z.
struct TrianglePositions {
    std::vector<float> x, y, z;

    std::size_t triangleCount() const { return x.size() / 3; }
    Vec3 corner(std::size_t index) const { return {x[index], y[index], z[index]}; }
    void resize(std::size_t triangles);
    Bounds bounds() const;
};

/// A primitive of the ordering: a contiguous range of triangles (one object, or one triangle).
struct PrimitiveRange {
    uint32_t first_triangle = 0;
    uint32_t triangle_count = 0;
};

} // namespace vissort
