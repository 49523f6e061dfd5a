// Building levels of detail with meshoptimizer (levels_of_detail.h).

#include "vissort/levels_of_detail.h"

#include <meshoptimizer.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace vissort {
namespace {

// A level that keeps more than this share of the triangles of the one before it is not worth
// its memory: the chain stops there.
constexpr double kLeastProgress = 0.85;

// The 12 triangles of a box, as corners 0-7 (bit 0: x, bit 1: y, bit 2: z at max), each face's
// two triangles facing out.
constexpr std::array<std::array<uint8_t, 3>, 12> kBoxTriangles = {{
    {0, 2, 1},
    {1, 2, 3}, // z min
    {4, 5, 6},
    {5, 7, 6}, // z max
    {0, 1, 4},
    {1, 5, 4}, // y min
    {2, 6, 3},
    {3, 6, 7}, // y max
    {0, 4, 2},
    {2, 4, 6}, // x min
    {1, 3, 5},
    {3, 7, 5}, // x max
}};

double diagonal(const Bounds& bounds) {
    const double dx = bounds.max.x - bounds.min.x, dy = bounds.max.y - bounds.min.y,
                 dz = bounds.max.z - bounds.min.z;
    return std::sqrt(dx * dx + dy * dy + dz * dz);
}

// One drawn part of one piece: its mesh welded by position, with its chain of simplified index
// buffers.
struct PartChain {
    std::vector<uint32_t> triangles;           // source triangle ids, in order
    std::vector<float> vertices;               // 3 per welded vertex
    std::vector<uint32_t> vertex_corner;       // welded vertex -> a source corner
    std::vector<std::vector<uint32_t>> levels; // index buffers, level 0 the source's own
    std::vector<float> errors;                 // world units, summed along the chain
    float scale = 1.0f;                        // meshopt_simplifyScale of the vertices

    // Welds the corners of the chain's triangles.
    void weld(PositionsView positions) {
        const std::size_t corners = triangles.size() * 3;
        std::vector<float> soup(corners * 3);
        for (std::size_t c = 0; c < corners; ++c) {
            const std::size_t from = std::size_t(triangles[c / 3]) * 3 + c % 3;
            soup[c * 3] = positions.x[from];
            soup[c * 3 + 1] = positions.y[from];
            soup[c * 3 + 2] = positions.z[from];
        }
        std::vector<uint32_t> remap(corners);
        const std::size_t unique = meshopt_generateVertexRemap(
            remap.data(), nullptr, corners, soup.data(), corners, 3 * sizeof(float));
        vertices.assign(unique * 3, 0.0f);
        vertex_corner.assign(unique, 0);
        std::vector<uint32_t> indices(corners);
        for (std::size_t c = corners; c-- > 0;) { // the first corner of each vertex wins
            const uint32_t v = remap[c];
            indices[c] = v;
            vertex_corner[v] = triangles[c / 3] * 3 + uint32_t(c % 3);
            std::copy_n(&soup[c * 3], 3, &vertices[std::size_t(v) * 3]);
        }
        // Level 0 keeps the source's corners as they are (not the welded vertices' first
        // corners): its triangles are the source's, bit for bit.
        levels.push_back(std::move(indices));
        errors.push_back(0.0f);
        scale =
            unique > 0 ? meshopt_simplifyScale(vertices.data(), unique, 3 * sizeof(float)) : 1.0f;
    }

