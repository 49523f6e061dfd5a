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

TEST(LevelsOfDetail, LevelZeroIsTheSourceAndCoarserLevelsShrink) {
    const Scene source = load("builtin:powerplant?scale=0.1");
    const LevelsOfDetail lod = LevelsOfDetail::build(source);
    const Scene& scene = lod.scene();
    ASSERT_EQ(scene.objects.size(), source.objects.size());
    EXPECT_TRUE(validateScene(scene).ok) << validateScene(scene).error;
    std::size_t simplified = 0, boxes = 0;
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
        for (uint32_t c = 0; c < from.triangle_count * 3; ++c) {
            const std::size_t s = std::size_t(from.first_triangle) * 3 + c;
            const std::size_t d = std::size_t(to.first_triangle) * 3 + c;
            ASSERT_EQ(scene.positions.x[d], source.positions.x[s]) << from.name;
            ASSERT_EQ(scene.positions.y[d], source.positions.y[s]) << from.name;
            ASSERT_EQ(scene.positions.z[d], source.positions.z[s]) << from.name;
        }
        EXPECT_EQ(lod.detailedTriangleOf(from.first_triangle), to.first_triangle);
        for (std::size_t l = 1; l < levels.size(); ++l) {
            EXPECT_LT(levels[l].triangle_count, levels[l - 1].triangle_count) << from.name;
            EXPECT_GE(levels[l].error, levels[l - 1].error) << from.name;
            EXPECT_EQ(levels[l].first_triangle,
                      levels[l - 1].first_triangle + levels[l - 1].triangle_count);
        }
        const DetailLevel& last = levels.back();
        EXPECT_EQ(last.first_triangle + last.triangle_count, to.first_triangle + to.triangle_count);
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
    EXPECT_GT(simplified, source.objects.size() / 4) << "few objects were simplified";
    EXPECT_GT(boxes, 0u);
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
        std::vector<Bounds> bounds;
        lod.expand(from, expanded, bounds);
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
            // Level 0 is this frame's source triangles; every simplified corner is one of them.
            const PrimitiveRange level0 = {lod.levels(o)[0].first_triangle, object.triangle_count};
            for (uint32_t c = 0; c < level0.triangle_count * 3; ++c)
                ASSERT_EQ(to.x[level0.first_triangle * 3 + c],
                          from.x[object.first_triangle * 3 + c]);
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
    const LevelsOfDetail lod = LevelsOfDetail::build(source);
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
        const uint8_t level = chooser.choose(lod, std::span(&bounds, 1), view)[0];
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
        chosen.push_back(steady.choose(lod, std::span(&bounds, 1), view)[0]);
        without.push_back(flickering.choose(lod, std::span(&bounds, 1), view)[0]);
    }
    for (std::size_t i = 2; i < chosen.size(); ++i) {
        EXPECT_EQ(chosen[i], chosen[1]) << "flickered at step " << i;
        EXPECT_NE(without[i], without[i - 1]) << "without hysteresis the level should switch";
    }
}

TEST(LevelChooser, ObjectsOutOfViewAreCulledAndOthersAreNot) {
    Bounds box;
    box.add({-1, -1, -1});
    box.add({1, 1, 1});
    CameraSpec camera;
    camera.eye = {0, 0, 10};
    camera.target = {0, 0, 0};
    const ViewProjection view = frameCamera(camera, box, 400, 300);
    EXPECT_FALSE(LevelChooser::outsideView(box, view));
    const auto moved = [&](double x, double y, double z) {
        Bounds b;
        b.add({box.min.x + x, box.min.y + y, box.min.z + z});
        b.add({box.max.x + x, box.max.y + y, box.max.z + z});
        return b;
    };
    EXPECT_TRUE(LevelChooser::outsideView(moved(0, 0, 30), view)); // behind the eye
    EXPECT_TRUE(LevelChooser::outsideView(moved(100, 0, 0), view));
    EXPECT_TRUE(LevelChooser::outsideView(moved(0, -100, 0), view));
    // The near plane is at about 8.2 (frameCamera): a box in front of it is out, one across it in.
    EXPECT_TRUE(LevelChooser::outsideView(moved(0, 0, 9.5), view));
    EXPECT_FALSE(LevelChooser::outsideView(moved(0, 0, 2), view));
    EXPECT_FALSE(LevelChooser::outsideView(moved(3.5, 0, 0), view)); // at the edge, partly in
    EXPECT_EQ(LevelChooser::pixelsPerUnit(moved(0, 0, 10), view), INFINITY); // across the eye
}

} // namespace
} // namespace vissort
