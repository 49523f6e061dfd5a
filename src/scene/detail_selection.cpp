// A source scene's levels of detail frame by frame (levels_of_detail.h: DetailSelection).

#include <stdexcept>
#include <string>

#include "vissort/levels_of_detail.h"

namespace vissort {

DetailSelection::DetailSelection(const Scene& source, std::shared_ptr<const LevelsOfDetail> levels,
                                 float max_error_px)
    : source_(&source), levels_(std::move(levels)), chooser_(max_error_px) {
    if (!levels_)
        throw std::invalid_argument("no levels of detail");
    if (levels_->sourceTriangleCount() != source.triangleCount() ||
        levels_->objectCount() != source.objects.size())
        throw std::invalid_argument(
            "the levels of detail are of another scene (" + std::to_string(levels_->objectCount()) +
            " objects, " + std::to_string(levels_->sourceTriangleCount()) +
            " triangles; the scene has " + std::to_string(source.objects.size()) + " and " +
            std::to_string(source.triangleCount()) + ")");
}

void DetailSelection::select(PositionsView source_positions, const ViewProjection& view) {
    const PositionsView own = source_->positions;
    const bool is_own =
        source_positions.x.data() == own.x.data() && source_positions.y.data() == own.y.data() &&
        source_positions.z.data() == own.z.data() && source_positions.x.size() == own.x.size();
    const std::vector<Bounds>* bounds = &levels_->bounds();
    if (is_own) {
        positions_ = levels_->scene().positions;
    } else {
        levels_->expand(source_positions, expanded_, bounds_);
        positions_ = expanded_;
        bounds = &bounds_;
    }
    chooser_.choose(*levels_, *bounds, view);
}

const DetailFrame& DetailSelection::gather() {
    const std::span<const uint8_t> chosen = chooser_.chosen();
    DetailFrame& frame = frame_;
    frame.objects.assign(chosen.size(), PrimitiveRange{});
    frame.detailed_triangle.clear();
    frame.boxed_objects = frame.culled_objects = 0;
    for (uint32_t o = 0; o < chosen.size(); ++o) {
        const uint32_t first = uint32_t(frame.detailed_triangle.size());
        frame.objects[o] = {first, 0};
        if (chosen[o] == LevelChooser::kCulled) {
            ++frame.culled_objects;
            continue;
        }
        const DetailLevel& level = levels_->levels(o)[chosen[o]];
        frame.boxed_objects += level.box ? 1 : 0;
        for (uint32_t t = 0; t < level.triangle_count; ++t)
            frame.detailed_triangle.push_back(level.first_triangle + t);
        frame.objects[o].triangle_count = level.triangle_count;
    }
    frame.triangles = frame.detailed_triangle.size();
    frame.positions.resize(frame.triangles);
    for (std::size_t t = 0; t < frame.triangles; ++t)
        for (std::size_t k = 0; k < 3; ++k) {
            const std::size_t from = std::size_t(frame.detailed_triangle[t]) * 3 + k;
            frame.positions.x[t * 3 + k] = positions_.x[from];
            frame.positions.y[t * 3 + k] = positions_.y[from];
            frame.positions.z[t * 3 + k] = positions_.z[from];
        }
    return frame;
}

} // namespace vissort