    // The next level aiming at `reduction` of the last one's indices; false when the simplifier
    // could not go far enough (or would leave nothing).
    bool simplify(float reduction) {
        const std::vector<uint32_t>& last = levels.back();
        const std::size_t target =
            std::max<std::size_t>(3, std::size_t(double(last.size() / 3) * reduction) * 3);
        if (last.size() <= 3)
            return false;
        std::vector<uint32_t> next(last.size());
        float relative = 0.0f;
        // Borders locked: an open edge of the part (its seam with another part or piece, or a
        // hole) keeps its vertices, so parts and pieces stay joined at any mix of levels and
        // holes keep their outline. Any error allowed
        // (1 = the part's extent): the chain records what each level costs, the selection
        // decides where it is worth it.
        const std::size_t count = meshopt_simplify(
            next.data(), last.data(), last.size(), vertices.data(), vertices.size() / 3,
            3 * sizeof(float), target, 1.0f, meshopt_SimplifyLockBorder, &relative);
        if (count == 0 || double(count) > kLeastProgress * double(last.size()))
            return false;
        next.resize(count);
        levels.push_back(std::move(next));
        errors.push_back(errors.back() + relative * scale);
        return true;
    }
};

// Cuts an object's triangles into pieces of at most max_triangles: halves them (by count)
// across the longest extent of their centres, again and again, so that a piece is compact and
// pieces next to each other in the list are near each other in space. Each piece's triangles
// in source order.
std::vector<std::vector<uint32_t>> cutIntoPieces(PositionsView positions, const SceneObject& object,
                                                 uint32_t max_triangles) {
    std::vector<uint32_t> all(object.triangle_count);
    std::iota(all.begin(), all.end(), object.first_triangle);
    if (all.size() <= max_triangles)
        return {std::move(all)};
    std::vector<Vec3> centre(all.size());
    for (std::size_t i = 0; i < all.size(); ++i) {
        const std::size_t c = std::size_t(all[i]) * 3;
        const Vec3 a = positions.corner(c), b = positions.corner(c + 1),
                   d = positions.corner(c + 2);
        centre[i] = {(a.x + b.x + d.x) / 3, (a.y + b.y + d.y) / 3, (a.z + b.z + d.z) / 3};
    }
    const auto centreOf = [&](uint32_t t) { return centre[t - object.first_triangle]; };
    std::vector<std::vector<uint32_t>> pieces, stack{std::move(all)};
    while (!stack.empty()) {
        std::vector<uint32_t> piece = std::move(stack.back());
        stack.pop_back();
        if (piece.size() <= max_triangles) {
            std::sort(piece.begin(), piece.end());
            pieces.push_back(std::move(piece));
            continue;
        }
        Bounds extent;
        for (uint32_t t : piece)
            extent.add(centreOf(t));
        const double dx = extent.max.x - extent.min.x, dy = extent.max.y - extent.min.y,
                     dz = extent.max.z - extent.min.z;
        const int axis = dx >= dy && dx >= dz ? 0 : dy >= dz ? 1 : 2;
        const auto along = [&](uint32_t t) {
            const Vec3 c = centreOf(t);
            return axis == 0 ? c.x : axis == 1 ? c.y : c.z;
        };
        const auto middle = piece.begin() + std::ptrdiff_t(piece.size() / 2);
        std::nth_element(piece.begin(), middle, piece.end(),
                         [&](uint32_t a, uint32_t b) { return along(a) < along(b); });
        stack.emplace_back(middle, piece.end()); // the first half is cut first
        stack.emplace_back(piece.begin(), middle);
    }
    return pieces;
}

} // namespace

struct LevelsOfDetail::Expansion {
    std::vector<uint32_t> corner_source; // scene() corner -> source corner (box corners: 0)
    // Each piece's object and its level-0 ranges of scene() (piece p's are
    // [piece_range_start[p], piece_range_start[p + 1]) of level0_ranges), for its bounds.
    std::vector<uint32_t> piece_object, piece_range_start{0};
    std::vector<PrimitiveRange> level0_ranges;
    std::size_t object_count = 0;
    struct Box {
        uint32_t object, first_triangle; // its object, its first triangle in scene()
    };
    std::vector<Box> boxes;

