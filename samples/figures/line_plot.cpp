#include "figures/line_plot.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace vissort::samples {
namespace {

constexpr uint8_t kInk[3] = {30, 30, 30};
constexpr uint8_t kGrid[3] = {200, 200, 200};
constexpr uint8_t kFaintGrid[3] = {235, 235, 235};
// Distinct on white, in series order.
constexpr uint8_t kColours[][3] = {
    {214, 39, 40}, {31, 119, 180},  {44, 160, 44},   {255, 127, 14}, {148, 103, 189},
    {140, 86, 75}, {227, 119, 194}, {127, 127, 127}, {188, 189, 34}, {23, 190, 207}};
constexpr uint32_t kLeft = 80, kMinRight = 170, kTop = 60, kBottom = 60;
constexpr uint32_t kGlyphWidth = 11; // drawText's advance, with room to spare

void setPixel(Strip& s, int x, int y, const uint8_t c[3]) {
    if (x < 0 || y < 0 || x >= int(s.width) || y >= int(s.height))
        return;
    uint8_t* p = &s.rgba[(std::size_t(y) * s.width + std::size_t(x)) * 4];
    p[0] = c[0];
    p[1] = c[1];
    p[2] = c[2];
    p[3] = 255;
}

// A line thickness pixels wide, by stepping along its longer axis.
void drawLine(Strip& s, double x0, double y0, double x1, double y1, const uint8_t c[3],
              int thickness) {
    const int steps = int(std::max(std::abs(x1 - x0), std::abs(y1 - y0))) + 1;
    for (int i = 0; i <= steps; ++i) {
        const double t = double(i) / steps;
        const int x = int(std::lround(x0 + (x1 - x0) * t)),
                  y = int(std::lround(y0 + (y1 - y0) * t));
        for (int dy = -thickness / 2; dy <= thickness / 2; ++dy)
            for (int dx = -thickness / 2; dx <= thickness / 2; ++dx)
                setPixel(s, x + dx, y + dy, c);
    }
}

// 1, 2 or 5 times a power of ten, giving about five ticks up to top.
double tickStep(double top) {
    const double raw = top / 5, power = std::pow(10.0, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 5.0})
        if (m * power >= raw)
            return m * power;
    return 10 * power;
}

std::string number(double v) {
    std::ostringstream out;
    out << v;
    return out.str();
}

} // namespace

