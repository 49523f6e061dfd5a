// measureDepthComplexity and estimateDepthComplexity on stacks of quads whose per-pixel counts are
// known by construction (worked out from the orthographic camera's definition), with the setup
// checked unambiguous by the independent brute-force caster of test_scenes.h.

#include "vissort/depth_complexity.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "test_scenes.h"

namespace vissort {
namespace {

using test::addTriangle;

// The view: orthographic along -z, framing the box [-2, 2] x [-2, 2] x [-1, 1] (centre 0,
// radius r = 3), 16 x 12 pixels. Half-height r = 3, half-width r * 16 / 12 = 4: every pixel is
// 0.5 x 0.5, pixel (i, j) spans x in [-4 + 0.5 i, -3.5 + 0.5 i] and y in [2.5 - 0.5 j, 3 - 0.5 j].
// The eye plane is at z = 2r = 6, near = 0.5 r and far = 3.5 r: depths 0..1 are z in [-4.5, 4.5].
constexpr uint32_t kWidth = 16, kHeight = 12;
constexpr uint64_t kPixels = uint64_t(kWidth) * kHeight;

Bounds framingBounds() {
    Bounds bounds;
    bounds.add({-2, -2, -1});
    bounds.add({2, 2, 1});
    return bounds;
}

CameraSpec orthographicAlongMinusZ() {
    CameraSpec camera;
    camera.projection = Projection::orthographic;
    camera.ortho_direction = {0, 0, -1};
    return camera;
}

ViewProjection theView(uint32_t width = kWidth, uint32_t height = kHeight) {
    return frameCamera(orthographicAlongMinusZ(), framingBounds(), width, height);
}

/// The rectangle [x0, x1] x [y0, y1] at height z, as triangles (a, b, c) and (a, c, d) sharing the
/// diagonal from (x0, y0) to (x1, y1).
void addRectangle(TrianglePositions& positions, double x0, double x1, double y0, double y1,
                  double z) {
    addTriangle(positions, {x0, y0, z}, {x1, y0, z}, {x1, y1, z});
    addTriangle(positions, {x0, y0, z}, {x1, y1, z}, {x0, y1, z});
}

/// A quad far larger than the view, its diagonal y = x - 0.25 passing between pixel centres.
void addCoveringQuad(TrianglePositions& positions, double z) {
    addRectangle(positions, -9.75, 10.25, -10.0, 10.0, z);
}

// The small quad covers exactly the pixels i in [kI0, kI1), j in [kJ0, kJ1): its edges lie on
// pixel borders, 0.25 from the nearest centres.
constexpr uint32_t kI0 = 3, kI1 = 9, kJ0 = 2, kJ1 = 7;
constexpr uint64_t kSmallPixels = uint64_t(kI1 - kI0) * (kJ1 - kJ0); // 30

void addSmallQuad(TrianglePositions& positions, double z) {
    addRectangle(positions, -4.0 + 0.5 * kI0, -4.0 + 0.5 * kI1, 3.0 - 0.5 * kJ1, 3.0 - 0.5 * kJ0,
                 z);
}

constexpr int kStack = 4;

/// kStack covering quads at z = -1.5, -0.5, 0.5, 1.5 and the small quad in front at z = 2.5.
TrianglePositions stackScene() {
    TrianglePositions positions;
    for (int q = 0; q < kStack; ++q)
        addCoveringQuad(positions, -1.5 + q);
    addSmallQuad(positions, 2.5);
    return positions;
}

/// Pixel (i, j)'s expected count: one triangle per covering quad, one more inside the small one.
uint64_t expectedCount(uint32_t i, uint32_t j, int covering) {
    const bool small = i >= kI0 && i < kI1 && j >= kJ0 && j < kJ1;
    return uint64_t(covering) + (small ? 1 : 0);
}

/// The setup is unambiguous: the independent caster finds exactly the expected triangles at every
/// pixel, every hit robust (no ray on an edge or a shared diagonal).
void checkGroundTruth(const TrianglePositions& positions, const ViewProjection& view,
                      int covering) {
    const auto pixels = test::bruteForceHits(positions, view);
    for (uint32_t j = 0; j < view.height; ++j) {
        for (uint32_t i = 0; i < view.width; ++i) {
            const auto& hits = pixels[std::size_t(j) * view.width + i];
            ASSERT_EQ(hits.size(), expectedCount(i, j, covering)) << "pixel " << i << "," << j;
            for (const test::BruteHit& hit : hits)
                ASSERT_TRUE(hit.robust)
                    << "pixel " << i << "," << j << " triangle " << hit.triangle;
        }
    }
}

/// The expected result from the independent caster's per-pixel counts, every hit robust (so the
/// count of each ray is unambiguous).
DepthComplexity bruteForceResult(const TrianglePositions& positions, const ViewProjection& view) {
    const auto pixels = test::bruteForceHits(positions, view);
    DepthComplexity expected;
    expected.width = view.width;
    expected.height = view.height;
    expected.histogram.assign(1, 0);
    for (std::size_t p = 0; p < pixels.size(); ++p) {
        for (const test::BruteHit& hit : pixels[p])
            EXPECT_TRUE(hit.robust) << "pixel " << p << " triangle " << hit.triangle;
        const uint64_t n = pixels[p].size();
        if (n >= expected.histogram.size())
            expected.histogram.resize(n + 1, 0);
        ++expected.histogram[n];
        expected.max = std::max(expected.max, n);
        expected.hits += n;
        expected.covered_pixels += n > 0 ? 1 : 0;
    }
    expected.mean =
        expected.covered_pixels ? double(expected.hits) / double(expected.covered_pixels) : 0.0;
    return expected;
}

void expectSameResult(const DepthComplexity& a, const DepthComplexity& b) {
    EXPECT_EQ(a.width, b.width);
    EXPECT_EQ(a.height, b.height);
    EXPECT_EQ(a.max, b.max);
    EXPECT_EQ(a.covered_pixels, b.covered_pixels);
    EXPECT_EQ(a.hits, b.hits);
    EXPECT_EQ(a.mean, b.mean);
    EXPECT_EQ(a.histogram, b.histogram);
}

TEST(DepthComplexity, ViewMapsPixelsAsAssumed) {
    // The pixel geometry the expected counts rely on, from the documented ray of a pixel centre.
    const ViewProjection view = theView();
    ASSERT_EQ(view.projection, Projection::orthographic);
    for (uint32_t j : {0u, 5u, kHeight - 1}) {
        for (uint32_t i : {0u, 7u, kWidth - 1}) {
            Vec3 origin, direction;
            view.pixelRay(i + 0.5, j + 0.5, origin, direction);
            EXPECT_NEAR(origin.x, -3.75 + 0.5 * i, 1e-12);
            EXPECT_NEAR(origin.y, 2.75 - 0.5 * j, 1e-12);
            EXPECT_NEAR(direction.x, 0.0, 1e-12);
            EXPECT_NEAR(direction.y, 0.0, 1e-12);
            EXPECT_NEAR(direction.z, -1.0, 1e-12);
        }
    }
    EXPECT_NEAR(view.depthOf({0, 0, 4.4}), (1.6 - 1.5) / 9.0, 1e-12);
    EXPECT_GT(view.depthOf({0, 0, -5.0}), 1.0);
    EXPECT_LT(view.depthOf({0, 0, 5.0}), 0.0);
}

TEST(DepthComplexity, StackOfQuadsGivesKnownCounts) {
    const TrianglePositions positions = stackScene();
    const ViewProjection view = theView();
    checkGroundTruth(positions, view, kStack);

    const DepthComplexity result = measureDepthComplexity(positions, view, 1);
    EXPECT_EQ(result.width, kWidth);
    EXPECT_EQ(result.height, kHeight);
    EXPECT_EQ(result.max, uint64_t(kStack + 1));
    EXPECT_EQ(result.covered_pixels, kPixels);
    const uint64_t hits = kPixels * kStack + kSmallPixels; // 798
    EXPECT_EQ(result.hits, hits);
    EXPECT_DOUBLE_EQ(result.mean, double(hits) / double(kPixels));
    std::vector<uint64_t> histogram(kStack + 2, 0);
    histogram[kStack] = kPixels - kSmallPixels;
    histogram[kStack + 1] = kSmallPixels;
    EXPECT_EQ(result.histogram, histogram);
}

TEST(DepthComplexity, SameResultForAnyThreadCount) {
    const TrianglePositions positions = stackScene();
    const ViewProjection view = theView();
    const DepthComplexity one = measureDepthComplexity(positions, view, 1);
    const DepthComplexity three = measureDepthComplexity(positions, view, 3);
    const DepthComplexity automatic = measureDepthComplexity(positions, view, 0);
    expectSameResult(one, three);
    expectSameResult(one, automatic);
    EXPECT_EQ(three.max, uint64_t(kStack + 1));
}

TEST(DepthComplexity, UncoveredPixelsCountAsZero) {
    // Only the small quad: 30 pixels at 1, the rest of the view empty.
    TrianglePositions positions;
    addSmallQuad(positions, 0.0);
    const ViewProjection view = theView();
    checkGroundTruth(positions, view, 0);
    for (unsigned threads : {1u, 3u}) {
        const DepthComplexity result = measureDepthComplexity(positions, view, threads);
        EXPECT_EQ(result.max, 1u);
        EXPECT_EQ(result.covered_pixels, kSmallPixels);
        EXPECT_EQ(result.hits, kSmallPixels);
        EXPECT_DOUBLE_EQ(result.mean, 1.0);
        EXPECT_EQ(result.histogram, (std::vector<uint64_t>{kPixels - kSmallPixels, kSmallPixels}));
    }
}

TEST(DepthComplexity, NothingInViewIsAllZero) {
    const ViewProjection view = theView();
    TrianglePositions outside;
    addRectangle(outside, 5.0, 7.0, -1.0, 1.0, 0.0);       // beside the view (x > 4)
    addCoveringQuad(outside, -6.0);                        // beyond the far plane (d > 1)
    addCoveringQuad(outside, 7.0);                         // behind the eye plane (d < 0)
    addTriangle(outside, {0, 0, 0}, {1, 1, 0}, {2, 2, 0}); // degenerate: never counts
    for (const TrianglePositions& positions : {TrianglePositions{}, outside}) {
        for (unsigned threads : {1u, 3u}) {
            const DepthComplexity result = measureDepthComplexity(positions, view, threads);
            EXPECT_EQ(result.width, kWidth);
            EXPECT_EQ(result.height, kHeight);
            EXPECT_EQ(result.max, 0u);
            EXPECT_EQ(result.covered_pixels, 0u);
            EXPECT_EQ(result.hits, 0u);
            EXPECT_EQ(result.mean, 0.0);
            EXPECT_EQ(result.histogram, std::vector<uint64_t>{kPixels});
        }
    }
}

TEST(DepthComplexity, ClippedQuadsAreNotCounted) {
    // The stack plus covering quads beyond the far plane and behind the eye: same counts.
    TrianglePositions positions = stackScene();
    addCoveringQuad(positions, -6.0);
    addCoveringQuad(positions, 7.0);
    const DepthComplexity result = measureDepthComplexity(positions, theView(), 3);
    EXPECT_EQ(result.max, uint64_t(kStack + 1));
    EXPECT_EQ(result.covered_pixels, kPixels);
    EXPECT_EQ(result.hits, kPixels * kStack + kSmallPixels);
}

TEST(DepthComplexity, EstimateAtFullSizeMatchesTheMeasure) {
    const TrianglePositions positions = stackScene();
    const DepthComplexity measured = measureDepthComplexity(positions, theView(), 1);
    // max_side larger than the image: the full size.
    const DepthComplexity full = estimateDepthComplexity(positions, orthographicAlongMinusZ(),
                                                         framingBounds(), kWidth, kHeight, 256);
    expectSameResult(full, measured);
}

TEST(DepthComplexity, EstimateCastsAGridWithTheViewsAspectRatio) {
    const TrianglePositions positions = stackScene();
    const DepthComplexity measured = measureDepthComplexity(positions, theView(), 1);

    // 1600 x 1200 scaled to a side of 16: exactly the 16 x 12 view above, so the same counts.
    const DepthComplexity scaled = estimateDepthComplexity(positions, orthographicAlongMinusZ(),
                                                           framingBounds(), 1600, 1200, 16);
    EXPECT_EQ(scaled.width, 16u);
    EXPECT_EQ(scaled.height, 12u);
    expectSameResult(scaled, measured);

    // Portrait and wide images: the longer side becomes max_side, the aspect ratio is kept.
    struct Case {
        uint32_t width, height, max_side, grid_width, grid_height;
    };
    for (const Case& c :
         {Case{1000, 500, 64, 64, 32}, Case{300, 900, 45, 15, 45}, Case{4096, 4096, 20, 20, 20}}) {
        SCOPED_TRACE(::testing::Message() << c.width << "x" << c.height << " side " << c.max_side);
        const DepthComplexity estimate = estimateDepthComplexity(
            positions, orthographicAlongMinusZ(), framingBounds(), c.width, c.height, c.max_side);
        EXPECT_EQ(estimate.width, c.grid_width);
        EXPECT_EQ(estimate.height, c.grid_height);
        // The covering quads fill every grid, and the small quad (3 x 2.5 world units, far wider
        // than any grid's pixels here) is hit by some rays: the same max on the stack.
        EXPECT_EQ(estimate.max, uint64_t(kStack + 1));
        const uint64_t rays = uint64_t(c.grid_width) * c.grid_height;
        EXPECT_EQ(estimate.covered_pixels, rays);
        ASSERT_EQ(estimate.histogram.size(), std::size_t(kStack + 2));
        EXPECT_EQ(estimate.histogram[kStack] + estimate.histogram[kStack + 1], rays);
        EXPECT_GT(estimate.histogram[kStack + 1], 0u);
        EXPECT_EQ(estimate.hits, rays * kStack + estimate.histogram[kStack + 1]);
        // Exactly: the independent caster over the same grid of the same camera.
        expectSameResult(
            estimate,
            bruteForceResult(positions, frameCamera(orthographicAlongMinusZ(), framingBounds(),
                                                    c.grid_width, c.grid_height)));
    }
}

// A ray through the diagonal that a quad's two triangles share hits both at the same point: one
// surface, not two. Three quads far larger than the view, their diagonals y = x through the
// centres of the pixels with i + j = 13 (x = -3.75 + 0.5 i, y = 2.75 - 0.5 j): every pixel
// crosses 3 surfaces ('info builtin:slabs?layers=40' reported 45, the stack's diagonals).
TEST(DepthComplexity, SharedEdgesCountOnce) {
    TrianglePositions positions;
    for (const double z : {-0.5, 0.0, 0.5})
        addRectangle(positions, -10.0, 10.0, -10.0, 10.0, z);
    const ViewProjection view = theView();
    // The premise: the rays on the diagonal hit both triangles of each quad.
    const auto pixels = test::bruteForceHits(positions, view);
    std::size_t on_diagonal = 0;
    for (uint32_t j = 0; j < kHeight; ++j)
        for (uint32_t i = 0; i < kWidth; ++i)
            if (i + j == 13) {
                ++on_diagonal;
                EXPECT_EQ(pixels[std::size_t(j) * kWidth + i].size(), 6u)
                    << "pixel " << i << "," << j;
            }
    ASSERT_GT(on_diagonal, 0u);
    const DepthComplexity result = measureDepthComplexity(positions, view, 1);
    EXPECT_EQ(result.max, 3u);
    EXPECT_EQ(result.covered_pixels, kPixels);
    EXPECT_EQ(result.hits, 3 * kPixels);
    EXPECT_EQ(result.histogram, (std::vector<uint64_t>{0, 0, 0, kPixels}));
}

} // namespace
} // namespace vissort
