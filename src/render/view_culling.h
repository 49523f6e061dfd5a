#pragma once
// The view's clip transform as the renderer's shaders and its culling take it (which boxes the
// view cannot see is boxOutsideView, camera.h: a draw skips the objects whose bounding boxes lie
// wholly outside one side of the view volume, so the rasterizer never transforms their corners).

#include <glm/mat4x4.hpp>

#include "vissort/camera.h"
#include "vissort/geometry.h"

namespace vissort::detail {

/// World -> clip space of a view, the product in double (the oracles' transform,
/// cpu_reference_oracle.h, rule 1); the renderer rounds it once to float for its shaders.
glm::dmat4 clipTransform(const ViewProjection& view);

} // namespace vissort::detail