Strip plotLines(const std::vector<PlotSeries>& series, const std::string& title,
                const std::string& x_label, const std::string& y_label, uint32_t width,
                uint32_t height, AxisScale x_scale) {
    const bool log_x = x_scale == AxisScale::logarithmic;
    std::size_t longest = 0;
    for (const PlotSeries& line : series)
        longest = std::max(longest, line.name.size());
    const uint32_t kRight =
        std::clamp(uint32_t(60 + kGlyphWidth * longest), kMinRight, std::max(kMinRight, width / 2));
    Strip s;
    s.width = width;
    s.height = height;
    s.rgba.assign(std::size_t(width) * height * 4, 255);
    double x_low = INFINITY, x_top = 0, y_low = INFINITY, y_high = 0;
    for (const PlotSeries& line : series) {
        for (double x : line.x) {
            x_top = std::max(x_top, x);
            if (x > 0)
                x_low = std::min(x_low, x);
        }
        for (double y : line.y)
            if (y > 0) {
                y_low = std::min(y_low, y);
                y_high = std::max(y_high, y);
            }
    }
    if (!(y_high > 0))
        y_low = y_high = 1;
    if (!(x_top > 0))
        x_low = x_top = 1;
    // Linear x: from 0 to the largest x rounded up to a tick; logarithmic: the powers of ten
    // around the values, as y.
    const double x_step = tickStep(x_top);
    const double x_decade_low = std::floor(std::log10(x_low));
    const double x_decades = std::max(std::ceil(std::log10(x_top)) - x_decade_low, 1.0);
    const double x_left = log_x ? std::pow(10.0, x_decade_low) : 0;
    x_top = log_x ? std::pow(10.0, x_decade_low + x_decades) : std::ceil(x_top / x_step) * x_step;
    const double decade_low = std::floor(std::log10(y_low)),
                 decade_high = std::ceil(std::log10(y_high));
    const double decades = std::max(decade_high - decade_low, 1.0);
    const double plot_w = double(width - kLeft - kRight), plot_h = double(height - kTop - kBottom);
    const auto px = [&](double x) {
        if (!log_x)
            return kLeft + x / x_top * plot_w;
        const double t = (std::log10(std::max(x, 1e-300)) - x_decade_low) / x_decades;
        return kLeft + std::clamp(t, 0.0, 1.0) * plot_w;
    };
    const auto py = [&](double y) {
        const double t = (std::log10(std::max(y, 1e-300)) - decade_low) / decades;
        return kTop + plot_h - std::clamp(t, 0.0, 1.0) * plot_h;
    };
    const double y_bottom = std::pow(10.0, decade_low),
                 y_top = std::pow(10.0, decade_low + decades);

    for (double decade = decade_low; decade <= decade_low + decades + 1e-9; ++decade) {
        const double y = std::pow(10.0, decade);
        for (int m = 2; m < 10 && decade < decade_low + decades; ++m)
            drawLine(s, px(x_left), py(m * y), px(x_top), py(m * y), kFaintGrid, 1);
        drawLine(s, px(x_left), py(y), px(x_top), py(y), kGrid, 1);
        drawText(s, 8, uint32_t(py(y)) - 6, number(y), kInk);
    }
    const auto x_tick = [&](double x) {
        drawLine(s, px(x), py(y_bottom), px(x), py(y_top), kGrid, 1);
        drawText(s, uint32_t(px(x)) - 8, uint32_t(py(y_bottom)) + 8, number(x), kInk);
    };
    if (log_x) {
        for (double decade = x_decade_low; decade <= x_decade_low + x_decades + 1e-9; ++decade) {
            const double x = std::pow(10.0, decade);
            for (int m = 2; m < 10 && decade < x_decade_low + x_decades; ++m)
                drawLine(s, px(m * x), py(y_bottom), px(m * x), py(y_top), kFaintGrid, 1);
            x_tick(x);
        }
    } else {
        for (double x = 0; x <= x_top + 1e-9; x += x_step)
            x_tick(x);
    }
    drawLine(s, px(x_left), py(y_bottom), px(x_top), py(y_bottom), kInk, 1);
    drawLine(s, px(x_left), py(y_bottom), px(x_left), py(y_top), kInk, 1);
    drawText(s, kLeft, 8, title, kInk);
    drawText(s, uint32_t(kLeft + plot_w / 2 - 40), height - 28,
             log_x ? x_label + " (log scale)" : x_label, kInk);
    drawText(s, kLeft + 8, kTop - 22, y_label + " (log scale)", kInk);

    for (std::size_t i = 0; i < series.size(); ++i) {
        const uint8_t* colour = kColours[i % std::size(kColours)];
        const PlotSeries& line = series[i];
        for (std::size_t k = 0; k + 1 < line.x.size(); ++k) {
            const double x0 = px(line.x[k]), y0 = py(line.y[k]);
            const double x1 = px(line.x[k + 1]), y1 = py(line.y[k + 1]);
            if (!line.dashed) {
                drawLine(s, x0, y0, x1, y1, colour, 3);
                continue;
            }
            // Dashes of 10 pixels with gaps of 6.
            const double length = std::hypot(x1 - x0, y1 - y0);
            for (double at = 0; at < length; at += 16) {
                const double a = at / length, b = std::min(at + 10, length) / length;
                drawLine(s, x0 + (x1 - x0) * a, y0 + (y1 - y0) * a, x0 + (x1 - x0) * b,
                         y0 + (y1 - y0) * b, colour, 2);
            }
        }
        for (std::size_t k = 0; k < line.x.size() && !line.dashed; ++k)
            drawLine(s, px(line.x[k]) - 3, py(line.y[k]), px(line.x[k]) + 3, py(line.y[k]), colour,
                     7);
        const uint32_t legend_y = kTop + 10 + uint32_t(i) * 24;
        drawLine(s, width - kRight + 15, legend_y + 6, width - kRight + 40, legend_y + 6, colour,
                 line.dashed ? 2 : 3);
        drawText(s, width - kRight + 48, legend_y, line.name, kInk);
    }
    return s;
}

} // namespace vissort::samples
