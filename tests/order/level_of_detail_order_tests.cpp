// Ordering with levels of detail: every coherent frame of a walkthrough, at the levels the frame
// chose (a level switch is a primitive changing shape; objects out of view have no triangles),
// checked against its own exact ground truth; objects without triangles cost no query and come
// last; setObjects keeps object orders coherent and refuses another object count.

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "ground_truth.h"
#include "test_scene_loading.h"
#include "vissort/camera_path.h"
#include "vissort/levels_of_detail.h"
#include "vissort/oracles.h"
#include "vissort/scene_orderer.h"

namespace vissort {
namespace {

constexpr uint32_t kWidth = 160, kHeight = 120;

std::unique_ptr<GeometryOracle> cpuOracle() {
    Result<std::unique_ptr<GeometryOracle>> made = makeOracle(OracleKind::cpu);
    EXPECT_TRUE(made) << made.error;
    return std::move(*made.value);
}

TEST(LevelOfDetailOrder, WalkthroughFramesAreExactAtTheLevelsChosen) {
    const Scene scene = test::loadTestScene("builtin:powerplant?scale=0.05");
    const Bounds bounds = scene.positions.bounds();
    const auto levels = std::make_shared<const LevelsOfDetail>(LevelsOfDetail::build(scene));
    for (OrderLevel level : {OrderLevel::object, OrderLevel::multistage}) {
        SCOPED_TRACE(orderLevelName(level));
        std::unique_ptr<GeometryOracle> oracle = cpuOracle();
        SceneOrderer orderer(scene.objectPrimitives(), uint32_t(scene.triangleCount()), level,
                             *oracle);
        DetailSelection selection(scene, levels, 4.0f);
        uint32_t coarser = 0;
        for (int f : {0, 1, 2, 150, 151}) {
            SCOPED_TRACE("frame " + std::to_string(f));
            const ViewProjection view = frameCamera(
                cameraOnPath(*scene.camera, CameraPath::scene, f, bounds, scene.camera_path),
                bounds, kWidth, kHeight);
            selection.select(scene.positions, view);
            const DetailFrame& frame = selection.gather();
            for (uint8_t c : selection.chosen())
                coarser += c != 0 && c != LevelChooser::kCulled;
            ASSERT_GT(frame.culled_objects, 0u);
            orderer.setObjects(frame.objects, uint32_t(frame.triangles));
            const FrameOrder order = orderer.orderFrame(frame.positions, view);
            const std::vector<PrimitiveRange> primitives =
                levelPrimitives(frame.objects, uint32_t(frame.triangles), level);
            const test::OrderCheck check = test::checkVisibilityOrder(
                frame.positions, view, primitives, order.order, order.cycles);
            EXPECT_TRUE(check.valid_permutation);
            EXPECT_EQ(check.violation_count, 0u);
            EXPECT_GT(check.pairs_checked, 0u);
            if (level != OrderLevel::object)
                continue;
            // The objects out of view come last, after every object with triangles.
            const auto first_empty =
                std::find_if(order.order.begin(), order.order.end(),
                             [&](uint32_t o) { return frame.objects[o].triangle_count == 0; });
            EXPECT_EQ(
                std::count_if(first_empty, order.order.end(),
                              [&](uint32_t o) { return frame.objects[o].triangle_count == 0; }),
                frame.culled_objects);
        }
        EXPECT_GT(coarser, 0u);
    }
}

TEST(LevelOfDetailOrder, ObjectsWithoutTrianglesCostNoQuery) {
    // The same scene with a third of its objects emptied, and with them removed: Vis-sort sees
    // the same list either way (the depth-key order keeps its relative order), so it asks the
    // same queries.
    const Scene scene = test::loadTestScene("builtin:bunnies?n=9");
    const ViewProjection view =
        frameCamera(*scene.camera, scene.positions.bounds(), kWidth, kHeight);
    std::vector<PrimitiveRange> with_empty = scene.objectPrimitives(), without;
    TrianglePositions kept;
    for (uint32_t o = 0; o < with_empty.size(); ++o) {
        if (o % 3 == 1) {
            with_empty[o].triangle_count = 0;
            continue;
        }
        const PrimitiveRange range = with_empty[o];
        without.push_back({uint32_t(kept.triangleCount()), range.triangle_count});
        for (std::size_t c = std::size_t(range.first_triangle) * 3;
             c < std::size_t(range.first_triangle + range.triangle_count) * 3; ++c) {
            kept.x.push_back(scene.positions.x[c]);
            kept.y.push_back(scene.positions.y[c]);
            kept.z.push_back(scene.positions.z[c]);
        }
    }
    std::unique_ptr<GeometryOracle> a = cpuOracle(), b = cpuOracle();
    SceneOrderer emptied(scene.objectPrimitives(), uint32_t(scene.triangleCount()),
                         OrderLevel::object, *a);
    emptied.setObjects(with_empty, uint32_t(scene.triangleCount()));
    SceneOrderer removed(without, uint32_t(kept.triangleCount()), OrderLevel::object, *b);
    const FrameOrder x = emptied.orderFrame(scene.positions, view);
    const FrameOrder y = removed.orderFrame(kept, view);
    EXPECT_EQ(x.stats.queries, y.stats.queries);
    EXPECT_GT(x.stats.queries, 0u);
    ASSERT_EQ(x.order.size(), with_empty.size());
    for (std::size_t i = 0; i < x.order.size(); ++i)
        EXPECT_EQ(with_empty[x.order[i]].triangle_count == 0, i >= without.size()) << i;
    const test::OrderCheck check =
        test::checkVisibilityOrder(scene.positions, view, with_empty, x.order, x.cycles);
    EXPECT_EQ(check.violation_count, 0u);
    EXPECT_THROW(emptied.setObjects(without, uint32_t(kept.triangleCount())),
                 std::invalid_argument);
}

TEST(LevelOfDetailOrder, UnchangedRangesKeepCoherenceAndNewOnesStillSeedObjects) {
    const Scene scene = test::loadTestScene("builtin:bunnies?n=9");
    const ViewProjection view =
        frameCamera(*scene.camera, scene.positions.bounds(), kWidth, kHeight);
    std::unique_ptr<GeometryOracle> oracle = cpuOracle();
    SceneOrderer orderer(scene.objectPrimitives(), uint32_t(scene.triangleCount()),
                         OrderLevel::object, *oracle);
    const FrameOrder first = orderer.orderFrame(scene.positions, view);
    orderer.setObjects(scene.objectPrimitives(), uint32_t(scene.triangleCount())); // the same
    const FrameOrder second = orderer.orderFrame(scene.positions, view);
    std::vector<PrimitiveRange> one_empty = scene.objectPrimitives();
    one_empty[4].triangle_count = 0;
    orderer.setObjects(one_empty, uint32_t(scene.triangleCount()));
    const FrameOrder third = orderer.orderFrame(scene.positions, view);
    // A coherent frame of an unchanged list asks fewer queries than the first, from the
    // depth-key order; a frame after a range changed still starts from last frame's object
    // order, and asks no more than an orderer starting afresh on the same ranges.
    std::unique_ptr<GeometryOracle> other = cpuOracle();
    SceneOrderer afresh(scene.objectPrimitives(), uint32_t(scene.triangleCount()),
                        OrderLevel::object, *other);
    afresh.setObjects(one_empty, uint32_t(scene.triangleCount()));
    const FrameOrder fresh = afresh.orderFrame(scene.positions, view);
    EXPECT_LT(second.stats.queries, first.stats.queries);
    EXPECT_LE(third.stats.queries, fresh.stats.queries);
    EXPECT_EQ(third.order.back(), 4u);
}

} // namespace
} // namespace vissort
