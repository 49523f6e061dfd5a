#pragma once
// What the volume tests share: views around a grid, picture differences and settings by preset.

#include <algorithm>
#include <cmath>

#include "vissort/volume.h"

namespace vissort::test {

/// A camera at distance_radii bounding radii from the grid's centre, in the direction of
/// orbitOrientation(azimuth, elevation), looking at the centre; framed at size x size.
inline ViewProjection gridView(const TetGrid& grid, Projection projection, uint32_t size,
                               double azimuth, double elevation, double distance_radii = 4.0) {
    Bounds bounds;
    for (const Vec3& p : grid.points)
        bounds.add(p);
    const CameraSpec orbit = orbitOrientation(azimuth, elevation);
    CameraSpec camera;
    camera.projection = projection;
    camera.target = bounds.centre();
    camera.eye =
        bounds.centre() + normalized(orbit.eye - orbit.target) * (distance_radii * bounds.radius());
    camera.ortho_direction = normalized(camera.target - camera.eye);
    return frameCamera(camera, bounds, size, size);
}

/// The largest difference of two float pictures' channels.
inline double largestDifference(const Image& a, const Image& b) {
    double worst = 0;
    for (std::size_t i = 0; i < a.rgba.size(); ++i)
        worst = std::max(worst, double(std::abs(a.rgba[i] - b.rgba[i])));
    return worst;
}

/// The largest difference of the two pictures in 8 bits, in 1/255 units.
inline int largest8BitDifference(const Image& a, const Image& b) {
    return compareImages(a.toRgba8(), b.toRgba8()).max_abs;
}

inline VolumeSettings settingsWith(const char* preset, double density = 4.0) {
    VolumeSettings settings;
    settings.transfer = *loadTransferFunction(preset).value;
    settings.density = density;
    return settings;
}

} // namespace vissort::test
