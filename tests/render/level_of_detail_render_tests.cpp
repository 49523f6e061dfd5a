// The renderer with levels of detail: every coherent frame exact for the geometry it drew (its
// own A-buffer, ray cast through the triangles of the levels the frame chose), fewer triangles
// drawn than the scene has, levels that follow the distance, and lod_error 0 drawing what the
// renderer draws without levels, bit for bit.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "a_buffer.h"
#include "render_cases.h"
#include "vissort/camera_path.h"
#include "vissort/levels_of_detail.h"
#include "vissort/transparency_renderer.h"

namespace vissort {
namespace {

using test::context;
using test::kHeight;
using test::kWidth;
using test::triangleColours;

// The frame's drawn geometry: each object's chosen triangles (its box, or each piece in view at
// its level), with the colours of the levels' scene (test::triangleColours: each part's).
struct DrawnGeometry {
    TrianglePositions positions;
    std::vector<Rgba> colours;
    uint64_t triangles = 0;
};

DrawnGeometry drawnGeometry(const TransparencyRenderer& renderer, PositionsView frame,
                            const RenderSettings& settings) {
    const LevelsOfDetail& levels = *renderer.levels();
    const std::vector<Rgba> colours = triangleColours(levels.scene(), settings);
    const DetailSelection& selection = *renderer.levelSelection();
    DrawnGeometry drawn;
    for (uint32_t o = 0; o < levels.objectCount(); ++o)
        for (const PrimitiveRange& range : selection.chosenRanges(o)) {
            for (uint32_t t = range.first_triangle; t < range.first_triangle + range.triangle_count;
                 ++t) {
                for (std::size_t c = std::size_t(t) * 3; c < std::size_t(t) * 3 + 3; ++c) {
                    drawn.positions.x.push_back(frame.x[c]);
                    drawn.positions.y.push_back(frame.y[c]);
                    drawn.positions.z.push_back(frame.z[c]);
                }
                drawn.colours.push_back(colours[t]);
            }
            drawn.triangles += range.triangle_count;
        }
    return drawn;
}

TEST(LevelOfDetailRender, WalkthroughFramesAreExactForTheLevelsDrawn) {
    const Scene scene = test::loadTestScene("builtin:powerplant?scale=0.05");
    const Bounds bounds = scene.positions.bounds();
    const auto levels = std::make_shared<const LevelsOfDetail>(LevelsOfDetail::build(scene));
    for (OrderLevel level : {OrderLevel::object, OrderLevel::multistage}) {
        SCOPED_TRACE(orderLevelName(level));
        RenderSettings settings;
        settings.shading = Shading::flat;
        settings.level = level;
        settings.lod_error = 4.0f; // coarse enough that many objects change level on the way
        TransparencyRenderer renderer(context(), scene, settings, levels);
        std::vector<uint8_t> previous;
        uint32_t switched = 0, coarser = 0;
        for (int f : {0, 1, 2, 150, 151, 450}) {
            SCOPED_TRACE("frame " + std::to_string(f));
            const ViewProjection view = frameCamera(
                cameraOnPath(*scene.camera, CameraPath::scene, f, bounds, scene.camera_path),
                bounds, kWidth, kHeight);
            RenderStats stats;
            const std::vector<uint8_t> image =
                renderer.render(scene.positions, view, stats).toRgba8();
            const std::span<const uint8_t> chosen = renderer.levelSelection()->chosen();
            ASSERT_EQ(chosen.size(), levels->pieceCount());
            if (!previous.empty())
                for (std::size_t o = 0; o < chosen.size(); ++o)
                    switched += chosen[o] != previous[o];
            for (uint8_t c : chosen)
                coarser += c != 0 && c != LevelChooser::kCulled;
            previous.assign(chosen.begin(), chosen.end());
            const DrawnGeometry drawn =
                drawnGeometry(renderer, levels->scene().positions, settings);
            EXPECT_EQ(stats.triangles, drawn.triangles);
            EXPECT_LT(stats.triangles, scene.triangleCount());
            EXPECT_GT(stats.culled_objects, 0u);
            const test::ABufferComparison compared = test::compareWithABuffer(
                image,
                test::rayCastComposite(drawn.positions, view, drawn.colours, settings.background));
            EXPECT_GT(compared.compared, uint64_t(kWidth) * kHeight / 2);
            EXPECT_LE(compared.max_abs, 1)
                << "worst at (" << compared.worst_x << ", " << compared.worst_y << ")";
        }
        EXPECT_GT(coarser, 0u) << "no object was drawn coarser than its source";
        EXPECT_GT(switched, 0u) << "no object changed level along the path";
    }
}

TEST(LevelOfDetailRender, DeformingBunniesStayExactFrameByFrame) {
    const Scene scene = test::loadTestScene("builtin:bunnies?n=6");
    const Bounds bounds = scene.positions.bounds();
    RenderSettings settings;
    settings.shading = Shading::flat;
    settings.level = OrderLevel::multistage;
    settings.lod_error = 2.0f;
    TransparencyRenderer renderer(context(), scene, settings); // builds its own levels
    ASSERT_NE(renderer.levels(), nullptr);
    TrianglePositions positions;
    for (int f = 0; f < 3; ++f) {
        SCOPED_TRACE("frame " + std::to_string(f));
        scene.frame(f * kFrameInterval, positions);
        const ViewProjection view =
            frameCamera(cameraOnPath(*scene.camera, CameraPath::orbit, f, bounds),
                        positions.bounds(), kWidth, kHeight);
        RenderStats stats;
        const std::vector<uint8_t> image = renderer.render(positions, view, stats).toRgba8();
        // The levels' scene at this frame, independently: the source frame expanded.
        const TrianglePositions expanded = renderer.levels()->scene().frame(f * kFrameInterval);
        const DrawnGeometry drawn = drawnGeometry(renderer, expanded, settings);
        EXPECT_LT(stats.triangles, scene.triangleCount());
        const test::ABufferComparison compared = test::compareWithABuffer(
            image,
            test::rayCastComposite(drawn.positions, view, drawn.colours, settings.background));
        EXPECT_GT(compared.compared, uint64_t(kWidth) * kHeight / 4);
        EXPECT_LE(compared.max_abs, 1)
            << "worst at (" << compared.worst_x << ", " << compared.worst_y << ")";
    }
}

// With a bound so small that every object in view takes level 0, the levels' machinery (the
// levels' scene drawn, the part rebuilt each frame, objects out of view left out of the draw and
// the order) draws the picture the renderer draws without levels. (lod_error 0 is the renderer
// without levels: the command line's test compares those PNGs byte for byte.)
TEST(LevelOfDetailRender, LevelZeroEverywhereDrawsThePictureWithoutLevels) {
    const Scene scene = test::loadTestScene("builtin:powerplant?scale=0.05");
    const Bounds bounds = scene.positions.bounds();
    for (BlendMethod method : {BlendMethod::vissort, BlendMethod::unsorted, BlendMethod::peel}) {
        SCOPED_TRACE(blendMethodName(method));
        RenderSettings settings;
        settings.method = method;
        settings.shading = Shading::flat;
        RenderSettings fine = settings;
        fine.lod_error = 1e-6f;
        TransparencyRenderer plain(context(), scene, settings), levels(context(), scene, fine);
        for (int f : {0, 1, 150}) {
            const ViewProjection view = frameCamera(
                cameraOnPath(*scene.camera, CameraPath::scene, f, bounds, scene.camera_path),
                bounds, kWidth, kHeight);
            RenderStats a, b;
            const std::vector<uint8_t> without = plain.render(scene.positions, view, a).toRgba8();
            const std::vector<uint8_t> with = levels.render(scene.positions, view, b).toRgba8();
            uint32_t culled = 0;
            for (uint8_t c : levels.levelSelection()->chosen()) {
                EXPECT_TRUE(c == 0 || c == LevelChooser::kCulled);
                culled += c == LevelChooser::kCulled;
            }
            EXPECT_GT(culled, 0u) << "frame " << f;
            EXPECT_EQ(a.triangles, scene.triangleCount());
            EXPECT_LT(b.triangles, scene.triangleCount()) << "frame " << f;
            // The unsorted method blends in another submission order once objects are left
            // out; every other method's picture is the same.
            EXPECT_LE(compareImages(without, with).max_abs,
                      method == BlendMethod::unsorted ? 255 : 1)
                << "frame " << f;
            if (method != BlendMethod::unsorted) {
                EXPECT_EQ(compareImages(without, with).pixels_over_one, 0u) << "frame " << f;
            }
        }
    }
}

TEST(LevelOfDetailRender, FarAwayObjectsAreBoxesAndEveryMethodDrawsTheSameLevels) {
    const Scene scene = test::loadTestScene("builtin:bunnies?n=4");
    const Bounds bounds = scene.positions.bounds();
    CameraSpec far = *scene.camera;
    const Vec3 c = bounds.centre();
    far.eye = {c.x + (far.eye.x - c.x) * 400, c.y + (far.eye.y - c.y) * 400,
               c.z + (far.eye.z - c.z) * 400};
    far.target = c;
    const ViewProjection view = frameCamera(far, bounds, kWidth, kHeight);
    RenderSettings settings;
    settings.shading = Shading::flat;
    settings.lod_error = 1.0f;
    RenderSettings linked = settings;
    linked.method = BlendMethod::linked_list;
    const auto levels = std::make_shared<const LevelsOfDetail>(LevelsOfDetail::build(scene));
    TransparencyRenderer vissort(context(), scene, settings, levels),
        reference(context(), scene, linked, levels);
    RenderStats stats, reference_stats;
    const std::vector<uint8_t> image = vissort.render(scene.positions, view, stats).toRgba8();
    const std::vector<uint8_t> expected =
        reference.render(scene.positions, view, reference_stats).toRgba8();
    EXPECT_EQ(stats.triangles, reference_stats.triangles);
    EXPECT_LE(compareImages(image, expected).max_abs, 1);
    uint32_t boxes = 0; // objects whose every piece is at the box level
    const std::span<const uint8_t> chosen = vissort.levelSelection()->chosen();
    for (uint32_t o = 0; o < scene.objects.size(); ++o) {
        const PieceSpan pieces = levels->pieces(o);
        bool box = levels->levels(o).back().box;
        for (uint32_t p = pieces.first; p < pieces.first + pieces.count; ++p)
            box = box && chosen[p] == levels->levels(o).size() - 1;
        boxes += box;
    }
    EXPECT_GT(boxes, 0u);
    EXPECT_EQ(stats.boxed_objects, boxes);
    EXPECT_LT(stats.triangles, scene.triangleCount() / 20);
}

TEST(LevelOfDetailRender, BadErrorsAndLevelsOfAnotherSceneAreRefused) {
    const Scene scene = test::loadTestScene("builtin:bunnies?n=2");
    const Scene other = test::loadTestScene("builtin:bunnies?n=3");
    RenderSettings settings;
    settings.lod_error = -1.0f;
    EXPECT_THROW(TransparencyRenderer(context(), scene, settings), std::invalid_argument);
    settings.lod_error = INFINITY;
    EXPECT_THROW(TransparencyRenderer(context(), scene, settings), std::invalid_argument);
    settings.lod_error = 1.0f;
    const auto levels = std::make_shared<const LevelsOfDetail>(LevelsOfDetail::build(other));
    EXPECT_THROW(TransparencyRenderer(context(), scene, settings, levels), std::invalid_argument);
}

} // namespace
} // namespace vissort
