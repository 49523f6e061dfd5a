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
    const std::vector<Bounds>* piece_bounds = &levels_->pieceBounds();
    if (is_own) {
        positions_ = levels_->scene().positions;
    } else {
        levels_->expand(source_positions, expanded_, bounds_, piece_bounds_);
        positions_ = expanded_;
        bounds = &bounds_;
        piece_bounds = &piece_bounds_;
    }
    const std::span<const uint8_t> chosen = chooser_.choose(*levels_, *bounds, *piece_bounds, view);

    const std::size_t objects = levels_->objectCount();
    range_start_.assign(1, 0);
    ranges_.clear();
    triangles_ = 0;
    boxed_objects_ = culled_objects_ = 0;
    for (uint32_t o = 0; o < objects; ++o) {
        const PieceSpan pieces = levels_->pieces(o);
        const std::span<const DetailLevel> chain = levels_->levels(o);
        if (pieces.count > 0 && chosen[pieces.first] < chain.size() &&
            chain[chosen[pieces.first]].box) {
            const DetailLevel& box = chain[chosen[pieces.first]];
            ranges_.push_back({box.first_triangle, box.triangle_count});
            ++boxed_objects_;
        } else {
            for (uint32_t p = pieces.first; p < pieces.first + pieces.count; ++p)
                if (chosen[p] != LevelChooser::kCulled)
                    for (const PrimitiveRange& range : levels_->pieceLevel(p, chosen[p]).ranges)
                        ranges_.push_back(range);
            culled_objects_ += ranges_.size() == range_start_.back() ? 1 : 0;
        }
        for (std::size_t r = range_start_.back(); r < ranges_.size(); ++r)
            triangles_ += ranges_[r].triangle_count;
        range_start_.push_back(uint32_t(ranges_.size()));
    }
}

const DetailFrame& DetailSelection::gather() {
    const std::size_t objects = levels_->objectCount();
    DetailFrame& frame = frame_;
    frame.objects.assign(objects, PrimitiveRange{});
    frame.detailed_triangle.clear();
    frame.boxed_objects = boxed_objects_;
    frame.culled_objects = culled_objects_;
    for (uint32_t o = 0; o < objects; ++o) {
        const uint32_t first = uint32_t(frame.detailed_triangle.size());
        for (const PrimitiveRange& range : chosenRanges(o))
            for (uint32_t t = 0; t < range.triangle_count; ++t)
                frame.detailed_triangle.push_back(range.first_triangle + t);
        frame.objects[o] = {first, uint32_t(frame.detailed_triangle.size()) - first};
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
