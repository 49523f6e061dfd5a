// PLACEHOLDER (being replaced by the exact implementation): plain double arithmetic.
#include "collide/exact_predicates.h"

namespace vissort::detail {

int orient3d(const float a[3], const float b[3], const float c[3], const float d[3]) {
    const double bx = double(b[0]) - a[0], by = double(b[1]) - a[1], bz = double(b[2]) - a[2];
    const double cx = double(c[0]) - a[0], cy = double(c[1]) - a[1], cz = double(c[2]) - a[2];
    const double dx = double(d[0]) - a[0], dy = double(d[1]) - a[1], dz = double(d[2]) - a[2];
    const double det = bx * (cy * dz - cz * dy) - by * (cx * dz - cz * dx) + bz * (cx * dy - cy * dx);
    return (det > 0) - (det < 0);
}

int orient2d(const float a[2], const float b[2], const float c[2]) {
    const double det = (double(b[0]) - a[0]) * (double(c[1]) - a[1]) -
                       (double(b[1]) - a[1]) * (double(c[0]) - a[0]);
    return (det > 0) - (det < 0);
}

} // namespace vissort::detail
