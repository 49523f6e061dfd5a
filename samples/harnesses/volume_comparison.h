#pragma once
// Every volume rendering method on one frame, each against raycast (the exact reference), as one
// picture: `vissort volume --method all`, which makes the strips of docs/volume.md.

#include <vector>

#include "figures/comparison_strip.h"
#include "vissort/volume.h"

namespace vissort::bench {

/// One method's picture, its costs and its error against raycast's picture.
struct VolumePicture {
    VolumeMethod method{};
    std::vector<uint8_t> rgba;
    VolumeFrameStats stats;
    ImageError error;
};

struct VolumeComparison {
    std::vector<VolumePicture> methods; // vissort, centroid, mpvo, lists, raycast
    /// The pictures side by side, captioned with method and time, and below each its error map
    /// against raycast.
    samples::Strip strip;
};

/// Every method on grid through view; vissort asks `oracle`. Fails (one line) as
/// VolumeRenderer::render does.
Result<VolumeComparison> compareVolumeMethods(const TetGrid& grid, const VolumeSettings& settings,
                                              const ViewProjection& view, OracleKind oracle);

} // namespace vissort::bench
