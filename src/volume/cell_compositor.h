#pragma once
// Compositing cells' segments into a picture, front to back: in a given order of cells (with
// the cells of each cycle ordered per pixel), or every pixel's segments sorted by depth (lists).
// Each pixel's segment of a cell is the ray caster's (tet_crossing.h), so an exact order gives
// the ray caster's picture. Internal to src/volume/.

#include <cstdint>
#include <span>
#include <vector>

#include "vissort/volume.h"
#include "volume/tet_crossing.h"
#include "volume/volume_law.h"

namespace vissort::detail {

struct CompositeJob {
    const TetGrid& grid;
    const VolumeLaw& law;
    const PixelRayTable& rays;
    const ViewProjection& view;
    Rgba background;
    unsigned thread_count = 1;
};

/// The picture of the cells composited in `order` (front to back, every cell once); the members
/// of each of `cycles` (consecutive in the order) are composited together, each pixel's
/// segments of them sorted by depth. Adds to stats' segments and list_segments.
Image compositeInOrder(const CompositeJob& job, std::span<const uint32_t> order,
                       std::span<const std::vector<uint32_t>> cycles, VolumeFrameStats& stats);

/// The picture with every pixel's segments of every cell sorted by depth: per-pixel lists.
Image compositeLists(const CompositeJob& job, VolumeFrameStats& stats);

} // namespace vissort::detail
