// gatherPositions (vertex_positions.h): packed and interleaved vertex buffers, with and without
// indices, against corners written out by hand; every refusal is one line naming the problem.

#include "vissort/vertex_positions.h"

#include <gtest/gtest.h>

#include <limits>
#include <string>
#include <vector>

namespace vissort {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

void expectRefused(const VertexPositionsView& view, const std::string& contains) {
    TrianglePositions out;
    const Status status = gatherPositions(view, out);
    ASSERT_FALSE(status) << "expected an error containing '" << contains << "'";
    EXPECT_EQ(status.error.find('\n'), std::string::npos) << status.error;
    EXPECT_NE(status.error.find(contains), std::string::npos) << status.error;
}

TEST(GatherPositions, PackedWithoutIndicesIsTheCornersInOrder) {
    const std::vector<float> packed = {0, 1,  2,  3,  4,  5,  6,  7,  8,
                                       9, 10, 11, 12, 13, 14, 15, 16, 17};
    TrianglePositions out;
    ASSERT_TRUE(gatherPositions({packed.data(), 6}, out));
    EXPECT_EQ(out.x, (std::vector<float>{0, 3, 6, 9, 12, 15}));
    EXPECT_EQ(out.y, (std::vector<float>{1, 4, 7, 10, 13, 16}));
    EXPECT_EQ(out.z, (std::vector<float>{2, 5, 8, 11, 14, 17}));
}

TEST(GatherPositions, InterleavedIndexedReadsOnlyThePositionsOfTheVerticesNamed) {
    // Four vertices of a square, position then a normal that is not a position (NaN: it would
    // be refused if read); vertex 3 is never named and is not finite either.
    const std::vector<float> interleaved = {
        0,    0, 0, kNaN, kNaN, kNaN, //
        1,    0, 0, kNaN, kNaN, kNaN, //
        1,    1, 0, kNaN, kNaN, kNaN, //
        kNaN, 0, 0, 0,    0,    1,    //
        0,    1, 0, kNaN, kNaN, kNaN,
    };
    const std::vector<uint32_t> indices = {0, 1, 2, 0, 2, 4};
    TrianglePositions out;
    const Status status = gatherPositions({interleaved.data(), 5, 6 * sizeof(float), indices}, out);
    ASSERT_TRUE(status) << status.error;
    EXPECT_EQ(out.triangleCount(), 2u);
    EXPECT_EQ(out.x, (std::vector<float>{0, 1, 1, 0, 1, 0}));
    EXPECT_EQ(out.y, (std::vector<float>{0, 0, 1, 0, 1, 1}));
    EXPECT_EQ(out.z, (std::vector<float>(6, 0.0f)));
}

TEST(GatherPositions, ReusesTheOutputAcrossSizes) {
    const std::vector<float> packed(27, 1.0f);
    TrianglePositions out;
    ASSERT_TRUE(gatherPositions({packed.data(), 9}, out));
    EXPECT_EQ(out.triangleCount(), 3u);
    ASSERT_TRUE(gatherPositions({packed.data(), 3}, out));
    EXPECT_EQ(out.triangleCount(), 1u);
    EXPECT_EQ(out.x.size(), 3u);
}

TEST(GatherPositions, RefusesWhatItCannotRead) {
    const std::vector<float> v(18, 0.5f);
    expectRefused({v.data(), 6, 8}, "vertex stride 8 bytes");
    expectRefused({v.data(), 6, 14}, "vertex stride 14 bytes");
    expectRefused({v.data(), 1, 4096}, "vertex stride 4096 bytes");
    expectRefused({nullptr, 6}, "vertex data is null");
    expectRefused({v.data(), 5}, "5 vertices without indices");
    expectRefused({v.data(), 0}, "no triangles");
    const std::vector<uint32_t> four = {0, 1, 2, 3};
    expectRefused({v.data(), 6, 12, four}, "4 indices");
    const std::vector<uint32_t> outside = {0, 1, 2, 3, 4, 6};
    expectRefused({v.data(), 6, 12, outside}, "triangle 1 names vertex 6, outside 0..5");
    std::vector<float> infinite = v;
    infinite[3 * 4 + 1] = std::numeric_limits<float>::infinity();
    expectRefused({infinite.data(), 6}, "triangle 1, corner 1 is not finite (vertex 4)");
}

} // namespace
} // namespace vissort
