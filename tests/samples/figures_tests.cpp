// The samples' figures (samples/figures/): the side-by-side strip lays each tile out at its
// place, every pixel of it kept; the line plot draws each series in its colour, higher values
// higher up.

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "figures/comparison_strip.h"
#include "figures/line_plot.h"

namespace vissort::samples {
namespace {

std::vector<uint8_t> filled(uint32_t width, uint32_t height, uint8_t r, uint8_t g, uint8_t b) {
    std::vector<uint8_t> rgba;
    for (uint32_t i = 0; i < width * height; ++i)
        rgba.insert(rgba.end(), {r, g, b, 255});
    return rgba;
}

struct Found {
    uint64_t count = 0;
    double mean_x = 0, mean_y = 0;
};

// The pixels of one colour (x below max_x): how many and where on average.
Found find(const Strip& strip, const uint8_t colour[3], uint32_t max_x = UINT32_MAX) {
    Found found;
    for (uint32_t y = 0; y < strip.height; ++y)
        for (uint32_t x = 0; x < strip.width && x < max_x; ++x) {
            const uint8_t* p = &strip.rgba[(std::size_t(y) * strip.width + x) * 4];
            if (p[0] == colour[0] && p[1] == colour[1] && p[2] == colour[2]) {
                ++found.count;
                found.mean_x += x;
                found.mean_y += y;
            }
        }
    if (found.count > 0) {
        found.mean_x /= double(found.count);
        found.mean_y /= double(found.count);
    }
    return found;
}

TEST(ComparisonStrip, EveryTileAtItsPlaceInOrder) {
    constexpr uint32_t kW = 12, kH = 9;
    const uint8_t red[3] = {250, 10, 10}, green[3] = {10, 250, 10}, blue[3] = {10, 10, 250};
    const std::vector<StripTile> tiles = {{filled(kW, kH, 250, 10, 10), "red"},
                                          {filled(kW, kH, 10, 250, 10), "green\ntwo lines"},
                                          {filled(kW, kH, 10, 10, 250), ""}};
    const Strip strip = composeStrip(tiles, kW, kH, 2);
    ASSERT_EQ(strip.rgba.size(), std::size_t(strip.width) * strip.height * 4);
    EXPECT_GE(strip.width, 2 * kW);
    EXPECT_GE(strip.height, 2 * kH);
    const Found r = find(strip, red), g = find(strip, green), b = find(strip, blue);
    EXPECT_EQ(r.count, kW * kH); // every pixel of each tile, no caption over it
    EXPECT_EQ(g.count, kW * kH);
    EXPECT_EQ(b.count, kW * kH);
    EXPECT_LT(r.mean_x, g.mean_x);        // two to a row: green right of red
    EXPECT_DOUBLE_EQ(r.mean_y, g.mean_y); // on the same row
    EXPECT_GT(b.mean_y, r.mean_y + kH);   // blue a row below
    EXPECT_DOUBLE_EQ(b.mean_x, r.mean_x); // under red
}

TEST(LinePlot, EachSeriesInItsColourHigherValuesHigherUp) {
    const std::vector<PlotSeries> series = {{"low", {1, 2, 3, 4}, {1, 1, 1, 1}},
                                            {"high", {1, 2, 3, 4}, {100, 100, 100, 100}}};
    const Strip plot = plotLines(series, "title", "x", "y", 600, 400);
    ASSERT_EQ(plot.width, 600u);
    ASSERT_EQ(plot.height, 400u);
    ASSERT_EQ(plot.rgba.size(), 600u * 400 * 4);
    // The first two colours of the palette; the legend (right) is left out.
    const uint8_t first[3] = {214, 39, 40}, second[3] = {31, 119, 180};
    const Found low = find(plot, first, 300), high = find(plot, second, 300);
    EXPECT_GT(low.count, 100u);
    EXPECT_GT(high.count, 100u);
    EXPECT_LT(high.mean_y, low.mean_y - 50); // a hundred times larger: well above
}

// On a logarithmic x axis a decade is as wide wherever it lies; on a linear one, ten times wider
// from 10 to 100 than from 1 to 10. Each decade is a series of its own colour: their mean x are a
// decade apart.
TEST(LinePlot, LogarithmicXGivesEachDecadeTheSameWidth) {
    const std::vector<PlotSeries> series = {
        {"a", {1, 10}, {1, 1}}, {"b", {10, 100}, {10, 10}}, {"c", {100, 1000}, {100, 100}}};
    const uint8_t colours[3][3] = {{214, 39, 40}, {31, 119, 180}, {44, 160, 44}};
    const uint32_t plot_right = 900 - 170; // the legend, on the right, left out
    const auto decade_steps = [&](const Strip& plot) {
        double mean_x[3];
        for (int i = 0; i < 3; ++i) {
            const Found found = find(plot, colours[i], plot_right);
            EXPECT_GT(found.count, 20u) << i;
            mean_x[i] = found.mean_x;
        }
        return std::pair(mean_x[1] - mean_x[0], mean_x[2] - mean_x[1]);
    };
    const auto [log_first, log_second] =
        decade_steps(plotLines(series, "title", "x", "y", 900, 400, AxisScale::logarithmic));
    EXPECT_GT(log_first, 100);
    EXPECT_NEAR(log_second / log_first, 1.0, 0.1);
    const auto [linear_first, linear_second] =
        decade_steps(plotLines(series, "title", "x", "y", 900, 400));
    EXPECT_GT(linear_second, 5 * linear_first);
}

} // namespace
} // namespace vissort::samples
