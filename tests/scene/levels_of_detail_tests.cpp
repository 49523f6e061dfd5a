// Levels of detail: the chain's invariants (level 0 the source's own triangles, coarser levels
// smaller, closed solids closed, the box holding the object), dynamic scenes' frames, and the
// per-frame choice (the projected error within the bound, computed here from the camera;
// hysteresis; objects out of view).

#include "vissort/levels_of_detail.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>
#include <tuple>

#include "scenes/scene_library.h"
#include "vissort/camera.h"

namespace vissort {
namespace {

Scene load(const std::string& specification) {
    Result<Scene> loaded = samples::loadScene(specification);
    EXPECT_TRUE(loaded) << specification << ": " << loaded.error;
    return loaded ? std::move(*loaded.value) : Scene{};
}

// Each directed edge's uses minus its reverse's, corners compared by position: all zero for a
// closed, consistently wound surface (a solid may pinch, two sheets meeting at an edge, and stay
// closed).
using Point = std::tuple<float, float, float>;
std::map<std::pair<Point, Point>, int> edgeBalance(PositionsView positions, PrimitiveRange range) {
    std::map<std::pair<Point, Point>, int> uses;
    for (uint32_t t = range.first_triangle; t < range.first_triangle + range.triangle_count; ++t)
        for (uint32_t k = 0; k < 3; ++k) {
            const std::size_t a = std::size_t(t) * 3 + k, b = std::size_t(t) * 3 + (k + 1) % 3;
            Point p{positions.x[a], positions.y[a], positions.z[a]};
            Point q{positions.x[b], positions.y[b], positions.z[b]};
            if (q < p)
                --uses[{q, p}];
            else
                ++uses[{p, q}];
        }
    return uses;
}

bool closed(PositionsView positions, PrimitiveRange range) {
    for (const auto& [edge, balance] : edgeBalance(positions, range))
        if (balance != 0)
            return false;
    return true;
}

// The triangles of a set of ranges, as one range when they are one (tests of closedness take
// ranges one at a time, so a union is copied into a scene of its own).
TrianglePositions trianglesOf(PositionsView positions, std::span<const PrimitiveRange> ranges) {
    TrianglePositions out;
    for (const PrimitiveRange& range : ranges)
        for (std::size_t c = std::size_t(range.first_triangle) * 3;
             c < std::size_t(range.first_triangle + range.triangle_count) * 3; ++c) {
            out.x.push_back(positions.x[c]);
            out.y.push_back(positions.y[c]);
            out.z.push_back(positions.z[c]);
        }
    return out;
}

bool holds(const Bounds& outer, const Bounds& inner) {
    return inner.min.x >= outer.min.x && inner.min.y >= outer.min.y && inner.min.z >= outer.min.z &&
           inner.max.x <= outer.max.x && inner.max.y <= outer.max.y && inner.max.z <= outer.max.z;
}

// A closed pipe along z from 0 to length, its radius waving about 0.5 (so that its rings are
// worth keeping near the eye): rings of `segments` corners every unit, flat caps.
Scene longPipe(double length, int segments) {
    Scene scene;
    scene.name = "pipe";
    const auto corner = [&](int ring, int j) {
        const double a = 2 * M_PI * j / segments, radius = 0.5 + 0.15 * std::sin(ring * 0.7);
        return Vec3{radius * std::cos(a), radius * std::sin(a), double(ring)};
    };
    const auto add = [&](const Vec3& a, const Vec3& b, const Vec3& c) {
        for (const Vec3& p : {a, b, c}) {
            scene.positions.x.push_back(float(p.x));
            scene.positions.y.push_back(float(p.y));
            scene.positions.z.push_back(float(p.z));
        }
    };
    const int rings = int(length) + 1;
    for (int r = 0; r + 1 < rings; ++r)
        for (int j = 0; j < segments; ++j) {
            const int k = (j + 1) % segments;
            add(corner(r, j), corner(r, k), corner(r + 1, k));
            add(corner(r, j), corner(r + 1, k), corner(r + 1, j));
        }
    for (int j = 0; j < segments; ++j) {
        const int k = (j + 1) % segments;
        add({0, 0, 0}, corner(0, k), corner(0, j));
        add({0, 0, double(rings - 1)}, corner(rings - 1, j), corner(rings - 1, k));
    }
    scene.objects.push_back({"pipe",
                             {0.6f, 0.6f, 0.7f, 1.0f},
                             false,
                             0,
                             uint32_t(scene.positions.triangleCount()),
                             {}});
    CameraSpec camera;
    camera.eye = {0, 2, -3};
    camera.target = {0, 0, length / 2};
    scene.camera = camera;
    return scene;
}

class LevelsOfDetailPieces : public ::testing::TestWithParam<uint32_t> {};

TEST_P(LevelsOfDetailPieces, LevelZeroIsTheSourceAndCoarserLevelsShrink) {
    const Scene source = load("builtin:powerplant?scale=0.1");
    LodOptions options;
    options.piece_triangles = GetParam();
    const LevelsOfDetail lod = LevelsOfDetail::build(source, options);
    const Scene& scene = lod.scene();
    ASSERT_EQ(scene.objects.size(), source.objects.size());
    EXPECT_TRUE(validateScene(scene).ok) << validateScene(scene).error;
    std::size_t simplified = 0, boxes = 0, cut = 0;
    for (uint32_t o = 0; o < source.objects.size(); ++o) {
        const SceneObject& from = source.objects[o];
        const SceneObject& to = scene.objects[o];
        EXPECT_EQ(to.name, from.name);
        EXPECT_EQ(to.transparent, from.transparent);
        const std::span<const DetailLevel> levels = lod.levels(o);
        ASSERT_GE(levels.size(), 1u);
        EXPECT_EQ(levels[0].first_triangle, to.first_triangle);
        EXPECT_EQ(levels[0].triangle_count, from.triangle_count);
        EXPECT_EQ(levels[0].error, 0.0f);
        // Level 0 holds each source triangle once, its corners bit for bit (in the pieces'
        // order when the object is cut).
        std::vector<uint8_t> seen(from.triangle_count, 0);
        for (uint32_t t = from.first_triangle; t < from.first_triangle + from.triangle_count; ++t) {
            const uint32_t d = lod.detailedTriangleOf(t);
            ASSERT_GE(d, levels[0].first_triangle) << from.name;
            ASSERT_LT(d - levels[0].first_triangle, from.triangle_count) << from.name;
            ++seen[d - levels[0].first_triangle];
            for (uint32_t k = 0; k < 3; ++k) {
                ASSERT_EQ(scene.positions.x[d * 3 + k], source.positions.x[t * 3 + k]);
                ASSERT_EQ(scene.positions.y[d * 3 + k], source.positions.y[t * 3 + k]);
                ASSERT_EQ(scene.positions.z[d * 3 + k], source.positions.z[t * 3 + k]);
            }
        }
        EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), std::ptrdiff_t(from.triangle_count));
        for (std::size_t l = 1; l < levels.size(); ++l) {
            EXPECT_LT(levels[l].triangle_count, levels[l - 1].triangle_count) << from.name;
            EXPECT_GE(levels[l].error, levels[l - 1].error) << from.name;
            EXPECT_EQ(levels[l].first_triangle,
                      levels[l - 1].first_triangle + levels[l - 1].triangle_count);
        }
        const DetailLevel& last = levels.back();
        EXPECT_EQ(last.first_triangle + last.triangle_count, to.first_triangle + to.triangle_count);

