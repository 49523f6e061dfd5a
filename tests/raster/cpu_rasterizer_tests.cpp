// Coverage, watertightness, clipping and depth of the reference rasterizer, each checked against
// an independent reference: exact integer point-in-triangle on the snapped corners, hit counts
// of tiled meshes, and double-precision ray casting.

#include "raster/cpu_rasterizer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "raster_references.h"
#include "vissort/camera.h"

namespace vissort {
namespace {

using Clip = std::array<double, 4>;
using test::castCoverage;
using test::castDepth;
using test::referenceCovers;
using test::snappedScreen;

detail::ClipVertex toVertex(const Clip& c) {
    return {c[0], c[1], c[2], c[3]};
}

Bounds unitCube() {
    Bounds b;
    b.add({-1, -1, -1});
    b.add({1, 1, 1});
    return b;
}

ViewProjection makeView(Projection projection, uint32_t width, uint32_t height) {
    CameraSpec spec;
    spec.projection = projection;
    spec.eye = {0.3, 0.4, 5};
    spec.target = {0, 0, 0};
    spec.ortho_direction = {0.1, -0.2, -1};
    return frameCamera(spec, unitCube(), width, height);
}

struct Fragment {
    uint32_t px, py;
    float depth;
};

std::vector<Fragment> rasterize(const Clip& a, const Clip& b, const Clip& c, uint32_t width,
                                uint32_t height) {
    std::vector<Fragment> out;
    detail::rasterizeTriangle(toVertex(a), toVertex(b), toVertex(c), width, height,
                              [&](uint32_t px, uint32_t py, float depth) {
                                  out.push_back({px, py, depth});
                                  return false;
                              });
    return out;
}

// Hit counts per pixel of many triangles.
struct HitCounter {
    uint32_t width, height;
    std::vector<int> hits = std::vector<int>(std::size_t(width) * height, 0);

