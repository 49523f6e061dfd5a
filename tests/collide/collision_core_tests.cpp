// The collision layer on its own (vissort_collide, without vissort_peers): its methods work,
// and a peer method is a clear error until registerPeerColliders is called. The process-wide
// registration is why this is a test program of its own.

#include <gtest/gtest.h>

#include <map>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "vissort/collision.h"

namespace vissort {
namespace {

// Two unit cubes' worth of triangles is more than needed: two triangles that cross.
TrianglePositions twoCrossingTriangles() {
    TrianglePositions p;
    const float corners[6][3] = {{-1, 0, -1}, {1, 0, -1}, {0, 0, 1},     // in the plane y = 0
                                 {0, -1, 0},  {0, 1, 0},  {0.2f, 1, 0}}; // through it
    for (const auto& c : corners) {
        p.x.push_back(c[0]);
        p.y.push_back(c[1]);
        p.z.push_back(c[2]);
    }
    return p;
}

const std::vector<PrimitiveRange> kTwoObjects = {{0, 1}, {1, 1}};

TEST(CollisionCore, VissortAndBruteNeedNoPeers) {
    const TrianglePositions positions = twoCrossingTriangles();
    for (CollisionMethod method : {CollisionMethod::vissort, CollisionMethod::brute}) {
        CollisionSettings settings;
        settings.method = method;
        CollisionDetector detector(kTwoObjects, settings);
        const CollisionResult result = detector.collide(positions.view());
        ASSERT_EQ(result.pairs.size(), 1u) << collisionMethodName(method);
        EXPECT_EQ(result.pairs[0], (TrianglePair{0, 1}));
    }
}

// The colliding objects are named by their index in the detector's list, whatever order their
// triangles come in: three objects given in reverse triangle order, a far triangle between two
// crossing ones.
TEST(CollisionCore, ObjectPairsNameTheObjectsAsTheyWereGiven) {
    TrianglePositions positions = twoCrossingTriangles();
    // Triangle 1 moves far away and triangle 2 (a copy of the old triangle 1) crosses triangle 0.
    for (int k = 0; k < 3; ++k) {
        positions.x.push_back(positions.x[3 + k]);
        positions.y.push_back(positions.y[3 + k]);
        positions.z.push_back(positions.z[3 + k]);
        positions.x[3 + k] += 100;
    }
    const std::vector<PrimitiveRange> reversed = {{2, 1}, {1, 1}, {0, 1}}; // objects 0, 1, 2
    for (CollisionMethod method : {CollisionMethod::vissort, CollisionMethod::brute}) {
        SCOPED_TRACE(collisionMethodName(method));
        CollisionSettings settings;
        settings.method = method;
        CollisionDetector detector(reversed, settings);
        const CollisionResult result = detector.collide(positions.view());
        ASSERT_EQ(result.pairs, (std::vector<TrianglePair>{{0, 2}}));
        // Triangle 0 is object 2's, triangle 2 object 0's: the pair (0, 2), first < second.
        EXPECT_EQ(result.object_pairs, (std::vector<ObjectPair>{{0, 2}}));
        EXPECT_EQ(result.stats.colliding_object_pairs, 1u);
        // Apart, nothing collides.
        TrianglePositions apart = positions;
        for (int k = 6; k < 9; ++k)
            apart.x[k] -= 100;
        const CollisionResult none = detector.collide(apart.view());
        EXPECT_TRUE(none.object_pairs.empty());
        EXPECT_EQ(none.stats.colliding_object_pairs, 0u);
    }
}

TEST(CollisionStats, FieldTableNamesEveryFieldOnce) {
    CollisionStats s;
    s.box_object_pairs = 1;
    s.object_pairs = 2;
    s.box_triangle_pairs = 3;
    s.triangle_pairs = 4;
    s.intersecting = 5;
    s.candidate_objects = 6;
    s.colliding_object_pairs = 13;
    s.directions = 7;
    s.queries = 8;
    s.update_ms = 9.5;
    s.cull_ms = 10.5;
    s.exact_ms = 11.5;
    s.total_ms = 12.5;
    std::map<std::string, double> seen;
    forEachStat(s, [&](std::string_view name, auto value) {
        EXPECT_TRUE(seen.emplace(std::string(name), double(value)).second) << name;
    });
    EXPECT_EQ(seen, (std::map<std::string, double>{{"box_object_pairs", 1},
                                                   {"object_pairs", 2},
                                                   {"box_triangle_pairs", 3},
                                                   {"triangle_pairs", 4},
                                                   {"intersecting", 5},
                                                   {"candidate_objects", 6},
                                                   {"colliding_object_pairs", 13},
                                                   {"directions", 7},
                                                   {"queries", 8},
                                                   {"update_ms", 9.5},
                                                   {"cull_ms", 10.5},
                                                   {"exact_ms", 11.5},
                                                   {"total_ms", 12.5}}));
    EXPECT_EQ(sizeof(CollisionStats),
              6 * sizeof(uint64_t) + 2 * sizeof(uint32_t) + sizeof(uint64_t) + 4 * sizeof(double));
}

TEST(CollisionCore, PeerMethodsSayHowToGetThem) {
    for (CollisionMethod method : {CollisionMethod::bullet, CollisionMethod::fcl}) {
        CollisionSettings settings;
        settings.method = method;
        try {
            CollisionDetector detector(kTwoObjects, settings);
            ADD_FAILURE() << collisionMethodName(method) << " was made without the peers";
        } catch (const std::invalid_argument& e) {
            const std::string message = e.what();
            EXPECT_NE(message.find(collisionMethodName(method)), std::string::npos) << message;
            EXPECT_NE(message.find("vissort::peers"), std::string::npos) << message;
            EXPECT_NE(message.find("registerPeerColliders"), std::string::npos) << message;
        }
    }
}

} // namespace
} // namespace vissort
