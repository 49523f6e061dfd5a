// The `pile` scene (samples/scenes/pile_scene.cpp) against its specification in
// docs/builtin-scenes.md: parameters and errors, closed bodies, frames a pure function of t,
// seeds, rigid and deforming bodies, settling, contacts, the box it stays in and its camera.

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "reference_triangles.h"
#include "scene_checks.h"
#include "scenes/scene_library.h"
#include "solid_checks.h"

namespace vissort {
namespace {

// From the specification (docs/builtin-scenes.md), not from the generator.
constexpr std::size_t kTrianglesPerBody = 256; // 16 segments, 8 rings and two pole fans
constexpr std::size_t kCornersPerBody = 3 * kTrianglesPerBody;
constexpr double kSpacing = 0.8, kJitter = 0.12, kMaxReach = 0.648; // 0.6 radius, 8% wave
constexpr double kFrame = 1.0 / 30;
constexpr double kFloatSlack = 1e-4; // positions are floats of magnitude < 100

Scene makePile(const std::string& n, const std::string& seed = "1") {
    return test::makeCountedScene("pile", n, seed);
}

using test::frameAt;

/// The mean of a body's corners: for a rigid body a point fixed in it, so it moves as the body.
Vec3 centroidOf(const TrianglePositions& positions, std::size_t body) {
    Vec3 sum{0, 0, 0};
    for (std::size_t k = body * kCornersPerBody; k < (body + 1) * kCornersPerBody; ++k)
        sum = sum + positions.corner(k);
    return sum * (1.0 / kCornersPerBody);
}

/// The largest change of one of a body's edge lengths between two frames: zero (up to float
/// rounding) for a rigidly moved body.
double largestEdgeChange(const TrianglePositions& a, const TrianglePositions& b, std::size_t body) {
    double largest = 0;
    for (std::size_t k = body * kCornersPerBody; k < (body + 1) * kCornersPerBody; ++k) {
        const std::size_t next = k - k % 3 + (k + 1) % 3; // the next corner of the triangle
        largest = std::max(largest, std::abs(length(a.corner(next) - a.corner(k)) -
                                             length(b.corner(next) - b.corner(k))));
    }
    return largest;
}

Bounds bodyBounds(const TrianglePositions& positions, std::size_t body) {
    Bounds bounds{{1e30, 1e30, 1e30}, {-1e30, -1e30, -1e30}};
    for (std::size_t k = body * kCornersPerBody; k < (body + 1) * kCornersPerBody; ++k) {
        const Vec3 p = positions.corner(k);
        bounds.min = {std::min(bounds.min.x, p.x), std::min(bounds.min.y, p.y),
                      std::min(bounds.min.z, p.z)};
        bounds.max = {std::max(bounds.max.x, p.x), std::max(bounds.max.y, p.y),
                      std::max(bounds.max.z, p.z)};
    }
    return bounds;
}

bool boxesOverlap(const Bounds& a, const Bounds& b) {
    return a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y && b.min.y <= a.max.y &&
           a.min.z <= b.max.z && b.min.z <= a.max.z;
}

TEST(PileScene, DefaultsCountsAndNames) {
    const Result<Scene> defaults = samples::makeBuiltinScene("pile", {});
    ASSERT_TRUE(defaults) << defaults.error;
    const Scene& scene = *defaults.value;
    EXPECT_EQ(scene.name, "builtin:pile");
    EXPECT_TRUE(scene.isDynamic());
    test::expectNumberedObjects(scene, "body_", 1000, kTrianglesPerBody, 0.5f);
    TrianglePositions resized; // positionsAt sizes its output
    resized.resize(5);
    scene.animation->positionsAt(1.0, resized);
    EXPECT_EQ(resized.triangleCount(), 1000 * kTrianglesPerBody);

    EXPECT_EQ(makePile("1").triangleCount(), kTrianglesPerBody);
}

TEST(PileScene, ParameterErrorsAreOneLine) {
    const test::ParameterErrorCase cases[] = {
        {{{"n", "0"}}, "builtin:pile: parameter n=0 is out of range (allowed 1 to 100000)"},
        {{{"n", "100001"}}, "parameter n=100001 is out of range"},
        {{{"n", "many"}}, "parameter n='many' is not an integer"},
        {{{"seed", "-1"}}, "parameter seed='-1' is not a non-negative integer"},
        {{{"layers", "3"}}, "builtin:pile: unknown parameter 'layers' (accepted: n, seed)"},
        // 10,000,000 / 256 = 39062.5 bodies.
        {{{"n", "39063"}},
         "builtin:pile: parameter n=39063 gives 10000128 triangles, more than the limit of "
         "10000000"},
        {{{"n", "100000"}}, "parameter n=100000 gives 25600000 triangles"},
    };
    test::expectParameterErrors("pile", cases);
}

TEST(PileScene, EveryBodyIsClosedAndWoundOutwards) {
    const Scene scene = makePile("90", "3");
    Scene later = scene; // the blobs' deformation must keep them closed too
    later.positions = frameAt(scene, 2.7);
    for (const Scene* frame : std::array<const Scene*, 2>{&scene, &later})
        for (const SceneObject& object : frame->objects) {
            const test::MeshCheck mesh = test::checkMesh(*frame, object);
            EXPECT_EQ(mesh.unmatched_edges, 0u) << object.name;
            EXPECT_GT(mesh.smallest_area, 1e-4) << object.name;
            EXPECT_GT(mesh.volume, 0.0) << object.name << ": wound inwards";
        }
}

TEST(PileScene, FramesArePureFunctionsOfTime) {
    const Scene scene = makePile("40", "9");
    const TrianglePositions zero = frameAt(scene, 0);
    EXPECT_EQ(zero.x, scene.positions.x);
    EXPECT_EQ(zero.y, scene.positions.y);
    EXPECT_EQ(zero.z, scene.positions.z);
    const TrianglePositions first = frameAt(scene, 2.5);
    frameAt(scene, 0.4);
    TrianglePositions again = frameAt(scene, 9.0);
    scene.animation->positionsAt(2.5, again); // reusing a buffer holding another frame
    EXPECT_EQ(first.x, again.x);
    EXPECT_EQ(first.y, again.y);
    EXPECT_EQ(first.z, again.z);
    EXPECT_NE(first.y, zero.y);
}

TEST(PileScene, SameSeedSameSceneOtherSeedOtherScene) {
    const Scene a = makePile("50", "4"), b = makePile("50", "4"), c = makePile("50", "5");
    test::expectSameScene(a, b);
    EXPECT_EQ(frameAt(a, 1.7).x, frameAt(b, 1.7).x);
    EXPECT_NE(a.positions.x, c.positions.x);
    EXPECT_NE(frameAt(a, 1.7).y, frameAt(c, 1.7).y);
}

// A body is rigid (all its edges keep their lengths) or deforms visibly, and a third or so are
// blobs. The blobs still deform long after the pile has settled.
TEST(PileScene, AboutAThirdOfTheBodiesDeformForever) {
    const std::size_t n = 300;
    const Scene scene = makePile(std::to_string(n), "2");
    const TrianglePositions a = frameAt(scene, 5.0), b = frameAt(scene, 5.3);
    const TrianglePositions late_a = frameAt(scene, 100.0), late_b = frameAt(scene, 100.3);
    std::size_t deforming = 0;
    for (std::size_t body = 0; body < n; ++body) {
        const double change = largestEdgeChange(a, b, body);
        const bool deforms = change > 1e-3;
        EXPECT_TRUE(deforms || change < kFloatSlack) << "body " << body << ": " << change;
        deforming += deforms;
        if (deforms) {
            EXPECT_GT(largestEdgeChange(late_a, late_b, body), 1e-3) << "body " << body;
        } else {
            EXPECT_LT(largestEdgeChange(late_a, late_b, body), kFloatSlack) << "body " << body;
        }
    }
    EXPECT_GT(deforming, n / 5);
    EXPECT_LT(deforming, n / 2);
}

// Early frames move a lot, settled ones little: the rigid bodies' centroids move much less over
// a frame at t = 5 than over the first frame.
TEST(PileScene, BodiesSettle) {
    const std::size_t n = 200;
    const Scene scene = makePile(std::to_string(n), "6");
    const TrianglePositions start = frameAt(scene, 0), start_next = frameAt(scene, kFrame);
    const TrianglePositions late = frameAt(scene, 5), late_next = frameAt(scene, 5 + kFrame);
    const TrianglePositions probe = frameAt(scene, 5.3);
    double early_motion = 0, late_motion = 0;
    std::size_t rigid = 0;
    for (std::size_t body = 0; body < n; ++body) {
        if (largestEdgeChange(late, probe, body) > kFloatSlack)
            continue; // a blob: its centroid moves with its deformation
        ++rigid;
        early_motion += length(centroidOf(start_next, body) - centroidOf(start, body));
        late_motion += length(centroidOf(late_next, body) - centroidOf(late, body));
    }
    ASSERT_GT(rigid, n / 2);
    early_motion /= double(rigid);
    late_motion /= double(rigid);
    EXPECT_GT(early_motion, 0.02); // the fall, about 0.03 of a drop of 1.5 or more
    EXPECT_LT(late_motion, early_motion / 5);
    EXPECT_GT(late_motion, 0.0); // still bouncing a little
}

// Settled, the bodies touch their neighbours: more overlapping bounding boxes than bodies, and
// some meshes that truly intersect. All of it above the floor y = 0 and inside the footprint at
// every time; the pile starts high and comes down.
TEST(PileScene, ASettledPileHasContactsInsideItsBox) {
    const std::size_t n = 64; // 6 x 6 columns (1.4 cbrt 64 = 5.6), two layers
    const Scene scene = makePile(std::to_string(n));
    const TrianglePositions settled = frameAt(scene, 10);
    std::vector<Bounds> boxes;
    for (std::size_t body = 0; body < n; ++body)
        boxes.push_back(bodyBounds(settled, body));
    std::size_t overlapping = 0, intersecting = 0;
    for (std::size_t a = 0; a < n; ++a)
        for (std::size_t b = a + 1; b < n; ++b) {
            if (!boxesOverlap(boxes[a], boxes[b]))
                continue;
            ++overlapping;
            bool meet = false;
            for (std::size_t i = a * kCornersPerBody; i < (a + 1) * kCornersPerBody && !meet;
                 i += 3) {
                const std::array<Vec3, 3> ta = {settled.corner(i), settled.corner(i + 1),
                                                settled.corner(i + 2)};
                for (std::size_t j = b * kCornersPerBody; j < (b + 1) * kCornersPerBody && !meet;
                     j += 3)
                    meet = test::closedTrianglesMeet(
                        ta, {settled.corner(j), settled.corner(j + 1), settled.corner(j + 2)});
            }
            intersecting += meet;
        }
    EXPECT_GE(overlapping, n);
    EXPECT_GE(intersecting, n / 2); // at least one contact a body
    EXPECT_LE(intersecting, 4 * n); // a loose pile: at most 8 contacts a body

    // The footprint: columns 0.8 apart, jittered by 0.12, and the largest bounding sphere.
    const double half_footprint = 2.5 * kSpacing + kJitter + kMaxReach;
    // Two layers resting, plus what is left of a drop of at most 3 after 10 s (e^(-10/1.5)).
    const double settled_top = 2 * kMaxReach + kSpacing + kJitter + 3 * std::exp(-10 / 1.5);
    double start_top = 0;
    for (const double t : {0.0, 0.3, 1.0, 2.2, 10.0, 60.0}) {
        const Bounds bounds = frameAt(scene, t).bounds();
        EXPECT_GE(bounds.min.y, -kFloatSlack) << "through the floor at t " << t;
        for (const double c : {bounds.min.x, bounds.max.x, bounds.min.z, bounds.max.z})
            EXPECT_LE(std::abs(c), half_footprint + kFloatSlack) << "t " << t;
        if (t == 0)
            start_top = bounds.max.y;
        if (t >= 10) {
            EXPECT_LT(bounds.min.y, 0.1) << "t " << t; // the bottom layer rests on the floor
            EXPECT_LE(bounds.max.y, settled_top + kFloatSlack) << "t " << t;
        }
    }
    EXPECT_GT(start_top, settled_top + 1);
}

// The default camera frames the whole fall: every corner of every frame of the first 10 s is in
// the picture, which the pile at its start fills.
TEST(PileScene, DefaultCameraSeesTheWholeFall) {
    const Scene scene = makePile("30", "7");
    ASSERT_TRUE(scene.camera.has_value());
    const ViewProjection view = frameCamera(*scene.camera, scene.positions.bounds(), 512, 512);
    double widest = 0;
    TrianglePositions positions;
    for (int frame = 0; frame < 300; frame += 5) {
        scene.frame(frame * kFrame, positions);
        for (std::size_t i = 0; i < positions.x.size(); ++i) {
            const auto clip = view.toClip(positions.view().corner(i));
            ASSERT_GT(clip[3], 0.0);
            const double extent = std::max(std::abs(clip[0]), std::abs(clip[1])) / clip[3];
            ASSERT_LE(extent, 1.0) << "frame " << frame << " corner " << i;
            widest = std::max(widest, extent);
        }
    }
    EXPECT_GT(widest, 0.7);
}

} // namespace
} // namespace vissort
