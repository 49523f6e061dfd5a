// The OpenGL oracle on touching and coplanar faces at grazing views (tests/order's
// touching_faces_tests.cpp does the CPU oracles). Under depth tolerance 0 such faces meet at
// exactly equal depths, ties that the exact model never counts as behind but that gl, bounding
// depths in float, counts both ways: its cycles may be larger than the exact ones, never miss
// one (each exact cycle lies inside a gl cycle), and its order has no exact occlusion backwards
// outside a cycle. How many cycles the ties add is reported. With a positive tolerance the old
// rule holds: the slope-scaled polygon offset keeps touching faces from counting as behind
// each other, so the cycles are the exact occlusion graph's strongly connected components.

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "gl_test_support.h"
#include "ground_truth.h"
#include "tarjan_scc.h"
#include "touching_models.h"
#include "vissort/oracles.h"
#include "vissort/scene_orderer.h"

namespace vissort {
namespace {

// The views in which the exact occlusion graph has a cycle, and those where gl reports a cycle
// that contains no exact one (ties made it).
struct CycleCounts {
    int exact = 0, tie_made = 0;
};

CycleCounts expectGlCyclesContainTheExactOnes(const std::string& name, const test::Model& m,
                                              float tolerance = kDepthTolerance) {
    Result<std::unique_ptr<GeometryOracle>> oracle = makeOracle(OracleKind::gl);
    if (!oracle) {
        ADD_FAILURE() << oracle.error;
        return {};
    }
    (*oracle.value)->setDepthTolerance(tolerance);
    CycleCounts counts;
    for (const test::View& v : test::grazingViews()) {
        SCOPED_TRACE(name + " " + v.name);
        const ViewProjection view = frameCamera(v.camera, m.positions.bounds(), 256, 192);
        const auto truth =
            test::cyclicComponents(test::occlusionGraph(m.positions, view, m.objects));
        counts.exact += truth.empty() ? 0 : 1;
        SceneOrderer orderer(m.objects, uint32_t(m.positions.triangleCount()), OrderLevel::object,
                             **oracle.value);
        const FrameOrder frame = orderer.orderFrame(m.positions, view);
        if (tolerance > 0) {
            EXPECT_EQ(frame.cycles, truth);
        } else {
            EXPECT_TRUE(test::cyclesContained(truth, frame.cycles));
            for (const auto& cycle : frame.cycles)
                counts.tie_made += test::cyclesContained({cycle}, truth) ? 0 : 1;
        }
        EXPECT_EQ(
            test::checkVisibilityOrder(m.positions, view, m.objects, frame.order, frame.cycles)
                .violation_count,
            0u);
    }
    std::printf("[ cycles   ] %s, tolerance %g: %d views with exact cycles, %d gl cycles made by "
                "ties, over %zu views\n",
                name.c_str(), double(tolerance), counts.exact, counts.tie_made,
                test::grazingViews().size());
    return counts;
}

TEST(GlTouchingFaces, CyclesContainTheExactOnes) {
    for (const auto& [name, model] : {std::pair{"box grid", test::boxGrid()},
                                      {"house", test::house()},
                                      {"coplanar quads", test::coplanarQuads()}}) {
        const CycleCounts counts = expectGlCyclesContainTheExactOnes(name, model);
        EXPECT_EQ(counts.exact, 0) << name << ": the exact model has no cycle here";
    }
}

TEST(GlTouchingFaces, TrueCyclesStillFound) {
    EXPECT_GE(expectGlCyclesContainTheExactOnes("stick ring", test::stickRing()).exact, 1);
}

// The approximate rule of a positive tolerance, unchanged: no cycle from touching faces.
TEST(GlTouchingFaces, APositiveToleranceMakesNoCycleOfTouchingFaces) {
    constexpr float kPositive = 1.0f / (1 << 20);
    EXPECT_EQ(expectGlCyclesContainTheExactOnes("box grid", test::boxGrid(), kPositive).exact, 0);
    EXPECT_EQ(expectGlCyclesContainTheExactOnes("house", test::house(), kPositive).exact, 0);
    EXPECT_EQ(
        expectGlCyclesContainTheExactOnes("coplanar quads", test::coplanarQuads(), kPositive).exact,
        0);
    EXPECT_GE(expectGlCyclesContainTheExactOnes("stick ring", test::stickRing(), kPositive).exact,
              1);
}

} // namespace
} // namespace vissort
