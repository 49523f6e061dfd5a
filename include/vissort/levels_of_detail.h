#pragma once
// Levels of detail of a scene's objects (docs/lod.md): each object's triangles simplified into a
// chain of coarser meshes with their geometric error (meshoptimizer's meshopt_simplify, borders
// and the seams between parts kept), ending with the object's bounding box; and the choice, frame
// by frame, of the coarsest level whose error projects to at most a given number of pixels.
//
// The levels live in a scene of their own (LevelsOfDetail::scene): the same objects, in the same
// order, each holding its levels one after another, finest first. Level 0 is the source object's
// own triangles. An object of many triangles is cut into pieces (LodOptions::piece_triangles),
// simplified each with their shared borders kept, so that the far end of a long pipe run can be
// coarser than its near end: each piece takes its own level every frame, and renderers and
// orderers draw each object's chosen pieces (DetailSelection::chosenRanges).
//
// Layer: vissort::scene (the package's `scene` component; docs/architecture.md).

#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "vissort/camera.h"
#include "vissort/geometry.h"
#include "vissort/result.h"
#include "vissort/scene.h"

namespace vissort {

/// How the chains are built.
struct LodOptions {
    /// Each level aims at this fraction of the triangles of the level before it, in (0, 1).
    float reduction = 0.25f;
    /// At most this many levels an object, level 0 and the box included (2 to 16).
    uint32_t max_levels = 8;
    /// An object of more triangles is cut into pieces of at most this many (at least 16),
    /// halving it across its longest extent, each piece choosing its own level every frame.
    uint32_t piece_triangles = 1024;
};

/// One level of an object, every piece at that level: its range of LevelsOfDetail::scene's
/// triangles and its geometric error in world units (how far its surface may lie from the
/// source's: meshoptimizer's error, summed along the chain, as a bound; the largest of its
/// pieces'; the box's is its diagonal).
struct DetailLevel {
    uint32_t first_triangle = 0;
    uint32_t triangle_count = 0;
    float error = 0.0f;
    bool box = false; // the object's bounding box (12 triangles, made from each frame's corners)
};

/// One level of one piece of an object: its triangles (a range for each drawn part of the
/// object that the piece holds, within the object's DetailLevel) and its error in world units.
struct PieceLevel {
    std::span<const PrimitiveRange> ranges;
    float error = 0.0f;
};

/// The pieces of one object: indices [first, first + count) of LevelsOfDetail's pieces.
struct PieceSpan {
    uint32_t first = 0, count = 0;
};

class LevelsOfDetail {
public:
    /// The levels of every object of source (a valid scene). A dynamic source gives a dynamic
    /// scene whose frames are the source's frames expanded (simplified levels move with the
    /// source corners they keep; boxes follow each frame's corners). progress, when set, is
    /// called with the share of the source's triangles done (0 to 1).
    static LevelsOfDetail build(const Scene& source, const LodOptions& options = {},
                                const std::function<void(double)>& progress = {});

    /// Every object's levels, finest first: objects, names and colours as the source's, each
    /// level of each drawn part a part of its own (so that normals never mix levels).
    const Scene& scene() const { return scene_; }
    std::span<const DetailLevel> levels(uint32_t object) const;
    std::size_t objectCount() const { return level_start_.size() - 1; }
    /// Every object's levels together (the box included): levelCount() / objectCount() is the
    /// levels an object on average.
    std::size_t levelCount() const { return levels_.size(); }
    std::size_t sourceTriangleCount() const { return source_triangles_; }

    /// The pieces of an object (one when it has at most LodOptions::piece_triangles triangles).
    /// Each piece has the object's levels but its box: levels(object) less a last box level.
    PieceSpan pieces(uint32_t object) const {
        return {piece_start_[object], piece_start_[object + 1] - piece_start_[object]};
    }
    std::size_t pieceCount() const { return piece_bounds_.size(); }
    PieceLevel pieceLevel(uint32_t piece, uint32_t level) const;

    /// The positions of scene() for a frame of the source (positions with the source's triangle
    /// count) into out, and each object's and each piece's bounds at that frame.
    void expand(PositionsView source, TrianglePositions& out, std::vector<Bounds>& bounds,
                std::vector<Bounds>& piece_bounds) const;
    /// The objects' and the pieces' bounds at t = 0 (the source's positions).
    const std::vector<Bounds>& bounds() const { return bounds_; }
    const std::vector<Bounds>& pieceBounds() const { return piece_bounds_; }
    /// The triangle of scene() that is source triangle t at level 0 (t < sourceTriangleCount()).
    uint32_t detailedTriangleOf(uint32_t source_triangle) const;

