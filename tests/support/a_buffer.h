#pragma once
// The transparency ground truth: a per-pixel A-buffer by ray casting (castAllHits through every
// pixel centre), independent of every rasterizer, oracle and of the renderer. Each pixel's hits
// nearer than its nearest opaque hit are composited back to front in double precision with
// their triangle's flat colour, over that opaque colour or the background. Hits on copies of one
// triangle (at exactly the same depth) follow the tie rule of every exact method: the lower
// triangle id in front.

#include <cstdint>
#include <span>
#include <vector>

#include "vissort/camera.h"
#include "vissort/geometry.h"

namespace vissort::test {

/// Hits closer than this in depth d, but not on copies of one triangle, are a near tie: their
/// order at the pixel is not decided by the ray cast, so the pixel is left out of comparisons.
inline constexpr double kTieDepth = 1e-6;

struct ABuffer {
    uint32_t width = 0, height = 0;
    std::vector<double> rgb;      // 3 per pixel, row 0 at the top, unclamped
    std::vector<uint8_t> decided; // 1 when every hit that shows is robust (not on an edge),
                                  // no other triangle's edge passes within the robust margin
                                  // and no two hits that show are a near tie (exact ties
                                  // are decided by the tie rule)
    uint32_t max_layers = 0;      // the most transparent hits in front of the opaque, a pixel
};

/// triangle_colours: (r, g, b, alpha) per triangle of positions; alpha 1 is opaque.
ABuffer rayCastComposite(const TrianglePositions& positions, const ViewProjection& view,
                         std::span<const Rgba> triangle_colours, Rgba background);

/// The A-buffer of a supersampled image (RenderSettings::samples): `samples` cast through a view
/// columns x rows times as fine as the image, each pixel the mean of its block of samples (the
/// renderer's sample grid), decided when every sample of it is; max_layers is the samples'.
ABuffer resolveSamples(const ABuffer& samples, uint32_t columns, uint32_t rows);

/// Compares an 8-bit RGBA image with the A-buffer at its decided pixels: the largest channel
/// difference from the A-buffer rounded to 8 bits, and how many pixels were compared.
struct ABufferComparison {
    int max_abs = 0;
    uint64_t compared = 0;
    uint32_t worst_x = 0, worst_y = 0;
};
ABufferComparison compareWithABuffer(const std::vector<uint8_t>& rgba8, const ABuffer& reference);

} // namespace vissort::test