        // The pieces: within the size asked for, their bounds inside the object's, and at each
        // level together the object's level (triangles and error).
        const PieceSpan pieces = lod.pieces(o);
        ASSERT_GE(pieces.count, 1u);
        cut += pieces.count > 1;
        const std::size_t simplified_levels = levels.size() - (last.box ? 1 : 0);
        for (uint32_t p = pieces.first; p < pieces.first + pieces.count; ++p) {
            EXPECT_TRUE(holds(lod.bounds()[o], lod.pieceBounds()[p])) << from.name;
            uint32_t level0 = 0;
            for (const PrimitiveRange& range : lod.pieceLevel(p, 0).ranges)
                level0 += range.triangle_count;
            EXPECT_LE(level0, options.piece_triangles) << from.name;
        }
        for (std::size_t l = 0; l < simplified_levels; ++l) {
            uint32_t triangles = 0;
            float error = 0.0f;
            for (uint32_t p = pieces.first; p < pieces.first + pieces.count; ++p) {
                const PieceLevel level = lod.pieceLevel(p, uint32_t(l));
                error = std::max(error, level.error);
                for (const PrimitiveRange& range : level.ranges) {
                    EXPECT_GE(range.first_triangle, levels[l].first_triangle);
                    EXPECT_LE(range.first_triangle + range.triangle_count,
                              levels[l].first_triangle + levels[l].triangle_count);
                    triangles += range.triangle_count;
                }
            }
            EXPECT_EQ(triangles, levels[l].triangle_count) << from.name << " level " << l;
            EXPECT_EQ(error, levels[l].error) << from.name << " level " << l;
        }
        simplified += levels.size() > 1 + (last.box ? 1 : 0);
        if (!last.box)
            continue;
        ++boxes;
        EXPECT_EQ(last.triangle_count, 12u);
        // The box holds every source corner and each of its corners is a corner of the bounds.
        const Bounds& bounds = lod.bounds()[o];
        for (uint32_t c = 0; c < 36; ++c) {
            const std::size_t d = std::size_t(last.first_triangle) * 3 + c;
            EXPECT_TRUE(scene.positions.x[d] == float(bounds.min.x) ||
                        scene.positions.x[d] == float(bounds.max.x));
            EXPECT_TRUE(scene.positions.y[d] == float(bounds.min.y) ||
                        scene.positions.y[d] == float(bounds.max.y));
        }
        EXPECT_TRUE(closed(scene.positions, {last.first_triangle, 12}));
        const double dx = bounds.max.x - bounds.min.x, dy = bounds.max.y - bounds.min.y,
                     dz = bounds.max.z - bounds.min.z;
        EXPECT_NEAR(last.error, std::sqrt(dx * dx + dy * dy + dz * dz), 1e-3 * last.error);
    }
    std::size_t chained = 0;
    for (uint32_t o = 0; o < source.objects.size(); ++o)
        chained += lod.levels(o).size();
    EXPECT_EQ(lod.levelCount(), chained);
    EXPECT_GT(simplified, source.objects.size() / 4) << "few objects were simplified";
    EXPECT_GT(boxes, 0u);
    if (GetParam() < 100) {
        EXPECT_GT(cut, source.objects.size() / 4) << "few objects were cut";
    }
}