    /// How scene()'s corners are made from the source's (shared with a dynamic scene's
    /// animation).
    struct Expansion;

private:
    Scene scene_;
    std::vector<uint32_t> level_start_; // object -> its first entry of levels_; one past the last
    std::vector<DetailLevel> levels_;
    std::vector<Bounds> bounds_;
    std::vector<uint32_t> piece_start_; // object -> its first piece; one past the last
    struct PieceEntry {
        uint32_t first_range, range_count;
        float error;
    };
    std::vector<uint32_t> piece_level_start_; // piece -> its level 0 in piece_levels_
    std::vector<PieceEntry> piece_levels_;
    std::vector<PrimitiveRange> piece_ranges_;
    std::vector<Bounds> piece_bounds_;
    std::vector<uint32_t> detailed_triangle_; // source triangle -> scene()'s at level 0
    std::size_t source_triangles_ = 0;
    std::shared_ptr<Expansion> expansion_;
};

/// The level of detail of each piece of each object, frame by frame: the coarsest level whose
/// error projects to at most max_error_px pixels, seen through the frame's view from the nearest
/// corner of the piece's bounds, with hysteresis: a level is left for a coarser one only when the
/// coarser one's error projects to at most (1 - hysteresis) x max_error_px, so that pieces at the
/// threshold do not switch back and forth along a path. The error never exceeds max_error_px.
/// An object whose box is within the bound (seen from the object's bounds) is its box, every
/// piece of it; a piece, or a whole object, outside the view is culled.
class LevelChooser {
public:
    static constexpr uint8_t kCulled = 0xFF; // no corner of the piece's bounds in the view

    /// max_error_px > 0; hysteresis in [0, 1).
    explicit LevelChooser(float max_error_px, float hysteresis = 0.25f);

    /// This frame's level of each piece of levels (an index into levels.levels(o) of its object
    /// o: the box level when the object is its box), or kCulled for a piece wholly outside the
    /// view's frustum. bounds and piece_bounds: each object's and each piece's, this frame.
    std::span<const uint8_t> choose(const LevelsOfDetail& levels, std::span<const Bounds> bounds,
                                    std::span<const Bounds> piece_bounds,
                                    const ViewProjection& view);
    std::span<const uint8_t> chosen() const { return chosen_; }

    /// The pixels that a world length at bounds projects to at most (the largest over the box's
    /// depths, with the perspective's stretch at the frustum's edges); infinite when the box
    /// reaches the eye plane.
    static double pixelsPerUnit(const Bounds& bounds, const ViewProjection& view);

private:
    float max_error_px_, hysteresis_;
    std::vector<uint8_t> chosen_;
};

/// A frame at the levels chosen, compact: each object's chosen pieces' triangles, one object
/// after another (none for an object out of view), for orderers and detectors that take an
/// object's triangles as one contiguous range (SceneOrderer::setObjects).
struct DetailFrame {
    TrianglePositions positions;
    std::vector<PrimitiveRange> objects;     // each object's range of positions (empty: culled)
    std::vector<uint32_t> detailed_triangle; // positions' triangle -> LevelsOfDetail::scene()'s
    uint64_t triangles = 0;                  // positions.triangleCount()
    uint32_t boxed_objects = 0, culled_objects = 0;
};

/// Levels of detail frame by frame for one source scene: each frame's positions of the levels'
/// scene, every object's level (LevelChooser), and the frame gathered compactly on request.
class DetailSelection {
public:
    /// source must outlive the selection; levels are source's (std::invalid_argument when their
    /// object or triangle counts are not); max_error_px > 0 (LevelChooser).
    DetailSelection(const Scene& source, std::shared_ptr<const LevelsOfDetail> levels,
                    float max_error_px);

    /// Chooses the levels of the frame at source_positions (the source's triangle count) seen
    /// through view. The source's own positions (a static scene's frames, FrameDriver passing
    /// them without a copy) cost no expansion: the levels' scene holds them already.
    void select(PositionsView source_positions, const ViewProjection& view);

    /// This frame's positions of the levels' scene; valid until the next select.
    PositionsView levelsPositions() const { return positions_; }
    /// Each piece's level (LevelChooser::chosen).
    std::span<const uint8_t> chosen() const { return chooser_.chosen(); }
    /// The triangles of the levels' scene that draw an object this frame: its box, or each piece
    /// in view at its level (none for an object out of view).
    std::span<const PrimitiveRange> chosenRanges(uint32_t object) const {
        return std::span(ranges_).subspan(range_start_[object],
                                          range_start_[object + 1] - range_start_[object]);
    }
    /// This frame's triangles chosen in all, objects drawn as their box, objects out of view.
    uint64_t triangles() const { return triangles_; }
    uint32_t boxedObjects() const { return boxed_objects_; }
    uint32_t culledObjects() const { return culled_objects_; }
    const LevelsOfDetail& levels() const { return *levels_; }
    const std::shared_ptr<const LevelsOfDetail>& sharedLevels() const { return levels_; }
    /// The chosen levels gathered (DetailFrame), into a buffer reused from frame to frame.
    const DetailFrame& gather();
    /// The last gather's frame, without gathering again.
    const DetailFrame& frame() const { return frame_; }

private:
    const Scene* source_;
    std::shared_ptr<const LevelsOfDetail> levels_;
    LevelChooser chooser_;
    TrianglePositions expanded_;
    std::vector<Bounds> bounds_, piece_bounds_;
    PositionsView positions_;
    std::vector<uint32_t> range_start_; // object -> its first chosen range; one past the last
    std::vector<PrimitiveRange> ranges_;
    uint64_t triangles_ = 0;
    uint32_t boxed_objects_ = 0, culled_objects_ = 0;
    DetailFrame frame_;
};

} // namespace vissort
