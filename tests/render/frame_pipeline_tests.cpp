// FramePipeline (frame_pipeline.h), the one frame pipeline of `render`, the viewer and Python:
//  - its picture and its reference's are the A-buffer's (ray cast, independent of OpenGL), and
//    the error it reports is between those two pictures;
//  - with highlight_collisions, exactly the triangles CGAL finds meeting another object's are
//    drawn in the highlight colour and the rest dimmed (the A-buffer recoloured so), and the
//    counts are CGAL's;
//  - configure keeps a renderer whose settings did not change (its order seeds the next frame)
//    and remakes one whose settings did.

#include "vissort/frame_pipeline.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <set>
#include <vector>

#include "a_buffer.h"
#include "reference_triangles.h"
#include "render_cases.h"

namespace vissort {
namespace {

using namespace test; // render_cases.h

std::array<Vec3, 3> cornersOf(const Scene& scene, uint32_t t) {
    return {scene.positions.corner(3 * t), scene.positions.corner(3 * t + 1),
            scene.positions.corner(3 * t + 2)};
}

// CGAL's answer: every pair of triangles of different objects whose closed triangles meet.
struct Meeting {
    uint64_t pairs = 0;
    std::set<uint32_t> triangles;
};
Meeting meetingTriangles(const Scene& scene) {
    Meeting meeting;
    for (std::size_t a = 0; a < scene.objects.size(); ++a)
        for (std::size_t b = a + 1; b < scene.objects.size(); ++b) {
            const SceneObject& p = scene.objects[a];
            const SceneObject& q = scene.objects[b];
            for (uint32_t s = p.first_triangle; s < p.first_triangle + p.triangle_count; ++s)
                for (uint32_t t = q.first_triangle; t < q.first_triangle + q.triangle_count; ++t)
                    if (test::closedTrianglesMeet(cornersOf(scene, s), cornersOf(scene, t))) {
                        ++meeting.pairs;
                        meeting.triangles.insert({s, t});
                    }
        }
    return meeting;
}

TEST(FramePipeline, PictureAndReferenceMatchTheABuffer) {
    const Scene scene = test::loadTestScene("tests/data/scenes/interpenetrating.json");
    const RenderCase c{"Interpenetrating", "", true, 0.5f, {}, true, 4};
    const ViewProjection view = viewOf(scene, c);
    FramePipelineDef def;
    def.settings = settingsOf(c, BlendMethod::vissort);
    def.settings.shading = Shading::flat;
    def.reference = BlendMethod::linked_list;
    const test::ABuffer truth = test::rayCastComposite(
        scene.positions, view, triangleColours(scene, def.settings), def.settings.background);

    FramePipeline pipeline(context(), scene, def);
    PipelineFrame frame;
    pipeline.render(scene.positions, view, frame);
    ASSERT_EQ(frame.rgba.size(), std::size_t(kWidth) * kHeight * 4);
    EXPECT_LE(test::compareWithABuffer(frame.rgba, truth).max_abs, 1);
    EXPECT_LE(test::compareWithABuffer(frame.reference_rgba, truth).max_abs, 1);
    ASSERT_TRUE(frame.error);
    EXPECT_LE(frame.error->max_abs, 2);
    // The largest channel difference, counted here (RGB, as the error counts it).
    int largest = 0;
    for (std::size_t i = 0; i < frame.rgba.size(); ++i)
        if (i % 4 != 3)
            largest =
                std::max(largest, std::abs(int(frame.rgba[i]) - int(frame.reference_rgba[i])));
    EXPECT_EQ(frame.error->max_abs, largest);
    EXPECT_GT(frame.stats.order.queries, 0u);       // vissort ordered the picture
    EXPECT_GT(frame.reference_stats.fragments, 0u); // linked-list listed the reference's
    EXPECT_EQ(frame.colliding_pairs, 0u);           // nothing asked of the collision detector

    // Without a reference there is no second picture.
    def.reference.reset();
    pipeline.configure(def);
    pipeline.render(scene.positions, view, frame);
    EXPECT_TRUE(frame.reference_rgba.empty());
    EXPECT_FALSE(frame.error);
}

TEST(FramePipeline, HighlightsExactlyTheTrianglesThatMeetAnotherObjects) {
    const Scene scene = test::loadTestScene("tests/data/scenes/crossed_bars.json");
    const RenderCase c{"CrossedBars", "", true, 0.5f, {}, true, 2};
    const ViewProjection view = viewOf(scene, c);
    FramePipelineDef def;
    def.settings = settingsOf(c, BlendMethod::vissort);
    def.settings.shading = Shading::flat;
    def.highlight_collisions = true;
    const Meeting meeting = meetingTriangles(scene);
    ASSERT_GT(meeting.pairs, 0u); // the bars cross
    std::vector<Rgba> colours = triangleColours(scene, def.settings);
    const test::ABuffer plain =
        test::rayCastComposite(scene.positions, view, colours, def.settings.background);
    highlightColours(colours, {meeting.triangles.begin(), meeting.triangles.end()});
    const test::ABuffer highlighted =
        test::rayCastComposite(scene.positions, view, colours, def.settings.background);

    FramePipeline pipeline(context(), scene, def);
    PipelineFrame frame;
    pipeline.render(scene.positions, view, frame);
    EXPECT_EQ(frame.colliding_pairs, meeting.pairs);
    EXPECT_EQ(frame.colliding_triangles, meeting.triangles.size());
    EXPECT_GE(frame.collision_ms, 0.0);
    EXPECT_LE(test::compareWithABuffer(frame.rgba, highlighted).max_abs, 1);
    EXPECT_GT(test::compareWithABuffer(frame.rgba, plain).max_abs, 1); // the highlight shows

    // Turned off, the highlights go with it.
    def.highlight_collisions = false;
    pipeline.configure(def);
    pipeline.render(scene.positions, view, frame);
    EXPECT_EQ(frame.colliding_pairs, 0u);
    EXPECT_LE(test::compareWithABuffer(frame.rgba, plain).max_abs, 1);
}

TEST(FramePipeline, ConfigureKeepsTheOrderWhileTheSettingsStay) {
    const Scene scene = test::loadTestScene("builtin:bunnies");
    const RenderCase c{"Bunnies", "", false, 0.5f, {}, true, 4};
    const ViewProjection view = viewOf(scene, c);
    FramePipelineDef def;
    def.settings = settingsOf(c, BlendMethod::vissort);
    FramePipeline pipeline(context(), scene, def);
    PipelineFrame first, again, remade;
    pipeline.render(scene.positions, view, first);
    // An overlay changes, the method's settings do not: the last order seeds this frame.
    def.reference = BlendMethod::linked_list;
    pipeline.configure(def);
    pipeline.render(scene.positions, view, again);
    EXPECT_LT(again.stats.order.queries, first.stats.order.queries);
    // Another alpha is another renderer: it orders from scratch, as the first frame did.
    def.settings.alpha = 0.4f;
    pipeline.configure(def);
    pipeline.render(scene.positions, view, remade);
    EXPECT_EQ(remade.stats.order.queries, first.stats.order.queries);
    EXPECT_EQ(remade.stats.order.iterations, first.stats.order.iterations);
}

} // namespace
} // namespace vissort
