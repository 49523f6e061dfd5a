#include "reference_triangles.h"

#include <utility>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

namespace vissort::test {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;

// A triangle as what it is: a triangle, the segment between its extreme corners, or a point.
struct Shape {
    enum Kind { kPoint, kSegment, kTriangle } kind;
    Point p[3];
};

Shape shapeOf(const std::array<Vec3, 3>& t) {
    Point p[3];
    for (int c = 0; c < 3; ++c)
        p[c] = Point(t[c].x, t[c].y, t[c].z);
    if (!CGAL::collinear(p[0], p[1], p[2]))
        return {Shape::kTriangle, {p[0], p[1], p[2]}};
    const int pairs[3][3] = {{0, 1, 2}, {1, 2, 0}, {0, 2, 1}};
    for (const auto& ijk : pairs)
        if (p[ijk[0]] != p[ijk[1]] &&
            CGAL::collinear_are_ordered_along_line(p[ijk[0]], p[ijk[2]], p[ijk[1]]))
            return {Shape::kSegment, {p[ijk[0]], p[ijk[1]], p[ijk[1]]}};
    return {Shape::kPoint, {p[0], p[0], p[0]}};
}

} // namespace

bool isDegenerateTriangle(const std::array<Vec3, 3>& t) {
    return shapeOf(t).kind != Shape::kTriangle;
}

bool closedTrianglesMeet(const std::array<Vec3, 3>& ta, const std::array<Vec3, 3>& tb) {
    Shape a = shapeOf(ta), b = shapeOf(tb);
    if (a.kind < b.kind)
        std::swap(a, b); // a is the larger kind
    const Kernel::Triangle_3 triangle(a.p[0], a.p[1], a.p[2]);
    const Kernel::Segment_3 segment(a.p[0], a.p[1]);
    switch (a.kind) {
    case Shape::kTriangle:
        if (b.kind == Shape::kTriangle)
            return CGAL::do_intersect(triangle, Kernel::Triangle_3(b.p[0], b.p[1], b.p[2]));
        if (b.kind == Shape::kSegment)
            return CGAL::do_intersect(triangle, Kernel::Segment_3(b.p[0], b.p[1]));
        return CGAL::do_intersect(triangle, b.p[0]);
    case Shape::kSegment:
        if (b.kind == Shape::kSegment)
            return CGAL::do_intersect(segment, Kernel::Segment_3(b.p[0], b.p[1]));
        return CGAL::do_intersect(segment, b.p[0]);
    case Shape::kPoint:
        return a.p[0] == b.p[0];
    }
    return false;
}

} // namespace vissort::test