    void add(const Clip& a, const Clip& b, const Clip& c) {
        for (const Fragment& f : rasterize(a, b, c, width, height))
            ++hits[std::size_t(f.py) * width + f.px];
    }
};

// Compares the rasterizer's coverage with the exact reference at every pixel. The triangle must
// need no clipping (in front of the near plane, inside the guard band).
void expectCoverageMatches(const Clip& a, const Clip& b, const Clip& c, uint32_t width,
                           uint32_t height) {
    const std::array<std::array<int64_t, 2>, 3> snapped{snappedScreen(a, width, height),
                                                        snappedScreen(b, width, height),
                                                        snappedScreen(c, width, height)};
    std::vector<uint8_t> expected(std::size_t(width) * height, 0);
    for (uint32_t py = 0; py < height; ++py)
        for (uint32_t px = 0; px < width; ++px)
            expected[std::size_t(py) * width + px] = referenceCovers(snapped, px, py);
    std::vector<uint8_t> got(expected.size(), 0);
    for (const Fragment& f : rasterize(a, b, c, width, height)) {
        ASSERT_LT(f.px, width);
        ASSERT_LT(f.py, height);
        ++got[std::size_t(f.py) * width + f.px];
    }
    for (uint32_t py = 0; py < height; ++py)
        for (uint32_t px = 0; px < width; ++px)
            ASSERT_EQ(int(got[std::size_t(py) * width + px]),
                      int(expected[std::size_t(py) * width + px]))
                << "pixel " << px << "," << py << " of " << width << "x" << height;
}

// Clip coordinates (w = 1) of a screen point, given in pixels.
Clip screenToClip(double sx, double sy, double d, uint32_t width, uint32_t height) {
    return {2.0 * sx / width - 1.0, 1.0 - 2.0 * sy / height, d, 1.0};
}

TEST(CpuRasterizer, CoverageMatchesExactReferenceOnHalfPixelGrid) {
    // Corners on a half-pixel grid put pixel centres exactly on edges and corners: the ties.
    std::mt19937 rng(1);
    const std::array<std::array<uint32_t, 2>, 6> sizes{
        {{1, 1}, {3, 5}, {7, 3}, {16, 16}, {17, 13}, {31, 9}}};
    for (const auto& [width, height] : sizes) {
        std::uniform_int_distribution<int> gx(-4, int(2 * width) + 4), gy(-4, int(2 * height) + 4);
        for (int i = 0; i < 300; ++i) {
            const auto corner = [&] {
                return screenToClip(gx(rng) * 0.5, gy(rng) * 0.5, 0.5, width, height);
            };
            expectCoverageMatches(corner(), corner(), corner(), width, height);
        }
    }
}

TEST(CpuRasterizer, CoverageMatchesExactReferenceThroughBothProjections) {
    std::mt19937 rng(2);
    std::uniform_real_distribution<double> coord(-1.0, 1.0);
    const std::array<std::array<uint32_t, 2>, 4> sizes{{{1, 1}, {3, 5}, {33, 21}, {64, 48}}};
    for (Projection projection : {Projection::perspective, Projection::orthographic})
        for (const auto& [width, height] : sizes) {
            const ViewProjection vp = makeView(projection, width, height);
            for (int i = 0; i < 200; ++i) {
                const auto corner = [&] { return vp.toClip({coord(rng), coord(rng), coord(rng)}); };
                expectCoverageMatches(corner(), corner(), corner(), width, height);
            }
        }
}

TEST(CpuRasterizer, CoverageMatchesExactReferenceOnLargeViewport) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> coord(-1.0, 1.0);
    const ViewProjection vp = makeView(Projection::perspective, 1600, 1200);
    for (int i = 0; i < 3; ++i) {
        const auto corner = [&] { return vp.toClip({coord(rng), coord(rng), coord(rng)}); };
        expectCoverageMatches(corner(), corner(), corner(), 1600, 1200);
    }
    // A thin sliver across the whole screen.
    expectCoverageMatches(screenToClip(-3.3, 0.2, 0.5, 1600, 1200),
                          screenToClip(1603.1, 1197.7, 0.5, 1600, 1200),
                          screenToClip(1603.1, 1199.1, 0.5, 1600, 1200), 1600, 1200);
}

TEST(CpuRasterizer, DegenerateTrianglesDrawNothing) {
    const Clip a{0.1, 0.2, 0.5, 1}, b{0.4, -0.3, 0.5, 1};
    EXPECT_TRUE(rasterize(a, a, a, 8, 8).empty());
    EXPECT_TRUE(rasterize(a, b, a, 8, 8).empty());
    const Clip mid{0.25, -0.05, 0.5, 1}; // on the segment ab
    EXPECT_TRUE(rasterize(a, b, mid, 8, 8).empty());
    const double nan = std::nan("");
    EXPECT_TRUE(rasterize({nan, 0, 0.5, 1}, b, mid, 8, 8).empty());
    EXPECT_TRUE(rasterize({INFINITY, 0, 0.5, 1}, b, {0, 1, 0.5, 1}, 8, 8).empty());
    EXPECT_TRUE(rasterize({0, 0, 0.5, 0}, {1, 0, 0.5, 0}, {0, 1, 0.5, 0}, 8, 8).empty());
}

TEST(CpuRasterizer, BothWindingsCoverTheSamePixels) {
    std::mt19937 rng(4);
    std::uniform_real_distribution<double> coord(-1.5, 1.5);
    for (int i = 0; i < 100; ++i) {
        const Clip a{coord(rng), coord(rng), 0.5, 1}, b{coord(rng), coord(rng), 0.5, 1},
            c{coord(rng), coord(rng), 0.5, 1};
        const auto forward = rasterize(a, b, c, 20, 20), backward = rasterize(a, c, b, 20, 20);
        ASSERT_EQ(forward.size(), backward.size());
        for (std::size_t k = 0; k < forward.size(); ++k) {
            EXPECT_EQ(forward[k].px, backward[k].px);
            EXPECT_EQ(forward[k].py, backward[k].py);
        }
    }
}

// A grid of jittered quads, each split along a random diagonal with a random winding, reaching
// past every side of the screen: every pixel centre is hit exactly once.
TEST(CpuRasterizer, TiledGridCoversEveryPixelOnce) {
    std::mt19937 rng(5);
    for (const auto& [width, height] :
         std::array<std::array<uint32_t, 2>, 3>{{{1, 1}, {37, 23}, {160, 120}}}) {
        const int cells = 12;
        std::uniform_real_distribution<double> jitter(-0.3, 0.3);
        std::vector<Clip> grid;
        for (int j = 0; j <= cells; ++j)
            for (int i = 0; i <= cells; ++i) {
                const bool border_x = i == 0 || i == cells, border_y = j == 0 || j == cells;
                const double sx =
                    (i - 1.0) / (cells - 2) * width + (border_x ? 0 : jitter(rng) * width / cells);
                const double sy = (j - 1.0) / (cells - 2) * height +
                                  (border_y ? 0 : jitter(rng) * height / cells);
                grid.push_back(screenToClip(sx, sy, 0.5, width, height));
            }
        HitCounter counter{width, height};
        const auto at = [&](int i, int j) { return grid[std::size_t(j) * (cells + 1) + i]; };
        for (int j = 0; j < cells; ++j)
            for (int i = 0; i < cells; ++i) {
                const Clip p00 = at(i, j), p10 = at(i + 1, j), p01 = at(i, j + 1),
                           p11 = at(i + 1, j + 1);
                const bool flip = rng() & 1, diagonal = rng() & 1;
                const auto add = [&](const Clip& a, const Clip& b, const Clip& c) {
                    flip ? counter.add(a, c, b) : counter.add(a, b, c);
                };
                if (diagonal) {
                    add(p00, p10, p11);
                    add(p00, p11, p01);
                } else {
                    add(p00, p10, p01);
                    add(p10, p11, p01);
                }
            }
        for (std::size_t k = 0; k < counter.hits.size(); ++k)
            ASSERT_EQ(counter.hits[k], 1) << "pixel " << k % width << "," << k / width;
    }
}

// Fans around a centre vertex: one whose ring lies outside the screen (every pixel once), and
// one inside the screen (no pixel twice; pixels well inside once, well outside never).
TEST(CpuRasterizer, TriangleFansCoverEveryPixelOnce) {
    std::mt19937 rng(6);
    std::uniform_real_distribution<double> jitter(-0.2, 0.2);
    const uint32_t width = 97, height = 61;
    for (const double radius : {200.0, 25.0}) {
        const double cx = 48.3 + jitter(rng), cy = 30.7 + jitter(rng);
        const int spokes = 23;
        std::vector<std::array<double, 2>> ring;
        for (int k = 0; k < spokes; ++k) {
            const double angle = 2 * M_PI * (k + jitter(rng)) / spokes;
            ring.push_back({cx + radius * std::cos(angle), cy + radius * std::sin(angle)});
        }
        HitCounter counter{width, height};
        for (int k = 0; k < spokes; ++k) {
            const auto& p = ring[k];
            const auto& q = ring[(k + 1) % spokes];
            counter.add(screenToClip(cx, cy, 0.5, width, height),
                        screenToClip(p[0], p[1], 0.5, width, height),
                        screenToClip(q[0], q[1], 0.5, width, height));
        }
        for (uint32_t py = 0; py < height; ++py)
            for (uint32_t px = 0; px < width; ++px) {
                const int hits = counter.hits[std::size_t(py) * width + px];
                ASSERT_LE(hits, 1);
                // Signed distance of the centre to the (convex) ring polygon's edges.
                double inside = 1e300;
                for (int k = 0; k < spokes; ++k) {
                    const auto& p = ring[k];
                    const auto& q = ring[(k + 1) % spokes];
                    const double ex = q[0] - p[0], ey = q[1] - p[1];
                    const double dist =
                        (ex * (py + 0.5 - p[1]) - ey * (px + 0.5 - p[0])) / std::hypot(ex, ey);
                    inside = std::min(inside, dist);
                }
                if (inside > 1e-2) {
                    EXPECT_EQ(hits, 1) << px << "," << py;
                } else if (inside < -1e-2) {
                    EXPECT_EQ(hits, 0) << px << "," << py;
                }
            }
    }
}

// A tiled floor crossing the near plane under a perspective camera: shared edges must be clipped
// identically, so no pixel is hit twice, and every pixel the ray cast sees is hit once.
TEST(CpuRasterizer, TiledFloorCrossingNearPlaneIsWatertight) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> jitter(-0.3, 0.3);
    const uint32_t width = 80, height = 60;
    CameraSpec spec;
    spec.eye = {0, 0, 0};
    spec.target = {0.2, -0.1, -1};
    Bounds bounds;
    bounds.add({-1, -1, -4});
    bounds.add({1, 1, -2}); // near ~ 1.98: the floor under the camera is clipped by it
    const ViewProjection vp = frameCamera(spec, bounds, width, height);
    const int cells = 10;
    const double extent = 6.0, floor_y = -0.5;
    // Interior vertices jittered, the border kept on the square: the union is the square.
    std::vector<Vec3> grid;
    for (int j = 0; j <= cells; ++j)
        for (int i = 0; i <= cells; ++i) {
            const bool border = i == 0 || j == 0 || i == cells || j == cells;
            grid.push_back({(i + (border ? 0 : jitter(rng))) * 2 * extent / cells - extent, floor_y,
                            (j + (border ? 0 : jitter(rng))) * 2 * extent / cells - extent});
        }
    HitCounter counter{width, height};
    const auto at = [&](int a, int b) { return grid[std::size_t(b) * (cells + 1) + a]; };
    for (int j = 0; j < cells; ++j)
        for (int i = 0; i < cells; ++i) {
            counter.add(vp.toClip(at(i, j)), vp.toClip(at(i + 1, j)), vp.toClip(at(i + 1, j + 1)));
            counter.add(vp.toClip(at(i, j)), vp.toClip(at(i + 1, j + 1)), vp.toClip(at(i, j + 1)));
        }
    // The square as two triangles for the ray cast: their shared diagonal is no edge of the union,
    // so a pixel counts as certain when either triangle is certainly hit.
    const Vec3 c00{-extent, floor_y, -extent}, c10{extent, floor_y, -extent},
        c11{extent, floor_y, extent}, c01{-extent, floor_y, extent};
    int checked = 0, covered = 0;
    for (uint32_t py = 0; py < height; ++py)
        for (uint32_t px = 0; px < width; ++px) {
            const int hits = counter.hits[std::size_t(py) * width + px];
            ASSERT_LE(hits, 1) << px << "," << py;
            const std::optional<bool> a = castCoverage(vp, px, py, c00, c10, c11);
            const std::optional<bool> b = castCoverage(vp, px, py, c00, c11, c01);
            std::optional<bool> expected;
            if ((a && *a) || (b && *b))
                expected = true;
            else if (a && b)
                expected = false;
            if (!expected)
                continue;
            EXPECT_EQ(hits, int(*expected)) << px << "," << py;
            ++checked;
            covered += hits;
        }
    EXPECT_GT(checked, int(width * height) * 9 / 10);
    EXPECT_GT(covered, int(width * height) / 4);
}

