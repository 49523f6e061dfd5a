#pragma once
// The rays through pixels of a view, the one definition every exact decision samples with:
// ViewProjection::pixelRay is this, so the exact oracle, the rasterizers' exact arbitration and
// the tests' ground truth all meet a pixel centre with the very same doubles. Internal.

#include "vissort/camera.h"

namespace vissort::detail {

/// A ray O + t D, t >= 0: world-space origin and unit direction, as doubles.
struct PixelRay {
    Vec3 origin, direction;
};

/// The rays of one view: the inverse view matrix computed once, each ray then a few products.
class PixelRays {
public:
    explicit PixelRays(const ViewProjection& view);

    /// The ray through screen point (sx, sy), in pixels from the top-left corner of the image
    /// (pixel (i, j) has its centre at (i + 0.5, j + 0.5)): ViewProjection::pixelRay.
    PixelRay at(double sx, double sy) const;
    /// The ray through the centre of pixel (px, py).
    PixelRay centre(uint32_t px, uint32_t py) const { return at(px + 0.5, py + 0.5); }

private:
    bool perspective_;
    double width_, height_;
    double scale_x_, scale_y_; // the projection's p[0][0] and p[1][1]
    double inverse_view_[16];  // column-major
    Vec3 eye_position_, forward_;
};

} // namespace vissort::detail
