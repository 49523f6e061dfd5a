// Homogeneous clipping: shared edges cut identically whatever their direction, results inside
// every plane, untouched triangles passed through bit for bit.

#include "raster/homogeneous_clip.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace vissort {
namespace {

using detail::ClipVertex;
using detail::kGuardBand;
using Polygon = std::array<ClipVertex, detail::kMaxPolygonVertices>;

bool same(const ClipVertex& a, const ClipVertex& b) {
    return a.x == b.x && a.y == b.y && a.z == b.z && a.w == b.w;
}

TEST(HomogeneousClip, InsideTrianglePassesThroughUnchanged) {
    const ClipVertex a{0.1, 0.2, 0.3, 1}, b{-0.5, 0.7, 0.9, 2}, c{0.4, -0.3, 0.1, 0.5};
    Polygon out;
    ASSERT_EQ(detail::clipTriangle(a, b, c, out), 3);
    EXPECT_TRUE(same(out[0], a) && same(out[1], b) && same(out[2], c));
}

TEST(HomogeneousClip, OutsideTrianglesVanish) {
    Polygon out;
    EXPECT_EQ(detail::clipTriangle({0, 0, -1, 1}, {1, 0, -2, 1}, {0, 1, -0.5, 1}, out),
              0); // behind near
    EXPECT_EQ(detail::clipTriangle({0, 0, 2, 1}, {1, 0, 3, 1}, {0, 1, 1.5, 1}, out),
              0); // beyond far
    EXPECT_EQ(detail::clipTriangle({40, 0, 0.5, 1}, {50, 0, 0.5, 1}, {45, 1, 0.5, 1}, out), 0);
    EXPECT_EQ(detail::clipTriangle({0, 0, 0.5, 1}, {NAN, 0, 0.5, 1}, {0, 1, 0.5, 1}, out), 0);
}

// Two triangles sharing edge ab, traversed in opposite directions, each crossing some planes:
// the cut points on ab must be the same doubles in both polygons.
TEST(HomogeneousClip, SharedEdgesAreCutIdentically) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> xy(-80, 80), z(-1.0, 2.0), w(0.2, 2.0);
    int shared_cuts = 0;
    for (int i = 0; i < 2000; ++i) {
        const auto vertex = [&] {
            const double ww = w(rng);
            return ClipVertex{xy(rng) * ww, xy(rng) * ww, z(rng) * ww, ww};
        };
        const ClipVertex a = vertex(), b = vertex(), c = vertex(), d = vertex();
        Polygon first, second;
        const int n1 = detail::clipTriangle(a, b, c, first);
        const int n2 = detail::clipTriangle(b, a, d, second);
        const auto onAb = [&](const ClipVertex& v) {
            // Collinear with a and b in 4D, between them.
            const double dx = b.x - a.x, dy = b.y - a.y, dz = b.z - a.z, dw = b.w - a.w;
            const double len2 = dx * dx + dy * dy + dz * dz + dw * dw;
            const double t =
                ((v.x - a.x) * dx + (v.y - a.y) * dy + (v.z - a.z) * dz + (v.w - a.w) * dw) / len2;
            const double ex = a.x + t * dx - v.x, ey = a.y + t * dy - v.y, ez = a.z + t * dz - v.z,
                         ew = a.w + t * dw - v.w;
            return t > 1e-9 && t < 1 - 1e-9 && ex * ex + ey * ey + ez * ez + ew * ew < 1e-16 * len2;
        };
        for (int k = 0; k < n1; ++k) {
            if (!onAb(first[k]))
                continue;
            // A cut on ab that first keeps is inside every plane, so second keeps it too.
            bool found = false;
            for (int m = 0; m < n2; ++m)
                found = found || same(first[k], second[m]);
            EXPECT_TRUE(found) << "triangle pair " << i;
            shared_cuts += found;
        }
    }
    EXPECT_GT(shared_cuts, 200);
}

TEST(HomogeneousClip, ResultsLieInsideEveryPlane) {
    std::mt19937 rng(12);
    std::uniform_real_distribution<double> xy(-100, 100), z(-2.0, 3.0), w(-0.5, 2.0);
    int clipped = 0;
    for (int i = 0; i < 2000; ++i) {
        const auto vertex = [&] { return ClipVertex{xy(rng), xy(rng), z(rng), w(rng)}; };
        Polygon out;
        const int n = detail::clipTriangle(vertex(), vertex(), vertex(), out);
        ASSERT_TRUE(n == 0 || (n >= 3 && n <= 9));
        clipped += n > 3;
        for (int k = 0; k < n; ++k) {
            const ClipVertex& v = out[k];
            const double eps =
                1e-9 * (std::abs(v.x) + std::abs(v.y) + std::abs(v.z) + std::abs(v.w) + 1);
            EXPECT_GT(v.w, 0);
            EXPECT_GE(v.z, -eps);
            EXPECT_LE(v.z, v.w + eps);
            EXPECT_LE(std::abs(v.x), kGuardBand * v.w + eps);
            EXPECT_LE(std::abs(v.y), kGuardBand * v.w + eps);
        }
    }
    EXPECT_GT(clipped, 100);
}

} // namespace
} // namespace vissort
