// End to end: scenes composed of real meshes, ordered with each oracle at each level, checked
// against the ray-cast ground truth (tests/support): no pixel where a primitive in front comes
// after one behind it, except inside a reported cycle.
#include <algorithm>
#include <array>
#include <limits>
#include <map>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "ground_truth.h"
#include "scenes/scene_library.h"
#include "tarjan_scc.h"
#include "test_scene_loading.h"
#include "vissort/camera_path.h"
#include "vissort/oracles.h"
#include "vissort/scene_orderer.h"

namespace vissort {
namespace {

// The oracle of that kind, failing the test when it cannot be made.
std::unique_ptr<GeometryOracle> oracleOf(OracleKind kind, const OracleOptions& options = {}) {
    Result<std::unique_ptr<GeometryOracle>> oracle = makeOracle(kind, options);
    EXPECT_TRUE(oracle) << oracle.error;
    return oracle ? std::move(*oracle.value) : nullptr;
}

// An orderer of the scene's objects at a level.
SceneOrderer ordererOf(const Scene& scene, OrderLevel level, GeometryOracle& oracle) {
    return SceneOrderer(scene.objectPrimitives(), uint32_t(scene.triangleCount()), level, oracle);
}

struct Case {
    std::string scene;
    OracleKind oracle;
    OrderLevel level;
    Projection projection;
    uint32_t width, height;
};

// Readable parameters in test logs.
void PrintTo(const Case& c, std::ostream* os) {
    *os << c.scene << ' ' << oracleName(c.oracle) << ' ' << orderLevelName(c.level) << ' '
        << c.width << 'x' << c.height;
}

std::string caseName(const testing::TestParamInfo<Case>& info) {
    std::string name = info.param.scene.substr(info.param.scene.find_last_of("/:") + 1);
    name = name.substr(0, name.find_first_of(".?"));
    name += std::string("_") + oracleName(info.param.oracle) + "_" +
            orderLevelName(info.param.level) +
            (info.param.projection == Projection::perspective ? "_persp" : "_ortho");
    return name;
}

ViewProjection viewOf(const Scene& scene, const Case& c) {
    CameraSpec camera = scene.camera.value_or(defaultCamera(scene.positions.bounds()));
    if (c.projection == Projection::orthographic) {
        CameraSpec ortho;
        ortho.projection = Projection::orthographic;
        // Look along the perspective camera's direction so the same overlaps are seen.
        ortho.ortho_direction = {camera.target.x - camera.eye.x, camera.target.y - camera.eye.y,
                                 camera.target.z - camera.eye.z};
        camera = ortho;
    }
    return frameCamera(camera, scene.positions.bounds(), c.width, c.height);
}

std::set<std::vector<uint32_t>> trueCycles(const Scene& scene, const ViewProjection& view,
                                           std::span<const PrimitiveRange> primitives) {
    const auto graph = test::occlusionGraph(scene.positions, view, primitives);
    std::set<std::vector<uint32_t>> cycles;
    for (auto component : test::stronglyConnectedComponents(graph)) {
        std::sort(component.begin(), component.end());
        if (component.size() > 1)
            cycles.insert(component);
    }
    return cycles;
}

class OrderAgainstGroundTruth : public testing::TestWithParam<Case> {};

TEST_P(OrderAgainstGroundTruth, NoOcclusionIsOrderedBackwards) {
    const Case& c = GetParam();
    const Scene scene = test::loadTestScene(c.scene);
    ASSERT_FALSE(scene.objects.empty());
    const ViewProjection view = viewOf(scene, c);
    auto oracle = oracleOf(c.oracle);
    ASSERT_TRUE(oracle);
    SceneOrderer orderer = ordererOf(scene, c.level, *oracle);
    const FrameOrder frame = orderer.orderFrame(scene.positions, view);

    const auto primitives = primitivesOf(scene, c.level);
    const test::OrderCheck check =
        test::checkVisibilityOrder(scene.positions, view, primitives, frame.order, frame.cycles);
    ASSERT_TRUE(check.valid_permutation);
    EXPECT_GT(check.pairs_checked, 0u) << "the view shows no overlap: the test would prove nothing";
    EXPECT_EQ(check.violation_count, 0u)
        << "first: primitive " << (check.violations.empty() ? 0 : check.violations[0].front)
        << " in front of " << (check.violations.empty() ? 0 : check.violations[0].behind);

    // Every reported cycle is strongly connected in the true occlusion graph, and every true
    // cycle lies inside one reported cycle: reported cycles are the components, not the whole
    // stuck remainder.
    if (c.level != OrderLevel::multistage) {
        const auto truth = trueCycles(scene, view, primitives);
        for (const auto& true_cycle : truth) {
            const bool covered =
                std::any_of(frame.cycles.begin(), frame.cycles.end(), [&](auto& r) {
                    return std::includes(r.begin(), r.end(), true_cycle.begin(), true_cycle.end());
                });
            EXPECT_TRUE(covered) << "a true cycle of " << true_cycle.size() << " was not reported";
        }
        if (c.oracle == OracleKind::exact) {
            const std::set<std::vector<uint32_t>> reported(frame.cycles.begin(),
                                                           frame.cycles.end());
            EXPECT_EQ(reported, truth);
        }
    }
}

const Case kCases[] = {
    {"tests/data/scenes/disjoint.json", OracleKind::cpu, OrderLevel::object,
     Projection::perspective, 160, 120},
    {"tests/data/scenes/disjoint.json", OracleKind::exact, OrderLevel::object,
     Projection::orthographic, 160, 120},
    {"tests/data/scenes/disjoint.json", OracleKind::cpu, OrderLevel::triangle,
     Projection::perspective, 96, 72},
    {"tests/data/scenes/stack.json", OracleKind::cpu, OrderLevel::object, Projection::perspective,
     128, 128},
    {"tests/data/scenes/stack.json", OracleKind::exact, OrderLevel::object,
     Projection::orthographic, 128, 128},
    {"tests/data/scenes/stack.json", OracleKind::cpu, OrderLevel::triangle,
     Projection::orthographic, 96, 96},
    {"tests/data/scenes/interpenetrating.json", OracleKind::cpu, OrderLevel::object,
     Projection::perspective, 160, 120},
    {"tests/data/scenes/interpenetrating.json", OracleKind::exact, OrderLevel::object,
     Projection::perspective, 160, 120},
    {"tests/data/scenes/interpenetrating.json", OracleKind::cpu, OrderLevel::triangle,
     Projection::orthographic, 96, 72},
    {"tests/data/scenes/interpenetrating.json", OracleKind::cpu, OrderLevel::multistage,
     Projection::perspective, 96, 72},
    {"tests/data/scenes/interpenetrating.json", OracleKind::exact, OrderLevel::multistage,
     Projection::orthographic, 96, 72},
    {"tests/data/scenes/three_sticks.json", OracleKind::cpu, OrderLevel::object,
     Projection::perspective, 128, 128},
    {"tests/data/scenes/three_sticks.json", OracleKind::exact, OrderLevel::object,
     Projection::orthographic, 128, 128},
    {"tests/data/scenes/three_sticks.json", OracleKind::cpu, OrderLevel::triangle,
     Projection::perspective, 128, 128},
    {"tests/data/scenes/three_sticks.json", OracleKind::cpu, OrderLevel::multistage,
     Projection::orthographic, 128, 128},
    {"builtin:bunnies?n=6&seed=3", OracleKind::cpu, OrderLevel::object, Projection::perspective,
     128, 96},
    {"builtin:bunnies?n=6&seed=3", OracleKind::exact, OrderLevel::triangle,
     Projection::orthographic, 96, 96},
    {"builtin:bunnies?n=6&seed=3", OracleKind::cpu, OrderLevel::multistage, Projection::perspective,
     96, 96},
    {"builtin:slabs?layers=40", OracleKind::cpu, OrderLevel::triangle, Projection::perspective, 64,
     64},
    {"builtin:soup?n=400", OracleKind::cpu, OrderLevel::triangle, Projection::orthographic, 96, 96},
};

INSTANTIATE_TEST_SUITE_P(Scenes, OrderAgainstGroundTruth, testing::ValuesIn(kCases), caseName);

TEST(SceneOrderer, StackHasDepthComplexityOver30) {
    const Scene scene = test::loadTestScene("tests/data/scenes/stack.json");
    const ViewProjection view = frameCamera(*scene.camera, scene.positions.bounds(), 64, 64);
    const auto primitives = primitivesOf(scene, OrderLevel::object);
    auto oracle = oracleOf(OracleKind::cpu);
    ASSERT_TRUE(oracle);
    SceneOrderer orderer = ordererOf(scene, OrderLevel::object, *oracle);
    const FrameOrder frame = orderer.orderFrame(scene.positions, view);
    const auto check =
        test::checkVisibilityOrder(scene.positions, view, primitives, frame.order, {});
    EXPECT_GT(check.max_depth_complexity, 30u);
    EXPECT_EQ(check.violation_count, 0u);
    EXPECT_TRUE(frame.cycles.empty());
}

TEST(SceneOrderer, VertexBufferFramesAreOrderedAsTheirCorners) {
    // The stack as an indexed, interleaved vertex buffer (each distinct corner once, then a
    // padding float that is not finite, so reading it would be refused): the order is checked
    // against ground truth and equals the order of the same corners as arrays.
    const Scene scene = test::loadTestScene("tests/data/scenes/stack.json");
    std::vector<float> interleaved;
    std::vector<uint32_t> indices;
    std::map<std::array<float, 3>, uint32_t> vertex_of;
    for (std::size_t c = 0; c < scene.positions.x.size(); ++c) {
        const std::array<float, 3> p = {scene.positions.x[c], scene.positions.y[c],
                                        scene.positions.z[c]};
        const auto [at, added] = vertex_of.emplace(p, uint32_t(vertex_of.size()));
        if (added)
            interleaved.insert(interleaved.end(),
                               {p[0], p[1], p[2], std::numeric_limits<float>::quiet_NaN()});
        indices.push_back(at->second);
    }
    ASSERT_LT(vertex_of.size(), scene.positions.x.size()); // corners are shared
    const VertexPositionsView vertices{interleaved.data(), vertex_of.size(), 4 * sizeof(float),
                                       indices};
    const ViewProjection view = frameCamera(*scene.camera, scene.positions.bounds(), 64, 64);
    const auto primitives = primitivesOf(scene, OrderLevel::object);
    auto oracle = oracleOf(OracleKind::cpu);
    ASSERT_TRUE(oracle);
    SceneOrderer from_buffer = ordererOf(scene, OrderLevel::object, *oracle);
    FrameOrder frame;
    from_buffer.orderFrame(vertices, view, frame);
    EXPECT_EQ(test::checkVisibilityOrder(scene.positions, view, primitives, frame.order, {})
                  .violation_count,
              0u);
    auto other_oracle = oracleOf(OracleKind::cpu);
    SceneOrderer from_arrays = ordererOf(scene, OrderLevel::object, *other_oracle);
    EXPECT_EQ(frame.order, from_arrays.orderFrame(scene.positions, view).order);
    // A buffer of another size, or one gatherPositions refuses, orders nothing.
    const std::span<const uint32_t> fewer(indices.data(), indices.size() - 3);
    EXPECT_THROW(
        from_buffer.orderFrame({interleaved.data(), vertex_of.size(), 16, fewer}, view, frame),
        std::invalid_argument);
    EXPECT_THROW(
        from_buffer.orderFrame({interleaved.data(), vertex_of.size(), 10, indices}, view, frame),
        std::invalid_argument);
}

TEST(SceneOrderer, ThreeSticksFormOneCycleOfThree) {
    const Scene scene = test::loadTestScene("tests/data/scenes/three_sticks.json");
    const ViewProjection view = frameCamera(*scene.camera, scene.positions.bounds(), 128, 128);
    auto oracle = oracleOf(OracleKind::cpu);
    ASSERT_TRUE(oracle);
    SceneOrderer orderer = ordererOf(scene, OrderLevel::object, *oracle);
    const FrameOrder frame = orderer.orderFrame(scene.positions, view);
    ASSERT_EQ(frame.cycles.size(), 1u);
    EXPECT_EQ(frame.cycles[0], (std::vector<uint32_t>{0, 1, 2}));
}

TEST(SceneOrderer, CoherentFramesCostAboutLinearQueries) {
    const Scene scene = test::loadTestScene("builtin:bunnies?n=8&seed=5");
    ASSERT_TRUE(scene.isDynamic());
    auto oracle = oracleOf(OracleKind::cpu);
    ASSERT_TRUE(oracle);
    SceneOrderer orderer = ordererOf(scene, OrderLevel::object, *oracle);
    const CameraSpec camera = scene.camera.value_or(defaultCamera(scene.positions.bounds()));
    TrianglePositions positions;
    for (int f = 0; f < 6; ++f) {
        scene.frame(f / 30.0, positions);
        const ViewProjection view = frameCamera(camera, positions.bounds(), 96, 96);
        const FrameOrder frame = orderer.orderFrame(positions, view);
        const auto primitives = primitivesOf(scene, OrderLevel::object);
        EXPECT_EQ(test::checkVisibilityOrder(positions, view, primitives, frame.order, frame.cycles)
                      .violation_count,
                  0u);
        if (f > 0 && frame.cycles.empty()) {
            // Starting from the last order, one iteration of two passes: at most 2n queries.
            EXPECT_LE(frame.stats.queries, 2u * scene.objects.size()) << "frame " << f;
        }
    }
}

// A frame seeded with a visibility order (another orderer's answer for the same frame) starts
// where the depth-key order has to work its way to: one iteration, at most 2n queries, and a
// valid order; a list that is not a permutation is refused.
TEST(SceneOrderer, SeededFrameStartsFromTheGivenOrder) {
    const Scene scene = test::loadTestScene("builtin:plant");
    auto oracle = oracleOf(OracleKind::cpu);
    ASSERT_TRUE(oracle);
    const CameraSpec camera = scene.camera.value_or(defaultCamera(scene.positions.bounds()));
    const ViewProjection view = frameCamera(camera, scene.positions.bounds(), 96, 96);
    SceneOrderer first = ordererOf(scene, OrderLevel::object, *oracle);
    const FrameOrder known = first.orderFrame(scene.positions, view);
    ASSERT_TRUE(known.cycles.empty());
    SceneOrderer seeded = ordererOf(scene, OrderLevel::object, *oracle);
    seeded.seed(known.order);
    const FrameOrder frame = seeded.orderFrame(scene.positions, view);
    EXPECT_LE(frame.stats.queries, 2u * scene.objects.size());
    EXPECT_LT(frame.stats.queries, known.stats.queries);
    const auto primitives = primitivesOf(scene, OrderLevel::object);
    EXPECT_EQ(
        test::checkVisibilityOrder(scene.positions, view, primitives, frame.order, frame.cycles)
            .violation_count,
        0u);
    std::vector<uint32_t> repeated = known.order;
    repeated[1] = repeated[0];
    EXPECT_THROW(seeded.seed(repeated), std::invalid_argument);
    EXPECT_THROW(seeded.seed(std::span(known.order).first(3)), std::invalid_argument);
}

TEST(SceneOrderer, MultistageOutputsEveryTriangleOnce) {
    const Scene scene = test::loadTestScene("tests/data/scenes/interpenetrating.json");
    const ViewProjection view = frameCamera(*scene.camera, scene.positions.bounds(), 64, 64);
    auto oracle = oracleOf(OracleKind::cpu);
    ASSERT_TRUE(oracle);
    SceneOrderer orderer = ordererOf(scene, OrderLevel::multistage, *oracle);
    FrameOrder frame = orderer.orderFrame(scene.positions, view);
    ASSERT_EQ(frame.order.size(), scene.triangleCount());
    std::sort(frame.order.begin(), frame.order.end());
    for (uint32_t i = 0; i < frame.order.size(); ++i)
        ASSERT_EQ(frame.order[i], i);
}

// Objects may share triangles (the oracle sets each up once per primitive): multistage orders
// every object's triangles, a shared one once per object, on coherent frames too, where each
// group's start comes from last frame's order (a shared triangle belongs to no single group).
TEST(SceneOrderer, MultistageOrdersObjectsThatShareTriangles) {
    // Separate slabs, no cycle among them: every object is a group of its own.
    const Scene scene = test::loadTestScene("builtin:slabs?layers=4");
    std::vector<PrimitiveRange> objects = scene.objectPrimitives();
    ASSERT_GE(objects.size(), 2u);
    // One more object: the last half of object 0 and the first half of object 1.
    const PrimitiveRange& a = objects[0];
    const PrimitiveRange& b = objects[1];
    ASSERT_EQ(a.first_triangle + a.triangle_count, b.first_triangle);
    objects.push_back({a.first_triangle + a.triangle_count / 2,
                       a.triangle_count - a.triangle_count / 2 + b.triangle_count / 2});
    std::vector<uint32_t> expected_count(scene.triangleCount(), 0);
    for (const PrimitiveRange& object : objects)
        for (uint32_t t = 0; t < object.triangle_count; ++t)
            ++expected_count[object.first_triangle + t];
    auto oracle = oracleOf(OracleKind::cpu);
    ASSERT_TRUE(oracle);
    SceneOrderer orderer(objects, uint32_t(scene.triangleCount()), OrderLevel::multistage, *oracle);
    for (int f = 0; f < 3; ++f) {
        const CameraSpec camera =
            cameraOnPath(scene.camera.value_or(defaultCamera(scene.positions.bounds())),
                         CameraPath::orbit, f, scene.positions.bounds());
        const FrameOrder frame = orderer.orderFrame(
            scene.positions, frameCamera(camera, scene.positions.bounds(), 64, 64));
        std::vector<uint32_t> count(scene.triangleCount(), 0);
        for (uint32_t t : frame.order)
            ++count[t];
        EXPECT_EQ(count, expected_count) << "frame " << f;
    }
}

// Multistage binds each group after the frame's objects with rebind (the fast oracle copies the
// objects' set-ups). Over frames of deforming bunnies written into the same arrays, with the
// camera orbiting: the same orders and cycles as the reference oracle, which binds every time.
TEST(SceneOrderer, MultistageWithRebindsMatchesTheReferenceOnMovingFrames) {
    Scene scene = test::loadTestScene("builtin:bunnies?n=4&seed=2");
    ASSERT_TRUE(scene.isDynamic());
    auto fast = oracleOf(OracleKind::cpu);
    auto reference = oracleOf(OracleKind::cpu_reference);
    ASSERT_TRUE(fast && reference);
    SceneOrderer fast_orderer = ordererOf(scene, OrderLevel::multistage, *fast);
    SceneOrderer reference_orderer = ordererOf(scene, OrderLevel::multistage, *reference);
    const float* arrays = scene.positions.x.data();
    for (int f = 0; f < 4; ++f) {
        scene.animation->positionsAt(0.4 * f, scene.positions);
        ASSERT_EQ(scene.positions.x.data(), arrays); // rewritten in place: rebinds must notice
        const CameraSpec camera =
            cameraOnPath(scene.camera.value_or(defaultCamera(scene.positions.bounds())),
                         CameraPath::orbit, f * 3, scene.positions.bounds());
        const ViewProjection view = frameCamera(camera, scene.positions.bounds(), 96, 72);
        const FrameOrder got = fast_orderer.orderFrame(scene.positions, view);
        const FrameOrder expected = reference_orderer.orderFrame(scene.positions, view);
        EXPECT_EQ(got.order, expected.order) << "frame " << f;
        EXPECT_EQ(got.cycles, expected.cycles) << "frame " << f;
        ASSERT_EQ(got.order.size(), scene.triangleCount());
    }
}

} // namespace
} // namespace vissort
