// Brute-force checks of generated scenes' meshes and gaps (solid_checks.h).

#include "solid_checks.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <tuple>

namespace vissort::test {
namespace {

double distance2(const Vec3& a, const Vec3& b) {
    return dot(a - b, a - b);
}

// Squared distance between segments p1q1 and p2q2 (Ericson 5.1.9).
double segmentDistance2(const Vec3& p1, const Vec3& q1, const Vec3& p2, const Vec3& q2) {
    const Vec3 d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
    const double a = dot(d1, d1), e = dot(d2, d2), f = dot(d2, r);
    const double b = dot(d1, d2), c = dot(d1, r), denominator = a * e - b * b;
    double s = denominator > 0 ? std::clamp((b * f - c * e) / denominator, 0.0, 1.0) : 0.0;
    double t = (b * s + f) / e;
    if (t < 0) {
        t = 0;
        s = std::clamp(-c / a, 0.0, 1.0);
    } else if (t > 1) {
        t = 1;
        s = std::clamp((b - c) / a, 0.0, 1.0);
    }
    return distance2(p1 + d1 * s, p2 + d2 * t);
}

// Six times the signed volume of the tetrahedron (a, b, c, d).
double orient(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
    return dot(cross(b - a, c - a), d - a);
}

// Whether segment pq passes through the inside of triangle t, strictly: its ends on either side
// of t's plane and the line inside all three edges. Touching cases are left to the distances.
bool crossesStrictly(const Vec3& p, const Vec3& q, const Triangle& t) {
    const double sp = orient(t[0], t[1], t[2], p), sq = orient(t[0], t[1], t[2], q);
    if (!((sp > 0 && sq < 0) || (sp < 0 && sq > 0)))
        return false;
    const double e0 = orient(p, q, t[0], t[1]), e1 = orient(p, q, t[1], t[2]),
                 e2 = orient(p, q, t[2], t[0]);
    return (e0 > 0 && e1 > 0 && e2 > 0) || (e0 < 0 && e1 < 0 && e2 < 0);
}

} // namespace

Triangle triangleOf(const Scene& scene, std::size_t t) {
    return {scene.positions.corner(3 * t), scene.positions.corner(3 * t + 1),
            scene.positions.corner(3 * t + 2)};
}

bool rayHits(const Vec3& o, const Vec3& d, const Triangle& t) {
    const Vec3 e1 = t[1] - t[0], e2 = t[2] - t[0];
    const Vec3 p = cross(d, e2);
    const double det = dot(e1, p);
    if (std::abs(det) < 1e-15)
        return false;
    const Vec3 s = o - t[0];
    const double u = dot(s, p) / det;
    const Vec3 q = cross(s, e1);
    const double v = dot(d, q) / det;
    return u >= 0 && v >= 0 && u + v <= 1 && dot(e2, q) / det > 0;
}

Bounds boundsOf(const Scene& scene, uint32_t first, uint32_t count) {
    Bounds bounds;
    for (uint32_t t = first; t < first + count; ++t)
        for (int corner = 0; corner < 3; ++corner)
            bounds.add(scene.positions.corner(3 * std::size_t{t} + corner));
    return bounds;
}

double boxDistance(const Bounds& a, const Bounds& b) {
    const double dx = std::max({0.0, a.min.x - b.max.x, b.min.x - a.max.x});
    const double dy = std::max({0.0, a.min.y - b.max.y, b.min.y - a.max.y});
    const double dz = std::max({0.0, a.min.z - b.max.z, b.min.z - a.max.z});
    return std::sqrt(dx * dx + dy * dy + dz * dz);
}

// By Voronoi regions (Ericson 5.1.5).
Vec3 closestOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = dot(ab, ap), d2 = dot(ac, ap);
    if (d1 <= 0 && d2 <= 0)
        return a;
    const Vec3 bp = p - b;
    const double d3 = dot(ab, bp), d4 = dot(ac, bp);
    if (d3 >= 0 && d4 <= d3)
        return b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0)
        return a + ab * (d1 / (d1 - d3));
    const Vec3 cp = p - c;
    const double d5 = dot(ab, cp), d6 = dot(ac, cp);
    if (d6 >= 0 && d5 <= d6)
        return c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0)
        return a + ac * (d2 / (d2 - d6));
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0)
        return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
    const double denominator = 1 / (va + vb + vc);
    return a + (ab * (vb * denominator) + ac * (vc * denominator));
}