// Triangles crossing the near plane, the screen edges and the guard band: coverage equals a ray
// cast of the unclipped triangle at pixel centres, away from the edges.
void expectCoverageMatchesRayCast(const ViewProjection& vp, const std::array<Vec3, 3>& t,
                                  int& covered_pixels) {
    std::vector<uint8_t> got(std::size_t(vp.width) * vp.height, 0);
    for (const Fragment& f :
         rasterize(vp.toClip(t[0]), vp.toClip(t[1]), vp.toClip(t[2]), vp.width, vp.height))
        ++got[std::size_t(f.py) * vp.width + f.px];
    for (uint32_t py = 0; py < vp.height; ++py)
        for (uint32_t px = 0; px < vp.width; ++px) {
            const int hits = got[std::size_t(py) * vp.width + px];
            ASSERT_LE(hits, 1);
            const std::optional<bool> expected = castCoverage(vp, px, py, t[0], t[1], t[2]);
            if (!expected)
                continue;
            ASSERT_EQ(hits, int(*expected)) << "pixel " << px << "," << py;
            covered_pixels += hits;
        }
}

TEST(CpuRasterizer, NearPlaneCrossingMatchesRayCast) {
    const uint32_t width = 64, height = 48;
    CameraSpec spec;
    spec.eye = {0, 0, 0};
    spec.target = {0, 0, -1};
    Bounds bounds;
    bounds.add({-1, -1, -4});
    bounds.add({1, 1, -2});
    const ViewProjection vp = frameCamera(spec, bounds, width, height);
    int covered = 0;
    // The camera stands over a big floor triangle whose corners are behind the eye and far away.
    expectCoverageMatchesRayCast(
        vp, {Vec3{-50, -0.5, 20}, Vec3{50, -0.5, 20}, Vec3{0.3, -0.4, -60}}, covered);
    EXPECT_GT(covered, int(width * height) / 4);
    // A wall the eye is inside of the plane of, tilted so that it crosses the near plane on screen.
    expectCoverageMatchesRayCast(vp, {Vec3{-0.6, -3, 1}, Vec3{0.5, 3, 2}, Vec3{0.4, -0.2, -9}},
                                 covered);
    // A triangle entirely behind the eye draws nothing.
    int behind = 0;
    expectCoverageMatchesRayCast(vp, {Vec3{-1, -1, 1}, Vec3{1, -1, 1}, Vec3{0, 1, 1}}, behind);
    EXPECT_EQ(behind, 0);
}

