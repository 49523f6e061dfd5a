// The peers of the collision methods (src/collide/bullet_collider.cpp, fcl_collider.cpp) against
// brute force, the ground truth: bullet pair for pair, fcl measured (it uses its own tests).

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <iterator>
#include <string>
#include <vector>

#include "scenes/scene_library.h"
#include "vissort/collision.h"
#include "vissort/scene.h"
#include "vissort/worker_pool.h"

namespace vissort {
namespace {

CollisionSettings settingsFor(CollisionMethod method) {
    CollisionSettings settings;
    settings.method = method;
    return settings;
}

Scene loadBunnies(int n) {
    Result<Scene> loaded = samples::loadScene("builtin:bunnies?n=" + std::to_string(n));
    EXPECT_TRUE(loaded) << loaded.error;
    return loaded ? std::move(*loaded.value) : Scene{};
}

/// The stats every method must keep consistent with its pairs.
void expectConsistent(const CollisionResult& result) {
    EXPECT_EQ(result.stats.intersecting, result.pairs.size());
    EXPECT_GE(result.stats.triangle_pairs, result.stats.intersecting);
    EXPECT_TRUE(std::is_sorted(result.pairs.begin(), result.pairs.end()));
    EXPECT_TRUE(std::adjacent_find(result.pairs.begin(), result.pairs.end()) == result.pairs.end());
    for (const TrianglePair& p : result.pairs)
        EXPECT_LT(p.first, p.second);
}

/// Bullet against brute force on the same positions: the same pairs and, since both cull with
/// the same exact closed triangle boxes, the same candidate counts.
void expectBulletEqualsBrute(CollisionDetector& bullet, CollisionDetector& brute,
                             const TrianglePositions& positions, const std::string& what) {
    SCOPED_TRACE(what);
    const CollisionResult expected = brute.collide(positions);
    const CollisionResult actual = bullet.collide(positions);
    expectConsistent(actual);
    EXPECT_EQ(actual.pairs, expected.pairs);
    EXPECT_EQ(actual.stats.object_pairs, expected.stats.object_pairs);
    EXPECT_EQ(actual.stats.triangle_pairs, expected.stats.triangle_pairs);
    EXPECT_EQ(actual.stats.candidate_objects, expected.stats.candidate_objects);
}

/// The 12 triangles of the closed axis-aligned cube [x0, x0 + 1] x [0, 1] x [0, 1], appended.
void appendCube(TrianglePositions& positions, float x0) {
    const auto corner = [x0](int i) {
        return std::array<float, 3>{x0 + float(i & 1), float((i >> 1) & 1), float((i >> 2) & 1)};
    };
    // Two triangles per face, corners indexed by bits (x, y, z).
    static const int kFaces[6][4] = {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                     {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}};
    for (const auto& f : kFaces)
        for (const auto& tri : {std::array<int, 3>{f[0], f[1], f[2]}, {f[0], f[2], f[3]}})
            for (int c : tri) {
                const auto p = corner(c);
                positions.x.push_back(p[0]);
                positions.y.push_back(p[1]);
                positions.z.push_back(p[2]);
            }
}

/// Two unit cubes, the second starting at x = second_x.
TrianglePositions twoCubes(float second_x) {
    TrianglePositions positions;
    appendCube(positions, 0);
    appendCube(positions, second_x);
    return positions;
}

const std::vector<PrimitiveRange> kTwoCubeObjects = {{0, 12}, {12, 12}};

// --- bullet ---

TEST(PeerColliders, BulletEqualsBruteOnBunnyFrames) {
    const Scene scene = loadBunnies(18);
    const std::vector<PrimitiveRange> objects = scene.objectPrimitives();
    CollisionDetector bullet(objects, settingsFor(CollisionMethod::bullet));
    CollisionDetector brute(objects, settingsFor(CollisionMethod::brute));
    TrianglePositions positions;
    uint64_t found = 0;
    // Far-apart frames in one detector: the trees built at t = 0 are refitted, never rebuilt.
    for (double t : {0.0, 1.0 / 30, 0.5, 2.0}) {
        scene.frame(t, positions);
        expectBulletEqualsBrute(bullet, brute, positions, "t = " + std::to_string(t));
        found += bullet.collide(positions).pairs.size();
    }
    EXPECT_GT(found, 0u); // the frames do collide: the comparison is not vacuous
}

TEST(PeerColliders, BulletEqualsBruteOnThirtySixBunnies) {
    const Scene scene = loadBunnies(36);
    const std::vector<PrimitiveRange> objects = scene.objectPrimitives();
    CollisionDetector bullet(objects, settingsFor(CollisionMethod::bullet));
    CollisionDetector brute(objects, settingsFor(CollisionMethod::brute));
    expectBulletEqualsBrute(bullet, brute, scene.frame(0.5), "n = 36, t = 0.5");
}

TEST(PeerColliders, BulletStaysEqualToBruteFrameAfterFrame) {
    const Scene scene = loadBunnies(18);
    const std::vector<PrimitiveRange> objects = scene.objectPrimitives();
    CollisionDetector bullet(objects, settingsFor(CollisionMethod::bullet));
    CollisionDetector brute(objects, settingsFor(CollisionMethod::brute));
    TrianglePositions positions;
    CollisionResult actual, expected; // reused, as a steady-state caller does
    for (int frame = 0; frame < 5; ++frame) {
        SCOPED_TRACE("frame " + std::to_string(frame));
        scene.frame(1.0 + frame / 30.0, positions);
        bullet.collide(positions, actual);
        brute.collide(positions, expected);
        expectConsistent(actual);
        EXPECT_EQ(actual.pairs, expected.pairs);
        EXPECT_EQ(actual.stats.triangle_pairs, expected.stats.triangle_pairs);
    }
}

// The refits and the object pairs are shared over the threads, as the vissort method's are:
// the answer must not depend on how many, nor on the pool they come from.
TEST(PeerColliders, BulletOnAnyThreadsEqualsBrute) {
    const Scene scene = loadBunnies(18);
    const std::vector<PrimitiveRange> objects = scene.objectPrimitives();
    CollisionDetector brute(objects, settingsFor(CollisionMethod::brute));
    WorkerPool own_pool(3);
    for (uint32_t threads : {2u, 3u, 0u}) {
        for (WorkerPool* pool : {static_cast<WorkerPool*>(nullptr), &own_pool}) {
            CollisionSettings settings = settingsFor(CollisionMethod::bullet);
            settings.threads = threads;
            settings.pool = pool;
            CollisionDetector bullet(objects, settings);
            for (double t : {0.0, 1.0 / 30, 2.0})
                expectBulletEqualsBrute(bullet, brute, scene.frame(t),
                                        std::to_string(threads) + " threads" +
                                            (pool ? " of its own pool" : "") +
                                            ", t = " + std::to_string(t));
        }
    }
}

TEST(PeerColliders, BulletFindsCubesTouchingFaceToFace) {
    // The cubes share the plane x = 1 and touch nowhere else: every pair found lies on it.
    const TrianglePositions positions = twoCubes(1);
    CollisionDetector bullet(kTwoCubeObjects, settingsFor(CollisionMethod::bullet));
    CollisionDetector brute(kTwoCubeObjects, settingsFor(CollisionMethod::brute));
    const CollisionResult result = bullet.collide(positions);
    expectConsistent(result);
    EXPECT_EQ(result.pairs, brute.collide(positions).pairs);
    EXPECT_FALSE(result.pairs.empty());
    // The two faces on x = 1 (triangles 2, 3 of the first cube, 12, 13 of the second) meet
    // each other all four ways.
    for (uint32_t a : {2u, 3u})
        for (uint32_t b : {12u, 13u})
            EXPECT_TRUE(
                std::binary_search(result.pairs.begin(), result.pairs.end(), TrianglePair{a, b}))
                << a << " " << b;
    EXPECT_EQ(result.stats.object_pairs, 1u);
    EXPECT_EQ(result.stats.candidate_objects, 2u);
}

TEST(PeerColliders, BulletFindsNothingBetweenDisjointObjects) {
    const TrianglePositions positions = twoCubes(3);
    CollisionDetector bullet(kTwoCubeObjects, settingsFor(CollisionMethod::bullet));
    const CollisionResult result = bullet.collide(positions);
    EXPECT_TRUE(result.pairs.empty());
    EXPECT_EQ(result.stats.object_pairs, 0u);
    EXPECT_EQ(result.stats.triangle_pairs, 0u);
    EXPECT_EQ(result.stats.candidate_objects, 0u);
    // Nor within one object: the cube's own faces touch each other but are never reported.
    const std::vector<PrimitiveRange> one_object = {{0, 24}};
    CollisionDetector single(one_object, settingsFor(CollisionMethod::bullet));
    EXPECT_TRUE(single.collide(positions).pairs.empty());
}

TEST(PeerColliders, ObjectWithoutTrianglesMeetsNothing) {
    const TrianglePositions positions = twoCubes(1);
    const std::vector<PrimitiveRange> with_empty = {{0, 12}, {12, 0}, {12, 12}};
    CollisionDetector brute(kTwoCubeObjects, settingsFor(CollisionMethod::brute));
    const CollisionResult expected = brute.collide(positions);
    for (CollisionMethod method : {CollisionMethod::bullet, CollisionMethod::fcl}) {
        SCOPED_TRACE(collisionMethodName(method));
        CollisionDetector detector(with_empty, settingsFor(method));
        const CollisionResult result = detector.collide(positions);
        expectConsistent(result);
        EXPECT_EQ(result.stats.candidate_objects, 2u);
        if (method == CollisionMethod::bullet) {
            EXPECT_EQ(result.pairs, expected.pairs);
        }
    }
}

// --- fcl: measured against brute force, not required to equal it ---

struct Disagreement {
    std::vector<TrianglePair> misses, inventions;
};

Disagreement compare(const std::vector<TrianglePair>& expected,
                     const std::vector<TrianglePair>& actual) {
    Disagreement d;
    std::set_difference(expected.begin(), expected.end(), actual.begin(), actual.end(),
                        std::back_inserter(d.misses));
    std::set_difference(actual.begin(), actual.end(), expected.begin(), expected.end(),
                        std::back_inserter(d.inventions));
    return d;
}

void printDisagreement(const char* what, std::size_t truth, const Disagreement& d) {
    std::printf("[ fcl      ] %s: %zu true pairs, %zu missed, %zu invented", what, truth,
                d.misses.size(), d.inventions.size());
    for (std::size_t i = 0; i < std::min<std::size_t>(d.misses.size(), 5); ++i)
        std::printf("%s(%u,%u)", i == 0 ? "; missed " : " ", d.misses[i].first, d.misses[i].second);
    for (std::size_t i = 0; i < std::min<std::size_t>(d.inventions.size(), 5); ++i)
        std::printf("%s(%u,%u)", i == 0 ? "; invented " : " ", d.inventions[i].first,
                    d.inventions[i].second);
    std::printf("\n");
}

TEST(PeerColliders, FclFindsMostPairsOnBunnyFrames) {
    const Scene scene = loadBunnies(18);
    const std::vector<PrimitiveRange> objects = scene.objectPrimitives();
    CollisionDetector fcl(objects, settingsFor(CollisionMethod::fcl));
    CollisionDetector brute(objects, settingsFor(CollisionMethod::brute));
    TrianglePositions positions;
    for (double t : {0.0, 1.0 / 30, 0.5, 2.0}) {
        const std::string what = "t = " + std::to_string(t);
        SCOPED_TRACE(what);
        scene.frame(t, positions);
        const CollisionResult expected = brute.collide(positions);
        const CollisionResult actual = fcl.collide(positions);
        expectConsistent(actual);
        EXPECT_EQ(actual.stats.object_pairs, expected.stats.object_pairs);
        EXPECT_EQ(actual.stats.exact_ms, 0.0);
        const Disagreement d = compare(expected.pairs, actual.pairs);
        printDisagreement(what.c_str(), expected.pairs.size(), d);
        EXPECT_GE(2 * (expected.pairs.size() - d.misses.size()), expected.pairs.size());
    }
}

TEST(PeerColliders, FclOnTouchingAndDisjointCubes) {
    for (float second_x : {1.0f, 3.0f}) {
        const std::string what = "second cube at x = " + std::to_string(second_x);
        SCOPED_TRACE(what);
        const TrianglePositions positions = twoCubes(second_x);
        CollisionDetector fcl(kTwoCubeObjects, settingsFor(CollisionMethod::fcl));
        CollisionDetector brute(kTwoCubeObjects, settingsFor(CollisionMethod::brute));
        const CollisionResult expected = brute.collide(positions);
        const CollisionResult actual = fcl.collide(positions);
        expectConsistent(actual);
        printDisagreement(what.c_str(), expected.pairs.size(),
                          compare(expected.pairs, actual.pairs));
        if (expected.pairs.empty()) {
            EXPECT_TRUE(actual.pairs.empty()); // boxes apart: culled
        }
    }
}

} // namespace
} // namespace vissort
