// The vissort collision method against the ground truth: its pairs must be brute force's, pair
// for pair, on dynamic bunnies, real meshes that interpenetrate, boxes touching face to face and
// at small gaps either way, degenerate triangles and random soups, at any resolution and along
// any directions. Brute force itself is checked on cases whose answer is known by construction.

#include <cmath>
#include <memory>
#include <random>
#include <stdexcept>

#include <gtest/gtest.h>

#include "collide/interval_oracle.h"
#include "collide/triangle_intersection.h"
#include "scenes/scene_library.h"
#include "vissort/collision.h"
#include "vissort/scene.h"

namespace vissort {
namespace {

struct Objects {
    TrianglePositions positions;
    std::vector<PrimitiveRange> ranges;

    void addTriangle(const Vec3& a, const Vec3& b, const Vec3& c) {
        for (const Vec3& p : {a, b, c}) {
            positions.x.push_back(float(p.x));
            positions.y.push_back(float(p.y));
            positions.z.push_back(float(p.z));
        }
        ranges.back().triangle_count += 1;
    }
    void beginObject() { ranges.push_back({uint32_t(positions.triangleCount()), 0}); }
    /// A closed box from lo to hi, rotated by angle (radians) about the z axis through pivot.
    void addBox(const Vec3& lo, const Vec3& hi, double angle = 0, Vec3 pivot = {}) {
        beginObject();
        const auto corner = [&](int i) {
            Vec3 p{i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z};
            const double x = p.x - pivot.x, y = p.y - pivot.y;
            return Vec3{pivot.x + std::cos(angle) * x - std::sin(angle) * y,
                        pivot.y + std::sin(angle) * x + std::cos(angle) * y, p.z};
        };
        const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                 {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
        for (const auto& f : faces) {
            addTriangle(corner(f[0]), corner(f[1]), corner(f[2]));
            addTriangle(corner(f[0]), corner(f[2]), corner(f[3]));
        }
    }
};

CollisionResult run(const Objects& objects, CollisionSettings settings) {
    CollisionDetector detector(objects.ranges, settings);
    return detector.collide(objects.positions);
}

void expectSamePairs(const CollisionResult& expected, const CollisionResult& actual,
                     const std::string& what) {
    EXPECT_EQ(expected.pairs.size(), actual.pairs.size()) << what;
    EXPECT_TRUE(expected.pairs == actual.pairs) << what << ": the pairs differ";
}

CollisionSettings method(CollisionMethod m) {
    CollisionSettings settings;
    settings.method = m;
    return settings;
}

TEST(CollisionDetector, BunniesMatchBruteForceFrameByFrame) {
    const Result<Scene> scene = samples::loadScene("builtin:bunnies?n=18");
    ASSERT_TRUE(scene) << scene.error;
    const auto objects = scene.value->objectPrimitives();
    CollisionDetector brute(objects, method(CollisionMethod::brute));
    CollisionSettings paper = method(CollisionMethod::vissort);
    paper.object_stage = ObjectStage::always; // the object stage on every frame, coherent ones
    CollisionDetector vissort(objects, paper);
    TrianglePositions positions;
    CollisionResult expected, actual;
    uint64_t total = 0;
    for (int f = 0; f < 45; ++f) {
        scene.value->frame(f / 30.0, positions);
        brute.collide(positions, expected);
        vissort.collide(positions, actual);
        expectSamePairs(expected, actual, "frame " + std::to_string(f));
        total += expected.pairs.size();
        EXPECT_EQ(actual.stats.intersecting, actual.pairs.size());
        EXPECT_GE(actual.stats.triangle_pairs, actual.stats.intersecting);
        // Visibility culled object pairs that boxes alone keep.
        EXPECT_LE(actual.stats.object_pairs, expected.stats.object_pairs);
        EXPECT_GE(actual.stats.directions, 1u);
    }
    EXPECT_GT(total, 45u * 500) << "the bunnies collide many times a frame";
}

TEST(CollisionDetector, VertexBufferFramesGiveBruteForcesPairs) {
    // Frames of the bunnies as an interleaved buffer (position, then a normal-sized gap that is
    // not finite) with indices running backwards over it: the vissort method's pairs from the
    // buffer are brute force's from the arrays.
    const Result<Scene> scene = samples::loadScene("builtin:bunnies?n=6");
    ASSERT_TRUE(scene) << scene.error;
    const auto objects = scene.value->objectPrimitives();
    CollisionDetector brute(objects, method(CollisionMethod::brute));
    CollisionDetector vissort(objects, method(CollisionMethod::vissort));
    TrianglePositions positions;
    std::vector<float> interleaved;
    std::vector<uint32_t> indices;
    CollisionResult expected, actual;
    std::size_t total = 0;
    for (int f = 0; f < 4; ++f) {
        scene.value->frame(f / 10.0, positions);
        const std::size_t corners = positions.x.size();
        interleaved.assign(6 * corners, std::nanf(""));
        indices.resize(corners);
        for (std::size_t c = 0; c < corners; ++c) {
            const std::size_t v = corners - 1 - c; // the buffer holds the corners backwards
            interleaved[6 * v] = positions.x[c];
            interleaved[6 * v + 1] = positions.y[c];
            interleaved[6 * v + 2] = positions.z[c];
            indices[c] = uint32_t(v);
        }
        brute.collide(positions, expected);
        vissort.collide({interleaved.data(), corners, 6 * sizeof(float), indices}, actual);
        expectSamePairs(expected, actual, "frame " + std::to_string(f));
        total += expected.pairs.size();
    }
    EXPECT_GT(total, 0u) << "no frame has a pair to compare";
    indices[5] = uint32_t(interleaved.size()); // outside the buffer
    EXPECT_THROW(vissort.collide({interleaved.data(), indices.size(), 24, indices}, actual),
                 std::invalid_argument);
}

// The threads share the refits and the pairs: the answer must not depend on how many there are,
// or on which finished first (run under ThreadSanitizer by CI). The object stage runs on every
// frame or on none, so that the counts can be compared too (the adaptive schedule follows
// measured times, which differ from run to run; its pairs are tested against brute force's).
TEST(CollisionThreads, EveryThreadCountGivesThePairsOfOne) {
    const Result<Scene> scene = samples::loadScene("builtin:bunnies?n=12");
    ASSERT_TRUE(scene) << scene.error;
    const auto objects = scene.value->objectPrimitives();
    for (ObjectStage stage : {ObjectStage::always, ObjectStage::never}) {
        std::vector<std::unique_ptr<CollisionDetector>> detectors;
        for (uint32_t threads : {1u, 2u, 3u, 0u}) {
            CollisionSettings settings;
            settings.threads = threads;
            settings.object_stage = stage;
            detectors.push_back(std::make_unique<CollisionDetector>(objects, settings));
        }
        TrianglePositions positions;
        uint64_t total = 0;
        for (int f = 0; f < 4; ++f) {
            scene.value->frame(0.3 * f, positions);
            const CollisionResult one = detectors[0]->collide(positions);
            total += one.pairs.size();
            for (std::size_t d = 1; d < detectors.size(); ++d) {
                const CollisionResult many = detectors[d]->collide(positions);
                expectSamePairs(one, many,
                                "detector " + std::to_string(d) + " frame " + std::to_string(f));
                EXPECT_EQ(many.stats.triangle_pairs, one.stats.triangle_pairs);
                EXPECT_EQ(many.stats.object_pairs, one.stats.object_pairs);
            }
        }
        EXPECT_GT(total, 100u);
    }
}

// An object that meets others on some frames only: the vissort method refits the trees of
// last frame's paired objects first and the others once this frame's pairs are known, and
// Bullet's broad phase adds and drops the pair; every frame must still be brute force's.
TEST(CollisionDetector, ObjectsThatMeetOnSomeFramesOnlyMatchBruteForce) {
    Objects scene;
    scene.addBox({0, 0, 0}, {1, 1, 1});
    scene.addBox({3, 0, 0}, {4, 1, 1});
    scene.addBox({0, 0, 0}, {1, 1, 1}, 0.3, {0.5, 0.5, 0.5}); // moved each frame
    const std::size_t moving_first = 3 * scene.ranges[2].first_triangle;
    // Apart, through the first box, apart, through the second, through the first again.
    const double offsets[] = {1.6, 0.4, 1.6, 3.3, 0.6, 10};
    std::vector<std::pair<std::string, CollisionSettings>> methods;
    for (CollisionMethod m : {CollisionMethod::vissort, CollisionMethod::bullet})
        for (uint32_t threads : {1u, 2u}) {
            CollisionSettings settings = method(m);
            settings.threads = threads;
            methods.emplace_back(std::string(collisionMethodName(m)) + " on " +
                                     std::to_string(threads) + " threads",
                                 settings);
        }
    CollisionDetector brute(scene.ranges, method(CollisionMethod::brute));
    std::vector<std::unique_ptr<CollisionDetector>> detectors;
    for (const auto& [name, settings] : methods)
        detectors.push_back(std::make_unique<CollisionDetector>(scene.ranges, settings));
    std::size_t frames_with_pairs = 0;
    for (double offset : offsets) {
        TrianglePositions frame = scene.positions;
        for (std::size_t c = moving_first; c < frame.x.size(); ++c)
            frame.x[c] += float(offset);
        const CollisionResult expected = brute.collide(frame);
        frames_with_pairs += !expected.pairs.empty();
        for (std::size_t i = 0; i < methods.size(); ++i)
            expectSamePairs(expected, detectors[i]->collide(frame),
                            methods[i].first + " at offset " + std::to_string(offset));
    }
    EXPECT_EQ(frames_with_pairs, 3u); // the frames meant to touch do
}

// The object stage's schedule changes the time, never the pairs: every frame of every mode is
// brute force's; always runs it every frame, never on none, adaptive on the first at least.
TEST(CollisionDetector, EveryObjectStageScheduleGivesBruteForcesPairs) {
    const Result<Scene> scene = samples::loadScene("builtin:bunnies?n=18");
    ASSERT_TRUE(scene) << scene.error;
    const auto objects = scene.value->objectPrimitives();
    CollisionDetector brute(objects, method(CollisionMethod::brute));
    for (ObjectStage stage : {ObjectStage::adaptive, ObjectStage::always, ObjectStage::never}) {
        CollisionSettings settings;
        settings.object_stage = stage;
        CollisionDetector vissort(objects, settings);
        uint32_t frames_with_stage = 0;
        TrianglePositions positions;
        const int frames = 12;
        for (int f = 0; f < frames; ++f) {
            scene.value->frame(f / 30.0, positions);
            const CollisionResult result = vissort.collide(positions);
            expectSamePairs(brute.collide(positions), result,
                            std::string(objectStageName(stage)) + " frame " + std::to_string(f));
            frames_with_stage += result.stats.directions > 0;
            if (f == 0 && stage != ObjectStage::never) {
                EXPECT_GT(result.stats.directions, 0u) << objectStageName(stage);
            }
            if (result.stats.directions == 0) {
                EXPECT_EQ(result.stats.object_pairs, result.stats.box_object_pairs);
            }
        }
        if (stage == ObjectStage::always) {
            EXPECT_EQ(frames_with_stage, uint32_t(frames));
        }
        if (stage == ObjectStage::never) {
            EXPECT_EQ(frames_with_stage, 0u);
        }
    }
    EXPECT_TRUE(parseObjectStage("sometimes").error.find("sometimes") != std::string::npos);
}

// Small objects (boxes of 12 triangles) pair with each other by the scan of their triangle
// boxes and with large ones (bunnies of 3,674) by the trees; objects switch between the two as
// their partners and the object stage's frames change. Every frame must be brute force's.
TEST(CollisionDetector, SmallAndLargeObjectsTogetherMatchBruteForce) {
    const Result<Scene> bunnies = samples::loadScene("builtin:bunnies?n=6");
    ASSERT_TRUE(bunnies) << bunnies.error;
    Objects scene;
    scene.positions = bunnies.value->positions;
    scene.ranges = bunnies.value->objectPrimitives();
    const std::size_t bunny_corners = scene.positions.x.size();
    std::mt19937 random(5);
    std::uniform_real_distribution<double> place(-2.5, 2.5), turn(0, 3);
    for (int i = 0; i < 40; ++i) { // boxes of side 0.6, many overlapping each other or a bunny
        const Vec3 lo{place(random), place(random), place(random)};
        scene.addBox(lo, {lo.x + 0.6, lo.y + 0.6, lo.z + 0.6}, turn(random), lo);
    }
    CollisionDetector brute(scene.ranges, method(CollisionMethod::brute));
    for (ObjectStage stage : {ObjectStage::adaptive, ObjectStage::always, ObjectStage::never})
        for (uint32_t threads : {1u, 2u}) {
            CollisionSettings settings;
            settings.object_stage = stage;
            settings.threads = threads;
            CollisionDetector vissort(scene.ranges, settings);
            uint64_t small_pairs_found = 0;
            for (int f = 0; f < 8; ++f) {
                TrianglePositions frame = bunnies.value->frame(f / 10.0);
                frame.x.resize(scene.positions.x.size());
                frame.y.resize(scene.positions.y.size());
                frame.z.resize(scene.positions.z.size());
                for (std::size_t c = bunny_corners; c < frame.x.size(); ++c) {
                    frame.x[c] = scene.positions.x[c] + float(0.05 * f);
                    frame.y[c] = scene.positions.y[c];
                    frame.z[c] = scene.positions.z[c];
                }
                const CollisionResult expected = brute.collide(frame);
                expectSamePairs(expected, vissort.collide(frame),
                                std::string(objectStageName(stage)) + ", " +
                                    std::to_string(threads) + " threads, frame " +
                                    std::to_string(f));
                const uint32_t first_box_triangle = uint32_t(bunny_corners / 3);
                for (const TrianglePair& p : expected.pairs)
                    small_pairs_found += p.first >= first_box_triangle;
            }
            EXPECT_GT(small_pairs_found, 0u) << "boxes meet boxes: the scan is exercised";
        }
}

TEST(CollisionDetector, VisibilityCullsObjectPairsThatBoxesKeep) {
    const Result<Scene> scene = samples::loadScene("builtin:bunnies?n=36");
    ASSERT_TRUE(scene) << scene.error;
    const auto objects = scene.value->objectPrimitives();
    const TrianglePositions positions = scene.value->frame(1.0);
    const CollisionResult brute =
        CollisionDetector(objects, method(CollisionMethod::brute)).collide(positions);
    const CollisionResult vissort = CollisionDetector(objects).collide(positions);
    expectSamePairs(brute, vissort, "bunnies n=36");
    EXPECT_LT(vissort.stats.object_pairs, brute.stats.object_pairs);
}

TEST(CollisionDetector, RealMeshesThatInterpenetrate) {
    const Result<Scene> scene = samples::loadScene(std::string(VISSORT_SOURCE_DIR) +
                                                   "/tests/data/scenes/interpenetrating.json");
    ASSERT_TRUE(scene) << scene.error;
    const auto objects = scene.value->objectPrimitives();
    const CollisionResult brute =
        CollisionDetector(objects, method(CollisionMethod::brute)).collide(scene.value->positions);
    EXPECT_GT(brute.pairs.size(), 20u);
    for (uint32_t size : {1u, 7u, 64u, 512u}) {
        CollisionSettings settings;
        settings.width = settings.height = size;
        expectSamePairs(brute, run({scene.value->positions, objects}, settings),
                        "size " + std::to_string(size));
    }
}

// Collisions are between the objects a user names: two copies of a file of four meshes (claws
// piercing shells), far apart. Entries of a JSON scene are one object each: no pair meets.
// With every mesh an object, the claws meet their shells: brute force's pairs, all inside a copy.
TEST(CollisionDetector, ObjectsAreTheEntriesAUserNamed) {
    const std::string scenes = std::string(VISSORT_SOURCE_DIR) + "/tests/data/scenes/";
    const Result<Scene> entries = samples::loadScene(scenes + "two_crab_files.json");
    const Result<Scene> meshes = samples::loadScene(scenes + "two_crab_files_by_mesh.json");
    ASSERT_TRUE(entries) << entries.error;
    ASSERT_TRUE(meshes) << meshes.error;
    ASSERT_EQ(entries.value->objects.size(), 2u);
    ASSERT_EQ(meshes.value->objects.size(), 8u);
    for (CollisionMethod m : {CollisionMethod::brute, CollisionMethod::vissort}) {
        const CollisionResult whole =
            CollisionDetector(entries.value->objectPrimitives(), method(m))
                .collide(entries.value->positions);
        EXPECT_TRUE(whole.pairs.empty()) << collisionMethodName(m);
        EXPECT_TRUE(whole.object_pairs.empty()) << collisionMethodName(m);
    }
    const auto ranges = meshes.value->objectPrimitives();
    const CollisionResult brute =
        CollisionDetector(ranges, method(CollisionMethod::brute)).collide(meshes.value->positions);
    // Each claw crosses its shell's plane from (0.75, 1.1) to (1.25, 1), across the quad's
    // diagonal y = x: it meets both of its shell's triangles. 4 crabs, 2 pairs each.
    EXPECT_EQ(brute.pairs.size(), 8u);
    for (const ObjectPair& pair : brute.object_pairs) // both objects in one copy: 0-3 or 4-7
        EXPECT_EQ(pair.first / 4, pair.second / 4);
    expectSamePairs(brute, run({meshes.value->positions, ranges}, CollisionSettings{}), "by mesh");
}

// Two unit boxes, the second moved along x by 1 + gap (negative gaps overlap), then both turned
// about z: face-to-face contact exactly at gap 0 when unturned.
TEST(CollisionDetector, BoxesFaceToFaceAtSmallGaps) {
    for (double angle : {0.0, 0.3}) {
        for (double gap : {-1e-3, -1e-5, 0.0, 1e-5, 1e-3}) {
            Objects boxes;
            boxes.addBox({0, 0, 0}, {1, 1, 1}, angle);
            boxes.addBox({1 + gap, 0.25, 0.5}, {2 + gap, 1.25, 1.5}, angle);
            const CollisionResult brute = run(boxes, method(CollisionMethod::brute));
            const std::string what =
                "angle " + std::to_string(angle) + " gap " + std::to_string(gap);
            if (angle == 0.0) {
                // Exact coordinates: the answer is known.
                if (gap <= 0)
                    EXPECT_GT(brute.pairs.size(), 0u) << what;
                else
                    EXPECT_EQ(brute.pairs.size(), 0u) << what;
            }
            for (uint32_t size : {1u, 16u, 64u, 1024u}) {
                CollisionSettings settings;
                settings.width = settings.height = size;
                expectSamePairs(brute, run(boxes, settings),
                                what + " size " + std::to_string(size));
            }
        }
    }
}

// Random thin triangles, several per object, crowded so that many touch, graze or nearly miss;
// zero-area triangles (points and segments) among them.
Objects randomSoup(uint32_t seed, int objects, int triangles_per_object) {
    std::mt19937_64 rng(seed);
    const auto unit = [&] { return double(rng() >> 11) * 0x1.0p-53; };
    Objects soup;
    for (int o = 0; o < objects; ++o) {
        soup.beginObject();
        const Vec3 centre{unit() * 3, unit() * 3, unit() * 3};
        for (int t = 0; t < triangles_per_object; ++t) {
            Vec3 c[3];
            for (Vec3& p : c)
                p = {centre.x + (unit() - 0.5), centre.y + (unit() - 0.5),
                     centre.z + (unit() - 0.5)};
            switch (t % 7) {
            case 5:
                c[2] = c[1];
                break; // a segment
            case 6:
                c[1] = c[2] = c[0];
                break; // a point
            case 4:
                c[2] = {c[0].x, c[1].y, c[0].z};
                c[1].x = c[0].x;
                break; // edge-on along x
            default:
                break;
            }
            soup.addTriangle(c[0], c[1], c[2]);
        }
    }
    return soup;
}

TEST(CollisionDetector, RandomSoupsAtAnyResolutionAndDirection) {
    uint64_t total = 0;
    for (uint32_t seed = 1; seed <= 6; ++seed) {
        const Objects soup = randomSoup(seed, 12, 14);
        const CollisionResult brute = run(soup, method(CollisionMethod::brute));
        total += brute.pairs.size();
        for (uint32_t size : {1u, 3u, 64u, 300u}) {
            CollisionSettings settings;
            settings.width = size;
            settings.height = size / 3 + 1;
            if (seed % 2)
                settings.directions = {{0.3, -0.5, 0.8}, {-1, 0.2, 0.1}};
            expectSamePairs(brute, run(soup, settings),
                            "seed " + std::to_string(seed) + " size " + std::to_string(size));
        }
    }
    EXPECT_GT(total, 50u) << "the soups must collide";
}

// Triangles that touch at exactly one point or along an edge, in exactly representable
// coordinates, are found; moved apart by one float step they are not.
TEST(CollisionDetector, TouchingAtAPointOrAnEdgeCounts) {
    Objects touching;
    touching.beginObject();
    touching.addTriangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
    touching.beginObject();
    touching.addTriangle({0.25, 0.25, 0}, {0.25, 0.25, 1}, {1, 1, 1}); // a vertex on the face
    touching.beginObject();
    touching.addTriangle({1, 0, 0}, {2, 0, 0}, {1.5, 0, -1}); // shares the corner (1, 0, 0)
    const CollisionResult brute = run(touching, method(CollisionMethod::brute));
    const CollisionResult vissort = run(touching, {});
    ASSERT_EQ(brute.pairs.size(), 2u);
    expectSamePairs(brute, vissort, "touching");

    Objects apart = touching;
    apart.positions.z[3] = std::nextafter(0.0f, 1.0f); // the vertex just above the face
    apart.positions.x[6] = std::nextafter(1.0f, 2.0f); // the corner just beside
    apart.positions.x[7] = std::nextafter(2.0f, 3.0f);
    apart.positions.x[8] = std::nextafter(1.5f, 3.0f);
    EXPECT_EQ(run(apart, method(CollisionMethod::brute)).pairs.size(), 0u);
    EXPECT_EQ(run(apart, {}).pairs.size(), 0u);
}

TEST(CollisionDetector, EmptyAndSingleObjects) {
    Objects one;
    one.addBox({0, 0, 0}, {1, 1, 1});
    EXPECT_TRUE(run(one, {}).pairs.empty()) << "no self-collision";
    Objects none;
    EXPECT_TRUE(run(none, {}).pairs.empty());
}

TEST(CollisionDetector, RejectsBadSettings) {
    Objects one;
    one.addBox({0, 0, 0}, {1, 1, 1});
    CollisionSettings settings;
    settings.width = 0;
    EXPECT_THROW(CollisionDetector(one.ranges, settings), std::invalid_argument);
    settings = {};
    settings.height = 5000;
    EXPECT_THROW(CollisionDetector(one.ranges, settings), std::invalid_argument);
    settings = {};
    settings.directions = {{0, 0, 0}};
    EXPECT_THROW(CollisionDetector(one.ranges, settings), std::invalid_argument);
    settings.directions = {{NAN, 0, 1}};
    EXPECT_THROW(CollisionDetector(one.ranges, settings), std::invalid_argument);
}

TEST(CollisionDetector, RejectsPositionsThatDoNotFit) {
    Objects two;
    two.addBox({0, 0, 0}, {1, 1, 1});
    two.addBox({0.5, 0.5, 0.5}, {2, 2, 2});
    for (CollisionMethod m : collisionMethods()) {
        CollisionDetector detector(two.ranges, method(m));
        TrianglePositions short_positions = two.positions;
        short_positions.resize(20);
        EXPECT_THROW(detector.collide(short_positions), std::invalid_argument);
        TrianglePositions not_finite = two.positions;
        not_finite.y[40] = NAN;
        EXPECT_THROW(detector.collide(not_finite), std::invalid_argument);
        not_finite.y[40] = INFINITY;
        EXPECT_THROW(detector.collide(not_finite), std::invalid_argument);
        // At either end of an array too (the check runs in blocks, the last one partial).
        not_finite = two.positions;
        not_finite.x.front() = -INFINITY;
        EXPECT_THROW(detector.collide(not_finite), std::invalid_argument);
        not_finite = two.positions;
        not_finite.z.back() = NAN;
        EXPECT_THROW(detector.collide(not_finite), std::invalid_argument);
        EXPECT_FALSE(detector.collide(two.positions).pairs.empty()) << "still usable";
    }
}

// A triangle in two objects would collide with itself: refused, in any order of the ranges.
TEST(CollisionDetector, RejectsObjectsThatShareTriangles) {
    Objects two;
    two.addBox({0, 0, 0}, {1, 1, 1});
    two.addBox({3, 0, 0}, {4, 1, 1});
    std::vector<PrimitiveRange> shared = {two.ranges[1], two.ranges[0]};
    shared[0].first_triangle -= 1; // object 0 takes the last triangle of object 1
    shared[0].triangle_count += 1;
    for (CollisionMethod m : collisionMethods()) {
        try {
            CollisionDetector detector(shared, method(m));
            ADD_FAILURE() << collisionMethodName(m) << ": accepted shared triangles";
        } catch (const std::invalid_argument& e) {
            EXPECT_STREQ(e.what(), "collision objects 0 and 1 share triangles (each triangle "
                                   "belongs to one object)");
        }
        EXPECT_NO_THROW(CollisionDetector(two.ranges, method(m))) << "disjoint ranges";
    }
}

TEST(CollisionDetector, MethodNamesRoundTrip) {
    for (CollisionMethod m : collisionMethods()) {
        const Result<CollisionMethod> parsed = parseCollisionMethod(collisionMethodName(m));
        ASSERT_TRUE(parsed) << parsed.error;
        EXPECT_EQ(*parsed.value, m);
    }
    const Result<CollisionMethod> unknown = parseCollisionMethod("bvh");
    EXPECT_FALSE(unknown);
    EXPECT_NE(unknown.error, "");
}

TEST(CollisionDetector, CollidingTrianglesAreTheUnionOfThePairs) {
    const std::vector<TrianglePair> pairs{{1, 5}, {1, 7}, {3, 5}};
    EXPECT_EQ(collidingTriangles(pairs), (std::vector<uint32_t>{1, 3, 5, 7}));
}

// The oracle's promise, on its own: two triangles that share a point are each behind the other,
// whatever the direction and resolution (each bound as its own box).
TEST(IntervalOracle, TouchingTrianglesOccludeEachOther) {
    std::mt19937_64 rng(9);
    const auto unit = [&] { return double(rng() >> 11) * 0x1.0p-53; };
    int checked = 0, mutual_without_touching = 0;
    for (int round = 0; round < 400; ++round) {
        Objects pair;
        pair.beginObject();
        Vec3 a[3], b[3];
        for (Vec3& p : a)
            p = {unit(), unit(), unit()};
        for (Vec3& p : b)
            p = {unit(), unit(), unit()};
        if (round % 2)
            b[0] = a[0]; // share a corner exactly
        pair.addTriangle(a[0], a[1], a[2]);
        pair.beginObject();
        pair.addTriangle(b[0], b[1], b[2]);
        const bool touch = detail::trianglesIntersect(detail::cornersOf(pair.positions, 0),
                                                      detail::cornersOf(pair.positions, 1));
        detail::IntervalOracle oracle;
        const detail::Box3f frame{{0, 0, 0}, {1, 1, 1}};
        // Along an axis, or any direction.
        const Vec3 direction = round % 3 == 0 ? Vec3{0, 0, round % 2 ? 1.0 : -1.0}
                                              : Vec3{unit() - 0.5, unit() - 0.5, unit() - 0.5};
        std::vector<detail::Box3f> boxes;
        detail::computeTriangleBoxes(pair.positions, boxes);
        const std::vector<uint32_t> starts{0, 1, 2};
        oracle.bind(boxes, starts, frame, direction, 1 + round % 97, 1 + round % 31);
        oracle.clear();
        oracle.draw(0);
        const bool b_behind = oracle.anyBehind(1);
        oracle.clear();
        oracle.draw(1);
        const bool a_behind = oracle.anyBehind(0);
        if (touch) {
            ++checked;
            EXPECT_TRUE(a_behind && b_behind) << "round " << round;
        } else {
            mutual_without_touching += a_behind && b_behind;
        }
    }
    EXPECT_GT(checked, 150);
    EXPECT_LT(mutual_without_touching, 400 - checked) << "some apart pairs are told apart";
}

} // namespace
} // namespace vissort
