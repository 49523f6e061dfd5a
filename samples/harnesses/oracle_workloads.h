#pragma once
// Synthetic oracle workloads shared by `vissort bench oracle` and the Google Benchmarks:
// screen-space triangles of a fixed size, the setup-bound and fill-bound cases of a rasterizer.

#include <cstdint>
#include <vector>

#include "vissort/camera.h"
#include "vissort/geometry.h"

namespace vissort {

struct ScreenTriangleWorkload {
    TrianglePositions positions;            // world = pixel coordinates (x right, y down), z = d
    ViewProjection view;                    // orthographic, maps world x,y to pixels 1:1
    std::vector<PrimitiveRange> primitives; // one per triangle
    uint32_t background = 0; // id of a full-screen quad at the far depth (2 triangles)
};

/// count random right triangles with legs of leg_px pixels, inside a width x height image, at
/// depths that decrease with the id (so drawing in id order is back to front and every triangle
/// passes the depth test), plus one background primitive behind them all (the last id).
/// Deterministic for a seed. Querying any triangle against the background alone finds nothing
/// behind, so every such query tests every pixel of its triangle.
ScreenTriangleWorkload makeRightTriangleWorkload(uint32_t count, double leg_px, uint32_t width,
                                                 uint32_t height, uint64_t seed = 1);

} // namespace vissort
