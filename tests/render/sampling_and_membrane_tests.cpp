// Several samples a pixel (RenderSettings::samples) and membrane shading, on the machine's OpenGL
// driver:
//  - at 4 samples, every exact method (linked-list, peel, dual-peel, vissort at each level,
//    checked and unchecked) against the ray-cast A-buffer cast at the samples and averaged per
//    pixel (flat shading), on six of the test scenes, anti-aliased edges among the pixels
//    compared; the one-sample image misses that reference;
//  - the other grids, 2 and 8 samples, for vissort and linked-list;
//  - with membrane shading at 4 samples, vissort (each level, checked and unchecked), peel and
//    dual-peel within 1/255 of linked-list sampled the same way, on the scenes with cycles,
//    intersections, nesting and depth complexity 32;
//  - membrane's opacity against its formula on squares seen at known angles;
//  - sample counts other than 1, 2, 4 and 8 refused.

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "a_buffer.h"
#include "render_cases.h"
#include "vissort/transparency_renderer.h"

namespace vissort {
namespace {

using namespace test; // render_cases.h

// The view's camera on a raster columns x rows times as fine: the samples' rays.
ViewProjection finerView(ViewProjection view, uint32_t columns, uint32_t rows) {
    view.width *= columns;
    view.height *= rows;
    return view;
}

// The flat-shaded A-buffer of the scene at `samples` a pixel, resolved to the view's pixels.
ABuffer sampledReference(const Scene& scene, const RenderSettings& flat, const ViewProjection& view,
                         uint32_t samples) {
    const SampleGrid grid = *sampleGridOf(samples).value;
    return resolveSamples(rayCastComposite(scene.positions,
                                           finerView(view, grid.columns, grid.rows),
                                           triangleColours(scene, flat), flat.background),
                          grid.columns, grid.rows);
}

// Pixels whose samples' colours differ by more than 2/255: the edges that anti-aliasing blends.
uint64_t pixelsWithMixedSamples(const Scene& scene, const RenderSettings& flat,
                                const ViewProjection& view) {
    const ABuffer samples = rayCastComposite(scene.positions, finerView(view, 2, 2),
                                             triangleColours(scene, flat), flat.background);
    const ABuffer resolved = resolveSamples(samples, 2, 2);
    uint64_t mixed = 0;
    for (uint32_t y = 0; y < view.height; ++y)
        for (uint32_t x = 0; x < view.width; ++x) {
            if (!resolved.decided[std::size_t(y) * view.width + x])
                continue;
            double low = 1e9, high = -1e9;
            for (uint32_t s = 0; s < 4; ++s) {
                const std::size_t sample =
                    std::size_t(y * 2 + s / 2) * samples.width + x * 2 + s % 2;
                const double v = samples.rgb[sample * 3] + samples.rgb[sample * 3 + 1] +
                                 samples.rgb[sample * 3 + 2];
                low = std::min(low, v);
                high = std::max(high, v);
            }
            mixed += high - low > 2.0 / 255 ? 1 : 0;
        }
    return mixed;
}

struct Method {
    BlendMethod method;
    OrderLevel level;
    RenderSettings::OrderCheck check = RenderSettings::OrderCheck::automatic;
};

std::string describe(const Method& m) {
    std::string text = std::string(blendMethodName(m.method)) + " at " + orderLevelName(m.level);
    if (m.check == RenderSettings::OrderCheck::off)
        text += ", unchecked";
    return text;
}

const Method kExactMethods[] = {
    {BlendMethod::linked_list, OrderLevel::object},
    {BlendMethod::peel, OrderLevel::object},
    {BlendMethod::dual_peel, OrderLevel::object},
    {BlendMethod::vissort, OrderLevel::object},
    {BlendMethod::vissort, OrderLevel::triangle},
    {BlendMethod::vissort, OrderLevel::multistage},
    {BlendMethod::vissort, OrderLevel::object, RenderSettings::OrderCheck::off},
    {BlendMethod::vissort, OrderLevel::multistage, RenderSettings::OrderCheck::off},
};

RenderSettings withMethod(RenderSettings settings, const Method& m) {
    settings.method = m.method;
    settings.level = m.level;
    settings.check = m.check;
    return settings;
}

class SampledScenes : public testing::TestWithParam<RenderCase> {};

TEST_P(SampledScenes, ExactMethodsMatchTheSupersampledABuffer) {
    const RenderCase& c = GetParam();
    const Scene scene = loadTestScene(c.scene);
    const ViewProjection view = viewOf(scene, c);
    RenderSettings flat = settingsOf(c, BlendMethod::linked_list);
    flat.shading = Shading::flat;
    flat.samples = 4;
    const ABuffer reference = sampledReference(scene, flat, view, 4);
    uint64_t decided = 0;
    for (uint8_t d : reference.decided)
        decided += d;
    EXPECT_GT(decided, uint64_t(kWidth) * kHeight / 2);
    // Edges inside pixels are compared, where each sample counts.
    EXPECT_GT(pixelsWithMixedSamples(scene, flat, view), 20u);

    for (const Method& m : kExactMethods) {
        SCOPED_TRACE(describe(m));
        const ABufferComparison compared =
            compareWithABuffer(render(scene, withMethod(flat, m), view), reference);
        EXPECT_EQ(compared.compared, decided);
        EXPECT_LE(compared.max_abs, 1)
            << "worst at (" << compared.worst_x << ", " << compared.worst_y << ")";
    }
    // One sample a pixel is not that picture: the edges differ.
    RenderSettings one = flat;
    one.samples = 1;
    EXPECT_GT(compareWithABuffer(render(scene, one, view), reference).max_abs, 1);
}

TEST_P(SampledScenes, MembraneShadedVissortMatchesLinkedListAtFourSamples) {
    const RenderCase& c = GetParam();
    const Scene scene = loadTestScene(c.scene);
    const ViewProjection view = viewOf(scene, c);
    RenderSettings membrane = settingsOf(c, BlendMethod::linked_list);
    membrane.shading = Shading::membrane;
    membrane.samples = 4;
    const std::vector<uint8_t> reference = render(scene, membrane, view);
    for (const Method& m : kExactMethods) {
        if (m.method == BlendMethod::linked_list)
            continue;
        SCOPED_TRACE(describe(m));
        RenderStats stats;
        const ImageError error =
            compareImages(render(scene, withMethod(membrane, m), view, &stats), reference);
        EXPECT_LE(error.max_abs, 1) << error.pixels_over_one << " pixels off by more than 1/255";
    }
    // Membrane shading changes the picture: lit at the same samples differs.
    RenderSettings lit = membrane;
    lit.shading = Shading::lit;
    EXPECT_GT(compareImages(render(scene, lit, view), reference).max_abs, 1);
}

// The scenes with cycles, intersections, nesting, depth complexity 32, the bunnies and the plant;
// the one-sample suites (transparency_renderer_tests.cpp) cover the other two (the stack of
// depth 72 alone took a third of these tests' time, which the sanitizer build multiplies).
std::vector<RenderCase> sampledCases() {
    std::vector<RenderCase> cases;
    for (RenderCase& c : renderCases())
        if (c.name != "StackDepth72" && c.name != "InterpenetratingOrthographic")
            cases.push_back(std::move(c));
    return cases;
}

INSTANTIATE_TEST_SUITE_P(Scenes, SampledScenes, testing::ValuesIn(sampledCases()),
                         [](const testing::TestParamInfo<RenderCase>& info) {
                             return info.param.name;
                         });

// 2 samples (2 x 1) and 8 (4 x 2): the other grids, on a cycle and on nesting.
TEST(Sampling, EveryGridMatchesItsABuffer) {
    for (const RenderCase& c : renderCases()) {
        if (c.name != "ThreeSticksCycle" && c.name != "Nested")
            continue;
        const Scene scene = loadTestScene(c.scene);
        const ViewProjection view = viewOf(scene, c);
        for (uint32_t samples : {2u, 8u}) {
            RenderSettings flat = settingsOf(c, BlendMethod::linked_list);
            flat.shading = Shading::flat;
            flat.samples = samples;
            const ABuffer reference = sampledReference(scene, flat, view, samples);
            for (const Method& m : {kExactMethods[0], kExactMethods[3], kExactMethods[6]}) {
                SCOPED_TRACE(c.name + " at " + std::to_string(samples) + " samples, " +
                             describe(m));
                const std::vector<uint8_t> image = render(scene, withMethod(flat, m), view);
                ASSERT_EQ(image.size(), std::size_t(kWidth) * kHeight * 4); // resolved
                EXPECT_LE(compareWithABuffer(image, reference).max_abs, 1);
            }
        }
    }
}

// A black square of alpha 0.5 over the white background, seen orthographically down -z at
// |n . v| = facing, filling the view: the image is 1 - alpha' where it shows.
Scene tiltedSquare(double facing, float alpha) {
    const double sine = std::sqrt(1 - facing * facing);
    // Spans x in [-1, 1], and 2 along the screen's y after the tilt.
    const Vec3 across{1, 0, 0}, along{0, 1, -sine / facing};
    const auto corner = [&](double a, double b) {
        return Vec3{a * across.x + b * along.x, a * across.y + b * along.y,
                    a * across.z + b * along.z};
    };
    const Vec3 corners[6] = {corner(-1, -1), corner(1, -1), corner(1, 1),
                             corner(-1, -1), corner(1, 1),  corner(-1, 1)};
    Scene scene;
    scene.name = "tilted square";
    scene.positions.resize(2);
    for (std::size_t i = 0; i < 6; ++i) {
        scene.positions.x[i] = float(corners[i].x);
        scene.positions.y[i] = float(corners[i].y);
        scene.positions.z[i] = float(corners[i].z);
    }
    scene.objects.push_back({"square", Rgba{0, 0, 0, alpha}, alpha < 1.0f, 0, 2});
    return scene;
}

// The centre pixel's red, 0..255, over a white background.
int centreRed(const Scene& scene, Shading shading) {
    CameraSpec camera = orthographic({0, 0, -1});
    const ViewProjection view = frameCamera(camera, scene.positions.bounds(), 33, 33);
    RenderSettings settings;
    settings.background = {1, 1, 1, 1};
    settings.method = BlendMethod::linked_list;
    settings.shading = shading;
    const std::vector<uint8_t> image = render(scene, settings, view);
    return image[(16 * 33 + 16) * 4];
}

TEST(MembraneShading, OpacityIsAThinLayerSeenAtAnAngle) {
    // alpha' = 1 - (1 - alpha)^(1 / max(facing, 0.05)); black shows 1 - alpha' of the white.
    for (double facing : {1.0, 0.5, 0.25, 0.1}) {
        SCOPED_TRACE("facing " + std::to_string(facing));
        const Scene square = tiltedSquare(facing, 0.5f);
        const double shown = std::pow(0.5, 1 / facing);
        EXPECT_NEAR(centreRed(square, Shading::membrane), shown * 255, 1.0);
        // lit and flat keep the alpha at every angle.
        EXPECT_NEAR(centreRed(square, Shading::lit), 127.5, 1.0);
        EXPECT_NEAR(centreRed(square, Shading::flat), 127.5, 1.0);
    }
    // Nearly edge-on, the layer thickens at most 20 times: (0.9)^20 of the white shows, not 0.
    EXPECT_NEAR(centreRed(tiltedSquare(0.02, 0.1f), Shading::membrane), std::pow(0.9, 20) * 255,
                1.0);
    // Opaque stays opaque.
    EXPECT_EQ(centreRed(tiltedSquare(0.25, 1.0f), Shading::membrane), 0);
}

TEST(Sampling, OnlyOneTwoFourOrEightSamples) {
    const Scene scene = loadTestScene("tests/data/scenes/three_sticks.json");
    for (uint32_t samples : {0u, 3u, 16u, 1000000u}) {
        RenderSettings settings;
        settings.samples = samples;
        EXPECT_THROW(TransparencyRenderer(context(), scene, settings), std::invalid_argument)
            << samples;
    }
    // Pixels times samples are bounded as pixels alone are (kMaxImagePixels): 8192 x 8192 at
    // 2 samples is refused before anything is allocated.
    RenderSettings two;
    two.samples = 2;
    TransparencyRenderer renderer(context(), scene, two);
    RenderStats stats;
    const ViewProjection large =
        frameCamera(*scene.camera, scene.positions.bounds(), kMaxImageSide / 2, kMaxImageSide / 2);
    EXPECT_THROW(renderer.render(scene.positions, large, stats), std::invalid_argument);
    EXPECT_EQ(sampleGridOf(3).error, "samples must be 1, 2, 4 or 8, got 3");
}

} // namespace
} // namespace vissort
