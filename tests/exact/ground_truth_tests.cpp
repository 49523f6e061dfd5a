#include "ground_truth.h"

#include <cmath>
#include <numeric>

#include <gtest/gtest.h>

#include "tarjan_scc.h"
#include "test_scenes.h"

namespace vissort {
namespace {

using test::addQuad;
using test::addTriangle;
using test::checkVisibilityOrder;
using test::occlusionGraph;
using test::range;

using Graph = std::vector<std::vector<uint32_t>>;

TrianglePositions twoParallelQuads() {
    TrianglePositions positions;
    addQuad(positions, 1.0, 0.0);  // primitive 0, front
    addQuad(positions, 2.0, -1.0); // primitive 1, behind
    return positions;
}

const std::vector<PrimitiveRange> kTwoQuads = {range(0, 2), range(2, 2)};

// Three long sticks along the sides of a triangle, each high at its start and low at its end, so
// that at every corner the next stick lies over the previous one: 1 over 0, 2 over 1, 0 over 2.
TrianglePositions cyclicSticks() {
    TrianglePositions positions;
    const double pi = std::acos(-1.0);
    Vec3 corners[3];
    for (int i = 0; i < 3; ++i)
        corners[i] = {std::cos(pi / 2 + 2 * pi * i / 3), std::sin(pi / 2 + 2 * pi * i / 3), 0};
    for (int i = 0; i < 3; ++i) {
        const Vec3 a = corners[i], b = corners[(i + 1) % 3];
        const double length = std::hypot(b.x - a.x, b.y - a.y);
        const double dx = (b.x - a.x) / length, dy = (b.y - a.y) / length;
        const double nx = -dy * 0.1, ny = dx * 0.1;
        const Vec3 start{a.x - dx * 0.3, a.y - dy * 0.3, 1},
            end{b.x + dx * 0.3, b.y + dy * 0.3, -1};
        const Vec3 s0{start.x - nx, start.y - ny, 1}, s1{start.x + nx, start.y + ny, 1};
        const Vec3 e0{end.x - nx, end.y - ny, -1}, e1{end.x + nx, end.y + ny, -1};
        addTriangle(positions, s0, e0, e1);
        addTriangle(positions, s0, e1, s1);
    }
    return positions;
}

const std::vector<PrimitiveRange> kThreeSticks = {range(0, 2), range(2, 2), range(4, 2)};

ViewProjection topView(const TrianglePositions& positions) {
    return test::orthographicView(positions, {0, 0, -1}, 64, 64);
}

TEST(GroundTruth, CorrectOrderHasNoViolation) {
    const TrianglePositions positions = twoParallelQuads();
    const ViewProjection view = test::perspectiveView(positions, {0, 0, 5}, 32, 32);
    const std::vector<uint32_t> order = {0, 1};
    const test::OrderCheck check = checkVisibilityOrder(positions, view, kTwoQuads, order, {});
    EXPECT_TRUE(check.valid_permutation);
    EXPECT_EQ(check.violation_count, 0u);
    EXPECT_TRUE(check.violations.empty());
    EXPECT_GT(check.pairs_checked, 50u);
    EXPECT_EQ(check.max_depth_complexity, 2u);
}

TEST(GroundTruth, SwappedPairIsReportedWithItsDepths) {
    const TrianglePositions positions = twoParallelQuads();
    const uint32_t size = 32;
    const ViewProjection view = test::perspectiveView(positions, {0, 0, 5}, size, size);
    const std::vector<uint32_t> order = {1, 0};
    const test::OrderCheck check = checkVisibilityOrder(positions, view, kTwoQuads, order, {}, 5);
    EXPECT_TRUE(check.valid_permutation);
    // Every pair found is the front quad over the back one, and every one is violated.
    EXPECT_GT(check.violation_count, 50u);
    EXPECT_EQ(check.violation_count, check.pairs_checked);
    ASSERT_EQ(check.violations.size(), 5u);
    // Depths by hand: planes at distances 5 and 6 from the eye, d = 1 - near / distance.
    for (const test::OrderViolation& violation : check.violations) {
        EXPECT_EQ(violation.front, 0u);
        EXPECT_EQ(violation.behind, 1u);
        EXPECT_NEAR(violation.front_depth, 1 - view.near / 5, 1e-12);
        EXPECT_NEAR(violation.behind_depth, 1 - view.near / 6, 1e-12);
        // The front quad's half-size 1 at distance 5 spans the middle of the image.
        const double x_ndc = 2.0 * (violation.pixel_x + 0.5) / size - 1;
        EXPECT_LT(std::abs(x_ndc) * 5 * std::tan(std::acos(-1.0) / 8), 1.0);
    }
}

TEST(GroundTruth, PairInsideADeclaredCycleIsNotReported) {
    const TrianglePositions positions = twoParallelQuads();
    const ViewProjection view = test::perspectiveView(positions, {0, 0, 5}, 32, 32);
    const std::vector<uint32_t> order = {1, 0};
    const test::OrderCheck check =
        checkVisibilityOrder(positions, view, kTwoQuads, order, {{0, 1}});
    EXPECT_EQ(check.violation_count, 0u);
    EXPECT_GT(check.pairs_checked, 50u);
}

TEST(GroundTruth, NonPermutationsAreDetected) {
    const TrianglePositions positions = twoParallelQuads();
    const ViewProjection view = test::perspectiveView(positions, {0, 0, 5}, 8, 8);
    const std::vector<std::vector<uint32_t>> bad_orders = {{0, 0}, {0}, {0, 1, 1}, {0, 2}, {}};
    for (const std::vector<uint32_t>& order : bad_orders) {
        EXPECT_FALSE(checkVisibilityOrder(positions, view, kTwoQuads, order, {}).valid_permutation);
    }
}

TEST(GroundTruth, CoplanarQuadsHaveNoOcclusion) {
    TrianglePositions positions;
    addQuad(positions, 1.0, 0.0);
    addQuad(positions, 1.0, 0.0);
    const ViewProjection view = test::perspectiveView(positions, {0.3, 0.2, 5}, 32, 32);
    for (const std::vector<uint32_t>& order : {std::vector<uint32_t>{0, 1}, {1, 0}}) {
        const test::OrderCheck check = checkVisibilityOrder(positions, view, kTwoQuads, order, {});
        EXPECT_EQ(check.pairs_checked, 0u);
        EXPECT_EQ(check.violation_count, 0u);
        EXPECT_EQ(check.max_depth_complexity, 2u);
    }
    EXPECT_EQ(occlusionGraph(positions, view, kTwoQuads), (Graph{{}, {}}));
}

TEST(GroundTruth, OcclusionGraphOfPartialOverlap) {
    TrianglePositions positions;
    addQuad(positions, 1.0, -0.5);                                              // 0
    addTriangle(positions, {-0.5, -0.5, 0.5}, {0.5, -0.5, 0.5}, {0, 0.5, 0.5}); // 1: over 0
    addTriangle(positions, {1.5, 1.5, 0.8}, {1.9, 1.5, 0.8}, {1.7, 1.9, 0.8});  // 2: beside
    const std::vector<PrimitiveRange> primitives = {range(0, 2), range(2, 1), range(3, 1)};
    for (const ViewProjection& view :
         {test::perspectiveView(positions, {0.1, 0.2, 5}, 48, 48), topView(positions)}) {
        EXPECT_EQ(occlusionGraph(positions, view, primitives), (Graph{{}, {0}, {}}));
    }
}

TEST(GroundTruth, CyclicSticks) {
    const TrianglePositions positions = cyclicSticks();
    const ViewProjection view = topView(positions);
    const Graph graph = occlusionGraph(positions, view, kThreeSticks);
    EXPECT_EQ(graph, (Graph{{2}, {0}, {1}}));
    EXPECT_EQ(test::cyclicComponents(graph), (Graph{{0, 1, 2}}));

    // Every order breaks the cycle somewhere, unless the cycle is declared.
    std::vector<uint32_t> order = {0, 1, 2};
    do {
        EXPECT_GT(checkVisibilityOrder(positions, view, kThreeSticks, order, {}).violation_count,
                  0u);
        EXPECT_EQ(
            checkVisibilityOrder(positions, view, kThreeSticks, order, {{0, 1, 2}}).violation_count,
            0u);
    } while (std::next_permutation(order.begin(), order.end()));
    // A cycle that leaves out one stick excuses only the pairs inside it.
    const std::vector<uint32_t> two_one_zero = {2, 1, 0}; // violates 0 over 2 only
    const test::OrderCheck check =
        checkVisibilityOrder(positions, view, kThreeSticks, two_one_zero, {{0, 1}});
    ASSERT_FALSE(check.violations.empty());
    for (const test::OrderViolation& violation : check.violations) {
        EXPECT_EQ(violation.front, 0u);
        EXPECT_EQ(violation.behind, 2u);
        EXPECT_LT(violation.front_depth + test::kFrontMargin, violation.behind_depth);
    }
}

} // namespace
} // namespace vissort
