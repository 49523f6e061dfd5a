#pragma once
// The rendering law of volume.h in one place: how a cell's segment becomes a colour and an
// opacity. The ray caster, the rasterizing methods and their shaders all follow it (the shaders
// restate it in GLSL; tests compare their pictures). Internal to src/volume/.

#include <algorithm>
#include <cmath>

#include "vissort/tet_grid.h"
#include "vissort/volume.h"

namespace vissort::detail {

/// Premultiplied colour and opacity of one segment.
struct SegmentColour {
    double r = 0, g = 0, b = 0, a = 0;
};

/// What the law needs of a grid, measured once per grid rather than every frame: its bounds (the
/// unit of length is their diagonal) and its scalars' range.
struct GridMeasures {
    Bounds bounds;
    double scalar_min = 0, scalar_max = 0;

    explicit GridMeasures(const TetGrid& grid) {
        for (const Vec3& p : grid.points)
            bounds.add(p);
        if (!grid.scalars.empty()) {
            const auto [low, high] = std::minmax_element(grid.scalars.begin(), grid.scalars.end());
            scalar_min = *low;
            scalar_max = *high;
        }
    }
};

/// What turns a segment's scalars and world length into its colour: the transfer function's
/// scalar mapping (normalized: (s - min) / (max - min) over the grid's scalars; a constant field
/// maps to 0) and the unit of length (the grid's bounding-box diagonal).
class VolumeLaw {
public:
    VolumeLaw(const GridMeasures& grid, const VolumeSettings& settings) : settings_(settings) {
        length_unit_ = std::max(2 * grid.bounds.radius(), 1e-300);
        if (settings.transfer.normalized) {
            offset_ = grid.scalar_min;
            scale_ =
                grid.scalar_max > grid.scalar_min ? 1.0 / (grid.scalar_max - grid.scalar_min) : 0.0;
        }
    }

    double normalizedScalar(double s) const { return (s - offset_) * scale_; }

    /// The segment from scalar s_in to s_out, world length `length`.
    SegmentColour segment(double s_in, double s_out, double length) const {
        const TransferPoint p = settings_.transfer.at(normalizedScalar(0.5 * (s_in + s_out)));
        const double a = 1 - std::exp(-settings_.density * p.extinction * (length / length_unit_));
        return {p.r * a, p.g * a, p.b * a, a};
    }

private:
    const VolumeSettings& settings_;
    double length_unit_ = 1;
    double offset_ = 0, scale_ = 1;
};

/// Front-to-back accumulation of segments, then the background: the same picture as compositing
/// them back to front with "over" onto it.
struct FrontToBack {
    double r = 0, g = 0, b = 0, transmittance = 1;
    void add(const SegmentColour& s) {
        r += transmittance * s.r;
        g += transmittance * s.g;
        b += transmittance * s.b;
        transmittance *= 1 - s.a;
    }
    /// The pixel: what was accumulated over the background (alpha 1 - transmittance left times
    /// the background's transparency).
    void finish(const Rgba& background, float* rgba) const {
        rgba[0] = float(r + transmittance * background.r * background.a);
        rgba[1] = float(g + transmittance * background.g * background.a);
        rgba[2] = float(b + transmittance * background.b * background.a);
        rgba[3] = float(1 - transmittance * (1 - background.a));
    }
};

} // namespace vissort::detail
