// Choosing each object's level of detail per frame (levels_of_detail.h).

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "vissort/levels_of_detail.h"

namespace vissort {

LevelChooser::LevelChooser(float max_error_px, float hysteresis)
    : max_error_px_(max_error_px), hysteresis_(hysteresis) {
    if (!(max_error_px > 0.0f) || !std::isfinite(max_error_px))
        throw std::invalid_argument("the level of detail's error must be a positive number of "
                                    "pixels, got " +
                                    std::to_string(max_error_px));
    if (!(hysteresis >= 0.0f && hysteresis < 1.0f))
        throw std::invalid_argument("the hysteresis must be in [0, 1), got " +
                                    std::to_string(hysteresis));
}

double LevelChooser::pixelsPerUnit(const Bounds& bounds, const ViewProjection& view) {
    const std::array<double, 16>& p = view.projection_matrix;
    // Column-major: p[0] and p[5] scale eye x and y into clip space.
    const double scale_x = std::abs(p[0]) * 0.5 * view.width;
    const double scale_y = std::abs(p[5]) * 0.5 * view.height;
    const double scale = std::max(scale_x, scale_y);
    if (view.projection == Projection::orthographic)
        return scale;
    double nearest = std::numeric_limits<double>::infinity();
    for (unsigned c = 0; c < 8; ++c)
        nearest =
            std::min(nearest, view.toClip(bounds.corner(c))[3]); // w: the depth along the view
    if (!(nearest > 0.0))
        return std::numeric_limits<double>::infinity();
    // Nothing is drawn nearer than the near plane. A length at depth w spans scale / w pixels
    // facing the eye; towards the frustum's edges a length along the view also moves on screen,
    // by up to the tangent of the half-angle: sqrt(1 + tx^2 + ty^2) covers both.
    nearest = std::max(nearest, view.near);
    const double tx = p[0] != 0 ? 1.0 / std::abs(p[0]) : 0.0;
    const double ty = p[5] != 0 ? 1.0 / std::abs(p[5]) : 0.0;
    return scale / nearest * std::sqrt(1.0 + tx * tx + ty * ty);
}

std::span<const uint8_t> LevelChooser::choose(const LevelsOfDetail& levels,
                                              std::span<const Bounds> bounds,
                                              std::span<const Bounds> piece_bounds,
                                              const ViewProjection& view) {
    const std::size_t objects = levels.objectCount();
    if (bounds.size() != objects || piece_bounds.size() != levels.pieceCount())
        throw std::invalid_argument("bounds for " + std::to_string(bounds.size()) +
                                    " objects and " + std::to_string(piece_bounds.size()) +
                                    " pieces, the levels have " + std::to_string(objects) +
                                    " and " + std::to_string(levels.pieceCount()));
    const bool first_frame = chosen_.size() != levels.pieceCount();
    if (first_frame)
        chosen_.assign(levels.pieceCount(), 0);
    const double coarser_bound = double(max_error_px_) * (1.0 - double(hysteresis_));
    for (uint32_t o = 0; o < objects; ++o) {
        const PieceSpan pieces = levels.pieces(o);
        const std::span<uint8_t> chosen = std::span(chosen_).subspan(pieces.first, pieces.count);
        if (boxOutsideView(bounds[o], view)) {
            std::fill(chosen.begin(), chosen.end(), kCulled);
            continue;
        }
        const std::span<const DetailLevel> chain = levels.levels(o);
        // The box, seen from the object's bounds: kept while within the bound, taken within the
        // hysteresis' margin (or on a first sight).
        if (chain.back().box) {
            const uint8_t box = uint8_t(chain.size() - 1);
            const bool was_box = !first_frame && chosen[0] == box;
            const bool fresh = first_frame || chosen[0] == kCulled;
            const double limit = was_box || fresh ? max_error_px_ : coarser_bound;
            if (double(chain.back().error) * pixelsPerUnit(bounds[o], view) <= limit) {
                std::fill(chosen.begin(), chosen.end(), box);
                continue;
            }
        }
        const uint32_t simplified = uint32_t(chain.size()) - (chain.back().box ? 1 : 0);
        for (uint32_t i = 0; i < pieces.count; ++i) {
            const uint32_t piece = pieces.first + i;
            uint8_t& level = chosen[i];
            if (pieces.count > 1 && boxOutsideView(piece_bounds[piece], view)) {
                level = kCulled;
                continue;
            }
            const double per_unit = pixelsPerUnit(piece_bounds[piece], view);
            // The coarsest level whose error projects within `limit` pixels (level 0: none).
            const auto coarsestWithin = [&](double limit) {
                uint8_t best = 0;
                for (uint8_t l = 1; l < simplified; ++l)
                    if (double(levels.pieceLevel(piece, l).error) * per_unit <= limit)
                        best = l;
                return best;
            };
            if (first_frame || level == kCulled || level >= simplified) { // fresh, or was the box
                level = coarsestWithin(max_error_px_);
            } else if (double(levels.pieceLevel(piece, level).error) * per_unit > max_error_px_) {
                level = coarsestWithin(max_error_px_); // too coarse now: finer at once
            } else {
                level = std::max(level, coarsestWithin(coarser_bound)); // coarser with a margin
            }
        }
    }
    return chosen_;
}

} // namespace vissort
