#include "render/view_culling.h"

#include <cmath>
#include <glm/gtc/type_ptr.hpp>

namespace vissort::detail {

glm::dmat4 clipTransform(const ViewProjection& view) {
    return glm::make_mat4(view.projection_matrix.data()) * glm::make_mat4(view.view.data());
}

bool boxOutsideView(const Bounds& box, const glm::dmat4& clip) {
    if (box.isEmpty())
        return true;
    // The clip volume's planes are linear in clip space, so a box (the hull of its corners)
    // is outside a plane when its eight corners are.
    glm::dvec4 corners[8];
    for (int i = 0; i < 8; ++i)
        corners[i] = clip * glm::dvec4(i & 1 ? box.max.x : box.min.x, i & 2 ? box.max.y : box.min.y,
                                       i & 4 ? box.max.z : box.min.z, 1.0);
    // Inside each plane: w - x, w + x, w - y, w + y, z all >= 0. The margin covers the
    // rounding of the GPU's float transform (1e-5 of the coordinates' size).
    const auto outside = [&](auto distance) {
        for (const glm::dvec4& c : corners)
            if (distance(c) >=
                -1e-5 * (std::abs(c.x) + std::abs(c.y) + std::abs(c.z) + std::abs(c.w)))
                return false;
        return true;
    };
    return outside([](const glm::dvec4& c) { return c.w - c.x; }) ||
           outside([](const glm::dvec4& c) { return c.w + c.x; }) ||
           outside([](const glm::dvec4& c) { return c.w - c.y; }) ||
           outside([](const glm::dvec4& c) { return c.w + c.y; }) ||
           outside([](const glm::dvec4& c) { return c.z; });
}

} // namespace vissort::detail