INSTANTIATE_TEST_SUITE_P(PieceSizes, LevelsOfDetailPieces, ::testing::Values(1024u, 64u));

TEST(LevelsOfDetail, PiecesStayJoinedAtAnyMixOfLevels) {
    // A closed pipe cut into pieces: any level for each piece gives a closed surface, because
    // the borders between pieces keep their vertices at every level.
    const Scene source = longPipe(120, 24); // 5,808 triangles
    const LevelsOfDetail lod = LevelsOfDetail::build(source);
    const PieceSpan pieces = lod.pieces(0);
    ASSERT_GE(pieces.count, 4u);
    const std::size_t simplified = lod.levels(0).size() - (lod.levels(0).back().box ? 1 : 0);
    ASSERT_GE(simplified, 3u) << "the pipe should simplify";
    for (uint32_t mix = 0; mix < 12; ++mix) {
        std::vector<PrimitiveRange> ranges;
        for (uint32_t p = 0; p < pieces.count; ++p) {
            const uint32_t level = (p * 7 + mix * 3 + p * p * mix) % uint32_t(simplified);
            for (const PrimitiveRange& range : lod.pieceLevel(pieces.first + p, level).ranges)
                ranges.push_back(range);
        }
        const TrianglePositions joined = trianglesOf(lod.scene().positions, ranges);
        EXPECT_TRUE(closed(joined, {0, uint32_t(joined.triangleCount())})) << "mix " << mix;
    }
}

TEST(LevelsOfDetail, ClosedSolidsStayClosed) {
    // The power plant's parts are watertight solids (solid_shapes.h); the simplifier keeps a
    // manifold closed unless collapsing would change its topology, which it refuses.
    const Scene source = load("builtin:powerplant?scale=0.1");
    const LevelsOfDetail lod = LevelsOfDetail::build(source);
    std::size_t checked = 0, still_closed = 0;
    for (uint32_t o = 0; o < source.objects.size(); ++o) {
        const SceneObject& from = source.objects[o];
        if (from.parts.size() > 1 ||
            !closed(source.positions, {from.first_triangle, from.triangle_count}))
            continue;
        for (const DetailLevel& level : lod.levels(o)) {
            ++checked;
            still_closed +=
                closed(lod.scene().positions, {level.first_triangle, level.triangle_count});
        }
    }
    ASSERT_GT(checked, 20u);
    EXPECT_EQ(still_closed, checked);
}

