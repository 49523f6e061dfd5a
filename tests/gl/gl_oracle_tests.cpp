// The OpenGL oracle on whatever driver the machine has (Mesa's llvmpipe here and in CI): its
// context on both EGL platforms; under depth tolerance 0 its depths against the exact model's
// (lower bounds), its answers and pass-level batches against the exact oracle's (a superset), its
// orders against the exact ground truth and its cycles against the exact oracle's; under a
// non-zero tolerance its coverage, depths, answers and orders against the cpu oracle's same
// approximate rule; and its errors. gl_exact_superset_tests.cpp has the random scenes.
// These tests need an OpenGL 4.5 context: without one they fail, naming what is missing
// (scripts/install-deps.sh installs Mesa's).

#include "vissort/gl_oracle.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "gl_test_support.h"
#include "ground_truth.h"
#include "scenes/scene_library.h"
#include "test_scene_loading.h"
#include "vissort/cpu_oracle.h"
#include "vissort/exact_oracle.h"
#include "vissort/oracles.h"
#include "vissort/scene_orderer.h"

namespace vissort {
namespace {

// The default tolerance before tolerance 0 became the exact model: an approximate one.
constexpr float kApproximateTolerance = 1.0f / (1 << 20);

std::shared_ptr<GlContext> context() {
    return test::glContext();
}

ViewProjection viewOf(const Scene& scene, Projection projection, uint32_t width, uint32_t height) {
    return test::sceneView(scene, projection, width, height);
}

TEST(GlContext, BothEglPlatformsGiveOpenGl45) {
    for (GlPlatform platform : {GlPlatform::surfaceless, GlPlatform::device}) {
        SCOPED_TRACE(glPlatformName(platform));
        const Result<std::shared_ptr<GlContext>> created = GlContext::create(platform);
        ASSERT_TRUE(created) << created.error;
        const GlContextInfo& info = (*created.value)->info();
        EXPECT_EQ(info.platform, glPlatformName(platform));
        EXPECT_FALSE(info.renderer.empty());
        EXPECT_FALSE(info.vendor.empty());
        // Mesa's CPU renderer (every machine without a GPU, CI's included) is said to be one.
        if (info.renderer.find("llvmpipe") != std::string::npos) {
            EXPECT_TRUE(info.software) << info.renderer;
        }
        int major = 0, minor = 0;
        ASSERT_EQ(std::sscanf(info.version.c_str(), "%d.%d", &major, &minor), 2) << info.version;
        EXPECT_GE(major * 10 + minor, 45) << info.version;
    }
}

// EGL lets a context be current on one thread at a time: after releaseCurrent, another thread
// makes it current and draws (the Python module renders from whichever thread calls it).
TEST(GlContext, ReleasedContextWorksOnAnotherThread) {
    const Result<std::shared_ptr<GlContext>> created = GlContext::create();
    ASSERT_TRUE(created) << created.error;
    const std::shared_ptr<GlContext> gl = *created.value;
    const Scene scene = test::loadTestScene("builtin:slabs?layers=3");
    const ViewProjection view = viewOf(scene, Projection::perspective, 32, 32);
    const std::vector<PrimitiveRange> objects = scene.objectPrimitives();
    const auto orderOn = [&](const std::shared_ptr<GlContext>& context) {
        GlOracle oracle(context);
        SceneOrderer orderer(objects, uint32_t(scene.triangleCount()), OrderLevel::object, oracle);
        return orderer.orderFrame(scene.positions, view).order;
    };
    const std::vector<uint32_t> here = orderOn(gl);
    gl->releaseCurrent();
    std::vector<uint32_t> there;
    std::thread other([&] {
        there = orderOn(gl);
        gl->releaseCurrent();
    });
    other.join();
    EXPECT_EQ(there, here);
    EXPECT_EQ(here.size(), 3u);
}

TEST(GlContext, PlatformNamesAndARefusedSharedContext) {
    for (const char* name : {"auto", "device", "surfaceless"}) {
        const Result<GlPlatform> platform = parseGlPlatform(name);
        ASSERT_TRUE(platform) << name;
        EXPECT_STREQ(glPlatformName(*platform.value), name);
    }
    const Result<GlPlatform> unknown = parseGlPlatform("wayland");
    ASSERT_FALSE(unknown);
    EXPECT_NE(unknown.error.find("'wayland'"), std::string::npos) << unknown.error;
    EXPECT_NE(unknown.error.find("surfaceless"), std::string::npos) << unknown.error;
    // The library reads no environment: an application rules OpenGL out explicitly. Nothing
    // else would stop shared() from handing out a context that exists.
    GlContext::refuseShared("no OpenGL context: ruled out by the test");
    const Result<std::shared_ptr<GlContext>> refused = GlContext::shared();
    GlContext::setSharedPlatform(GlPlatform::automatic);
    ASSERT_FALSE(refused);
    EXPECT_EQ(refused.error, "no OpenGL context: ruled out by the test");
    EXPECT_TRUE(GlContext::shared()) << "setSharedPlatform lifts the refusal";
}

struct Case {
    std::string scene;
    OrderLevel level;
};

// Names the case in gtest's messages (it would print the struct's bytes otherwise).
void PrintTo(const Case& c, std::ostream* out) {
    *out << c.scene << " at " << orderLevelName(c.level) << " level";
}

class GlOnScenes : public testing::TestWithParam<Case> {};

// Everything drawn under tolerance 0: every pixel where the exact model has a fragment is
// covered, with a depth at most the exact nearest one (draws write lower bounds) and, but for a
// few pixels, within 2^-20 of it (the float depth buffer rounds down; the bound widens only on
// nearly edge-on triangles, where the triangle's depth range takes over). A pixel covered by gl
// alone would need a centre within the rounding of an edge: none here.
TEST_P(GlOnScenes, DepthsBoundTheExactOnesFromBelow) {
    const Scene scene = test::loadTestScene(GetParam().scene);
    const auto primitives = primitivesOf(scene, GetParam().level);
    for (Projection projection : {Projection::perspective, Projection::orthographic})
        for (auto [width, height] : {std::pair{1u, 1u}, {17u, 13u}, {203u, 111u}}) {
            SCOPED_TRACE(
                std::to_string(width) + "x" + std::to_string(height) +
                (projection == Projection::perspective ? " perspective" : " orthographic"));
            const ViewProjection view = viewOf(scene, projection, width, height);
            ExactOracle exact(1);
            GlOracle gl(context());
            exact.bind(scene.positions, view, primitives);
            gl.bind(scene.positions, view, primitives);
            std::vector<double> nearest(std::size_t(width) * height, INFINITY);
            for (uint32_t p = 0; p < primitives.size(); ++p) {
                gl.draw(p);
                for (const ExactOracle::Fragment& f : exact.fragments(p))
                    nearest[f.pixel] = std::min(nearest[f.pixel], f.nearest_depth);
            }
            const std::vector<float> got = gl.depthBuffer();
            ASSERT_EQ(got.size(), nearest.size());
            std::size_t covered = 0, loose = 0, gl_only = 0;
            for (std::size_t i = 0; i < got.size(); ++i) {
                if (std::isinf(nearest[i])) {
                    gl_only += got[i] < 1.0f ? 1 : 0;
                    continue;
                }
                ++covered;
                // The exact depth is rounded to double: a relative 2^-52 of slack.
                ASSERT_LE(double(got[i]), nearest[i] * (1 + 0x1p-52)) << "pixel " << i;
                loose += nearest[i] - got[i] > 0x1p-20 ? 1 : 0;
            }
            EXPECT_EQ(gl_only, 0u);
            EXPECT_LE(loose * 500, covered) << loose << " of " << covered;
            if (width * height > 1) {
                EXPECT_GT(covered, 0u);
            }
        }
}

// The pass-level batches on random sequences and query flags, then single draws and
// queries interleaved at random, against the exact oracle: no exact "behind" missed. The extra
// answers are reported (measured: at most 0.16% of the exact "not behind" ones, on the three
// sticks).
TEST_P(GlOnScenes, PassesAndSingleCallsContainTheExactAnswers) {
    const Scene scene = test::loadTestScene(GetParam().scene);
    const auto primitives = primitivesOf(scene, GetParam().level);
    test::Tally tally;
    for (Projection projection : {Projection::perspective, Projection::orthographic}) {
        const ViewProjection view = viewOf(scene, projection, 203, 111);
        ExactOracle exact(1);
        GlOracle gl(context());
        exact.bind(scene.positions, view, primitives);
        gl.bind(scene.positions, view, primitives);
        test::comparePasses(exact, gl, 11, 6, tally);
        test::interleave(exact, gl, 12, 300, tally);
    }
    std::printf("[ rates    ] %s: %s\n", testing::PrintToString(GetParam()).c_str(),
                tally.describe().c_str());
    EXPECT_EQ(tally.missed, 0u) << tally.describe();
    EXPECT_GT(tally.exact_behind, 0u) << "the sequences never found anything behind: a weak test";
}

// Vis-sort through OpenGL: no occlusion the exact ground truth sees ordered backwards outside a
// reported cycle, and every cycle the exact oracle's order reports inside one of gl's.
TEST_P(GlOnScenes, OrdersPassTheGroundTruth) {
    const Scene scene = test::loadTestScene(GetParam().scene);
    const auto primitives = primitivesOf(scene, GetParam().level);
    for (Projection projection : {Projection::perspective, Projection::orthographic}) {
        SCOPED_TRACE(projection == Projection::perspective ? "perspective" : "orthographic");
        const ViewProjection view = viewOf(scene, projection, 128, 96);
        ExactOracle exact;
        GlOracle gl(context());
        SceneOrderer exact_orderer(scene.objectPrimitives(), uint32_t(scene.triangleCount()),
                                   GetParam().level, exact);
        SceneOrderer gl_orderer(scene.objectPrimitives(), uint32_t(scene.triangleCount()),
                                GetParam().level, gl);
        const FrameOrder expected = exact_orderer.orderFrame(scene.positions, view);
        const FrameOrder got = gl_orderer.orderFrame(scene.positions, view);
        EXPECT_TRUE(test::cyclesContained(expected.cycles, got.cycles));
        const test::OrderCheck check =
            test::checkVisibilityOrder(scene.positions, view, primitives, got.order, got.cycles);
        ASSERT_TRUE(check.valid_permutation);
        EXPECT_GT(check.pairs_checked, 0u);
        EXPECT_EQ(check.violation_count, 0u);
    }
}

// A non-zero tolerance keeps the approximate float rule, as before tolerance 0 became exact:
// the vertex shader's offset and the snap slack as a polygon offset, against the cpu oracle's
// same rule. Everything drawn: the same covered pixels, and depths within the tolerance but for
// a few in a thousand (the driver interpolates depth in float, the CPU in double; and on nearly
// edge-on triangles OpenGL clamps the fragment's depth and the CPU rasterizer does not). Then the
// pass-level batches and single calls: answers may differ where a depth difference is within a
// rounding of the tolerance (measured 0.3% of the three sticks' triangle queries, none
// elsewhere): at most 1% may, for a positive tolerance and a negative one. Then Vis-sort with
// the positive one: the cpu oracle's order, cycles and query counts.
TEST_P(GlOnScenes, ApproximateToleranceAnswersAsCpu) {
    const Scene scene = test::loadTestScene(GetParam().scene);
    const auto primitives = primitivesOf(scene, GetParam().level);
    for (Projection projection : {Projection::perspective, Projection::orthographic})
        for (auto [width, height] : {std::pair{17u, 13u}, {203u, 111u}, {640u, 480u}}) {
            SCOPED_TRACE(
                std::to_string(width) + "x" + std::to_string(height) +
                (projection == Projection::perspective ? " perspective" : " orthographic"));
            const ViewProjection view = viewOf(scene, projection, width, height);
            CpuOracle cpu;
            GlOracle gl(context());
            cpu.setDepthTolerance(kApproximateTolerance);
            gl.setDepthTolerance(kApproximateTolerance);
            cpu.bind(scene.positions, view, primitives);
            gl.bind(scene.positions, view, primitives);
            for (uint32_t p = 0; p < primitives.size(); ++p) {
                cpu.draw(p);
                gl.draw(p);
            }
            const std::span<const float> expected = cpu.depthBuffer();
            const std::vector<float> got = gl.depthBuffer();
            ASSERT_EQ(got.size(), expected.size());
            std::size_t covered = 0, beyond_tolerance = 0;
            for (std::size_t i = 0; i < got.size(); ++i) {
                // The CPU clears to +infinity, OpenGL to 1 (gl_oracle.h).
                ASSERT_EQ(std::isinf(expected[i]), got[i] == 1.0f) << "pixel " << i;
                if (std::isinf(expected[i]))
                    continue;
                ++covered;
                const double difference = std::abs(double(got[i]) - expected[i]);
                beyond_tolerance += difference > kApproximateTolerance ? 1 : 0;
            }
            if (covered >= 1000) {
                EXPECT_LE(beyond_tolerance * 200, covered) << beyond_tolerance << " of " << covered;
            }
        }
    for (float tolerance : {kApproximateTolerance, -kApproximateTolerance}) {
        SCOPED_TRACE("tolerance " + std::to_string(tolerance));
        const ViewProjection view = viewOf(scene, Projection::perspective, 203, 111);
        CpuOracle cpu;
        GlOracle gl(context());
        cpu.setDepthTolerance(tolerance);
        gl.setDepthTolerance(tolerance);
        cpu.bind(scene.positions, view, primitives);
        gl.bind(scene.positions, view, primitives);
        std::mt19937 rng(11);
        const auto n = uint32_t(primitives.size());
        std::size_t answers = 0, differing = 0;
        const auto compare = [&](const std::vector<uint8_t>& got,
                                 const std::vector<uint8_t>& expected) {
            for (std::size_t i = 0; i < got.size(); ++i) {
                answers += expected[i] != 7 ? 1 : 0;
                differing += got[i] != expected[i] ? 1 : 0;
            }
        };
        for (int round = 0; round < 6; ++round) {
            std::vector<uint32_t> sequence(n);
            for (uint32_t i = 0; i < n; ++i)
                sequence[i] = i;
            std::shuffle(sequence.begin(), sequence.end(), rng);
            std::vector<uint8_t> query(n);
            for (uint8_t& q : query)
                q = uint8_t(rng() % 3 != 0);
            std::vector<uint8_t> expected(n, 7), got(n, 7);
            cpu.backToFrontPass(sequence, query, expected);
            gl.backToFrontPass(sequence, query, got);
            compare(got, expected);
            expected.assign(n, 7);
            got.assign(n, 7);
            cpu.frontToBackPass(sequence, query, expected);
            gl.frontToBackPass(sequence, query, got);
            compare(got, expected);
            const std::span<const uint32_t> occluders(sequence.data(), n / 2);
            const std::span<const uint32_t> targets(sequence.data() + n / 2, n - n / 2);
            std::vector<uint8_t> expected_group(targets.size()), got_group(targets.size());
            cpu.queryAgainst(occluders, targets, expected_group);
            gl.queryAgainst(occluders, targets, got_group);
            compare(got_group, expected_group);
        }
        cpu.clear();
        gl.clear();
        std::uniform_int_distribution<uint32_t> pick(0, n - 1);
        for (int op = 0; op < 300; ++op) {
            const uint32_t id = pick(rng);
            const unsigned action = rng() % 100;
            if (action < 3) {
                cpu.clear();
                gl.clear();
            } else if (action < 50) {
                cpu.draw(id);
                gl.draw(id);
            } else {
                const bool expected = cpu.anyBehind(id);
                ++answers;
                differing += gl.anyBehind(id) != expected ? 1 : 0;
            }
        }
        EXPECT_LE(differing * 100, answers) << differing << " of " << answers << " answers differ";
        if (tolerance < 0)
            continue; // near ties count both ways: one differing answer can change a cycle
        CpuOracle cpu_ordering;
        GlOracle gl_ordering(context());
        cpu_ordering.setDepthTolerance(tolerance);
        gl_ordering.setDepthTolerance(tolerance);
        SceneOrderer cpu_orderer(scene.objectPrimitives(), uint32_t(scene.triangleCount()),
                                 GetParam().level, cpu_ordering);
        SceneOrderer gl_orderer(scene.objectPrimitives(), uint32_t(scene.triangleCount()),
                                GetParam().level, gl_ordering);
        const ViewProjection small = viewOf(scene, Projection::perspective, 128, 96);
        const FrameOrder expected_order = cpu_orderer.orderFrame(scene.positions, small);
        const FrameOrder got_order = gl_orderer.orderFrame(scene.positions, small);
        EXPECT_EQ(got_order.order, expected_order.order);
        EXPECT_EQ(got_order.cycles, expected_order.cycles);
        EXPECT_EQ(got_order.stats.queries, expected_order.stats.queries);
    }
}

std::string caseName(const testing::TestParamInfo<Case>& info) {
    std::string name = info.param.scene.substr(info.param.scene.find_last_of("/:") + 1);
    name = name.substr(0, name.find_first_of(".?"));
    return name + "_" + orderLevelName(info.param.level);
}

INSTANTIATE_TEST_SUITE_P(
    Scenes, GlOnScenes,
    testing::Values(Case{"tests/data/scenes/stack.json", OrderLevel::object},
                    Case{"tests/data/scenes/stack.json", OrderLevel::triangle},
                    Case{"tests/data/scenes/interpenetrating.json", OrderLevel::object},
                    Case{"tests/data/scenes/three_sticks.json", OrderLevel::triangle},
                    Case{"builtin:bunnies?n=3&seed=2", OrderLevel::object},
                    Case{"builtin:soup?n=300", OrderLevel::triangle}),
    caseName);

// Bunnies at 256 x 256 at every level: the gl order has no exact occlusion out of order outside
// a cycle, and its cycles contain the exact oracle's.
TEST(GlOracle, BunnyOrdersAtEveryLevelPassTheGroundTruth) {
    const Scene scene = test::loadTestScene("builtin:bunnies?n=6&seed=3");
    const ViewProjection view = viewOf(scene, Projection::perspective, 256, 256);
    for (OrderLevel level : {OrderLevel::object, OrderLevel::triangle, OrderLevel::multistage}) {
        SCOPED_TRACE(orderLevelName(level));
        const auto primitives = primitivesOf(scene, level);
        ExactOracle exact;
        GlOracle gl(context());
        SceneOrderer exact_orderer(scene.objectPrimitives(), uint32_t(scene.triangleCount()), level,
                                   exact);
        SceneOrderer gl_orderer(scene.objectPrimitives(), uint32_t(scene.triangleCount()), level,
                                gl);
        const FrameOrder expected = exact_orderer.orderFrame(scene.positions, view);
        const FrameOrder got = gl_orderer.orderFrame(scene.positions, view);
        EXPECT_TRUE(test::cyclesContained(expected.cycles, got.cycles));
        const test::OrderCheck check =
            test::checkVisibilityOrder(scene.positions, view, primitives, got.order, got.cycles);
        ASSERT_TRUE(check.valid_permutation);
        EXPECT_GT(check.pairs_checked, 0u);
        EXPECT_EQ(check.violation_count, 0u);
        std::printf("[ cycles   ] bunnies at %s level: %zu exact, %zu gl\n", orderLevelName(level),
                    expected.cycles.size(), got.cycles.size());
    }
}

// Each frame of a dynamic scene binds the new positions: every frame's gl order passes the
// exact ground truth at that frame, and the depth buffer of the frame's bind, everything drawn,
// bounds that frame's exact depths from below within 2^-20 (stale corners would not).
TEST(GlOracle, FramesOfADynamicSceneUpdateTheVertexBuffer) {
    const Scene scene = test::loadTestScene("builtin:bunnies?n=4&seed=7");
    ASSERT_TRUE(scene.isDynamic());
    const auto primitives = primitivesOf(scene, OrderLevel::object);
    GlOracle gl(context());
    SceneOrderer gl_orderer(scene.objectPrimitives(), uint32_t(scene.triangleCount()),
                            OrderLevel::object, gl);
    TrianglePositions positions;
    for (int f = 0; f < 4; ++f) {
        SCOPED_TRACE("frame " + std::to_string(f));
        scene.frame(f * 0.3, positions);
        const ViewProjection view = frameCamera(*scene.camera, positions.bounds(), 96, 96);
        const FrameOrder got = gl_orderer.orderFrame(positions, view);
        EXPECT_EQ(test::checkVisibilityOrder(positions, view, primitives, got.order, got.cycles)
                      .violation_count,
                  0u);
        ExactOracle exact(1);
        exact.bind(positions, view, primitives);
        gl.clear();
        std::vector<double> nearest(96 * 96, INFINITY);
        for (uint32_t p = 0; p < primitives.size(); ++p) {
            gl.draw(p);
            for (const ExactOracle::Fragment& fragment : exact.fragments(p))
                nearest[fragment.pixel] = std::min(nearest[fragment.pixel], fragment.nearest_depth);
        }
        const std::vector<float> depths = gl.depthBuffer();
        std::size_t covered = 0, wrong = 0;
        for (std::size_t i = 0; i < depths.size(); ++i) {
            covered += std::isfinite(nearest[i]) ? 1 : 0;
            const bool bounded = std::isinf(nearest[i])
                                     ? depths[i] == 1.0f
                                     : depths[i] <= nearest[i] && nearest[i] - depths[i] <= 0x1p-20;
            wrong += bounded ? 0 : 1;
        }
        EXPECT_GT(covered, 500u);
        EXPECT_LE(wrong * 500, covered) << wrong << " of " << covered;
    }
}

TEST(GlOracle, StatsCountQueriesDrawsAndCalls) {
    const Scene scene = test::loadTestScene("tests/data/scenes/stack.json");
    const auto primitives = primitivesOf(scene, OrderLevel::object);
    GlOracle gl(context());
    gl.bind(scene.positions, viewOf(scene, Projection::perspective, 64, 64), primitives);
    const auto n = uint32_t(primitives.size());
    std::vector<uint32_t> sequence(n);
    for (uint32_t i = 0; i < n; ++i)
        sequence[i] = i;
    std::vector<uint8_t> query(n, 0), behind(n, 0);
    query[0] = query[n / 2] = 1;
    gl.resetStats();
    gl.backToFrontPass(sequence, query, behind);
    EXPECT_EQ(gl.stats().queries, 2u);
    EXPECT_EQ(gl.stats().draws, n);
    // Draws between queries go out together: the 2 queries and at most 3 runs of draws.
    EXPECT_LE(gl.stats().draw_calls, 5u);
}

TEST(GlOracle, ErrorsNameTheLimit) {
    const Scene scene = test::loadTestScene("tests/data/scenes/stack.json");
    const auto primitives = primitivesOf(scene, OrderLevel::object);
    GlOracle gl(context());
    ViewProjection huge = viewOf(scene, Projection::perspective, 64, 64);
    huge.width = 1u << 16;
    try {
        gl.bind(scene.positions, huge, primitives);
        ADD_FAILURE() << "a 65536-pixel-wide framebuffer was accepted";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("65536x64"), std::string::npos) << e.what();
    }
    // Still usable at a size the driver allows.
    gl.bind(scene.positions, viewOf(scene, Projection::perspective, 32, 32), primitives);
    for (uint32_t p = 0; p < primitives.size(); ++p)
        gl.draw(p);
    const std::vector<float> depths = gl.depthBuffer();
    ASSERT_EQ(depths.size(), 32u * 32u);
    EXPECT_LT(*std::min_element(depths.begin(), depths.end()), 1.0f);
}

TEST(GlOracle, MadeByNameSharingOneContext) {
    const Result<OracleKind> parsed = parseOracleKind("gl");
    ASSERT_TRUE(parsed) << parsed.error;
    const OracleKind kind = *parsed.value;
    EXPECT_EQ(kind, OracleKind::gl);
    EXPECT_STREQ(oracleName(kind), "gl");
    const Result<std::unique_ptr<GeometryOracle>> first = makeOracle(OracleKind::gl);
    const Result<std::unique_ptr<GeometryOracle>> second = makeOracle(OracleKind::gl);
    ASSERT_TRUE(first) << first.error;
    ASSERT_TRUE(second) << second.error;
    const auto& a = dynamic_cast<const GlOracle&>(**first.value);
    const auto& b = dynamic_cast<const GlOracle&>(**second.value);
    EXPECT_EQ(&a.context(), &b.context());
}

} // namespace
} // namespace vissort