TEST(CpuRasterizer, ScreenEdgesAndGuardBandMatchRayCast) {
    std::mt19937 rng(8);
    for (Projection projection : {Projection::perspective, Projection::orthographic}) {
        const ViewProjection vp = makeView(projection, 41, 29);
        int covered = 0;
        // Crossing the screen edges.
        std::uniform_real_distribution<double> wide(-3.0, 3.0), depth(-1.0, 1.0);
        for (int i = 0; i < 20; ++i) {
            const auto corner = [&] { return Vec3{wide(rng), wide(rng), depth(rng)}; };
            expectCoverageMatchesRayCast(vp, {corner(), corner(), corner()}, covered);
        }
        // Huge triangles, far beyond the guard band, still in the view volume's depth range.
        std::uniform_real_distribution<double> huge(-1e5, 1e5);
        for (int i = 0; i < 10; ++i) {
            const auto corner = [&] { return Vec3{huge(rng), huge(rng), depth(rng)}; };
            expectCoverageMatchesRayCast(vp, {corner(), corner(), corner()}, covered);
        }
        EXPECT_GT(covered, 1000);
    }
}

// Depth at each fragment vs the depth of the point where the pixel's ray meets the triangle's
// plane, in double.
TEST(CpuRasterizer, DepthMatchesRayPlaneIntersection) {
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> coord(-1.0, 1.0);
    for (Projection projection : {Projection::perspective, Projection::orthographic}) {
        const ViewProjection vp = makeView(projection, 48, 40);
        std::size_t fragments = 0;
        for (int i = 0; i < 200; ++i) {
            const Vec3 p0{coord(rng), coord(rng), coord(rng)},
                p1{coord(rng), coord(rng), coord(rng)}, p2{coord(rng), coord(rng), coord(rng)};
            const Vec3 e1{p1.x - p0.x, p1.y - p0.y, p1.z - p0.z},
                e2{p2.x - p0.x, p2.y - p0.y, p2.z - p0.z};
            const Vec3 n{e1.y * e2.z - e1.z * e2.y, e1.z * e2.x - e1.x * e2.z,
                         e1.x * e2.y - e1.y * e2.x};
            for (const Fragment& f :
                 rasterize(vp.toClip(p0), vp.toClip(p1), vp.toClip(p2), vp.width, vp.height)) {
                Vec3 origin, dir;
                vp.pixelRay(f.px + 0.5, f.py + 0.5, origin, dir);
                const double denom = n.x * dir.x + n.y * dir.y + n.z * dir.z;
                // Nearly edge-on triangles: depth varies too fast across a pixel to compare.
                if (std::abs(denom) < 1e-3 * std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z))
                    continue;
                const double t =
                    (n.x * (p0.x - origin.x) + n.y * (p0.y - origin.y) + n.z * (p0.z - origin.z)) /
                    denom;
                const double expected =
                    vp.depthOf({origin.x + t * dir.x, origin.y + t * dir.y, origin.z + t * dir.z});
                ASSERT_NEAR(f.depth, expected, 1e-6 * std::abs(expected)) << f.px << "," << f.py;
                ++fragments;
            }
        }
        EXPECT_GT(fragments, 5000u);
    }
}

