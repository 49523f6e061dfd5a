// View culling (boxOutsideView, camera.h; the renderer's draws and the levels of detail's
// choice): a box is culled only when no point of it is in the view volume, checked with the
// camera's own clip transform (ViewProjection::toClip) on its corners and points inside it, over
// random perspective and orthographic views; and culling does happen, on boxes beside, behind and
// straddling the eye.

#include <gtest/gtest.h>

#include <random>

#include "vissort/camera.h"

namespace vissort {
namespace {

// Inside the clip volume the renderer draws: |x|, |y| <= w and z >= 0 (zero-to-one depth).
bool inView(const ViewProjection& view, const Vec3& point) {
    const std::array<double, 4> c = view.toClip(point);
    return c[3] - c[0] >= 0 && c[3] + c[0] >= 0 && c[3] - c[1] >= 0 && c[3] + c[1] >= 0 &&
           c[2] >= 0;
}

TEST(ViewCulling, ABoxIsCulledOnlyWhenNoPointOfItIsInView) {
    std::mt19937 random(11);
    std::uniform_real_distribution<double> place(-12, 12), unit(0, 1), fov(20, 110);
    const Bounds scene{{-10, -10, -10}, {10, 10, 10}};
    int culled = 0, seen = 0, boxes = 0;
    for (int v = 0; v < 40; ++v) {
        CameraSpec camera;
        camera.eye = {place(random) / 2, place(random) / 2, place(random) / 2};
        camera.target = {place(random), place(random), place(random)};
        camera.fov_degrees = fov(random);
        if (v % 4 == 3) {
            camera.projection = Projection::orthographic;
            camera.ortho_direction = camera.target - camera.eye;
        }
        SCOPED_TRACE(testing::Message() << "view " << v);
        const ViewProjection view = frameCamera(camera, scene, 64, 48);
        for (int b = 0; b < 300; ++b, ++boxes) {
            const Vec3 centre{place(random), place(random), place(random)};
            // Sizes from 0.01 to 5 a side, one side in ten flat (a wall seen edge-on).
            const auto half = [&] {
                return unit(random) < 0.1 ? 0.0 : 0.01 * std::pow(500.0, unit(random));
            };
            const Vec3 h{half(), half(), half()};
            Bounds box;
            box.add(centre - h);
            box.add(centre + h);
            bool any_in_view = false;
            for (unsigned i = 0; i < 8 && !any_in_view; ++i)
                any_in_view = inView(view, box.corner(i));
            for (int i = 0; i < 40 && !any_in_view; ++i)
                any_in_view = inView(view, {box.min.x + unit(random) * (box.max.x - box.min.x),
                                            box.min.y + unit(random) * (box.max.y - box.min.y),
                                            box.min.z + unit(random) * (box.max.z - box.min.z)});
            const bool outside = boxOutsideView(box, view);
            if (outside) {
                EXPECT_FALSE(any_in_view) << "box " << b << " culled with a point in view";
            }
            culled += outside;
            seen += any_in_view;
        }
    }
    // Both answers occur often: culling is not a no-op, nor everything.
    EXPECT_GT(culled, boxes / 5);
    EXPECT_GT(seen, boxes / 10);
}

TEST(ViewCulling, BoxesBehindTheEyeAreCulledAndOnesAroundItAreNot) {
    CameraSpec camera; // at (0, 0, 5) looking along -z
    const ViewProjection view = frameCamera(camera, Bounds{{-1, -1, -1}, {1, 1, 1}}, 64, 48);
    EXPECT_TRUE(boxOutsideView(Bounds{{-1, -1, 6}, {1, 1, 8}}, view));   // behind
    EXPECT_TRUE(boxOutsideView(Bounds{{40, -1, -1}, {42, 1, 1}}, view)); // far right
    // Near plane at 3.2 from the eye (frameCamera): a box around the eye but not past it is not
    // drawn; one from the eye into the view is.
    EXPECT_TRUE(boxOutsideView(Bounds{{-1, -1, 4}, {1, 1, 6}}, view));
    EXPECT_FALSE(boxOutsideView(Bounds{{-1, -1, -1}, {1, 1, 6}}, view));
    EXPECT_FALSE(boxOutsideView(Bounds{{-1, -1, -1}, {1, 1, 1}}, view)); // ahead
    EXPECT_TRUE(boxOutsideView(Bounds{}, view));                         // empty
}

} // namespace
} // namespace vissort
