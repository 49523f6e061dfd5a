// The CPU side of the checked blend's repair (no OpenGL): the marks read back from the stencil
// (MarkedPixels: count, bounds, the tiles that hold one) and the triangles that may cover them
// (trianglesCovering), against brute force over every pixel; and the groups blended in sequence
// (blendGroupsInSequence).

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "render/draw_sequence.h"
#include "render/marked_pixels.h"
#include "vissort/camera.h"

namespace vissort::detail {
namespace {

std::vector<uint8_t> randomMarks(uint32_t width, uint32_t height, double density,
                                 std::mt19937& random) {
    std::bernoulli_distribution marked(density);
    std::vector<uint8_t> stencil(std::size_t(width) * height);
    for (uint8_t& s : stencil)
        s = marked(random) ? 1 : 0;
    return stencil;
}

bool anyMarkedIn(const std::vector<uint8_t>& stencil, uint32_t width, uint32_t height, uint32_t x0,
                 uint32_t y0, uint32_t x1, uint32_t y1) { // [x0, x1) x [y0, y1)
    for (uint32_t y = y0; y < std::min(y1, height); ++y)
        for (uint32_t x = x0; x < std::min(x1, width); ++x)
            if (stencil[std::size_t(y) * width + x] != 0)
                return true;
    return false;
}

TEST(MarkedPixels, CountBoundsAndTilesMatchBruteForce) {
    std::mt19937 random(7);
    const uint32_t side = MarkedPixels::kTileSide;
    for (const auto& [width, height, density] :
         {std::tuple{37u, 21u, 0.0}, std::tuple{37u, 21u, 0.002}, std::tuple{64u, 40u, 0.01},
          std::tuple{100u, 3u, 0.05}, std::tuple{1u, 1u, 1.0}, std::tuple{9u, 17u, 0.3}}) {
        SCOPED_TRACE(testing::Message() << width << "x" << height << " density " << density);
        const std::vector<uint8_t> stencil = randomMarks(width, height, density, random);
        const MarkedPixels marked(stencil, width, height);
        uint64_t count = 0;
        uint32_t x0 = width, y0 = height, x1 = 0, y1 = 0;
        for (uint32_t y = 0; y < height; ++y)
            for (uint32_t x = 0; x < width; ++x)
                if (stencil[std::size_t(y) * width + x] != 0) {
                    ++count;
                    x0 = std::min(x0, x), y0 = std::min(y0, y);
                    x1 = std::max(x1, x), y1 = std::max(y1, y);
                }
        EXPECT_EQ(marked.count(), count);
        if (count == 0) {
            EXPECT_TRUE(marked.bounds().empty());
        } else {
            EXPECT_EQ(marked.bounds().x, x0);
            EXPECT_EQ(marked.bounds().y, y0);
            EXPECT_EQ(marked.bounds().width, x1 - x0 + 1);
            EXPECT_EQ(marked.bounds().height, y1 - y0 + 1);
        }
        std::uniform_int_distribution<uint32_t> coordinate(0, std::max(width, height) + 4);
        for (int trial = 0; trial < 500; ++trial) {
            const PixelRect rect{coordinate(random), coordinate(random), coordinate(random) / 2,
                                 coordinate(random) / 2};
            // The answer is per tile: any mark in the tiles the rectangle overlaps.
            const bool expected =
                !rect.empty() &&
                anyMarkedIn(stencil, width, height, rect.x / side * side, rect.y / side * side,
                            (rect.x + rect.width + side - 1) / side * side,
                            (rect.y + rect.height + side - 1) / side * side);
            EXPECT_EQ(marked.anyTileIn(rect), expected)
                << rect.x << "," << rect.y << " " << rect.width << "x" << rect.height;
        }
        // The tiles listed for the repair's resolve: exactly those holding a mark, in rows.
        std::vector<uint32_t> tiles;
        for (uint32_t ty = 0; ty < height; ty += side)
            for (uint32_t tx = 0; tx < width; tx += side)
                if (anyMarkedIn(stencil, width, height, tx, ty, tx + side, ty + side))
                    tiles.insert(tiles.end(), {tx, ty});
        EXPECT_EQ(marked.tileOrigins(), tiles);
    }
}

// Whether the triangle's projection covers the centre of pixel (px, py), by edge functions in
// double: the rasterizers' rule up to rounding on the edges.
bool coversCentre(const ViewProjection& view, const std::array<Vec3, 3>& corners, uint32_t px,
                  uint32_t py) {
    std::array<double, 3> sx, sy;
    for (int k = 0; k < 3; ++k) {
        const std::array<double, 4> clip = view.toClip(corners[k]);
        sx[k] = (clip[0] / clip[3] + 1) * 0.5 * view.width;
        sy[k] = (1 - clip[1] / clip[3]) * 0.5 * view.height;
    }
    const double cx = px + 0.5, cy = py + 0.5;
    double sign = 0;
    for (int k = 0; k < 3; ++k) {
        const int n = (k + 1) % 3;
        const double edge = (sx[n] - sx[k]) * (cy - sy[k]) - (sy[n] - sy[k]) * (cx - sx[k]);
        if (edge != 0 && sign != 0 && (edge > 0) != (sign > 0))
            return false;
        if (edge != 0)
            sign = edge;
    }
    return true;
}

TEST(TrianglesCovering, KeepsEveryTriangleOverAMarkedPixel) {
    std::mt19937 random(11);
    const uint32_t width = 96, height = 64;
    CameraSpec camera;
    camera.eye = {0, 0, 6};
    camera.target = {0, 0, 0};
    Bounds bounds;
    bounds.add({-2, -2, -2});
    bounds.add({2, 2, 2});
    const ViewProjection view = frameCamera(camera, bounds, width, height);
    std::uniform_real_distribution<float> centre(-2.0f, 2.0f), offset(-0.4f, 0.4f);
    TrianglePositions positions;
    const std::size_t count = 400;
    positions.resize(count);
    for (std::size_t t = 0; t < count; ++t) {
        const float cx = centre(random), cy = centre(random), cz = centre(random);
        for (std::size_t k = 0; k < 3; ++k) {
            positions.x[t * 3 + k] = cx + offset(random);
            positions.y[t * 3 + k] = cy + offset(random);
            positions.z[t * 3 + k] = cz + offset(random);
        }
    }
    std::vector<uint32_t> all(count);
    for (uint32_t t = 0; t < count; ++t)
        all[t] = t;
    for (double density : {0.0005, 0.003, 0.02}) {
        SCOPED_TRACE(density);
        const std::vector<uint8_t> stencil = randomMarks(width, height, density, random);
        const MarkedPixels marked(stencil, width, height);
        std::vector<uint32_t> covering;
        trianglesCovering(positions, all, view, marked, covering);
        EXPECT_TRUE(std::is_sorted(covering.begin(), covering.end())); // the order given
        EXPECT_LT(covering.size(), count); // a selection, not everything
        uint32_t over_marks = 0;
        for (uint32_t t = 0; t < count; ++t) {
            const std::array<Vec3, 3> corners{positions.corner(t * 3), positions.corner(t * 3 + 1),
                                              positions.corner(t * 3 + 2)};
            bool over_mark = false;
            for (uint32_t y = 0; y < height && !over_mark; ++y)
                for (uint32_t x = 0; x < width && !over_mark; ++x)
                    over_mark = stencil[std::size_t(y) * width + x] != 0 &&
                                coversCentre(view, corners, x, y);
            if (!over_mark)
                continue;
            ++over_marks;
            EXPECT_TRUE(std::binary_search(covering.begin(), covering.end(), t))
                << "triangle " << t << " covers a marked pixel";
        }
        EXPECT_GT(over_marks, 0u); // the check above checked something
    }
    // No marks: nothing to draw again.
    const std::vector<uint8_t> none(std::size_t(width) * height, 0);
    std::vector<uint32_t> covering{1, 2};
    trianglesCovering(positions, all, view, MarkedPixels(none, width, height), covering);
    EXPECT_TRUE(covering.empty());
}

TEST(BlendGroupsInSequence, GroupsGoBackToFrontInOneRun) {
    // Five triangles, one a unit farther along -z than the last: ids 0 (z = 0) to 4 (z = -4).
    TrianglePositions positions;
    positions.resize(5);
    for (std::size_t t = 0; t < 5; ++t)
        for (std::size_t k = 0; k < 3; ++k) {
            positions.x[t * 3 + k] = k == 1 ? 1.0f : 0.0f;
            positions.y[t * 3 + k] = k == 2 ? 1.0f : 0.0f;
            positions.z[t * 3 + k] = -float(t);
        }
    CameraSpec camera;
    camera.eye = {0, 0, 5};
    camera.target = {0, 0, 0};
    const ViewProjection view = frameCamera(camera, positions.bounds(), 64, 64);
    // Back to front: 4 alone; then a group {0, 3, 1} in id order; then 2 alone.
    DrawSequence sequence;
    sequence.triangles = {4, 0, 3, 1, 2};
    sequence.segments = {{0, 1, false, {}}, {1, 3, true, {}}, {4, 1, false, {}}};
    blendGroupsInSequence(positions, view, sequence);
    EXPECT_EQ(sequence.triangles, (std::vector<uint32_t>{4, 3, 1, 0, 2}));
    ASSERT_EQ(sequence.segments.size(), 1u);
    EXPECT_EQ(sequence.segments[0].first_triangle, 0u);
    EXPECT_EQ(sequence.segments[0].triangle_count, 5u);
    EXPECT_FALSE(sequence.segments[0].per_pixel);

    DrawSequence empty;
    blendGroupsInSequence(positions, view, empty);
    EXPECT_TRUE(empty.segments.empty());
}

} // namespace
} // namespace vissort::detail
