// The OpenGL oracle under depth tolerance 0 against the exact oracle (the exact fragment model,
// exact_oracle.h): gl decides with error bounds and counts what it cannot decide as behind, so
// every exact "behind" must be a gl "behind". Checked on random interleavings of clear, draw and
// anyBehind and on the pass-level batches, over random soups (one seen from inside, crossing the
// near plane and the screen's edges), slabs, shared-edge grids and bunnies, both projections,
// several viewport sizes; the extra gl answers are counted and must stay rare (at most 0.2% of
// the exact "not behind" answers) on these scenes, which have no touching faces: only mesh
// neighbours, whose shared edges tie where they pass exactly through a pixel centre. Then a
// grazing edge: gl must decide a pixel centre 1e-6 and 1e-9 pixel inside (and outside) a triangle
// as the model does; and a near tie: a triangle one float step behind another must be behind for
// gl too.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "geometry/pixel_rays.h"
#include "gl_test_support.h"
#include "test_scene_loading.h"

namespace vissort {
namespace {

using test::Tally;

struct Case {
    Projection projection;
    uint32_t width, height;
};

std::string caseName(const ::testing::TestParamInfo<Case>& info) {
    return std::string(info.param.projection == Projection::perspective ? "Perspective" : "Ortho") +
           std::to_string(info.param.width) + "x" + std::to_string(info.param.height);
}

class GlContainsExact : public ::testing::TestWithParam<Case> {
protected:
    // Interleavings and passes over one binding, tallied into total.
    void compare(const TrianglePositions& p, const ViewProjection& view,
                 std::span<const PrimitiveRange> primitives, uint32_t seed, int operations,
                 int rounds) {
        ExactOracle exact(1);
        GlOracle gl(test::glContext());
        exact.bind(p, view, primitives);
        gl.bind(p, view, primitives);
        test::interleave(exact, gl, seed, operations, total_);
        test::comparePasses(exact, gl, seed + 1000, rounds, total_);
    }

    // Reports the tally and checks it: nothing missed, the extra answers at most max_rate of the
    // exact "not behind" ones, and both answers exercised where there are pixels enough.
    void report(const char* what, double max_rate) {
        const Case c = GetParam();
        std::printf("[ rates    ] %s, %s %ux%u: %s\n", what,
                    c.projection == Projection::perspective ? "perspective" : "orthographic",
                    c.width, c.height, total_.describe().c_str());
        RecordProperty("extra_behind", std::to_string(total_.extra));
        RecordProperty("answers", std::to_string(total_.answers));
        EXPECT_EQ(total_.missed, 0u) << total_.describe();
        EXPECT_LE(total_.extraRate(), max_rate) << total_.describe();
        if (c.width * c.height >= 17 * 13) {
            EXPECT_GT(total_.exact_behind, 0u) << "never behind: a weak test";
        }
    }

