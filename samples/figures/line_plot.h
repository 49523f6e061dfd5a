#pragma once
// A small line chart as an RGBA image: the plots of the benchmarks (ms against N).

#include <string>
#include <vector>

#include "figures/comparison_strip.h"

namespace vissort::samples {

struct PlotSeries {
    std::string name;
    std::vector<double> x, y; // same length; points joined in order
    bool dashed = false;      // a reference (a value reported elsewhere): dashed, no markers
};

enum class AxisScale { linear, logarithmic };

/// A width x height chart of the series, y logarithmic over the powers of ten around the values
/// (which must be positive): peers a thousand times apart stay readable. x linear from 0 to the
/// largest x, or logarithmic as y (how a cost grows with N: a power law is a straight line). With
/// the title on top, axis labels, tick values and a legend as wide as the longest name needs (up
/// to half the width).
Strip plotLines(const std::vector<PlotSeries>& series, const std::string& title,
                const std::string& x_label, const std::string& y_label, uint32_t width,
                uint32_t height, AxisScale x_scale = AxisScale::linear);

} // namespace vissort::samples
