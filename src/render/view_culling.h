#pragma once
// Which boxes the view cannot see: a draw skips the objects whose bounding boxes lie wholly
// outside one side of the view volume (or behind its near plane), so the rasterizer never
// transforms their corners. On the power plant's walkthrough much of the scene is
// out of view on every frame.

#include <glm/mat4x4.hpp>

#include "vissort/camera.h"
#include "vissort/geometry.h"

namespace vissort::detail {

/// World -> clip space of a view, the product in double (the oracles' transform,
/// cpu_reference_oracle.h, rule 1); the renderer rounds it once to float for its shaders.
glm::dmat4 clipTransform(const ViewProjection& view);

/// Whether every point of box is outside one plane of the clip volume of clip (the view's
/// world -> clip transform): left, right, bottom, top (|x|, |y| <= w) or near (z >= 0, the
/// renderer's zero-to-one depth). Conservative: a box within a rounding error of a plane
/// counts as seen. The far plane is not tested (perspective views have none).
bool boxOutsideView(const Bounds& box, const glm::dmat4& clip);

} // namespace vissort::detail