TEST(LevelsOfDetail, DynamicScenesFramesExpandTheSources) {
    const Scene source = load("builtin:bunnies?n=2");
    ASSERT_TRUE(source.isDynamic());
    const LevelsOfDetail lod = LevelsOfDetail::build(source);
    ASSERT_TRUE(lod.scene().isDynamic());
    for (double t : {0.0, 0.35, 1.2}) {
        const TrianglePositions from = source.frame(t);
        const TrianglePositions to = lod.scene().frame(t);
        TrianglePositions expanded;
        std::vector<Bounds> bounds, piece_bounds;
        lod.expand(from, expanded, bounds, piece_bounds);
        ASSERT_EQ(expanded.x, to.x);
        ASSERT_EQ(expanded.z, to.z);
        for (uint32_t o = 0; o < source.objects.size(); ++o) {
            const SceneObject& object = source.objects[o];
            Bounds expected;
            for (std::size_t c = std::size_t(object.first_triangle) * 3;
                 c < std::size_t(object.first_triangle + object.triangle_count) * 3; ++c)
                expected.add(from.corner(c));
            EXPECT_EQ(bounds[o].min.x, expected.min.x);
            EXPECT_EQ(bounds[o].max.z, expected.max.z);
            // Level 0 is this frame's source triangles.
            for (uint32_t t = object.first_triangle;
                 t < object.first_triangle + object.triangle_count; ++t)
                for (uint32_t k = 0; k < 3; ++k)
                    ASSERT_EQ(to.x[lod.detailedTriangleOf(t) * 3 + k], from.x[t * 3 + k]);
            // Each piece's bounds are this frame's, of its level-0 triangles.
            const PieceSpan pieces = lod.pieces(o);
            for (uint32_t p = pieces.first; p < pieces.first + pieces.count; ++p) {
                Bounds piece;
                for (const PrimitiveRange& range : lod.pieceLevel(p, 0).ranges)
                    for (std::size_t c = std::size_t(range.first_triangle) * 3;
                         c < std::size_t(range.first_triangle + range.triangle_count) * 3; ++c)
                        piece.add(PositionsView(to).corner(c));
                EXPECT_EQ(piece_bounds[p].min.y, piece.min.y);
                EXPECT_EQ(piece_bounds[p].max.x, piece.max.x);
            }
            const DetailLevel& box = lod.levels(o).back();
            if (box.box) { // the box follows the frame's corners
                EXPECT_EQ(to.x[box.first_triangle * 3], float(expected.min.x));
            }
        }
    }
    EXPECT_GT(lod.levels(0).size(), 2u) << "the bunny should simplify";
}

TEST(LevelsOfDetail, BadOptionsAreRefused) {
    const Scene source = load("builtin:slabs");
    EXPECT_THROW(LevelsOfDetail::build(source, {0.0f, 8}), std::invalid_argument);
    EXPECT_THROW(LevelsOfDetail::build(source, {1.0f, 8}), std::invalid_argument);
    EXPECT_THROW(LevelsOfDetail::build(source, {0.25f, 1}), std::invalid_argument);
    EXPECT_THROW(LevelsOfDetail::build(source, {0.25f, 8, 15}), std::invalid_argument);
    EXPECT_THROW(LevelChooser(0.0f), std::invalid_argument);
    EXPECT_THROW(LevelChooser(NAN), std::invalid_argument);
    EXPECT_THROW(LevelChooser(1.0f, 1.0f), std::invalid_argument);
}

// The pixels a world length at distance `depth` in front of a perspective camera spans at most,
// from the camera's field of view: (height / 2) / tan(fov / 2) / depth, stretched towards the
// frustum's edges by at most sqrt(1 + tx^2 + ty^2).
double expectedPixelsPerUnit(const ViewProjection& view, const CameraSpec& camera, double depth) {
    const double ty = std::tan(camera.fov_degrees * M_PI / 360.0);
    const double tx = ty * view.width / view.height;
    const double per_unit = std::max(view.height / 2.0 / ty, view.width / 2.0 / tx) / depth;
    return per_unit * std::sqrt(1 + tx * tx + ty * ty);
}