    void expand(PositionsView source, TrianglePositions& out, std::vector<Bounds>& bounds,
                std::vector<Bounds>& piece_bounds) const {
        out.resize(corner_source.size() / 3);
        for (std::size_t c = 0; c < corner_source.size(); ++c) {
            const uint32_t from = corner_source[c];
            out.x[c] = source.x[from];
            out.y[c] = source.y[from];
            out.z[c] = source.z[from];
        }
        const PositionsView expanded = out;
        bounds.assign(object_count, Bounds{});
        piece_bounds.assign(piece_object.size(), Bounds{});
        for (std::size_t p = 0; p < piece_object.size(); ++p) {
            for (uint32_t r = piece_range_start[p]; r < piece_range_start[p + 1]; ++r) {
                const PrimitiveRange range = level0_ranges[r];
                for (std::size_t c = std::size_t(range.first_triangle) * 3;
                     c < std::size_t(range.first_triangle + range.triangle_count) * 3; ++c)
                    piece_bounds[p].add(expanded.corner(c));
            }
            Bounds& object = bounds[piece_object[p]];
            if (!piece_bounds[p].isEmpty()) {
                object.add(piece_bounds[p].min);
                object.add(piece_bounds[p].max);
            }
        }
        for (const Box& box : boxes)
            writeBox(bounds[box.object], box.first_triangle, out);
    }

    static void writeBox(const Bounds& bounds, uint32_t first_triangle, TrianglePositions& out) {
        std::size_t c = std::size_t(first_triangle) * 3;
        for (const auto& triangle : kBoxTriangles)
            for (uint8_t corner : triangle) {
                const Vec3 p = bounds.corner(corner);
                out.x[c] = float(p.x);
                out.y[c] = float(p.y);
                out.z[c] = float(p.z);
                ++c;
            }
    }
};

namespace {

// A dynamic source's frames, expanded into the levels' scene.
class DetailedAnimation final : public Animation {
public:
    DetailedAnimation(std::shared_ptr<const Animation> source,
                      std::shared_ptr<const LevelsOfDetail::Expansion> expansion)
        : source_(std::move(source)), expansion_(std::move(expansion)) {}

    void positionsAt(double t, TrianglePositions& out) const override {
        TrianglePositions frame;
        source_->positionsAt(t, frame);
        std::vector<Bounds> bounds, piece_bounds;
        expansion_->expand(frame, out, bounds, piece_bounds);
    }

private:
    std::shared_ptr<const Animation> source_;
    std::shared_ptr<const LevelsOfDetail::Expansion> expansion_;
};

} // namespace

std::span<const DetailLevel> LevelsOfDetail::levels(uint32_t object) const {
    return std::span(levels_).subspan(level_start_[object],
                                      level_start_[object + 1] - level_start_[object]);
}

void LevelsOfDetail::expand(PositionsView source, TrianglePositions& out,
                            std::vector<Bounds>& bounds, std::vector<Bounds>& piece_bounds) const {
    if (source.triangleCount() != source_triangles_)
        throw std::invalid_argument("positions have " + std::to_string(source.triangleCount()) +
                                    " triangles, the levels' source " +
                                    std::to_string(source_triangles_));
    expansion_->expand(source, out, bounds, piece_bounds);
}

PieceLevel LevelsOfDetail::pieceLevel(uint32_t piece, uint32_t level) const {
    const PieceEntry& entry = piece_levels_[piece_level_start_[piece] + level];
    return {std::span(piece_ranges_).subspan(entry.first_range, entry.range_count), entry.error};
}

uint32_t LevelsOfDetail::detailedTriangleOf(uint32_t source_triangle) const {
    return detailed_triangle_.at(source_triangle);
}

