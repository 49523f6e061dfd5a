#include "vissort/geometry.h"

#include <algorithm>
#include <cmath>

namespace vissort {

void Bounds::add(const Vec3& p) {
    min = {std::min(min.x, p.x), std::min(min.y, p.y), std::min(min.z, p.z)};
    max = {std::max(max.x, p.x), std::max(max.y, p.y), std::max(max.z, p.z)};
}

Vec3 Bounds::centre() const {
    if (isEmpty())
        return {};
    return (min + max) / 2;
}

double Bounds::radius() const {
    if (isEmpty())
        return 0;
    return length(max - min) / 2;
}

void TrianglePositions::resize(std::size_t triangles) {
    x.resize(triangles * 3);
    y.resize(triangles * 3);
    z.resize(triangles * 3);
}

Bounds PositionsView::bounds() const {
    Bounds b;
    for (std::size_t i = 0; i < x.size(); ++i)
        b.add(corner(i));
    return b;
}

} // namespace vissort
