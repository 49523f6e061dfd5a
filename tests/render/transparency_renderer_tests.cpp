// The transparency renderer on the machine's OpenGL driver (Mesa's llvmpipe here and in CI):
//  - every exact method (linked-list, peel, dual-peel, vissort at each level) against an
//    independent ray-cast A-buffer with flat shading (tests/support/a_buffer.h);
//  - vissort against the linked-list reference with the lit shading, at object, triangle and
//    multistage level, to 1/255 on every pixel, on scenes with cycles, intersections, nesting and
//    depth complexity over 30, while centroid and unsorted miss by more on the same scenes;
//  - the peeling pass counts, fragment lists split into bands, coherent frames, the gl oracle,
//    opaque-only scenes, determinism and bad settings;
//  - the method names.
// These tests need an OpenGL 4.5 context: without one they fail, naming what is missing.

#include "vissort/transparency_renderer.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <ostream>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "a_buffer.h"
#include "render_cases.h"
#include "vissort/camera_path.h"

namespace vissort {
namespace {

using namespace test; // render_cases.h

class RenderScenes : public testing::TestWithParam<RenderCase> {};

// Whether a box may be in the view volume: some point of it on the inner side of every clip
// plane, sampled on a 5x5x5 lattice (the boxes here are the objects', out of view by far or not).
bool inViewVolume(const ViewProjection& view, const Bounds& box) {
    for (int i = 0; i < 125; ++i) {
        const double u = (i % 5) / 4.0, v = (i / 5 % 5) / 4.0, w = (i / 25) / 4.0;
        const std::array<double, 4> c = view.toClip({box.min.x + u * (box.max.x - box.min.x),
                                                     box.min.y + v * (box.max.y - box.min.y),
                                                     box.min.z + w * (box.max.z - box.min.z)});
        if (std::abs(c[0]) <= c[3] && std::abs(c[1]) <= c[3] && c[2] >= 0)
            return true;
    }
    return false;
}

TEST_P(RenderScenes, ExactMethodsMatchTheRayCastABuffer) {
    const RenderCase& c = GetParam();
    const Scene scene = test::loadTestScene(c.scene);
    const ViewProjection view = viewOf(scene, c);
    RenderSettings flat = settingsOf(c, BlendMethod::linked_list);
    flat.shading = Shading::flat;
    const test::ABuffer reference = test::rayCastComposite(
        scene.positions, view, triangleColours(scene, flat), flat.background);
    EXPECT_GE(reference.max_layers, c.min_layers);
    uint64_t decided = 0;
    for (uint8_t d : reference.decided)
        decided += d;
    EXPECT_GT(decided, uint64_t(kWidth) * kHeight / 2);

    struct Method {
        BlendMethod method;
        OrderLevel level;
    };
    for (const Method& m : {Method{BlendMethod::linked_list, OrderLevel::object},
                            Method{BlendMethod::peel, OrderLevel::object},
                            Method{BlendMethod::dual_peel, OrderLevel::object},
                            Method{BlendMethod::vissort, OrderLevel::object},
                            Method{BlendMethod::vissort, OrderLevel::triangle},
                            Method{BlendMethod::vissort, OrderLevel::multistage}}) {
        SCOPED_TRACE(std::string(blendMethodName(m.method)) + " at " + orderLevelName(m.level));
        RenderSettings settings = flat;
        settings.method = m.method;
        settings.level = m.level;
        const test::ABufferComparison compared =
            test::compareWithABuffer(render(scene, settings, view), reference);
        EXPECT_EQ(compared.compared, decided);
        EXPECT_LE(compared.max_abs, 1)
            << "worst at (" << compared.worst_x << ", " << compared.worst_y << ")";
    }
    if (c.wrong_methods_show) { // an approximate method is caught by the same comparison
        RenderSettings weighted = flat;
        weighted.method = BlendMethod::weighted;
        EXPECT_GT(test::compareWithABuffer(render(scene, weighted, view), reference).max_abs, 1);
    }
}

TEST_P(RenderScenes, VissortMatchesLinkedListAtEveryLevel) {
    const RenderCase& c = GetParam();
    const Scene scene = test::loadTestScene(c.scene);
    const ViewProjection view = viewOf(scene, c);
    const std::vector<uint8_t> reference =
        render(scene, settingsOf(c, BlendMethod::linked_list), view);
    for (OrderLevel level : {OrderLevel::object, OrderLevel::triangle, OrderLevel::multistage}) {
        SCOPED_TRACE(orderLevelName(level));
        RenderStats stats;
        const std::vector<uint8_t> image =
            render(scene, settingsOf(c, BlendMethod::vissort, level), view, &stats);
        const ImageError error = compareImages(image, reference);
        EXPECT_LE(error.max_abs, 1) << error.pixels_over_one << " pixels off by more than 1/255";
        EXPECT_GT(stats.order.queries, 0u);
        EXPECT_GE(stats.passes, 1u);
    }
}

// Unsorted everywhere; centroid on every scene but the stack of parallel slabs, which centroids
// order right.
TEST_P(RenderScenes, CentroidAndUnsortedMissWhereVissortIsExact) {
    const RenderCase& c = GetParam();
    const Scene scene = test::loadTestScene(c.scene);
    const ViewProjection view = viewOf(scene, c);
    const std::vector<uint8_t> reference =
        render(scene, settingsOf(c, BlendMethod::linked_list), view);
    const int unsorted =
        compareImages(render(scene, settingsOf(c, BlendMethod::unsorted), view), reference).max_abs;
    const int centroid =
        compareImages(render(scene, settingsOf(c, BlendMethod::centroid), view), reference).max_abs;
    EXPECT_GT(unsorted, 1);
    if (c.wrong_methods_show) {
        EXPECT_GT(centroid, 1);
    }
}

INSTANTIATE_TEST_SUITE_P(Scenes, RenderScenes, testing::ValuesIn(renderCases()),
                         [](const testing::TestParamInfo<RenderCase>& info) {
                             return info.param.name;
                         });

// The cycles and groups the scenes are chosen for are really there.
// What the viewer's panel and render's header count as transparent is what is drawn so: an
// object marked transparent with alpha below 1, or every object with all_transparent (the panel
// said "0 transparent" then).
TEST(TransparencyRenderer, DrawnTransparentIsWhatTheRendererBlends) {
    SceneObject glass{"glass", Rgba{1, 1, 1, 0.5f}, true, 0, 1};
    SceneObject steel{"steel", Rgba{1, 1, 1, 1}, false, 1, 1};
    SceneObject marked_opaque{"marked", Rgba{1, 1, 1, 1}, true, 2, 1}; // alpha 1: opaque
    RenderSettings settings;
    EXPECT_TRUE(drawnTransparent(glass, settings));
    EXPECT_FALSE(drawnTransparent(steel, settings));
    EXPECT_FALSE(drawnTransparent(marked_opaque, settings));
    settings.all_transparent = true;
    EXPECT_TRUE(drawnTransparent(steel, settings));
    EXPECT_TRUE(drawnTransparent(marked_opaque, settings));
}

TEST(TransparencyRenderer, CycleScenesAreCompositedPerPixel) {
    for (const RenderCase& c : renderCases()) {
        if (c.name != "ThreeSticksCycle" && c.name != "Nested")
            continue;
        SCOPED_TRACE(c.name);
        const Scene scene = test::loadTestScene(c.scene);
        RenderStats stats;
        render(scene, settingsOf(c, BlendMethod::vissort), viewOf(scene, c), &stats);
        EXPECT_GE(stats.groups, 1u);
        EXPECT_GT(stats.fragments, 0u);
        EXPECT_GT(stats.order.stuck_iterations, 0u); // Vis-sort met a cycle
    }
}

// Where two layers' depths nearly tie (a fold of a bunny seen edge-on), the default tolerance
// leaves their order to chance: at this size, two pixels of the bunnies were 4/255 off at
// triangle level, unchecked. Checked (the default), the renderer orders with the default
// tolerance and the check repairs those pixels; unchecked, the blending tolerance makes such
// pairs a cycle, composited per pixel. Both exact.
//
// The bunnies at triangle level, 512 x 512, checked and unchecked, at their default view and
// at their former one (their cube's bounding sphere framed), where near ties were found: under
// the exact rule the order itself is right at both, so the unchecked render matches too (before
// it, 8/255 off at one pixel of the default view). The check may still repair a few pixels: it
// compares the GPU's own float depths, which can tie or swap where the exact order is right.
TEST(TransparencyRenderer, UncheckedBunniesMatchLinkedListAtBothViews) {
    const Scene scene = test::loadTestScene("builtin:bunnies");
    const double reach = 3.05; // half the cube's side of 18 bunnies, plus the deformation
    const CameraSpec former =
        defaultCamera(Bounds{{-reach, -reach, -reach}, {reach, reach, reach}});
    const CameraSpec standard = scene.camera.value_or(defaultCamera(scene.positions.bounds()));
    for (int i = 0; i < 2; ++i) {
        const CameraSpec& camera = i == 0 ? standard : former;
        const char* name = i == 0 ? "default view" : "former view";
        SCOPED_TRACE(name);
        const ViewProjection view = frameCamera(camera, scene.positions.bounds(), 512, 512);
        const RenderCase c{"Bunnies512", "", false, 0.5f, {}, true, 0};
        const std::vector<uint8_t> reference =
            render(scene, settingsOf(c, BlendMethod::linked_list), view);
        RenderSettings settings = settingsOf(c, BlendMethod::vissort, OrderLevel::triangle);
        RenderStats checked, unchecked;
        const ImageError checked_error =
            compareImages(render(scene, settings, view, &checked), reference);
        EXPECT_LE(checked_error.max_abs, 1)
            << checked_error.pixels_over_one << " pixels off by more than 1/255";
        settings.check = RenderSettings::OrderCheck::off;
        const ImageError unchecked_error =
            compareImages(render(scene, settings, view, &unchecked), reference);
        EXPECT_LE(unchecked_error.max_abs, 1)
            << unchecked_error.pixels_over_one << " pixels off by more than 1/255";
        EXPECT_EQ(unchecked.repaired_pixels, 0u);
        std::printf("[ bunnies  ] %s: checked repaired %llu pixels, %llu groups; unchecked %llu "
                    "groups\n",
                    name, (unsigned long long)checked.repaired_pixels,
                    (unsigned long long)checked.groups, (unsigned long long)unchecked.groups);
    }
}

// Checked, the groups (cycles; at object level every object, its triangles by centroid depth)
// are blended in the sequence and the check marks where their fragments came out of depth order:
// one geometry pass and one list pass for the whole frame, exact. Unchecked, each group takes a
// list pass of its own.
TEST(TransparencyRenderer, CheckedGroupsShareTheRepairsListPass) {
    const RenderCase c = renderCases()[1]; // interpenetrating: cycles at both levels
    const Scene scene = test::loadTestScene(c.scene);
    const ViewProjection view = frameCamera(*scene.camera, scene.positions.bounds(), 384, 288);
    const std::vector<uint8_t> reference =
        render(scene, settingsOf(c, BlendMethod::linked_list), view);
    for (OrderLevel level : {OrderLevel::object, OrderLevel::multistage}) {
        SCOPED_TRACE(orderLevelName(level));
        RenderSettings settings = settingsOf(c, BlendMethod::vissort, level);
        RenderStats checked, unchecked;
        const ImageError checked_error =
            compareImages(render(scene, settings, view, &checked), reference);
        EXPECT_LE(checked_error.max_abs, 1)
            << checked_error.pixels_over_one << " pixels off by more than 1/255";
        EXPECT_GE(checked.groups, 2u);
        EXPECT_EQ(checked.passes, 2u);
        EXPECT_GT(checked.repaired_pixels, 0u);
        EXPECT_GT(checked.fragments, 0u);
        settings.check = RenderSettings::OrderCheck::off;
        const ImageError unchecked_error =
            compareImages(render(scene, settings, view, &unchecked), reference);
        EXPECT_LE(unchecked_error.max_abs, 1)
            << unchecked_error.pixels_over_one << " pixels off by more than 1/255";
        EXPECT_GE(unchecked.passes, 1u + unchecked.groups); // more where lists grew
        EXPECT_GE(unchecked.groups, checked.groups);
    }
}

// The check and repair on their own: blending in submission order is wrong on these scenes, and
// checked it is exact, every wrong pixel found and composited again (over the background, and
// on the plant over its opaque surfaces drawn again); vissort unchecked still composites its
// groups per pixel.
TEST(TransparencyRenderer, TheCheckRepairsAnyOrder) {
    for (const RenderCase& c : {renderCases()[1], renderCases()[4], renderCases()[7]}) {
        SCOPED_TRACE(c.name);
        const Scene scene = test::loadTestScene(c.scene);
        const ViewProjection view = viewOf(scene, c);
        const std::vector<uint8_t> reference =
            render(scene, settingsOf(c, BlendMethod::linked_list), view);
        RenderSettings unsorted = settingsOf(c, BlendMethod::unsorted);
        RenderStats stats;
        EXPECT_GT(compareImages(render(scene, unsorted, view, &stats), reference).max_abs, 1);
        EXPECT_EQ(stats.repaired_pixels, 0u);
        unsorted.check = RenderSettings::OrderCheck::on;
        EXPECT_LE(compareImages(render(scene, unsorted, view, &stats), reference).max_abs, 1);
        EXPECT_GT(stats.repaired_pixels, 100u);
        RenderSettings vissort = settingsOf(c, BlendMethod::vissort, OrderLevel::object);
        vissort.check = RenderSettings::OrderCheck::off;
        EXPECT_LE(compareImages(render(scene, vissort, view, &stats), reference).max_abs, 1);
        EXPECT_EQ(stats.repaired_pixels, 0u);
        EXPECT_GE(stats.groups, 1u);
    }
}

TEST(TransparencyRenderer, PeelingPassesFollowTheDepthComplexity) {
    // builtin:slabs seen down the stack: 8 layers over the middle of the image.
    const RenderCase c{"Slabs", "builtin:slabs?layers=8", false, 0.5f, {}, true, 8};
    const Scene scene = test::loadTestScene(c.scene);
    const ViewProjection view = viewOf(scene, c);
    RenderStats peel, dual, linked;
    const std::vector<uint8_t> reference =
        render(scene, settingsOf(c, BlendMethod::linked_list), view, &linked);
    const std::vector<uint8_t> peeled =
        render(scene, settingsOf(c, BlendMethod::peel), view, &peel);
    const std::vector<uint8_t> dual_peeled =
        render(scene, settingsOf(c, BlendMethod::dual_peel), view, &dual);
    EXPECT_EQ(peel.passes, 8u + 1u);      // one a layer, and the empty one that stops it
    EXPECT_EQ(dual.passes, 1u + 4u + 1u); // the depth range, two layers a pass, the empty one
    EXPECT_EQ(linked.passes, 1u);
    EXPECT_LE(compareImages(peeled, reference).max_abs, 1);
    EXPECT_LE(compareImages(dual_peeled, reference).max_abs, 1);
}

TEST(TransparencyRenderer, FragmentListsSplitIntoBandsWhenMemoryIsShort) {
    const RenderCase c = renderCases()[4]; // nested boxes, depth complexity 32
    const Scene scene = test::loadTestScene(c.scene);
    const ViewProjection view = viewOf(scene, c);
    RenderStats roomy, tight;
    // The first frame grows the lists from 4 fragments a pixel and draws again; the next fits.
    TransparencyRenderer renderer(context(), scene, settingsOf(c, BlendMethod::linked_list));
    renderer.render(scene.positions, view, roomy);
    EXPECT_EQ(roomy.passes, 2u);
    const std::vector<uint8_t> reference = renderer.render(scene.positions, view, roomy).toRgba8();
    EXPECT_EQ(roomy.passes, 1u);
    RenderSettings settings = settingsOf(c, BlendMethod::linked_list);
    settings.list_bytes = 24 * 3000; // 3000 fragments at a time: bands of a few rows
    const std::vector<uint8_t> banded = render(scene, settings, view, &tight);
    EXPECT_GT(tight.passes, 10u);
    EXPECT_EQ(tight.fragments, roomy.fragments);
    EXPECT_EQ(banded, reference);
    // A pixel with more fragments than the memory holds cannot be split: a clear error.
    settings.list_bytes = 24 * 16;
    try {
        render(scene, settings, view);
        ADD_FAILURE() << "no error with 16 fragments of memory and 32 layers";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("fragments"), std::string::npos) << e.what();
    }
}

TEST(TransparencyRenderer, CoherentFramesOfTheBunniesStayExact) {
    const Scene scene = test::loadTestScene("builtin:bunnies");
    const Bounds bounds = scene.positions.bounds();
    const CameraSpec base = *scene.camera;
    RenderSettings vissort;
    vissort.level = OrderLevel::multistage;
    RenderSettings linked;
    linked.method = BlendMethod::linked_list;
    TransparencyRenderer ordered(context(), scene, vissort);
    TransparencyRenderer reference(context(), scene, linked);
    TrianglePositions positions;
    for (int f = 0; f < 3; ++f) {
        SCOPED_TRACE("frame " + std::to_string(f));
        scene.frame(f * kFrameInterval, positions);
        const ViewProjection view = frameCamera(cameraOnPath(base, CameraPath::orbit, f, bounds),
                                                positions.bounds(), kWidth, kHeight);
        RenderStats stats, reference_stats;
        const std::vector<uint8_t> image = ordered.render(positions, view, stats).toRgba8();
        const std::vector<uint8_t> expected =
            reference.render(positions, view, reference_stats).toRgba8();
        EXPECT_LE(compareImages(image, expected).max_abs, 1);
    }
}

// From inside the power plant, as its walkthrough goes: much of the scene lies beside and behind
// the eye, and the renderer draws only the opaque objects whose boxes may be in view
// (view_culling.h). Each frame, rendered coherently from the last, against its own A-buffer.
TEST(TransparencyRenderer, WalkthroughFramesInsideThePlantMatchTheABuffer) {
    const Scene scene = test::loadTestScene("builtin:powerplant?scale=0.05");
    const Bounds bounds = scene.positions.bounds();
    RenderSettings settings;
    settings.shading = Shading::flat;
    TransparencyRenderer renderer(context(), scene, settings);
    const std::vector<Rgba> colours = triangleColours(scene, settings);
    for (int f : {0, 1, 150, 450}) {
        SCOPED_TRACE("frame " + std::to_string(f));
        const ViewProjection view = frameCamera(
            cameraOnPath(*scene.camera, CameraPath::scene, f, bounds, scene.camera_path), bounds,
            kWidth, kHeight);
        // The frame exercises the culling: objects out of view, by the boxes' own points.
        uint32_t out_of_view = 0;
        for (const SceneObject& object : scene.objects) {
            Bounds box;
            for (uint32_t c = object.first_triangle * 3;
                 c < (object.first_triangle + object.triangle_count) * 3; ++c)
                box.add(scene.positions.corner(c));
            out_of_view += !inViewVolume(view, box);
        }
        EXPECT_GT(out_of_view, scene.objects.size() / 5);
        RenderStats stats;
        const test::ABufferComparison compared = test::compareWithABuffer(
            renderer.render(scene.positions, view, stats).toRgba8(),
            test::rayCastComposite(scene.positions, view, colours, settings.background));
        EXPECT_GT(compared.compared, uint64_t(kWidth) * kHeight / 2);
        EXPECT_LE(compared.max_abs, 1)
            << "worst at (" << compared.worst_x << ", " << compared.worst_y << ")";
    }
}

TEST(TransparencyRenderer, AStillFrameStartsFromTheLastOrder) {
    const RenderCase c = renderCases()[4]; // nested boxes, static
    const Scene scene = test::loadTestScene(c.scene);
    const ViewProjection view = viewOf(scene, c);
    TransparencyRenderer renderer(context(), scene,
                                  settingsOf(c, BlendMethod::vissort, OrderLevel::triangle));
    RenderStats first, second;
    const std::vector<uint8_t> a = renderer.render(scene.positions, view, first).toRgba8();
    const std::vector<uint8_t> b = renderer.render(scene.positions, view, second).toRgba8();
    EXPECT_EQ(a, b);
    // Coherence: the second frame starts from the first's order, a visibility order already.
    EXPECT_LT(second.order.iterations, first.order.iterations);
    EXPECT_LT(second.order.queries, first.order.queries);
}

TEST(TransparencyRenderer, GlOracleOrdersAsExactly) {
    const RenderCase c = renderCases()[1]; // interpenetrating
    const Scene scene = test::loadTestScene(c.scene);
    const ViewProjection view = viewOf(scene, c);
    const std::vector<uint8_t> reference =
        render(scene, settingsOf(c, BlendMethod::linked_list), view);
    for (OrderLevel level : {OrderLevel::object, OrderLevel::multistage}) {
        RenderSettings settings = settingsOf(c, BlendMethod::vissort, level);
        settings.oracle = OracleKind::gl;
        EXPECT_LE(compareImages(render(scene, settings, view), reference).max_abs, 1)
            << orderLevelName(level);
    }
}

TEST(TransparencyRenderer, WithoutTransparentObjectsEveryMethodDrawsTheOpaqueImage) {
    const Scene scene = test::loadTestScene("tests/data/scenes/three_sticks.json"); // all opaque
    const RenderCase c{"Opaque", "", false, 0.5f, {}, false, 0};
    const ViewProjection view = viewOf(scene, c);
    RenderStats stats;
    const std::vector<uint8_t> expected = render(scene, settingsOf(c, BlendMethod::unsorted), view);
    for (BlendMethod method :
         {BlendMethod::vissort, BlendMethod::centroid, BlendMethod::peel, BlendMethod::dual_peel,
          BlendMethod::linked_list, BlendMethod::weighted}) {
        EXPECT_EQ(render(scene, settingsOf(c, method), view, &stats), expected)
            << blendMethodName(method);
        EXPECT_EQ(stats.passes, 0u) << blendMethodName(method);
        EXPECT_EQ(stats.fragments, 0u) << blendMethodName(method);
    }
    // And the opaque image is not the background: something was drawn.
    std::size_t white = 0;
    for (std::size_t i = 0; i < expected.size(); i += 4)
        white += expected[i] == 255 && expected[i + 1] == 255;
    EXPECT_LT(white, expected.size() / 4);
}

// colour_cycles: the three sticks form a cycle by construction, the box beside them overlaps
// nothing. At object level the cycle is the three sticks (multistage splits it into the
// triangles of its own cycles, whichever they are): the ray-cast A-buffer with the sticks in the
// palette's first colour (shading.h: orange) and the box in its own is what vissort must draw.
// A highlighted triangle stays magenta over it, the untinted box dimmed; without cycles nothing
// changes.
TEST(TransparencyRenderer, ColourCyclesPaintsEachCycleOverTheABuffer) {
    const Scene scene = test::loadTestScene("tests/data/scenes/three_sticks_and_box.json");
    const RenderCase c{"SticksAndBox", "", true, 0.5f, {}, true, 2};
    const ViewProjection view = viewOf(scene, c);
    RenderSettings settings = settingsOf(c, BlendMethod::vissort);
    settings.shading = Shading::flat;
    settings.colour_cycles = true;
    std::vector<Rgba> colours = triangleColours(scene, settings);
    const SceneObject& box = scene.objects[3];
    for (uint32_t t = 0; t < box.first_triangle; ++t)
        colours[t] = {1.0f, 0.55f, 0.0f, c.alpha}; // the palette's colour 0
    const test::ABuffer painted =
        test::rayCastComposite(scene.positions, view, colours, settings.background);
    const test::ABuffer plain = test::rayCastComposite(
        scene.positions, view, triangleColours(scene, settings), settings.background);
    RenderStats stats;
    const std::vector<uint8_t> image = render(scene, settings, view, &stats);
    EXPECT_GE(stats.order.stuck_iterations, 1u);
    EXPECT_LE(test::compareWithABuffer(image, painted).max_abs, 1);
    EXPECT_GT(test::compareWithABuffer(image, plain).max_abs, 1); // the paint shows

    // Highlights are drawn over the cycle colours.
    TransparencyRenderer renderer(context(), scene, settings);
    std::vector<uint32_t> first_stick(scene.objects[0].triangle_count);
    for (uint32_t t = 0; t < first_stick.size(); ++t)
        first_stick[t] = scene.objects[0].first_triangle + t;
    renderer.setHighlightedTriangles(first_stick);
    const std::vector<uint8_t> highlighted =
        renderer.render(scene.positions, view, stats).toRgba8();
    // The box carries no cycle tint: it is dimmed; the sticks keep their cycle colour.
    std::vector<bool> untinted(colours.size(), false);
    for (uint32_t t = box.first_triangle; t < box.first_triangle + box.triangle_count; ++t)
        untinted[t] = true;
    highlightColours(colours, first_stick, &untinted);
    EXPECT_LE(
        test::compareWithABuffer(highlighted, test::rayCastComposite(scene.positions, view, colours,
                                                                     settings.background))
            .max_abs,
        1);

    // The stack's slabs, seen from below, have no cycle: the same image as without the setting.
    const RenderCase stack = renderCases()[5];
    const Scene slabs = test::loadTestScene(stack.scene);
    const ViewProjection slab_view = viewOf(slabs, stack);
    RenderSettings slab_settings = settingsOf(stack, BlendMethod::vissort);
    const std::vector<uint8_t> unpainted = render(slabs, slab_settings, slab_view);
    slab_settings.colour_cycles = true;
    EXPECT_EQ(render(slabs, slab_settings, slab_view, &stats), unpainted);
    EXPECT_EQ(stats.groups, 0u);
}

TEST(TransparencyRenderer, SameFrameSameBits) {
    const Scene scene = test::loadTestScene("builtin:bunnies");
    const RenderCase c{"Bunnies", "", false, 0.5f, {}, true, 0};
    const ViewProjection view = viewOf(scene, c);
    for (BlendMethod method :
         {BlendMethod::vissort, BlendMethod::linked_list, BlendMethod::dual_peel}) {
        TransparencyRenderer first(context(), scene, settingsOf(c, method));
        TransparencyRenderer second(context(), scene, settingsOf(c, method));
        RenderStats stats;
        const Image a = first.render(scene.positions, view, stats);
        const Image b = second.render(scene.positions, view, stats);
        ASSERT_EQ(a.rgba.size(), b.rgba.size());
        EXPECT_EQ(std::memcmp(a.rgba.data(), b.rgba.data(), a.rgba.size() * sizeof(float)), 0)
            << blendMethodName(method);
    }
}

TEST(TransparencyRenderer, BadSettingsAndPositionsAreRejected) {
    const Scene scene = test::loadTestScene("tests/data/scenes/three_sticks.json");
    for (float alpha : {0.0f, -0.5f, 1.5f, std::numeric_limits<float>::quiet_NaN()}) {
        RenderSettings settings;
        settings.all_transparent = true;
        settings.alpha = alpha;
        EXPECT_THROW(TransparencyRenderer(context(), scene, settings), std::invalid_argument)
            << alpha;
    }
    EXPECT_THROW(TransparencyRenderer(nullptr, scene, RenderSettings{}), std::invalid_argument);
    TransparencyRenderer renderer(context(), scene, RenderSettings{});
    TrianglePositions fewer = scene.positions;
    fewer.resize(scene.triangleCount() - 1);
    RenderStats stats;
    const ViewProjection view = frameCamera(*scene.camera, scene.positions.bounds(), 16, 16);
    EXPECT_THROW(renderer.render(fewer, view, stats), std::invalid_argument);
}

TEST(BlendMethodNames, RoundTripAndRejectUnknown) {
    std::set<std::string> names;
    for (BlendMethod method :
         {BlendMethod::vissort, BlendMethod::unsorted, BlendMethod::centroid, BlendMethod::peel,
          BlendMethod::dual_peel, BlendMethod::linked_list, BlendMethod::weighted}) {
        const Result<BlendMethod> parsed = parseBlendMethod(blendMethodName(method));
        ASSERT_TRUE(parsed) << blendMethodName(method) << ": " << parsed.error;
        EXPECT_EQ(*parsed.value, method);
        names.insert(blendMethodName(method));
        EXPECT_NE(blendMethodNames().find(blendMethodName(method)), std::string::npos);
    }
    EXPECT_EQ(names.size(), 7u);
    EXPECT_FALSE(parseBlendMethod("linked_list"));
    EXPECT_NE(parseBlendMethod("linked_list").error, "");
    EXPECT_FALSE(parseBlendMethod(""));
}

} // namespace
} // namespace vissort
