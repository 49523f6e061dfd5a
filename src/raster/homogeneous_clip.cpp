// This work is based on: Ivan E. Sutherland, Gary W. Hodgman. Reentrant Polygon Clipping. 1974;
// and James F. Blinn, Martin E. Newell. Clipping Using Homogeneous Coordinates. 1978.

#include "raster/homogeneous_clip.h"

#include <cmath>
#include <utility>

namespace vissort::detail {
namespace {

using Polygon = std::array<ClipVertex, kMaxPolygonVertices>;

enum class Plane { near, far, left, right, bottom, top };

double signedDistance(const ClipVertex& v, Plane plane) {
    switch (plane) {
    case Plane::near:
        return v.z;
    case Plane::far:
        return v.w - v.z;
    case Plane::left:
        return kGuardBand * v.w + v.x;
    case Plane::right:
        return kGuardBand * v.w - v.x;
    case Plane::bottom:
        return kGuardBand * v.w + v.y;
    case Plane::top:
        return kGuardBand * v.w - v.y;
    }
    return 0;
}

// signedDistance(v, plane) >= 0 for all six planes, the same expressions without the branches
// (the test runs for every triangle of every bind).
bool insideAllPlanes(const ClipVertex& v) {
    const double guard = kGuardBand * v.w;
    return (v.z >= 0) & (v.w - v.z >= 0) & (guard + v.x >= 0) & (guard - v.x >= 0) &
           (guard + v.y >= 0) & (guard - v.y >= 0);
}

bool lexicographicallyLess(const ClipVertex& a, const ClipVertex& b) {
    if (a.x != b.x)
        return a.x < b.x;
    if (a.y != b.y)
        return a.y < b.y;
    if (a.z != b.z)
        return a.z < b.z;
    return a.w < b.w;
}

// Only called when exactly one endpoint is inside, so the denominator is positive or negative,
// never zero, and t lies in [0, 1].
ClipVertex cutEdge(const ClipVertex& a, double dist_a, const ClipVertex& b, double dist_b) {
    const bool a_first = lexicographicallyLess(a, b);
    const ClipVertex& p = a_first ? a : b;
    const ClipVertex& q = a_first ? b : a;
    const double dist_p = a_first ? dist_a : dist_b;
    const double dist_q = a_first ? dist_b : dist_a;
    const double t = dist_p / (dist_p - dist_q);
    return {p.x + t * (q.x - p.x), p.y + t * (q.y - p.y), p.z + t * (q.z - p.z),
            p.w + t * (q.w - p.w)};
}

// One Sutherland-Hodgman stage. Returns the output count, or -1 when it would overflow.
int clipToPlane(const Polygon& in, int count, Plane plane, Polygon& out) {
    int written = 0;
    for (int i = 0; i < count; ++i) {
        const ClipVertex& current = in[i];
        const ClipVertex& next = in[(i + 1) % count];
        const double dist_current = signedDistance(current, plane);
        const double dist_next = signedDistance(next, plane);
        const bool current_inside = dist_current >= 0;
        const bool next_inside = dist_next >= 0;
        if (current_inside) {
            if (written == kMaxPolygonVertices)
                return -1;
            out[written++] = current;
        }
        if (current_inside != next_inside) {
            if (written == kMaxPolygonVertices)
                return -1;
            out[written++] = cutEdge(current, dist_current, next, dist_next);
        }
    }
    return written;
}

bool isFinite(const ClipVertex& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w);
}

} // namespace

int clipTriangle(const ClipVertex& a, const ClipVertex& b, const ClipVertex& c, Polygon& out) {
    if (!isFinite(a) || !isFinite(b) || !isFinite(c))
        return 0;
    out[0] = a;
    out[1] = b;
    out[2] = c;
    // Most triangles lie inside every plane: each pass below would then keep the three vertices
    // as they are, in order, so the result is the same without the passes.
    if (insideAllPlanes(a) & insideAllPlanes(b) & insideAllPlanes(c))
        return a.w > 0 && b.w > 0 && c.w > 0 ? 3 : 0;
    Polygon scratch;
    int count = 3;
    // Ping-pong between out and scratch; six planes, so the result ends up back in out.
    Polygon* from = &out;
    Polygon* to = &scratch;
    for (Plane plane :
         {Plane::near, Plane::far, Plane::left, Plane::right, Plane::bottom, Plane::top}) {
        count = clipToPlane(*from, count, plane, *to);
        if (count < 3)
            return 0;
        std::swap(from, to);
    }
    for (int i = 0; i < count; ++i)
        if (!(out[i].w > 0))
            return 0;
    return count;
}

} // namespace vissort::detail
