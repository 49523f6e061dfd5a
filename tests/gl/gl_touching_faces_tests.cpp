// The OpenGL oracle on touching and coplanar faces at grazing views (tests/order's
// touching_faces_tests.cpp does the CPU oracles): its slope-scaled polygon offset keeps such
// faces from counting as behind each other, so its cycles are the ray-cast occlusion graph's
// strongly connected components, and true cycles are still found.

#include <gtest/gtest.h>

#include <string>

#include "ground_truth.h"
#include "tarjan_scc.h"
#include "touching_models.h"
#include "vissort/oracles.h"
#include "vissort/scene_orderer.h"

namespace vissort {
namespace {

int expectGlCyclesAreTrue(const std::string& name, const test::Model& m) {
    Result<std::unique_ptr<GeometryOracle>> oracle = makeOracle(OracleKind::gl);
    if (!oracle) {
        ADD_FAILURE() << oracle.error;
        return 0;
    }
    int cyclic = 0;
    for (const test::View& v : test::grazingViews()) {
        SCOPED_TRACE(name + " " + v.name);
        const ViewProjection view = frameCamera(v.camera, m.positions.bounds(), 256, 192);
        const auto truth =
            test::cyclicComponents(test::occlusionGraph(m.positions, view, m.objects));
        cyclic += truth.empty() ? 0 : 1;
        SceneOrderer orderer(m.objects, uint32_t(m.positions.triangleCount()), OrderLevel::object,
                             **oracle.value);
        const FrameOrder frame = orderer.orderFrame(m.positions, view);
        EXPECT_EQ(frame.cycles, truth);
        EXPECT_EQ(
            test::checkVisibilityOrder(m.positions, view, m.objects, frame.order, frame.cycles)
                .violation_count,
            0u);
    }
    return cyclic;
}

TEST(GlTouchingFaces, BoxesWallsAndCoplanarFacesMakeNoCycle) {
    EXPECT_EQ(expectGlCyclesAreTrue("box grid", test::boxGrid()), 0);
    EXPECT_EQ(expectGlCyclesAreTrue("house", test::house()), 0);
    EXPECT_EQ(expectGlCyclesAreTrue("coplanar quads", test::coplanarQuads()), 0);
}

TEST(GlTouchingFaces, TrueCyclesStillFound) {
    EXPECT_GE(expectGlCyclesAreTrue("stick ring", test::stickRing()), 1);
}

} // namespace
} // namespace vissort
