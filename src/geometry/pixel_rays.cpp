#include "geometry/pixel_rays.h"

#include <glm/glm.hpp>
#include <glm/gtc/type_ptr.hpp>

namespace vissort::detail {

PixelRays::PixelRays(const ViewProjection& view)
    : perspective_(view.projection == Projection::perspective), width_(view.width),
      height_(view.height), scale_x_(view.projection_matrix[0]),
      scale_y_(view.projection_matrix[5]), eye_position_(view.eye_position),
      forward_(view.forward) {
    const glm::dmat4 inverse = glm::inverse(glm::make_mat4(view.view.data()));
    const double* p = glm::value_ptr(inverse);
    std::copy(p, p + 16, inverse_view_);
}

PixelRay PixelRays::at(double sx, double sy) const {
    const double x_ndc = 2.0 * sx / width_ - 1.0;
    const double y_ndc = 1.0 - 2.0 * sy / height_;
    const glm::dmat4 inverse_view = glm::make_mat4(inverse_view_);
    PixelRay ray;
    if (perspective_) {
        const glm::dvec3 eye_direction(x_ndc / scale_x_, y_ndc / scale_y_, -1.0);
        const glm::dvec3 world =
            glm::normalize(glm::dvec3(inverse_view * glm::dvec4(eye_direction, 0.0)));
        ray.origin = eye_position_;
        ray.direction = {world.x, world.y, world.z};
    } else {
        const glm::dvec3 eye_point(x_ndc / scale_x_, y_ndc / scale_y_, 0.0);
        const glm::dvec3 world = glm::dvec3(inverse_view * glm::dvec4(eye_point, 1.0));
        ray.origin = {world.x, world.y, world.z};
        ray.direction = forward_;
    }
    return ray;
}

} // namespace vissort::detail
