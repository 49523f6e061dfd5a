// PLACEHOLDER (being replaced by the exact test): six segment-triangle tests in double.
#include "collide/triangle_intersection.h"

#include "collide/exact_predicates.h"

namespace vissort::detail {
namespace {

bool segmentMeetsTriangle(const std::array<float, 3>& p, const std::array<float, 3>& q,
                          const TriangleCorners& t) {
    const int sp = orient3d(t[0].data(), t[1].data(), t[2].data(), p.data());
    const int sq = orient3d(t[0].data(), t[1].data(), t[2].data(), q.data());
    if (sp * sq > 0) return false;
    const int e0 = orient3d(p.data(), q.data(), t[0].data(), t[1].data());
    const int e1 = orient3d(p.data(), q.data(), t[1].data(), t[2].data());
    const int e2 = orient3d(p.data(), q.data(), t[2].data(), t[0].data());
    return (e0 >= 0 && e1 >= 0 && e2 >= 0) || (e0 <= 0 && e1 <= 0 && e2 <= 0);
}

} // namespace

bool trianglesIntersect(const TriangleCorners& a, const TriangleCorners& b) {
    for (int i = 0; i < 3; ++i) {
        if (segmentMeetsTriangle(a[i], a[(i + 1) % 3], b)) return true;
        if (segmentMeetsTriangle(b[i], b[(i + 1) % 3], a)) return true;
    }
    return false;
}

} // namespace vissort::detail