// Unless an edge of one passes through the other (then they meet), the distance is reached
// between two edges or between a corner and the other triangle, also for coplanar triangles
// (overlapping ones have crossing edges or a corner inside).
double triangleDistance(const Triangle& a, const Triangle& b) {
    for (int i = 0; i < 3; ++i)
        if (crossesStrictly(a[i], a[(i + 1) % 3], b) || crossesStrictly(b[i], b[(i + 1) % 3], a))
            return 0;
    double best = 1e300;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j)
            best = std::min(best, segmentDistance2(a[i], a[(i + 1) % 3], b[j], b[(j + 1) % 3]));
        best = std::min(best, distance2(a[i], closestOnTriangle(a[i], b[0], b[1], b[2])));
        best = std::min(best, distance2(b[i], closestOnTriangle(b[i], a[0], a[1], a[2])));
    }
    return std::sqrt(best);
}

MeshCheck checkMesh(const Scene& scene, const SceneObject& object) {
    std::map<std::tuple<float, float, float>, int> ids;
    std::map<std::pair<int, int>, int> directed;
    MeshCheck check;
    check.smallest_area = 1e300;
    for (uint32_t t = object.first_triangle; t < object.first_triangle + object.triangle_count;
         ++t) {
        int corner_id[3];
        for (int c = 0; c < 3; ++c) {
            const std::size_t i = 3 * std::size_t{t} + c;
            const auto key =
                std::make_tuple(scene.positions.x[i], scene.positions.y[i], scene.positions.z[i]);
            corner_id[c] = ids.emplace(key, static_cast<int>(ids.size())).first->second;
        }
        for (int c = 0; c < 3; ++c)
            ++directed[{corner_id[c], corner_id[(c + 1) % 3]}];
        const Triangle tri = triangleOf(scene, t);
        const Vec3 n = cross(tri[1] - tri[0], tri[2] - tri[0]);
        check.smallest_area = std::min(check.smallest_area, std::sqrt(dot(n, n)) / 2);
        check.volume += dot(tri[0], cross(tri[1], tri[2])) / 6;
    }
    for (const auto& [edge, count] : directed) {
        const auto reverse = directed.find({edge.second, edge.first});
        check.unmatched_edges += count != 1 || reverse == directed.end() || reverse->second != 1;
    }
    return check;
}

GapCheck checkGaps(const Scene& scene, double minimum, double reach) {
    GapCheck check;
    std::vector<Bounds> bounds;
    for (const SceneObject& object : scene.objects)
        bounds.push_back(boundsOf(scene, object.first_triangle, object.triangle_count));
    std::set<std::string> reported;
    for (std::size_t i = 0; i < scene.objects.size(); ++i)
        for (std::size_t j = i + 1; j < scene.objects.size(); ++j) {
            if (boxDistance(bounds[i], bounds[j]) >= reach)
                continue;
            const SceneObject &a = scene.objects[i], &b = scene.objects[j];
            for (uint32_t s = a.first_triangle; s < a.first_triangle + a.triangle_count; ++s) {
                const Bounds bs = boundsOf(scene, s, 1);
                if (boxDistance(bs, bounds[j]) >= reach)
                    continue;
                const Triangle ts = triangleOf(scene, s);
                for (uint32_t t = b.first_triangle; t < b.first_triangle + b.triangle_count; ++t) {
                    if (boxDistance(bs, boundsOf(scene, t, 1)) >= reach)
                        continue;
                    ++check.pairs_checked;
                    const double d = triangleDistance(ts, triangleOf(scene, t));
                    check.closest = std::min(check.closest, d);
                    if (d <= minimum && reported.insert(a.name + " and " + b.name).second)
                        check.too_close.push_back(a.name + " and " + b.name);
                }
            }
        }
    return check;
}

} // namespace vissort::test
