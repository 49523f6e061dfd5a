#include "cli/line_plot.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace vissort::cli {
namespace {

constexpr uint8_t kInk[3] = {30, 30, 30};
constexpr uint8_t kGrid[3] = {215, 215, 215};
// Distinct on white, in series order.
constexpr uint8_t kColours[][3] = {{214, 39, 40}, {31, 119, 180}, {44, 160, 44},
                                   {255, 127, 14}, {148, 103, 189}, {140, 86, 75}};
constexpr uint32_t kLeft = 80, kRight = 170, kTop = 50, kBottom = 60;

void setPixel(Strip& s, int x, int y, const uint8_t c[3]) {
    if (x < 0 || y < 0 || x >= int(s.width) || y >= int(s.height)) return;
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
        const int x = int(std::lround(x0 + (x1 - x0) * t)), y = int(std::lround(y0 + (y1 - y0) * t));
        for (int dy = -thickness / 2; dy <= thickness / 2; ++dy)
            for (int dx = -thickness / 2; dx <= thickness / 2; ++dx) setPixel(s, x + dx, y + dy, c);
    }
}

// 1, 2 or 5 times a power of ten, giving about five ticks up to top.
double tickStep(double top) {
    const double raw = top / 5, power = std::pow(10.0, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 5.0})
        if (m * power >= raw) return m * power;
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
                uint32_t height) {
    Strip s;
    s.width = width;
    s.height = height;
    s.rgba.assign(std::size_t(width) * height * 4, 255);
    double x_top = 0, y_top = 0;
    for (const PlotSeries& line : series) {
        for (double x : line.x) x_top = std::max(x_top, x);
        for (double y : line.y) y_top = std::max(y_top, y);
    }
    const double x_step = tickStep(x_top > 0 ? x_top : 1), y_step = tickStep(y_top > 0 ? y_top : 1);
    x_top = std::ceil((x_top > 0 ? x_top : 1) / x_step) * x_step;
    y_top = std::ceil((y_top > 0 ? y_top : 1) / y_step) * y_step;
    const double plot_w = double(width - kLeft - kRight), plot_h = double(height - kTop - kBottom);
    const auto px = [&](double x) { return kLeft + x / x_top * plot_w; };
    const auto py = [&](double y) { return kTop + plot_h - y / y_top * plot_h; };

    for (double y = 0; y <= y_top + 1e-9; y += y_step) {
        drawLine(s, px(0), py(y), px(x_top), py(y), kGrid, 1);
        drawText(s, 8, uint32_t(py(y)) - 6, number(y), kInk);
    }
    for (double x = 0; x <= x_top + 1e-9; x += x_step) {
        drawLine(s, px(x), py(0), px(x), py(y_top), kGrid, 1);
        drawText(s, uint32_t(px(x)) - 8, uint32_t(py(0)) + 8, number(x), kInk);
    }
    drawLine(s, px(0), py(0), px(x_top), py(0), kInk, 1);
    drawLine(s, px(0), py(0), px(0), py(y_top), kInk, 1);
    drawText(s, kLeft, 12, title, kInk);
    drawText(s, uint32_t(kLeft + plot_w / 2 - 40), height - 28, x_label, kInk);
    drawText(s, 8, kTop - 30, y_label, kInk);

    for (std::size_t i = 0; i < series.size(); ++i) {
        const uint8_t* colour = kColours[i % std::size(kColours)];
        const PlotSeries& line = series[i];
        for (std::size_t k = 0; k + 1 < line.x.size(); ++k)
            drawLine(s, px(line.x[k]), py(line.y[k]), px(line.x[k + 1]), py(line.y[k + 1]), colour, 3);
        for (std::size_t k = 0; k < line.x.size(); ++k)
            drawLine(s, px(line.x[k]) - 3, py(line.y[k]), px(line.x[k]) + 3, py(line.y[k]), colour, 7);
        const uint32_t legend_y = kTop + 10 + uint32_t(i) * 24;
        drawLine(s, width - kRight + 15, legend_y + 6, width - kRight + 40, legend_y + 6, colour, 3);
        drawText(s, width - kRight + 48, legend_y, line.name, kInk);
    }
    return s;
}

} // namespace vissort::cli