LevelsOfDetail LevelsOfDetail::build(const Scene& source, const LodOptions& options,
                                     const std::function<void(double)>& progress) {
    if (!(options.reduction > 0.0f && options.reduction < 1.0f))
        throw std::invalid_argument("the levels' reduction must be in (0, 1), got " +
                                    std::to_string(options.reduction));
    if (options.max_levels < 2 || options.max_levels > 16)
        throw std::invalid_argument("an object has 2 to 16 levels, not " +
                                    std::to_string(options.max_levels));
    if (options.piece_triangles < 16)
        throw std::invalid_argument("a piece has at least 16 triangles, not " +
                                    std::to_string(options.piece_triangles));
    LevelsOfDetail lod;
    lod.source_triangles_ = source.triangleCount();
    lod.detailed_triangle_.assign(lod.source_triangles_, 0);
    lod.scene_.name = source.name;
    lod.scene_.camera = source.camera;
    lod.scene_.cameras = source.cameras;
    lod.scene_.camera_path = source.camera_path;
    lod.level_start_.push_back(0);
    lod.piece_start_.push_back(0);
    lod.expansion_ = std::make_shared<Expansion>();
    Expansion& expansion = *lod.expansion_;
    expansion.object_count = source.objects.size();
    const PositionsView positions = source.positions;
    std::size_t done = 0;
    for (const SceneObject& object : source.objects) {
        Bounds bounds;
        for (std::size_t c = std::size_t(object.first_triangle) * 3;
             c < std::size_t(object.first_triangle + object.triangle_count) * 3; ++c)
            bounds.add(positions.corner(c));
        lod.bounds_.push_back(bounds);

        // A chain for each drawn part of each piece: chain p * parts + k is part k of piece p.
        const std::vector<ObjectPart> parts = object.drawnParts();
        const std::vector<std::vector<uint32_t>> pieces =
            cutIntoPieces(positions, object, options.piece_triangles);
        std::vector<PartChain> chains;
        for (const std::vector<uint32_t>& piece : pieces) {
            Bounds piece_bounds;
            for (uint32_t t : piece)
                for (std::size_t c = std::size_t(t) * 3; c < std::size_t(t) * 3 + 3; ++c)
                    piece_bounds.add(positions.corner(c));
            lod.piece_bounds_.push_back(piece_bounds);
            for (const ObjectPart& part : parts) {
                PartChain chain;
                const auto first =
                    std::lower_bound(piece.begin(), piece.end(), part.first_triangle);
                const auto last =
                    std::lower_bound(first, piece.end(), part.first_triangle + part.triangle_count);
                chain.triangles.assign(first, last);
                chain.weld(positions);
                chains.push_back(std::move(chain));
            }
        }
        // Every chain one step further while the object as a whole still shrinks; the box last,
        // when it is coarser than the coarsest level.
        std::size_t level_count = 1;
        std::size_t last_triangles = object.triangle_count;
        while (level_count + 1 < options.max_levels) {
            std::size_t triangles = 0;
            bool any = false;
            for (PartChain& chain : chains) {
                if (chain.levels.size() == level_count)
                    any = chain.simplify(options.reduction) || any;
                if (chain.levels.size() == level_count) { // this chain stays as it was
                    chain.levels.push_back(chain.levels.back());
                    chain.errors.push_back(chain.errors.back());
                }
                triangles += chain.levels.back().size() / 3;
            }
            if (!any || double(triangles) > kLeastProgress * double(last_triangles)) {
                for (PartChain& chain : chains) {
                    chain.levels.pop_back();
                    chain.errors.pop_back();
                }
                break;
            }
            ++level_count;
            last_triangles = triangles;
        }

        // Level by level, part by part, piece by piece: an object's level is one range, a drawn
        // part at a level one part of the levels' scene (its normals smooth across pieces), and
        // a piece at a level a range for each part it holds.
        SceneObject detailed;
        detailed.name = object.name;
        detailed.colour = object.colour;
        detailed.transparent = object.transparent;
        detailed.first_triangle = uint32_t(lod.scene_.triangleCount());
        TrianglePositions& out = lod.scene_.positions;
        const auto addTriangle = [&](const std::array<uint32_t, 3>& source_corners) {
            for (uint32_t corner : source_corners) {
                out.x.push_back(positions.x[corner]);
                out.y.push_back(positions.y[corner]);
                out.z.push_back(positions.z[corner]);
                expansion.corner_source.push_back(corner);
            }
        };
        std::vector<PrimitiveRange> chain_ranges(chains.size() * level_count); // [chain][level]
        for (std::size_t level = 0; level < level_count; ++level) {
            DetailLevel entry;
            entry.first_triangle = uint32_t(out.triangleCount());
            for (std::size_t k = 0; k < parts.size(); ++k) {
                ObjectPart part = parts[k];
                part.first_triangle = uint32_t(out.triangleCount());
                for (std::size_t p = 0; p < pieces.size(); ++p) {
                    const std::size_t c = p * parts.size() + k;
                    const PartChain& chain = chains[c];
                    const uint32_t first = uint32_t(out.triangleCount());
                    const std::vector<uint32_t>& indices = chain.levels[level];
                    for (std::size_t i = 0; i < indices.size(); i += 3) {
                        if (level == 0) { // the source's corners, as they are
                            const uint32_t t = chain.triangles[i / 3];
                            lod.detailed_triangle_[t] = uint32_t(out.triangleCount());
                            addTriangle({t * 3, t * 3 + 1, t * 3 + 2});
                        } else {
                            addTriangle({chain.vertex_corner[indices[i]],
                                         chain.vertex_corner[indices[i + 1]],
                                         chain.vertex_corner[indices[i + 2]]});
                        }
                    }
                    chain_ranges[c * level_count + level] = {first,
                                                             uint32_t(out.triangleCount()) - first};
                    entry.error = std::max(entry.error, chain.errors[level]);
                }
                part.triangle_count = uint32_t(out.triangleCount()) - part.first_triangle;
                if (part.triangle_count > 0)
                    detailed.parts.push_back(part);
            }
            entry.triangle_count = uint32_t(out.triangleCount()) - entry.first_triangle;
            lod.levels_.push_back(entry);
        }
        for (std::size_t p = 0; p < pieces.size(); ++p) {
            expansion.piece_object.push_back(uint32_t(lod.scene_.objects.size()));
            lod.piece_level_start_.push_back(uint32_t(lod.piece_levels_.size()));
            for (std::size_t level = 0; level < level_count; ++level) {
                PieceEntry entry{uint32_t(lod.piece_ranges_.size()), 0, 0.0f};
                for (std::size_t k = 0; k < parts.size(); ++k) {
                    const std::size_t c = p * parts.size() + k;
                    const PrimitiveRange range = chain_ranges[c * level_count + level];
                    entry.error = std::max(entry.error, chains[c].errors[level]);
                    if (range.triangle_count == 0)
                        continue;
                    lod.piece_ranges_.push_back(range);
                    ++entry.range_count;
                    if (level == 0)
                        expansion.level0_ranges.push_back(range);
                }
                lod.piece_levels_.push_back(entry);
            }
            expansion.piece_range_start.push_back(uint32_t(expansion.level0_ranges.size()));
        }
        lod.piece_start_.push_back(uint32_t(lod.piece_bounds_.size()));
        if (last_triangles > kBoxTriangles.size()) {
            DetailLevel box;
            box.box = true;
            box.first_triangle = uint32_t(out.triangleCount());
            box.triangle_count = uint32_t(kBoxTriangles.size());
            box.error = float(diagonal(bounds));
            out.resize(out.triangleCount() + kBoxTriangles.size());
            expansion.corner_source.resize(expansion.corner_source.size() + 36, 0);
            Expansion::writeBox(bounds, box.first_triangle, out);
            expansion.boxes.push_back({uint32_t(lod.scene_.objects.size()), box.first_triangle});
            detailed.parts.push_back(
                {object.name + " (box)", object.colour, box.first_triangle, box.triangle_count});
            lod.levels_.push_back(box);
        }
        detailed.triangle_count = uint32_t(out.triangleCount()) - detailed.first_triangle;
        lod.scene_.objects.push_back(std::move(detailed));
        lod.level_start_.push_back(uint32_t(lod.levels_.size()));
        done += object.triangle_count;
        if (progress)
            progress(double(done) / double(std::max<std::size_t>(1, lod.source_triangles_)));
    }
    if (source.animation)
        lod.scene_.animation =
            std::make_shared<DetailedAnimation>(source.animation, lod.expansion_);
    return lod;
}

} // namespace vissort
