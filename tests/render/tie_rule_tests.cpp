// The tie rule of every exact method (docs/robustness.md): fragments at exactly the same depth
// composite with the lower triangle id in front. Touching and coplanar transparent faces (boxes
// sharing faces, walls on a slab, faces lying on faces, the same face in several objects) seen
// at grazing views: vissort at every level equals linked-list to 1/255 on every pixel, and both
// equal the ray-cast A-buffer, which applies the same rule. Depth peeling keeps one of two
// fragments at the same depth: it differs where faces coincide, as documented.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "a_buffer.h"
#include "render_cases.h"
#include "touching_models.h"
#include "vissort/image.h"
#include "vissort/oracles.h"
#include "vissort/scene_orderer.h"
#include "vissort/transparency_renderer.h"

namespace vissort {
namespace {

using test::context; // render_cases.h

// The model as a scene, each object its own colour.
Scene sceneOf(const test::Model& m) {
    Scene scene;
    scene.name = "touching";
    scene.positions = m.positions;
    for (std::size_t i = 0; i < m.objects.size(); ++i) {
        SceneObject object;
        object.name = "object_" + std::to_string(i);
        object.colour = {float((i * 37) % 11) / 10.0f, float((i * 53) % 7) / 6.0f,
                         float((i * 19) % 5) / 4.0f, 1.0f};
        object.first_triangle = m.objects[i].first_triangle;
        object.triangle_count = m.objects[i].triangle_count;
        scene.objects.push_back(object);
    }
    return scene;
}

// One face in three objects, the same corners in the same order: exact ties everywhere it shows;
// and a box standing on it.
test::Model duplicatedFaces() {
    test::Model m;
    for (int copy = 0; copy < 3; ++copy)
        test::addFloorQuad(m, -1, -1, 1, 1, 0);
    test::addBox(m, {-0.3, 0, -0.3}, {0.3, 0.5, 0.3});
    return m;
}

RenderSettings settingsOf(BlendMethod method, OrderLevel level = OrderLevel::object) {
    RenderSettings settings;
    settings.method = method;
    settings.level = level;
    settings.all_transparent = true;
    settings.alpha = 0.4f;
    return settings;
}

std::vector<uint8_t> render(const Scene& scene, const RenderSettings& settings,
                            const ViewProjection& view) {
    TransparencyRenderer renderer(context(), scene, settings);
    RenderStats stats;
    return renderer.render(scene.positions, view, stats).toRgba8();
}

std::vector<test::View> someViews() {
    const std::vector<test::View> all = test::grazingViews();
    return {all[0], all[1], all[4], all[6]};
}

void expectVissortEqualsLinkedList(const std::string& name, const test::Model& m) {
    const Scene scene = sceneOf(m);
    for (const test::View& v : someViews()) {
        SCOPED_TRACE(name + " " + v.name);
        const ViewProjection view = frameCamera(v.camera, scene.positions.bounds(), 160, 120);
        const std::vector<uint8_t> reference =
            render(scene, settingsOf(BlendMethod::linked_list), view);
        for (OrderLevel level :
             {OrderLevel::object, OrderLevel::triangle, OrderLevel::multistage}) {
            SCOPED_TRACE(orderLevelName(level));
            // Checked (the default: near ties repaired) and unchecked (near ties in groups).
            for (const auto check :
                 {RenderSettings::OrderCheck::automatic, RenderSettings::OrderCheck::off}) {
                RenderSettings settings = settingsOf(BlendMethod::vissort, level);
                settings.check = check;
                const ImageError error = compareImages(render(scene, settings, view), reference);
                EXPECT_LE(error.max_abs, 1)
                    << error.pixels_over_one << " pixels off by more than 1, check "
                    << (check == RenderSettings::OrderCheck::off ? "off" : "on");
            }
        }
    }
}

TEST(TieRule, VissortEqualsLinkedListOnTouchingAndCoplanarFaces) {
    expectVissortEqualsLinkedList("duplicated faces", duplicatedFaces());
    expectVissortEqualsLinkedList("box grid", test::boxGrid());
    expectVissortEqualsLinkedList("house", test::house());
    expectVissortEqualsLinkedList("coplanar quads", test::coplanarQuads());
}

// Touching faces cost the checked renderer no more ordering than `vissort order`: it orders
// with the same tolerance (the check and repair take the near ties), so it asks exactly the
// queries that an orderer over the same oracle does and composites exactly its cycles per pixel.
// Unchecked, the blending tolerance makes the near ties cycles: more groups, more queries (on
// the IFC house of assimp's models that was 304 groups and 5.9 times the ordering time).
TEST(TieRule, CheckedRenderOrdersTouchingFacesAsOrderDoes) {
    for (const auto& [name, model] :
         {std::pair{"house", test::house()}, std::pair{"box grid", test::boxGrid()}}) {
        const Scene scene = sceneOf(model);
        for (const test::View& v : someViews()) {
            SCOPED_TRACE(std::string(name) + " " + v.name);
            const ViewProjection view = frameCamera(v.camera, scene.positions.bounds(), 160, 120);
            Result<std::unique_ptr<GeometryOracle>> oracle = makeOracle(OracleKind::cpu);
            ASSERT_TRUE(oracle) << oracle.error;
            SceneOrderer orderer(scene.objectPrimitives(), uint32_t(scene.triangleCount()),
                                 OrderLevel::triangle, **oracle.value);
            const FrameOrder order = orderer.orderFrame(scene.positions, view);

            RenderSettings settings = settingsOf(BlendMethod::vissort, OrderLevel::triangle);
            TransparencyRenderer checked_renderer(context(), scene, settings);
            RenderStats checked;
            checked_renderer.render(scene.positions, view, checked);
            EXPECT_EQ(checked.order.queries, order.stats.queries);
            EXPECT_EQ(checked.order.draws, order.stats.draws);
            EXPECT_EQ(checked.groups, order.cycles.size());

            settings.check = RenderSettings::OrderCheck::off;
            TransparencyRenderer unchecked_renderer(context(), scene, settings);
            RenderStats unchecked;
            unchecked_renderer.render(scene.positions, view, unchecked);
            EXPECT_GT(unchecked.groups, checked.groups);
            EXPECT_GT(unchecked.order.queries, checked.order.queries);
        }
    }
}

// The rule itself, against the ray cast: flat shading, the same face in three objects.
TEST(TieRule, LinkedListAndVissortApplyTheRuleOfTheABuffer) {
    const Scene scene = sceneOf(duplicatedFaces());
    CameraSpec camera;
    camera.eye = {0.4, 2.5, 1.5};
    const ViewProjection view = frameCamera(camera, scene.positions.bounds(), 160, 120);
    std::vector<Rgba> colours(scene.triangleCount());
    for (const SceneObject& object : scene.objects)
        for (uint32_t t = 0; t < object.triangle_count; ++t)
            colours[object.first_triangle + t] = {object.colour.r, object.colour.g, object.colour.b,
                                                  0.4f};
    RenderSettings settings = settingsOf(BlendMethod::linked_list);
    settings.shading = Shading::flat;
    const test::ABuffer reference =
        test::rayCastComposite(scene.positions, view, colours, settings.background);
    for (BlendMethod method : {BlendMethod::linked_list, BlendMethod::vissort}) {
        SCOPED_TRACE(blendMethodName(method));
        settings.method = method;
        const test::ABufferComparison result =
            test::compareWithABuffer(render(scene, settings, view), reference);
        EXPECT_LE(result.max_abs, 1) << "at " << result.worst_x << "," << result.worst_y;
        EXPECT_GT(result.compared, 160u * 120u / 3); // the tied face fills much of the view
    }
    // The opposite rule (higher id in front) would differ: the colours are distinct.
    std::vector<Rgba> reversed = colours;
    std::swap(reversed[0], reversed[4]);
    std::swap(reversed[1], reversed[5]);
    const test::ABuffer other =
        test::rayCastComposite(scene.positions, view, reversed, settings.background);
    settings.method = BlendMethod::linked_list;
    EXPECT_GT(test::compareWithABuffer(render(scene, settings, view), other).max_abs, 1);
}

// Depth peeling peels one fragment per depth: of fragments at exactly the same depth it keeps
// one and loses the rest (docs/robustness.md), so on a face shared by three objects it differs.
TEST(TieRule, DepthPeelingKeepsOneOfTiedFragments) {
    const Scene scene = sceneOf(duplicatedFaces());
    const ViewProjection view =
        frameCamera(someViews()[0].camera, scene.positions.bounds(), 160, 120);
    const std::vector<uint8_t> reference =
        render(scene, settingsOf(BlendMethod::linked_list), view);
    const ImageError peel =
        compareImages(render(scene, settingsOf(BlendMethod::peel), view), reference);
    EXPECT_GT(peel.max_abs, 1);
    EXPECT_GT(peel.pixels_over_one, 1000u);
}

} // namespace
} // namespace vissort
