// Boxes as columns (collide/box_columns.h): a mask of four or eight tests must say exactly what
// boxesOverlap says of each pair, touching boxes included, and never set a bit past the boxes.

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "collide/box_columns.h"

namespace vissort::detail {
namespace {

// Boxes on a coarse integer grid, so that many pairs touch exactly (closed boxes meet there).
Box3f gridBox(std::mt19937& random) {
    std::uniform_int_distribution<int> corner(0, 6), extent(0, 3);
    Box3f box;
    for (int k = 0; k < 3; ++k) {
        box.min[k] = float(corner(random));
        box.max[k] = box.min[k] + float(extent(random));
    }
    return box;
}

TEST(BoxColumns, MasksOfFourSayWhatEachPairTestSays) {
    std::mt19937 random(7);
    for (int round = 0; round < 200; ++round) {
        std::vector<Box3f> boxes(1 + round % 13);
        BoxColumns columns;
        for (Box3f& box : boxes) {
            box = gridBox(random);
            columns.push(box);
        }
        columns.pad();
        ASSERT_EQ(columns.size(), boxes.size());
        const Box3f probe = gridBox(random);
        const BoxLanes lanes(probe);
        for (std::size_t first = 0; first < boxes.size(); ++first) {
            const unsigned mask = overlapMask4(lanes, columns, first);
            for (std::size_t i = 0; i < BoxColumns::kLanes; ++i) {
                const bool expected =
                    first + i < boxes.size() && boxesOverlap(probe, boxes[first + i]);
                EXPECT_EQ(((mask >> i) & 1) != 0, expected)
                    << "round " << round << " box " << first + i;
            }
        }
    }
}

TEST(BoxColumns, TouchingBoxesMeetAndSeparatedOnesDoNot) {
    BoxColumns columns;
    columns.push({{1, 0, 0}, {2, 1, 1}});                      // touches the probe's face x = 1
    columns.push({{1.0001f, 0, 0}, {2, 1, 1}});                // just past it
    columns.push({{0, 0, 1}, {1, 1, 2}});                      // touches the face z = 1
    columns.push({{0.25f, 0.25f, 0.25f}, {0.5f, 0.5f, 0.5f}}); // inside
    columns.pad();
    const Box3f probe = {{0, 0, 0}, {1, 1, 1}};
    EXPECT_EQ(overlapMask4(BoxLanes(probe), columns, 0), 0b1101u);
}

TEST(BoxColumns, MasksOfEightKeepToTheCountAsked) {
    std::mt19937 random(11);
    BoxColumns columns;
    std::vector<Box3f> boxes(20);
    for (Box3f& box : boxes) {
        box = {{0, 0, 0}, {4, 4, 4}}; // every one meets the probe
        columns.push(box);
    }
    columns.pad();
    const BoxLanes lanes(Box3f{{1, 1, 1}, {2, 2, 2}});
    for (std::size_t first = 0; first < boxes.size(); ++first)
        for (std::size_t count = 1; count <= 8 && first + count <= boxes.size(); ++count)
            EXPECT_EQ(overlapMask8(lanes, columns, first, count), (1u << count) - 1)
                << "first " << first << " count " << count;
    // The boxes past the last one are the padding's empty boxes: never a bit there.
    EXPECT_EQ(overlapMask8(lanes, columns, boxes.size() - 1, 8), 1u);
}

TEST(BoxColumns, ClearedColumnsForgetTheirBoxes) {
    BoxColumns columns;
    for (int i = 0; i < 9; ++i)
        columns.push({{0, 0, 0}, {1, 1, 1}});
    columns.pad();
    columns.clear();
    columns.push({{5, 5, 5}, {6, 6, 6}});
    columns.pad();
    // Only the new box: the old ones after it are padding now.
    EXPECT_EQ(overlapMask8(BoxLanes(Box3f{{0, 0, 0}, {1, 1, 1}}), columns, 0, 8), 0u);
    EXPECT_EQ(overlapMask8(BoxLanes(Box3f{{5.5f, 5.5f, 5.5f}, {7, 7, 7}}), columns, 0, 8), 1u);
}

TEST(BoxColumns, SetBoxesReadBack) {
    std::mt19937 random(3);
    BoxColumns columns;
    columns.resize(6);
    std::vector<Box3f> boxes(6);
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        boxes[i] = gridBox(random);
        columns.set(i, boxes[i]);
    }
    for (std::size_t i = 0; i < boxes.size(); ++i)
        for (int k = 0; k < 3; ++k) {
            EXPECT_EQ(columns.box(i).min[k], boxes[i].min[k]);
            EXPECT_EQ(columns.box(i).max[k], boxes[i].max[k]);
        }
    // Past the boxes, the padding: meets nothing.
    EXPECT_EQ(overlapMask4(BoxLanes(Box3f{{-100, -100, -100}, {100, 100, 100}}), columns, 5), 1u);
}

} // namespace
} // namespace vissort::detail