TEST(LevelChooser, ChoosesTheCoarsestLevelWithinTheBoundAndHoldsItWithHysteresis) {
    const Scene source = load("builtin:bunnies?n=1");
    LodOptions whole; // one piece: the object's levels are the piece's
    whole.piece_triangles = source.triangleCount();
    const LevelsOfDetail lod = LevelsOfDetail::build(source, whole);
    ASSERT_EQ(lod.pieceCount(), 1u);
    const std::span<const DetailLevel> levels = lod.levels(0);
    ASSERT_GE(levels.size(), 3u);
    const Bounds bounds = lod.bounds()[0];
    const Vec3 centre = bounds.centre();
    const double radius = bounds.radius();
    const auto viewAt = [&](double distance) {
        CameraSpec camera;
        camera.eye = {centre.x, centre.y, centre.z + distance};
        camera.target = centre;
        ViewProjection view = frameCamera(camera, bounds, 800, 600);
        return std::pair(view, camera);
    };
    const float bound = 1.0f;
    // Along a path away from the bunny and back: each frame's level keeps its projected error
    // within the bound, recomputed here; far away the box, near the full mesh.
    LevelChooser chooser(bound);
    std::vector<double> distances;
    for (int i = 0; i <= 60; ++i)
        distances.push_back(radius * 1.5 * std::pow(1.15, i));
    for (int i = 60; i >= 0; --i)
        distances.push_back(radius * 1.5 * std::pow(1.15, i));
    int switches = 0;
    uint8_t last = 0;
    for (std::size_t f = 0; f < distances.size(); ++f) {
        const auto [view, camera] = viewAt(distances[f]);
        const uint8_t level =
            chooser.choose(lod, std::span(&bounds, 1), std::span(&bounds, 1), view)[0];
        ASSERT_NE(level, LevelChooser::kCulled);
        const double nearest = distances[f] - (bounds.max.z - centre.z);
        const double per_unit = expectedPixelsPerUnit(view, camera, nearest);
        EXPECT_LE(levels[level].error * per_unit, bound * 1.0001) << "frame " << f;
        if (level + 1u < levels.size()) { // not coarser than needed, beyond the hysteresis
            EXPECT_GT(levels[level + 1].error * per_unit, bound * 0.75 * 0.9999) << "frame " << f;
        }
        switches += f > 0 && level != last;
        last = level;
    }
    EXPECT_EQ(last, 0) << "back near the bunny";
    EXPECT_EQ(chooser.chosen()[0], 0);
    EXPECT_GE(switches, 2 * int(levels.size() - 1) - 2);

    // Back and forth across one level's threshold by 5%: the level holds.
    const double threshold =
        levels[1].error *
        expectedPixelsPerUnit(viewAt(10 * radius).first, viewAt(10 * radius).second, 1.0) /
        bound; // the depth at which level 1's error projects to the bound
    LevelChooser steady(bound), flickering(bound, 0.0f);
    std::vector<uint8_t> chosen, without;
    for (int i = 0; i < 20; ++i) {
        const double depth = threshold * (i % 2 ? 1.05 : 0.95);
        const double distance = depth + (bounds.max.z - centre.z);
        const ViewProjection view = viewAt(distance).first;
        chosen.push_back(steady.choose(lod, std::span(&bounds, 1), std::span(&bounds, 1), view)[0]);
        without.push_back(
            flickering.choose(lod, std::span(&bounds, 1), std::span(&bounds, 1), view)[0]);
    }
    for (std::size_t i = 2; i < chosen.size(); ++i) {
        EXPECT_EQ(chosen[i], chosen[1]) << "flickered at step " << i;
        EXPECT_NE(without[i], without[i - 1]) << "without hysteresis the level should switch";
    }
}

