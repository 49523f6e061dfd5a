// Touching and coplanar faces, as architecture and CAD models are full of (boxes sharing a face,
// walls standing on a slab, faces lying on faces), seen at grazing angles in both projections.
// The rasterizing oracles must never count such faces as behind each other (docs/robustness.md,
// "The exact model"): their cycles equal the strongly connected components of the exact
// occlusion graph, and equal the exact oracle's, and the order has no ground-truth violation.
// Surfaces truly apart by more than the documented bound must still count.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "ground_truth.h"
#include "tarjan_scc.h"
#include "touching_models.h"
#include "vissort/cpu_reference_oracle.h"
#include "vissort/oracles.h"
#include "vissort/scene_orderer.h"

namespace vissort {
namespace {

using test::Model;
using test::View;

FrameOrder orderWith(OracleKind kind, const Model& m, const ViewProjection& view) {
    Result<std::unique_ptr<GeometryOracle>> oracle = makeOracle(kind);
    EXPECT_TRUE(oracle) << oracle.error;
    SceneOrderer orderer(m.objects, uint32_t(m.positions.triangleCount()), OrderLevel::object,
                         **oracle.value);
    return orderer.orderFrame(m.positions, view);
}

// Orders m at object level with every oracle, over every view at two sizes: each oracle's
// cycles equal the ray-cast occlusion graph's cyclic components (and so each other's), with no
// ground-truth violation. Returns in how many cases the graph had a cycle.
int expectTrueCycles(const std::string& name, const Model& m) {
    int cyclic = 0;
    for (const View& v : test::grazingViews())
        for (uint32_t size : {64u, 256u}) {
            SCOPED_TRACE(name + " " + v.name + " " + std::to_string(size));
            const ViewProjection view =
                frameCamera(v.camera, m.positions.bounds(), size, size * 3 / 4);
            const auto truth =
                test::cyclicComponents(test::occlusionGraph(m.positions, view, m.objects));
            cyclic += truth.empty() ? 0 : 1;
            for (OracleKind kind :
                 {OracleKind::cpu, OracleKind::cpu_reference, OracleKind::exact}) {
                SCOPED_TRACE(oracleName(kind));
                const FrameOrder frame = orderWith(kind, m, view);
                EXPECT_EQ(frame.cycles, truth);
                const test::OrderCheck check = test::checkVisibilityOrder(
                    m.positions, view, m.objects, frame.order, frame.cycles);
                EXPECT_TRUE(check.valid_permutation);
                EXPECT_EQ(check.violation_count, 0u);
            }
        }
    return cyclic;
}

TEST(TouchingFaces, BoxesSharingFacesMakeNoCycle) {
    EXPECT_EQ(expectTrueCycles("box grid", test::boxGrid()), 0);
}

TEST(TouchingFaces, WallsOnASlabMakeNoCycle) {
    EXPECT_EQ(expectTrueCycles("house", test::house()), 0);
}

TEST(TouchingFaces, CoplanarFacesMakeNoCycle) {
    EXPECT_EQ(expectTrueCycles("coplanar quads", test::coplanarQuads()), 0);
}

TEST(TouchingFaces, TrueCyclesStillFound) {
    // Seen from above the ring is a cycle; from the side it need not be.
    EXPECT_GE(expectTrueCycles("stick ring", test::stickRing()), 2);
}

// The bound: a steep quad (seen almost edge-on) over a parallel one. At a gap of zero, or below
// the tolerance, neither is behind the other; at a gap beyond the tolerance plus both quads'
// snap slack the far one is behind, with each rasterizing oracle.
TEST(TouchingFaces, ParallelFacesApartByMoreThanTheBoundAreBehind) {
    for (Projection projection : {Projection::orthographic, Projection::perspective}) {
        const auto scene = [](double gap) {
            Model m;
            test::addFloorQuad(m, -1, -1, 1, 1, 0);
            test::addFloorQuad(m, -0.8, -0.8, 0.8, 0.8, -gap); // below, seen from above: behind
            return m;
        };
        CameraSpec camera;
        camera.projection = projection;
        camera.ortho_direction = {0.05, -0.2, -1}; // grazing: the quads are steep in depth
        camera.eye = {0.1, 0.45, 3};
        camera.target = {0, 0, 0};
        const ViewProjection view = frameCamera(camera, scene(0).positions.bounds(), 200, 150);
        // The slopes of the planes (equal for both quads), from the depths of corners.
        const double per_pixel = std::abs(view.depthOf({0, 0, -1}) - view.depthOf({0, 0, 1})) /
                                 150.0 * 4; // a generous over-estimate of |ddx| + |ddy|
        const double bound = kDepthTolerance + 2 * per_pixel / 256 + 1e-6;
        for (const double gap_in_depth : {0.0, 0.4 * double(kDepthTolerance), 3 * bound}) {
            // The gap in world units that gives this gap in depth at the centre.
            const double dd = view.depthOf({0, -0.01, 0}) - view.depthOf({0, 0, 0});
            const double gap = gap_in_depth * 0.01 / dd;
            const Model m = scene(gap);
            {
                CpuReferenceOracle reference;
                reference.bind(m.positions, view, m.objects);
                reference.draw(0);
                Result<std::unique_ptr<GeometryOracle>> fast = makeOracle(OracleKind::cpu);
                ASSERT_TRUE(fast);
                (*fast.value)->bind(m.positions, view, m.objects);
                (*fast.value)->draw(0);
                const bool behind = gap_in_depth > bound;
                SCOPED_TRACE("gap in depth " + std::to_string(gap_in_depth));
                EXPECT_EQ(reference.anyBehind(1), behind);
                EXPECT_EQ((*fast.value)->anyBehind(1), behind);
            }
        }
    }
}

} // namespace
} // namespace vissort