TEST(CpuRasterizer, VisitCanStopEarly) {
    int visits = 0;
    const bool stopped =
        detail::rasterizeTriangle({-1, -1, 0.5, 1}, {3, -1, 0.5, 1}, {-1, 3, 0.5, 1}, 10, 10,
                                  [&](uint32_t, uint32_t, float) { return ++visits == 5; });
    EXPECT_TRUE(stopped);
    EXPECT_EQ(visits, 5);
}

// snapToFixed is llround(v * 256) done inline: the same integers on halves (both signs), values
// next to halves, zero, the limits and random values over the whole allowed range.
TEST(CpuRasterizer, SnapToFixedRoundsLikeLlround) {
    const double limit = double(detail::kMaxSnapped) / double(detail::kSubpixelScale);
    std::vector<double> values = {0.0,        -0.0,      limit,      -limit,       1.0 / 512,
                                  -1.0 / 512, 3.0 / 512, -3.0 / 512, 1000.5 / 256, -1000.5 / 256};
    for (double half : {0.5, 1.5, 2.5, 12345.5, -0.5, -1.5, -2.5, -12345.5}) {
        const double v = half / 256;
        values.insert(values.end(), {v, std::nextafter(v, 0.0), std::nextafter(v, 2 * v)});
    }
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> any(-limit, limit), small(-4, 4);
    for (int i = 0; i < 100000; ++i)
        values.push_back(i % 2 ? any(rng) : small(rng));
    for (double v : values)
        ASSERT_EQ(detail::snapToFixed(v), std::llround(v * double(detail::kSubpixelScale))) << v;
}

} // namespace
} // namespace vissort
