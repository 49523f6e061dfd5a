#pragma once
// What the blending methods draw, back to front: runs of triangles blended in sequence, and
// groups composited per pixel from fragment lists (cycles, self-overlapping objects, or every
// transparent triangle for the linked-list method).

#include <cstdint>
#include <span>
#include <vector>

#include "render/marked_pixels.h"
#include "render/pixel_rect.h"
#include "vissort/camera.h"
#include "vissort/scene.h"

namespace vissort::detail {

struct DrawSegment {
    uint32_t first_triangle = 0; // index into DrawSequence::triangles
    uint32_t triangle_count = 0;
    bool per_pixel = false;
    PixelRect rect; // per_pixel: the pixels its triangles may cover (screenRectOf)
};

struct DrawSequence {
    std::vector<uint32_t> triangles; // triangle ids, in draw order
    std::vector<DrawSegment> segments;

    void clear() {
        triangles.clear();
        segments.clear();
    }
};

/// The sequence for a front-to-back order of primitives with groups to composite per pixel:
/// `group_of[p]` is the group of primitive p (members of one group are consecutive in the order,
/// as Vis-sort outputs a cycle), or kNoGroup. Primitives are drawn back to front.
inline constexpr uint32_t kNoGroup = 0xFFFFFFFFu;
void sequenceFromOrder(std::span<const uint32_t> front_to_back,
                       std::span<const PrimitiveRange> primitives,
                       std::span<const uint32_t> group_of, DrawSequence& sequence);

/// Turns the sequence's groups into runs blended in sequence, for a checked blend
/// (verified_blending.h): the check marks every pixel where fragments of a group came out of
/// depth order, and its repair composites all those pixels in one list pass, where a group per
/// pixel costs a list pass of its own. Each group's triangles (scene ids into positions) are put
/// back to front by centroid depth, so that few pixels need the repair; runs are merged into one
/// segment (one draw).
void blendGroupsInSequence(PositionsView positions, const ViewProjection& view,
                           DrawSequence& sequence);

/// Primitives sorted by the depth of their centroid (the mean of their corners), farthest first:
/// the engines' approximation. Ties keep id order.
std::vector<uint32_t> centroidBackToFront(PositionsView positions,
                                          std::span<const PrimitiveRange> primitives,
                                          const ViewProjection& view);

/// The pixels whose centres triangles (scene triangle ids into positions) may cover in view,
/// with a pixel's margin; the whole image when a corner is at or behind the eye plane.
PixelRect screenRectOf(PositionsView positions, std::span<const uint32_t> triangles,
                       const ViewProjection& view);

/// The triangles (scene ids into positions) whose screen rectangle (screenRectOf) overlaps a tile
/// holding a marked pixel, in the order given: every triangle that may cover a marked pixel.
void trianglesCovering(PositionsView positions, std::span<const uint32_t> triangles,
                       const ViewProjection& view, const MarkedPixels& marked,
                       std::vector<uint32_t>& covering);

} // namespace vissort::detail