    Tally total_;
};

TEST_P(GlContainsExact, RandomSoups) {
    const Case c = GetParam();
    for (uint32_t seed = 1; seed <= 3; ++seed) {
        const TrianglePositions p = test::randomSoup(seed, 150, 0.02, 0.6);
        const ViewProjection view = test::obliqueView(p.bounds(), c.projection, c.width, c.height);
        compare(p, view, test::eachTriangle(p), seed, 800, 3);
    }
    report("random soups", 0.002);
}

// The eye inside the soup: many triangles cross the near plane or lie behind the eye (covered by
// the box of their part beyond half the near distance, or the whole viewport), many reach past
// the screen's edges.
TEST_P(GlContainsExact, SoupSeenFromInside) {
    const Case c = GetParam();
    const TrianglePositions p = test::randomSoup(11, 240, 0.1, 1.0);
    std::vector<PrimitiveRange> primitives;
    for (uint32_t t = 0; t + 3 <= p.triangleCount(); t += 3)
        primitives.push_back({t, 3});
    const ViewProjection view =
        test::obliqueView(p.bounds(), c.projection, c.width, c.height, {0.1, 0.05, 0.2});
    compare(p, view, primitives, 5, 800, 3);
    report("soup seen from inside", 0.002);
}

TEST_P(GlContainsExact, SharedEdgeGridLayers) {
    const Case c = GetParam();
    const TrianglePositions p = test::sharedEdgeGrid(9, 3);
    std::vector<PrimitiveRange> per_layer;
    const uint32_t per = uint32_t(p.triangleCount() / 3);
    for (uint32_t l = 0; l < 3; ++l)
        per_layer.push_back({l * per, per});
    const ViewProjection view = test::obliqueView(p.bounds(), c.projection, c.width, c.height);
    compare(p, view, test::eachTriangle(p), 7, 1500, 3);
    compare(p, view, per_layer, 8, 200, 4);
    report("shared-edge grid", 0.002);
}

// At odd sizes each slab's diagonal, shared by its two triangles, runs through the centre
// pixel's centre: an exact tie there, behind for gl (measured 37 extra answers of 41,441 at 1x1
// and 17x13, none at 64x48).
TEST_P(GlContainsExact, SlabsAndBunnies) {
    const Case c = GetParam();
    for (const char* spec : {"builtin:slabs?layers=4", "builtin:bunnies?n=3&seed=2"}) {
        const Scene scene = test::loadTestScene(spec);
        const ViewProjection view = test::sceneView(scene, c.projection, c.width, c.height);
        compare(scene.positions, view, scene.objectPrimitives(), 21, 300, 4);
        compare(scene.positions, view, scene.trianglePrimitives(), 22, 1500, 2);
    }
    report("slabs and bunnies", 0.002);
}

INSTANTIATE_TEST_SUITE_P(ProjectionsAndSizes, GlContainsExact,
                         ::testing::Values(Case{Projection::perspective, 1, 1},
                                           Case{Projection::orthographic, 1, 1},
                                           Case{Projection::perspective, 17, 13},
                                           Case{Projection::orthographic, 17, 13},
                                           Case{Projection::perspective, 64, 48},
                                           Case{Projection::orthographic, 64, 48}),
                         caseName);

// A triangle whose vertical edge passes `offset` pixels to the right of the centre pixel's
// centre (negative: to its left), in front of (or behind) a small triangle that covers that pixel
// centre alone: the two overlap at that pixel at most. Corners near the origin keep the float
// corners as fine as the offset needs.
struct Grazing {
    TrianglePositions positions; // triangle 0: the grazing one, 1: the small one
    ViewProjection view;
};

Grazing grazingPair(Projection projection, double offset, bool grazing_in_front) {
    CameraSpec spec;
    spec.projection = projection;
    spec.eye = {0, 0, 5};
    spec.target = {0, 0, 0};
    spec.ortho_direction = {0, 0, -1};
    const Bounds bounds{{-1, -1, -1}, {1, 1, 1}};
    Grazing g;
    g.view = frameCamera(spec, bounds, 65, 65); // odd: the centre pixel's ray is the axis
    const detail::PixelRays rays(g.view);
    const auto hitAt = [](const detail::PixelRay& ray, double z) {
        const double t = (z - ray.origin.z) / ray.direction.z;
        return Vec3{ray.origin.x + t * ray.direction.x, ray.origin.y + t * ray.direction.y, z};
    };
    const double near_z = 0.2, far_z = -0.2;
    const double grazing_z = grazing_in_front ? near_z : far_z;
    const double small_z = grazing_in_front ? far_z : near_z;
    // Pixel sizes in world units at each plane, from the neighbouring pixel's ray.
    const Vec3 centre_g = hitAt(rays.centre(32, 32), grazing_z);
    const double size_g = hitAt(rays.centre(33, 32), grazing_z).x - centre_g.x;
    const Vec3 centre_s = hitAt(rays.centre(32, 32), small_z);
    const double size_s = hitAt(rays.centre(33, 32), small_z).x - centre_s.x;
    const auto add = [&](double x, double y, double z) {
        g.positions.x.push_back(float(x));
        g.positions.y.push_back(float(y));
        g.positions.z.push_back(float(z));
    };
    // The grazing triangle: everything left of x = centre + offset pixels, 20 pixels around.
    const double edge = centre_g.x + offset * size_g;
    add(edge, centre_g.y - 20 * size_g, grazing_z);
    add(edge, centre_g.y + 20 * size_g, grazing_z);
    add(centre_g.x - 20 * size_g, centre_g.y, grazing_z);
    // The small one: corners 0.4 pixel below-left of the centre, and 0.9 right or up: it covers
    // the centre, and no neighbour's (x + y <= 0.5 pixel).
    add(centre_s.x - 0.4 * size_s, centre_s.y - 0.4 * size_s, small_z);
    add(centre_s.x + 0.9 * size_s, centre_s.y - 0.4 * size_s, small_z);
    add(centre_s.x - 0.4 * size_s, centre_s.y + 0.9 * size_s, small_z);
    return g;
}

// Whether `queried` is behind `drawn` for the oracle, alone in the depth buffer.
bool behindAlone(GeometryOracle& oracle, const Grazing& g, uint32_t drawn, uint32_t queried) {
    const std::vector<PrimitiveRange> primitives{{0, 1}, {1, 1}};
    oracle.bind(g.positions, g.view, primitives);
    oracle.draw(drawn);
    return oracle.anyBehind(queried);
}

// A millionth and a billionth of a pixel inside and outside: gl must give the exact relation,
// both ways (its uncertainty is some 1e-13 pixel). On the edge (the centre's ray meeting the
// edge, as near as floats allow): whatever the model says, gl may only add "behind".
TEST(GlGrazingEdge, DecidedAsTheExactModelAMillionthOfAPixelFromTheEdge) {
    for (Projection projection : {Projection::perspective, Projection::orthographic})
        for (bool grazing_in_front : {true, false})
            for (double offset : {1e-6, 1e-9, 0.0, -1e-9, -1e-6}) {
                char trace[96];
                std::snprintf(trace, sizeof(trace), "%s, grazing %s, edge %g pixel",
                              projection == Projection::perspective ? "perspective"
                                                                    : "orthographic",
                              grazing_in_front ? "in front" : "behind", offset);
                SCOPED_TRACE(trace);
                const Grazing g = grazingPair(projection, offset, grazing_in_front);
                const uint32_t front = grazing_in_front ? 0 : 1, back = 1 - front;
                ExactOracle exact(1);
                GlOracle gl(test::glContext());
                // The construction: the pair overlaps at the centre pixel alone, and only when
                // the grazing edge passes right of its centre.
                const bool overlap = behindAlone(exact, g, front, back);
                if (offset != 0) {
                    ASSERT_EQ(overlap, offset > 0);
                }
                ASSERT_FALSE(behindAlone(exact, g, back, front));
                int pixels = 0;
                for (const ExactOracle::Fragment& f : exact.fragments(1))
                    pixels += f.pixel == 32 * 65 + 32 ? 1 : 100;
                ASSERT_EQ(pixels, 1) << "the small triangle covers the centre pixel alone";
                if (offset == 0) {
                    if (overlap) {
                        EXPECT_TRUE(behindAlone(gl, g, front, back));
                    }
                    continue;
                }
                EXPECT_EQ(behindAlone(gl, g, front, back), overlap);
                EXPECT_FALSE(behindAlone(gl, g, back, front));
            }
}

// Two copies of a triangle, the second moved one float step farther along the view: exactly
// behind the first everywhere they overlap, by a depth difference far below the float depth
// buffer's resolution. gl must still say behind (its depth bounds count such near ties both
// ways, so the reverse may be behind too).
TEST(GlNearTies, AFloatStepFartherIsBehind) {
    for (Projection projection : {Projection::perspective, Projection::orthographic}) {
        SCOPED_TRACE(projection == Projection::perspective ? "perspective" : "orthographic");
        CameraSpec spec;
        spec.projection = projection;
        spec.eye = {0.1, 0.2, 5};
        spec.target = {0, 0, 0};
        spec.ortho_direction = {0, 0, -1};
        const ViewProjection view = frameCamera(spec, {{-1, -1, -1}, {1, 1, 1}}, 48, 40);
        TrianglePositions p;
        for (float z : {0.25f, std::nextafter(0.25f, -1.0f)}) {
            const float xs[3] = {-0.6f, 0.7f, -0.2f}, ys[3] = {-0.5f, -0.3f, 0.8f};
            for (int k = 0; k < 3; ++k) {
                p.x.push_back(xs[k]);
                p.y.push_back(ys[k]);
                p.z.push_back(z + 0.1f * xs[k]); // tilted: depth varies across the pixels
            }
        }
        const std::vector<PrimitiveRange> primitives{{0, 1}, {1, 1}};
        ExactOracle exact(1);
        GlOracle gl(test::glContext());
        for (GeometryOracle* oracle :
             {static_cast<GeometryOracle*>(&exact), static_cast<GeometryOracle*>(&gl)}) {
            oracle->bind(p, view, primitives);
            oracle->draw(0);
        }
        ASSERT_TRUE(exact.anyBehind(1));
        EXPECT_TRUE(gl.anyBehind(1));
    }
}

} // namespace
} // namespace vissort
