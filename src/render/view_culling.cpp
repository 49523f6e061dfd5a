#include "render/view_culling.h"

#include <glm/gtc/type_ptr.hpp>

namespace vissort::detail {

glm::dmat4 clipTransform(const ViewProjection& view) {
    return glm::make_mat4(view.projection_matrix.data()) * glm::make_mat4(view.view.data());
}

} // namespace vissort::detail
