#include "vissort/exact_oracle.h"

#include <algorithm>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "vissort/scene.h"

#include "scenes/scene_library.h"
#include "test_scenes.h"

namespace vissort {
namespace {

using test::addQuad;
using test::addTriangle;
using test::range;

// The oracle's contract replayed on brute-force hits (test_scenes.h), edges included.
class BruteForceOracle {
public:
    BruteForceOracle(const TrianglePositions& positions, const ViewProjection& view,
                     const std::vector<PrimitiveRange>& primitives)
        : hits_(test::bruteForceHits(positions, view)), primitive_of_(positions.triangleCount()),
          buffer_(hits_.size()) {
        std::fill(primitive_of_.begin(), primitive_of_.end(), kNone);
        for (uint32_t p = 0; p < primitives.size(); ++p) {
            for (uint32_t t = 0; t < primitives[p].triangle_count; ++t)
                primitive_of_[primitives[p].first_triangle + t] = p;
        }
        clear();
    }
    void clear() { std::fill(buffer_.begin(), buffer_.end(), kInfinity); }
    void draw(uint32_t p) {
        for (std::size_t pixel = 0; pixel < hits_.size(); ++pixel) {
            for (const test::BruteHit& hit : hits_[pixel])
                if (primitive_of_[hit.triangle] == p)
                    buffer_[pixel] = std::min(buffer_[pixel], hit.depth);
        }
    }
    bool anyBehind(uint32_t p) const {
        for (std::size_t pixel = 0; pixel < hits_.size(); ++pixel) {
            for (const test::BruteHit& hit : hits_[pixel])
                if (primitive_of_[hit.triangle] == p && hit.depth > buffer_[pixel])
                    return true;
        }
        return false;
    }
    // Pixels covered by p, with p's nearest and farthest hit there.
    std::vector<ExactOracle::Fragment> fragments(uint32_t p) const {
        std::vector<ExactOracle::Fragment> out;
        for (std::size_t pixel = 0; pixel < hits_.size(); ++pixel) {
            ExactOracle::Fragment f{uint32_t(pixel), 0, 0, kInfinity, -kInfinity};
            for (const test::BruteHit& hit : hits_[pixel]) {
                if (primitive_of_[hit.triangle] != p)
                    continue;
                f.nearest_depth = std::min(f.nearest_depth, hit.depth);
                f.farthest_depth = std::max(f.farthest_depth, hit.depth);
            }
            if (f.nearest_depth != kInfinity)
                out.push_back(f);
        }
        return out;
    }

private:
    static constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();
    static constexpr double kInfinity = std::numeric_limits<double>::infinity();
    std::vector<std::vector<test::BruteHit>> hits_;
    std::vector<uint32_t> primitive_of_;
    std::vector<double> buffer_;
};

TrianglePositions twoParallelQuads() {
    TrianglePositions positions;
    addQuad(positions, 1.0, 0.0);  // primitive 0, front
    addQuad(positions, 2.0, -1.0); // primitive 1, behind, larger
    return positions;
}

const std::vector<PrimitiveRange> kTwoQuads = {range(0, 2), range(2, 2)};

class ExactOracleViews : public ::testing::TestWithParam<Projection> {
protected:
    ViewProjection view(const TrianglePositions& positions, uint32_t width, uint32_t height) const {
        return GetParam() == Projection::perspective
                   ? test::perspectiveView(positions, {0.2, 0.1, 5}, width, height)
                   : test::orthographicView(positions, {0.05, -0.02, -1}, width, height);
    }
};

TEST_P(ExactOracleViews, FrontQuadHidesPartOfTheBackQuad) {
    const TrianglePositions positions = twoParallelQuads();
    ExactOracle oracle;
    oracle.bind(positions, view(positions, 40, 32), kTwoQuads);
    ASSERT_EQ(oracle.primitiveCount(), 2u);
    // The back quad is larger, so it covers every pixel of the front one and more.
    EXPECT_GT(oracle.fragments(1).size(), oracle.fragments(0).size());
    EXPECT_GT(oracle.fragments(0).size(), 20u);

    oracle.draw(0);
    EXPECT_TRUE(oracle.anyBehind(1));
    EXPECT_FALSE(oracle.anyBehind(0)); // a primitive is never behind itself
    oracle.clear();
    oracle.draw(1);
    EXPECT_FALSE(oracle.anyBehind(0));
    EXPECT_FALSE(oracle.anyBehind(1));
    oracle.draw(0);
    EXPECT_TRUE(oracle.anyBehind(1));
    oracle.clear();
    EXPECT_FALSE(oracle.anyBehind(0));
    EXPECT_FALSE(oracle.anyBehind(1));
}

TEST_P(ExactOracleViews, IdenticalCoplanarQuadsNeverOcclude) {
    TrianglePositions positions;
    addQuad(positions, 1.0, 0.0);
    addQuad(positions, 1.0, 0.0);
    ExactOracle oracle;
    oracle.bind(positions, view(positions, 32, 32), kTwoQuads);
    EXPECT_EQ(oracle.fragments(0).size(), oracle.fragments(1).size());
    oracle.draw(0);
    EXPECT_FALSE(oracle.anyBehind(1));
    oracle.clear();
    oracle.draw(1);
    EXPECT_FALSE(oracle.anyBehind(0));
}

TEST_P(ExactOracleViews, TriangleHidesOnlyWhatItCovers) {
    TrianglePositions positions;
    addQuad(positions, 1.0, -0.5); // 0: the quad, behind
    addTriangle(positions, {-0.5, -0.5, 0.5}, {0.5, -0.5, 0.5}, {0, 0.5, 0.5}); // 1: over it
    addTriangle(positions, {1.5, 1.5, 0.8}, {1.9, 1.5, 0.8}, {1.7, 1.9, 0.8});  // 2: beside it
    const std::vector<PrimitiveRange> primitives = {range(0, 2), range(2, 1), range(3, 1)};
    ExactOracle oracle;
    oracle.bind(positions, view(positions, 48, 48), primitives);
    oracle.draw(1);
    EXPECT_TRUE(oracle.anyBehind(0));
    EXPECT_FALSE(oracle.anyBehind(2));
    oracle.clear();
    oracle.draw(2);
    EXPECT_FALSE(oracle.anyBehind(0));
    EXPECT_FALSE(oracle.anyBehind(1));
    oracle.clear();
    oracle.draw(0);
    EXPECT_FALSE(oracle.anyBehind(1));
    EXPECT_FALSE(oracle.anyBehind(2));
}

INSTANTIATE_TEST_SUITE_P(BothProjections, ExactOracleViews,
                         ::testing::Values(Projection::perspective, Projection::orthographic));

TEST(ExactOracle, EmptyPrimitiveAndUnlistedTriangles) {
    const TrianglePositions positions = twoParallelQuads();
    // Primitive 0 has no triangle; triangles 0 and 1 (the front quad) belong to no primitive.
    const std::vector<PrimitiveRange> primitives = {range(0, 0), range(2, 2)};
    ExactOracle oracle;
    oracle.bind(positions, test::perspectiveView(positions, {0, 0, 5}, 16, 16), primitives);
    EXPECT_TRUE(oracle.fragments(0).empty());
    oracle.draw(0);
    EXPECT_FALSE(oracle.anyBehind(0));
    EXPECT_FALSE(oracle.anyBehind(1)); // the unlisted front quad is not drawn
    oracle.draw(1);
    EXPECT_FALSE(oracle.anyBehind(0));
}

TEST(ExactOracle, NoPrimitives) {
    const TrianglePositions positions = twoParallelQuads();
    ExactOracle oracle;
    oracle.bind(positions, test::perspectiveView(positions, {0, 0, 5}, 8, 8), {});
    EXPECT_EQ(oracle.primitiveCount(), 0u);
    oracle.clear();
}

// Random draws and queries, answered by the oracle and by brute force.
void expectSameAnswersAsBruteForce(const TrianglePositions& positions, const ViewProjection& view,
                                   const std::vector<PrimitiveRange>& primitives, uint32_t seed) {
    ExactOracle oracle(2);
    oracle.bind(positions, view, primitives);
    BruteForceOracle reference(positions, view, primitives);
    const uint32_t n = uint32_t(primitives.size());
    for (uint32_t p = 0; p < n; ++p) {
        const auto expected = reference.fragments(p);
        const auto actual = oracle.fragments(p);
        ASSERT_EQ(actual.size(), expected.size()) << "primitive " << p;
        for (std::size_t i = 0; i < expected.size(); ++i) {
            EXPECT_EQ(actual[i].pixel, expected[i].pixel);
            // Depths from two double computations of the same hit (the ranks are exact).
            EXPECT_NEAR(actual[i].nearest_depth, expected[i].nearest_depth, 1e-9);
            EXPECT_NEAR(actual[i].farthest_depth, expected[i].farthest_depth, 1e-9);
        }
    }
    std::mt19937 rng(seed);
    int behind_count = 0, query_count = 0;
    for (int round = 0; round < 12; ++round) {
        oracle.clear();
        reference.clear();
        const uint32_t draws = rng() % (n / 2 + 1);
        for (uint32_t i = 0; i < draws; ++i) {
            const uint32_t p = rng() % n;
            oracle.draw(p);
            reference.draw(p);
        }
        for (uint32_t p = 0; p < n; ++p) {
            const bool expected = reference.anyBehind(p);
            ASSERT_EQ(oracle.anyBehind(p), expected) << "round " << round << " primitive " << p;
            behind_count += expected;
            ++query_count;
        }
    }
    // Both answers must have occurred, or the comparison proves little.
    EXPECT_GT(behind_count, query_count / 10);
    EXPECT_LT(behind_count, query_count);
}

// One to three consecutive triangles per primitive.
std::vector<PrimitiveRange> randomGrouping(uint32_t triangle_count, uint32_t seed) {
    std::mt19937 rng(seed);
    std::vector<PrimitiveRange> primitives;
    for (uint32_t t = 0; t < triangle_count;) {
        const uint32_t count = std::min<uint32_t>(1 + rng() % 3, triangle_count - t);
        primitives.push_back(range(t, count));
        t += count;
    }
    return primitives;
}

TEST(ExactOracle, MatchesBruteForceOnRandomSoupsPerspective) {
    for (uint32_t seed : {21u, 22u, 23u}) {
        const TrianglePositions positions = test::randomLayeredSoup(45, seed);
        expectSameAnswersAsBruteForce(positions,
                                      test::perspectiveView(positions, {0.5, 0.3, 3.5}, 40, 36),
                                      randomGrouping(45, seed), seed);
    }
}

TEST(ExactOracle, MatchesBruteForceOnRandomSoupsOrthographic) {
    for (uint32_t seed : {31u, 32u}) {
        const TrianglePositions positions = test::randomLayeredSoup(45, seed);
        expectSameAnswersAsBruteForce(positions,
                                      test::orthographicView(positions, {-0.3, 0.2, -1}, 38, 42),
                                      randomGrouping(45, seed), seed);
    }
}

TEST(ExactOracle, MatchesBruteForceOnOneTrianglePerPrimitive) {
    const TrianglePositions positions = test::randomLayeredSoup(30, 41);
    std::vector<PrimitiveRange> primitives;
    for (uint32_t t = 0; t < 30; ++t)
        primitives.push_back(range(t, 1));
    expectSameAnswersAsBruteForce(
        positions, test::perspectiveView(positions, {-0.4, 0.6, 3}, 36, 36), primitives, 41);
}

TEST(ExactOracle, MatchesBruteForceOnSpotMesh) {
    const Result<Scene> loaded = samples::loadScene(VISSORT_SOURCE_DIR "/assets/models/spot.obj");
    ASSERT_TRUE(loaded) << loaded.error;
    const TrianglePositions& positions = loaded.value->positions;
    ASSERT_GT(positions.triangleCount(), 1000u);
    const Bounds bounds = positions.bounds();
    // Primitives of 64 consecutive triangles: patches of the surface that overlap on screen.
    std::vector<PrimitiveRange> primitives;
    for (uint32_t t = 0; t < positions.triangleCount(); t += 64)
        primitives.push_back(
            range(t, std::min<uint32_t>(64, uint32_t(positions.triangleCount()) - t)));
    expectSameAnswersAsBruteForce(positions, frameCamera(defaultCamera(bounds), bounds, 40, 40),
                                  primitives, 51);
    CameraSpec side;
    side.projection = Projection::orthographic;
    side.ortho_direction = {1, -0.2, 0.1};
    expectSameAnswersAsBruteForce(positions, frameCamera(side, bounds, 36, 30), primitives, 52);
}

} // namespace
} // namespace vissort