TEST(LevelChooser, EachPieceTakesItsOwnLevelAndPiecesBehindTheEyeAreLeftOut) {
    // From inside a pipe 200 long, at z = 30 looking along it: the pieces behind the eye are
    // culled, the near ones fine, the far ones coarse, each within the bound from its own depth.
    const Scene source = longPipe(200, 24);
    auto lod = std::make_shared<const LevelsOfDetail>(LevelsOfDetail::build(source));
    const PieceSpan pieces = lod->pieces(0);
    ASSERT_GE(pieces.count, 8u);
    CameraSpec camera;
    camera.eye = {0, 0, 30};
    camera.target = {0, 0, 100};
    camera.up = {0, 1, 0};
    const ViewProjection view = frameCamera(camera, lod->bounds()[0], 800, 600);
    const float bound = 1.0f;
    DetailSelection selection(source, lod, bound);
    selection.select(source.positions, view);
    const std::span<const uint8_t> chosen = selection.chosen();
    ASSERT_EQ(chosen.size(), lod->pieceCount());
    uint32_t culled = 0, drawn_triangles = 0;
    uint8_t nearest_level = 0xFF, farthest_level = 0;
    double nearest_depth = INFINITY, farthest_depth = 0;
    for (uint32_t p = pieces.first; p < pieces.first + pieces.count; ++p) {
        const Bounds& piece = lod->pieceBounds()[p];
        if (piece.max.z < 30 - 1e-3) { // wholly behind the eye
            EXPECT_EQ(chosen[p], LevelChooser::kCulled) << "piece " << p;
            ++culled;
            continue;
        }
        ASSERT_NE(chosen[p], LevelChooser::kCulled) << "piece " << p;
        for (const PrimitiveRange& range : lod->pieceLevel(p, chosen[p]).ranges)
            drawn_triangles += range.triangle_count;
        const double depth = piece.min.z - 30;
        if (depth <= view.near) {
            EXPECT_EQ(chosen[p], 0) << "piece " << p << " reaches the eye";
            continue;
        }
        const double per_unit = expectedPixelsPerUnit(view, camera, depth);
        EXPECT_LE(lod->pieceLevel(p, chosen[p]).error * per_unit, bound * 1.0001) << "piece " << p;
        if (depth < nearest_depth)
            nearest_depth = depth, nearest_level = chosen[p];
        if (depth > farthest_depth)
            farthest_depth = depth, farthest_level = chosen[p];
    }
    EXPECT_GT(culled, 0u);
    EXPECT_GT(farthest_level, nearest_level) << "the far end should be coarser";
    // The selection draws exactly the chosen pieces, and the gathered frame holds them.
    const std::span<const PrimitiveRange> ranges = selection.chosenRanges(0);
    uint32_t selected = 0;
    for (const PrimitiveRange& range : ranges)
        selected += range.triangle_count;
    EXPECT_EQ(selected, drawn_triangles);
    EXPECT_EQ(selection.triangles(), drawn_triangles);
    EXPECT_EQ(selection.gather().objects[0].triangle_count, drawn_triangles);
    EXPECT_LT(drawn_triangles, source.triangleCount() / 2);
}

TEST(LevelChooser, ObjectsOutOfViewAreCulledAndOthersAreNot) {
    Bounds box;
    box.add({-1, -1, -1});
    box.add({1, 1, 1});
    CameraSpec camera;
    camera.eye = {0, 0, 10};
    camera.target = {0, 0, 0};
    const ViewProjection view = frameCamera(camera, box, 400, 300);
    EXPECT_FALSE(boxOutsideView(box, view));
    const auto moved = [&](double x, double y, double z) {
        Bounds b;
        b.add({box.min.x + x, box.min.y + y, box.min.z + z});
        b.add({box.max.x + x, box.max.y + y, box.max.z + z});
        return b;
    };
    EXPECT_TRUE(boxOutsideView(moved(0, 0, 30), view)); // behind the eye
    EXPECT_TRUE(boxOutsideView(moved(100, 0, 0), view));
    EXPECT_TRUE(boxOutsideView(moved(0, -100, 0), view));
    // The near plane is at about 8.2 (frameCamera): a box in front of it is out, one across it in.
    EXPECT_TRUE(boxOutsideView(moved(0, 0, 9.5), view));
    EXPECT_FALSE(boxOutsideView(moved(0, 0, 2), view));
    EXPECT_FALSE(boxOutsideView(moved(3.5, 0, 0), view)); // at the edge, partly in
    EXPECT_EQ(LevelChooser::pixelsPerUnit(moved(0, 0, 10), view), INFINITY); // across the eye
}

} // namespace
} // namespace vissort
