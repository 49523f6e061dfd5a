// Editing transfer functions (transfer_editing.h).

#include "viewer/transfer_editing.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <vector>

namespace vissort::viewer {

void moveTransferPoint(TransferFunction& tf, std::size_t i, double s) {
    std::vector<TransferPoint>& points = tf.points;
    if (!std::isfinite(s))
        return;
    // Strictly between the neighbours: the nearest doubles inside them.
    if (i > 0)
        s = std::max(s, std::nextafter(points[i - 1].scalar, INFINITY));
    if (i + 1 < points.size())
        s = std::min(s, std::nextafter(points[i + 1].scalar, -INFINITY));
    if ((i == 0 || s > points[i - 1].scalar) &&
        (i + 1 == points.size() || s < points[i + 1].scalar))
        points[i].scalar = s;
}

std::size_t insertTransferPoint(TransferFunction& tf, std::size_t i) {
    std::vector<TransferPoint>& points = tf.points;
    const double here = points[i].scalar;
    double next = here + (tf.normalized ? std::max(0.0, 1.0 - here) : 1.0);
    if (i + 1 < points.size())
        next = points[i + 1].scalar;
    if (!(next > here)) // the last point at 1 (or beyond) in a normalized range
        next = here + 0.1;
    TransferPoint point = tf.at(0.5 * (here + next));
    point.scalar = 0.5 * (here + next);
    if (!(point.scalar > here && point.scalar < next)) // neighbours a double apart
        return i;
    points.insert(points.begin() + std::ptrdiff_t(i) + 1, point);
    return i + 1;
}

bool removeTransferPoint(TransferFunction& tf, std::size_t i) {
    if (tf.points.size() <= 2 || i >= tf.points.size())
        return false;
    tf.points.erase(tf.points.begin() + std::ptrdiff_t(i));
    return true;
}

void clampTransferPoint(TransferPoint& point) {
    for (double* c : {&point.r, &point.g, &point.b})
        *c = std::clamp(std::isfinite(*c) ? *c : 0.0, 0.0, 1.0);
    point.extinction = std::isfinite(point.extinction) ? std::max(point.extinction, 0.0) : 0.0;
}

std::string nextTransferPreset(const std::string& name) {
    const std::vector<TransferPreset> presets = transferPresets();
    const auto at = std::find_if(presets.begin(), presets.end(),
                                 [&](const TransferPreset& p) { return name == p.name; });
    if (at == presets.end() || std::next(at) == presets.end())
        return presets.front().name;
    return std::next(at)->name;
}

} // namespace vissort::viewer
