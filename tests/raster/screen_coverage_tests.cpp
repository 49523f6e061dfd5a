// screenCoverage (cpu_rasterizer.h), the screen-space shortcut of the exact rule's band
// decisions, against the exact fragment model it stands in for: wherever it answers (+1 or -1),
// the model must say the same, on random triangles of every shape, slivers whose corners turn
// the other way than their snapped corners included (a sliver of the IFC house was refused a
// pixel it covers when the shortcut took the snapped orientation for the true one).
#include <array>
#include <cstdint>
#include <random>

#include <gtest/gtest.h>

#include "geometry/exact_fragments.h"
#include "raster/cpu_rasterizer.h"
#include "vissort/camera.h"

namespace vissort::detail {
namespace {

TEST(ScreenCoverage, AgreesWithTheExactModelWhereverItAnswers) {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> unit(-1, 1);
    Bounds bounds;
    bounds.add({-1, -1, -1});
    bounds.add({1, 1, 1});
    uint64_t answered = 0, inside = 0, flipped_slivers = 0, flipped_inside = 0;
    for (Projection projection : {Projection::perspective, Projection::orthographic}) {
        CameraSpec spec;
        spec.projection = projection;
        spec.eye = {0.3, 0.2, 4};
        spec.ortho_direction = {-0.1, -0.05, -1};
        const ViewProjection view = frameCamera(spec, bounds, 128, 96);
        const Matrix4 m = multiply(view.projection_matrix, view.view);
        const ExactFragments model(view);
        TrianglePositions p;
        for (int i = 0; i < 4000; ++i) {
            const Vec3 a{unit(rng), unit(rng), unit(rng)};
            Vec3 b{unit(rng), unit(rng), unit(rng)}, c{unit(rng), unit(rng), unit(rng)};
            if (i % 2 == 0) // a sliver: two corners a few thousandths of a pixel apart
                b = a + Vec3{unit(rng), unit(rng), unit(rng)} * 1e-4;
            for (const Vec3& v : {a, b, c}) {
                p.x.push_back(float(v.x));
                p.y.push_back(float(v.y));
                p.z.push_back(float(v.z));
            }
        }
        const PrimitiveRange all{0, uint32_t(p.triangleCount())};
        const ScreenErrors errors = screenErrorsOf(m, view, p, {&all, 1});
        for (std::size_t t = 0; t < p.triangleCount(); ++t) {
            std::array<double, 3> ux, uy;
            std::array<int64_t, 3> fx, fy;
            bool usable = true;
            for (int k = 0; k < 3; ++k) {
                const std::size_t i = 3 * t + std::size_t(k);
                const ClipVertex clip = toClipSpace(m, p.x[i], p.y[i], p.z[i]);
                usable = usable && clip.w > 0;
                const ScreenVertex s = toScreen(clip, view.width, view.height);
                ux[k] = s.x;
                uy[k] = s.y;
                fx[k] = snapToFixed(s.x);
                fy[k] = snapToFixed(s.y);
            }
            if (!usable)
                continue;
            const double area =
                (ux[1] - ux[0]) * (uy[2] - uy[0]) - (uy[1] - uy[0]) * (ux[2] - ux[0]);
            const int64_t snapped_area =
                (fx[1] - fx[0]) * (fy[2] - fy[0]) - (fy[1] - fy[0]) * (fx[2] - fx[0]);
            const bool flipped = (area < 0) != (snapped_area < 0) && snapped_area != 0;
            flipped_slivers += flipped ? 1 : 0;
            const TriangleCorners corners = TriangleCorners::of(p, t);
            const int x0 = int(std::floor(std::min({ux[0], ux[1], ux[2]}))) - 1;
            const int x1 = int(std::ceil(std::max({ux[0], ux[1], ux[2]}))) + 1;
            const int y0 = int(std::floor(std::min({uy[0], uy[1], uy[2]}))) - 1;
            const int y1 = int(std::ceil(std::max({uy[0], uy[1], uy[2]}))) + 1;
            for (int py = std::max(y0, 0); py <= std::min(y1, int(view.height) - 1); ++py)
                for (int px = std::max(x0, 0); px <= std::min(x1, int(view.width) - 1); ++px) {
                    const int answer = screenCoverage(ux, uy, uint32_t(px), uint32_t(py), errors);
                    if (answer == 0)
                        continue;
                    ++answered;
                    const bool covers =
                        model.covers(model.rays().centre(uint32_t(px), uint32_t(py)), corners);
                    ASSERT_EQ(answer > 0, covers)
                        << "triangle " << t << " at pixel (" << px << ", " << py << ")"
                        << (flipped ? ", its snapped corners turning the other way" : "");
                    inside += covers ? 1 : 0;
                    flipped_inside += covers && flipped ? 1 : 0;
                }
        }
    }
    // Both answers, and the slivers whose snapped corners turn the other way, covering pixels.
    EXPECT_GT(answered, 100000u);
    EXPECT_GT(inside, 10000u);
    EXPECT_GT(flipped_slivers, 20u);
    EXPECT_GT(flipped_inside, 0u);
}

} // namespace
} // namespace vissort::detail
