// Bounds and cameras, checked against values computed independently in the test: glm::lookAt and
// glm::perspective for the perspective camera, hand-derived frames for the orthographic one, and
// the depth definitions of camera.h (d = 1 - near / z, d = (z - near) / (far - near)).

#include "vissort/camera.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace vissort {
namespace {

glm::dvec3 toGlm(const Vec3& v) {
    return {v.x, v.y, v.z};
}
Vec3 fromGlm(const glm::dvec3& v) {
    return {v.x, v.y, v.z};
}

Bounds boxBounds(const Vec3& lo, const Vec3& hi) {
    Bounds b;
    b.add(lo);
    b.add(hi);
    return b;
}

std::vector<Vec3> boxCorners(const Bounds& b) {
    std::vector<Vec3> corners;
    for (int i = 0; i < 8; ++i)
        corners.push_back({(i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y,
                           (i & 4) ? b.max.z : b.min.z});
    return corners;
}

// Points spread over a sphere (a Fibonacci lattice), plus its six axis extremes.
std::vector<Vec3> spherePoints(const Vec3& centre, double r, int count = 200) {
    std::vector<Vec3> points;
    const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
    for (int i = 0; i < count; ++i) {
        const double y = 1.0 - 2.0 * (i + 0.5) / count;
        const double ring = std::sqrt(1.0 - y * y);
        const double phi = golden * i;
        points.push_back({centre.x + r * ring * std::cos(phi), centre.y + r * y,
                          centre.z + r * ring * std::sin(phi)});
    }
    for (int axis = 0; axis < 3; ++axis)
        for (double sign : {-1.0, 1.0}) {
            glm::dvec3 offset(0.0);
            offset[axis] = sign * r;
            points.push_back(fromGlm(toGlm(centre) + offset));
        }
    return points;
}

struct Ndc {
    double x, y, d;
};

Ndc toNdc(const ViewProjection& vp, const Vec3& p) {
    const auto clip = vp.toClip(p);
    return {clip[0] / clip[3], clip[1] / clip[3], clip[2] / clip[3]};
}

// Screen coordinates (pixels, row 0 at the top) of a world point.
glm::dvec2 toScreen(const ViewProjection& vp, const Vec3& p) {
    const Ndc ndc = toNdc(vp, p);
    return {(ndc.x + 1) / 2 * vp.width, (1 - ndc.y) / 2 * vp.height};
}

// Least-squares fit of value = a * sx + b * sy + c; returns the largest residual.
double planeFitResidual(const std::vector<glm::dvec2>& screen, const std::vector<double>& value) {
    glm::dmat3 normal(0.0);
    glm::dvec3 rhs(0.0);
    for (std::size_t i = 0; i < screen.size(); ++i) {
        const glm::dvec3 row(screen[i].x, screen[i].y, 1.0);
        normal += glm::outerProduct(row, row);
        rhs += row * value[i];
    }
    const glm::dvec3 coefficients = glm::inverse(normal) * rhs;
    double worst = 0;
    for (std::size_t i = 0; i < screen.size(); ++i) {
        const double fitted = glm::dot(glm::dvec3(screen[i].x, screen[i].y, 1.0), coefficients);
        worst = std::max(worst, std::abs(fitted - value[i]));
    }
    return worst;
}

CameraSpec perspectiveCamera(const Vec3& eye, const Vec3& target, const Vec3& up, double fov) {
    CameraSpec camera;
    camera.projection = Projection::perspective;
    camera.eye = eye;
    camera.target = target;
    camera.up = up;
    camera.fov_degrees = fov;
    return camera;
}

CameraSpec orthographicCamera(const Vec3& direction) {
    CameraSpec camera;
    camera.projection = Projection::orthographic;
    camera.ortho_direction = direction;
    return camera;
}

// ---------------------------------------------------------------------------------------------
// Bounds

TEST(CameraBounds, EmptyUntilAPointIsAdded) {
    Bounds b;
    EXPECT_TRUE(b.isEmpty());
    EXPECT_EQ(b.radius(), 0.0);
    b.add({1, -2, 3});
    EXPECT_FALSE(b.isEmpty());
    EXPECT_EQ(b.min.x, 1);
    EXPECT_EQ(b.max.y, -2);
    EXPECT_EQ(b.centre().z, 3);
    EXPECT_EQ(b.radius(), 0.0);
}

TEST(CameraBounds, AddCentreAndRadius) {
    Bounds b;
    b.add({4, 2, 0});
    b.add({1, -2, 5});
    b.add({2, 0, 12}); // inside in x and y, extends z
    b.add({3, 1, 6});  // inside: changes nothing
    EXPECT_EQ(b.min.x, 1);
    EXPECT_EQ(b.min.y, -2);
    EXPECT_EQ(b.min.z, 0);
    EXPECT_EQ(b.max.x, 4);
    EXPECT_EQ(b.max.y, 2);
    EXPECT_EQ(b.max.z, 12);
    const Vec3 c = b.centre();
    EXPECT_DOUBLE_EQ(c.x, 2.5);
    EXPECT_DOUBLE_EQ(c.y, 0.0);
    EXPECT_DOUBLE_EQ(c.z, 6.0);
    // Diagonal (3, 4, 12) has length 13.
    EXPECT_DOUBLE_EQ(b.radius(), 6.5);
}

TEST(CameraBounds, TrianglePositionsBounds) {
    TrianglePositions positions;
    positions.resize(2);
    const float xs[6] = {0, 1, 2, -1, 0, 0}, ys[6] = {0, 0, 3, 0, -1, 0},
                zs[6] = {0, 0, 0, 1, 2, -2};
    for (int i = 0; i < 6; ++i) {
        positions.x[i] = xs[i];
        positions.y[i] = ys[i];
        positions.z[i] = zs[i];
    }
    EXPECT_EQ(positions.triangleCount(), 2u);
    const Bounds b = positions.bounds();
    EXPECT_EQ(b.min.x, -1);
    EXPECT_EQ(b.max.x, 2);
    EXPECT_EQ(b.min.y, -1);
    EXPECT_EQ(b.max.y, 3);
    EXPECT_EQ(b.min.z, -2);
    EXPECT_EQ(b.max.z, 2);
    EXPECT_TRUE(TrianglePositions{}.bounds().isEmpty());
}

// ---------------------------------------------------------------------------------------------
// Perspective

TEST(CameraPerspective, ViewMatrixIsLookAt) {
    const Bounds bounds = boxBounds({-1, -1, -1}, {1, 1, 1});
    const CameraSpec cameras[] = {
        perspectiveCamera({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 45),
        perspectiveCamera({3, 2, -4}, {0.5, -0.2, 0.1}, {0, 2, 0.3},
                          60), // up neither unit nor orthogonal
        perspectiveCamera({0.2, 0.1, 0.3}, {5, 0, 0}, {0, 0, 1}, 90), // eye inside the sphere
    };
    for (const CameraSpec& camera : cameras) {
        const ViewProjection vp = frameCamera(camera, bounds, 64, 48);
        const glm::dmat4 expected =
            glm::lookAt(toGlm(camera.eye), toGlm(camera.target), toGlm(camera.up));
        for (int col = 0; col < 4; ++col)
            for (int row = 0; row < 4; ++row)
                EXPECT_NEAR(vp.view[col * 4 + row], expected[col][row], 1e-12)
                    << "column " << col << " row " << row;
        EXPECT_EQ(vp.projection, Projection::perspective);
        EXPECT_EQ(vp.width, 64u);
        EXPECT_EQ(vp.height, 48u);
        const glm::dvec3 forward = glm::normalize(toGlm(camera.target) - toGlm(camera.eye));
        EXPECT_NEAR(vp.forward.x, forward.x, 1e-12);
        EXPECT_NEAR(vp.forward.y, forward.y, 1e-12);
        EXPECT_NEAR(vp.forward.z, forward.z, 1e-12);
        EXPECT_EQ(vp.eye_position.x, camera.eye.x);
        EXPECT_EQ(vp.eye_position.y, camera.eye.y);
        EXPECT_EQ(vp.eye_position.z, camera.eye.z);
    }
}

TEST(CameraPerspective, ClipXYWMatchGlmPerspective) {
    const Bounds bounds = boxBounds({-2, -1, -1}, {2, 1, 3});
    const CameraSpec camera = perspectiveCamera({4, 3, 8}, {0, 0.5, 1}, {0, 1, 0}, 50);
    for (auto [w, h] : {std::pair<uint32_t, uint32_t>{64, 48}, {7, 3}, {3, 7}, {1, 1}}) {
        const ViewProjection vp = frameCamera(camera, bounds, w, h);
        const double aspect = double(w) / double(h);
        // x, y and w rows of glm::perspective do not depend on near and far.
        const glm::dmat4 expected =
            glm::perspective(glm::radians(camera.fov_degrees), aspect, 0.25, 100.0) *
            glm::lookAt(toGlm(camera.eye), toGlm(camera.target), toGlm(camera.up));
        for (const Vec3& p : spherePoints(bounds.centre(), bounds.radius(), 40)) {
            const glm::dvec4 e = expected * glm::dvec4(toGlm(p), 1.0);
            const auto clip = vp.toClip(p);
            EXPECT_NEAR(clip[0], e.x, 1e-10);
            EXPECT_NEAR(clip[1], e.y, 1e-10);
            EXPECT_NEAR(clip[3], e.w, 1e-10);
        }
    }
}

TEST(CameraPerspective, HandComputedProjectionScale) {
    // fov 90 degrees: tan(45) = 1, so a point at distance z with height y has ndc y = y / z,
    // and x is divided by the aspect ratio 2.
    const Bounds bounds = boxBounds({-1, -1, -1}, {1, 1, 1});
    const ViewProjection vp =
        frameCamera(perspectiveCamera({0, 0, 10}, {0, 0, 0}, {0, 1, 0}, 90), bounds, 200, 100);
    const Ndc ndc = toNdc(vp, {1, 1, 0});
    EXPECT_NEAR(ndc.x, 0.1 / 2, 1e-12);
    EXPECT_NEAR(ndc.y, 0.1, 1e-12);
    const Ndc far_corner = toNdc(vp, {4, -2, 6}); // distance 4
    EXPECT_NEAR(far_corner.x, 1.0 / 2, 1e-12);
    EXPECT_NEAR(far_corner.y, -0.5, 1e-12);
}

TEST(CameraPerspective, NearPlane) {
    const Bounds bounds = boxBounds({1, 1, 1}, {3, 3, 3}); // centre (2, 2, 2), r = sqrt(3)
    const double r = std::sqrt(3.0);
    struct Case {
        Vec3 eye;
        double expected_near;
    };
    const Case cases[] = {
        {{5, 6, 2}, (5 - r) * 0.99},                   // distance 5, outside
        {{2, 2, 12}, (10 - r) * 0.99},                 // distance 10
        {{2.1, 2, 2}, r * 1e-3 * 0.99},                // inside the sphere
        {{2, 2, 2 + r * (1 + 1e-4)}, r * 1e-3 * 0.99}, // just outside: r * 1e-3 wins
        {{2, 2 - 1.5 * r, 2}, std::max(0.5 * r, r * 1e-3) * 0.99},
    };
    for (const Case& c : cases) {
        // The target is not the centre: near depends on the distance to the sphere only.
        const CameraSpec camera = perspectiveCamera(c.eye, {2.3, 2.1, 1.9}, {0, 1, 0}, 45);
        ASSERT_EQ(validateCamera(camera).error, "");
        const ViewProjection vp = frameCamera(camera, bounds, 32, 32);
        EXPECT_NEAR(vp.near, c.expected_near, 1e-12 * std::max(1.0, c.expected_near));
        EXPECT_TRUE(std::isinf(vp.far));
    }
}

TEST(CameraPerspective, DepthIsOneMinusNearOverDistance) {
    const Bounds bounds = boxBounds({-1, -2, 0}, {3, 1, 2});
    const CameraSpec camera = perspectiveCamera({-3, 4, 9}, {1, -0.5, 1}, {0.1, 1, 0}, 40);
    const ViewProjection vp = frameCamera(camera, bounds, 80, 60);
    const glm::dvec3 eye = toGlm(camera.eye);
    const glm::dvec3 forward = glm::normalize(toGlm(camera.target) - eye);
    const double near = (glm::length(eye - toGlm(bounds.centre())) - bounds.radius()) * 0.99;
    ASSERT_NEAR(vp.near, near, 1e-12);
    std::vector<Vec3> points = spherePoints(bounds.centre(), bounds.radius());
    points.push_back(fromGlm(eye + forward * 1e6));
    for (const Vec3& p : points) {
        const double z = glm::dot(toGlm(p) - eye, forward);
        const double expected = 1 - near / z;
        EXPECT_NEAR(vp.depthOf(p), expected, 1e-12);
        const auto clip = vp.toClip(p);
        EXPECT_NEAR(clip[2] / clip[3], expected, 1e-12);
        EXPECT_NEAR(clip[3], z, 1e-9);
        // Every point of the sphere is beyond the near plane and before the infinite far plane.
        EXPECT_GT(vp.depthOf(p), 0.0);
        EXPECT_LT(vp.depthOf(p), 1.0);
    }
    // On the near plane d = 0; behind it d < 0.
    EXPECT_NEAR(vp.depthOf(fromGlm(eye + forward * near)), 0.0, 1e-12);
    EXPECT_LT(vp.depthOf(fromGlm(eye + forward * (near * 0.5))), 0.0);
}

TEST(CameraPerspective, DepthIsAffineInScreenSpace) {
    const Bounds bounds = boxBounds({-1, -1, -1}, {1, 1, 1});
    const CameraSpec camera = perspectiveCamera({1, 2, 6}, {0, 0.3, 0}, {0, 1, 0}, 50);
    const ViewProjection vp = frameCamera(camera, bounds, 80, 60);
    const glm::dvec3 origins[] = {{0.2, -0.1, 0.4}, {-0.5, 0.5, -0.8}};
    const glm::dvec3 e1s[] = {{1, 0.3, -0.5}, {0.2, 0.1, 1.5}};
    const glm::dvec3 e2s[] = {{-0.2, 0.8, 0.6}, {1.0, -0.4, 0.3}};
    for (int plane = 0; plane < 2; ++plane) {
        std::vector<glm::dvec2> screen;
        std::vector<double> depth, distance;
        for (int i = 0; i <= 6; ++i)
            for (int j = 0; j <= 6; ++j) {
                const double u = i / 6.0 - 0.5, v = j / 6.0 - 0.5;
                const Vec3 p = fromGlm(origins[plane] + u * e1s[plane] + v * e2s[plane]);
                screen.push_back(toScreen(vp, p));
                depth.push_back(vp.depthOf(p));
                distance.push_back(vp.toClip(p)[3]);
            }
        EXPECT_LT(planeFitResidual(screen, depth), 1e-10) << "plane " << plane;
        // The check has teeth: the distance itself is not affine in screen space.
        EXPECT_GT(planeFitResidual(screen, distance), 1e-4) << "plane " << plane;
    }
}

// ---------------------------------------------------------------------------------------------
// Pixel rays

void expectRaysThroughPixelCentres(const ViewProjection& vp, double t_beyond) {
    for (uint32_t py = 0; py < vp.height; ++py)
        for (uint32_t px = 0; px < vp.width; ++px) {
            Vec3 origin, direction;
            vp.pixelRay(px + 0.5, py + 0.5, origin, direction);
            EXPECT_NEAR(glm::length(toGlm(direction)), 1.0, 1e-12);
            const Vec3 p = fromGlm(toGlm(origin) + t_beyond * toGlm(direction));
            EXPECT_GT(vp.depthOf(p), 0.0);
            const glm::dvec2 s = toScreen(vp, p);
            EXPECT_NEAR(s.x, px + 0.5, 1e-9)
                << vp.width << "x" << vp.height << " pixel " << px << "," << py;
            EXPECT_NEAR(s.y, py + 0.5, 1e-9)
                << vp.width << "x" << vp.height << " pixel " << px << "," << py;
        }
}

TEST(CameraPixelRay, PerspectiveRaysProjectToPixelCentres) {
    const Bounds bounds = boxBounds({-1, -1, -1}, {1, 1, 1});
    const CameraSpec camera = perspectiveCamera({2, 1.5, 5}, {0.1, 0, -0.2}, {0, 1, 0}, 45);
    for (auto [w, h] : {std::pair<uint32_t, uint32_t>{7, 3}, {3, 7}, {1, 1}, {16, 9}}) {
        const ViewProjection vp = frameCamera(camera, bounds, w, h);
        // Every ray starts at the eye.
        Vec3 origin, direction;
        vp.pixelRay(0.5, 0.5, origin, direction);
        EXPECT_EQ(origin.x, camera.eye.x);
        EXPECT_EQ(origin.y, camera.eye.y);
        EXPECT_EQ(origin.z, camera.eye.z);
        expectRaysThroughPixelCentres(vp, 10.0); // beyond near even on slanted rays
    }
}

TEST(CameraPixelRay, OrthographicRaysProjectToPixelCentres) {
    const Bounds bounds = boxBounds({-1, 0, -2}, {2, 1, 1});
    const double r = bounds.radius();
    for (const Vec3& dir : {Vec3{0, 0, -1}, Vec3{1, -0.5, -2}, Vec3{0.1, -1, 0.2}}) {
        for (auto [w, h] : {std::pair<uint32_t, uint32_t>{7, 3}, {3, 7}, {1, 1}, {16, 9}}) {
            const ViewProjection vp = frameCamera(orthographicCamera(dir), bounds, w, h);
            const glm::dvec3 expected_dir = glm::normalize(toGlm(dir));
            for (uint32_t py = 0; py < h; ++py)
                for (uint32_t px = 0; px < w; ++px) {
                    Vec3 origin, direction;
                    vp.pixelRay(px + 0.5, py + 0.5, origin, direction);
                    // Parallel rays along the view direction, starting before the whole sphere.
                    EXPECT_NEAR(glm::length(toGlm(direction) - expected_dir), 0.0, 1e-12);
                    EXPECT_LE(vp.depthOf(origin), 0.0);
                }
            expectRaysThroughPixelCentres(vp, 2.0 * r);
        }
    }
}

TEST(CameraPixelRay, RowZeroIsTheTop) {
    const Bounds bounds = boxBounds({-1, -1, -1}, {1, 1, 1});
    const uint32_t w = 21, h = 15;
    const CameraSpec cameras[] = {
        perspectiveCamera({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 45),
        perspectiveCamera({5, 0, 0}, {0, 0, 0}, {0, 0, 1}, 45), // up is +z here
        orthographicCamera({0, 0, -1}),
    };
    for (const CameraSpec& camera : cameras) {
        const ViewProjection vp = frameCamera(camera, bounds, w, h);
        const glm::dvec3 up =
            camera.projection == Projection::perspective ? toGlm(camera.up) : glm::dvec3(0, 1, 0);
        const glm::dvec3 target = camera.projection == Projection::perspective
                                      ? toGlm(camera.target)
                                      : toGlm(bounds.centre());
        // A point above the target lands in the top half, one below in the bottom half.
        const glm::dvec2 above = toScreen(vp, fromGlm(target + 0.8 * up));
        const glm::dvec2 below = toScreen(vp, fromGlm(target - 0.8 * up));
        EXPECT_LT(above.y, h / 2.0 - 1);
        EXPECT_GT(below.y, h / 2.0 + 1);
        EXPECT_NEAR(above.x, w / 2.0, 1e-9);
        // The ray through the top row goes up (perspective) or starts high (orthographic).
        Vec3 origin, direction, mid_origin, mid_direction;
        vp.pixelRay(w / 2.0, 0.5, origin, direction);
        vp.pixelRay(w / 2.0, h / 2.0, mid_origin, mid_direction);
        if (camera.projection == Projection::perspective)
            EXPECT_GT(glm::dot(toGlm(direction) - toGlm(mid_direction), up), 0.0);
        else
            EXPECT_GT(glm::dot(toGlm(origin) - toGlm(mid_origin), up), 0.0);
    }
}

TEST(CameraPixelRay, ScreenPointsOtherThanCentres) {
    // pixelRay takes screen coordinates: (0, 0) is the top-left corner of the image.
    const Bounds bounds = boxBounds({-1, -1, -1}, {1, 1, 1});
    const ViewProjection vp =
        frameCamera(perspectiveCamera({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 90), bounds, 8, 4);
    Vec3 origin, direction;
    vp.pixelRay(0, 0, origin, direction);
    // tan(45) = 1 and aspect 2: the corner ray is (-2, 1, -1) normalized.
    const glm::dvec3 expected = glm::normalize(glm::dvec3(-2, 1, -1));
    EXPECT_NEAR(direction.x, expected.x, 1e-12);
    EXPECT_NEAR(direction.y, expected.y, 1e-12);
    EXPECT_NEAR(direction.z, expected.z, 1e-12);
}

// ---------------------------------------------------------------------------------------------
// Orthographic

// Checks that the view frames the sphere with the given image right and up vectors.
void expectOrthographicFrame(const ViewProjection& vp, const Bounds& bounds,
                             const glm::dvec3& right, const glm::dvec3& up) {
    const glm::dvec3 c = toGlm(bounds.centre());
    const double r = bounds.radius();
    const double aspect = double(vp.width) / double(vp.height);
    const auto expectNdc = [&](const glm::dvec3& p, double x, double y) {
        const auto clip = vp.toClip(fromGlm(p));
        EXPECT_NEAR(clip[3], 1.0, 1e-12);
        EXPECT_NEAR(clip[0] / clip[3], x, 1e-12);
        EXPECT_NEAR(clip[1] / clip[3], y, 1e-12);
    };
    expectNdc(c, 0, 0);
    expectNdc(c + r * up, 0, 1);
    expectNdc(c - r * up, 0, -1);
    expectNdc(c + r * aspect * right, 1, 0);
    expectNdc(c - r * aspect * right, -1, 0);
    expectNdc(c + 0.5 * r * up - 0.25 * r * aspect * right, -0.25, 0.5);
}

TEST(CameraOrthographic, LookingDownMinusZ) {
    const Bounds bounds = boxBounds({-2, -1, 0}, {2, 1, 4}); // centre (0, 0, 2), r = 3
    ASSERT_DOUBLE_EQ(bounds.radius(), 3.0);
    for (auto [w, h] : {std::pair<uint32_t, uint32_t>{200, 100}, {100, 200}, {1, 1}}) {
        const ViewProjection vp = frameCamera(orthographicCamera({0, 0, -1}), bounds, w, h);
        EXPECT_EQ(vp.projection, Projection::orthographic);
        EXPECT_NEAR(vp.forward.x, 0, 1e-15);
        EXPECT_NEAR(vp.forward.y, 0, 1e-15);
        EXPECT_NEAR(vp.forward.z, -1, 1e-15);
        expectOrthographicFrame(vp, bounds, {1, 0, 0}, {0, 1, 0});
        // Hand-computed: (3, 1.5, 2) at 200x100 (aspect 2) is at ndc (0.5, 0.5).
        if (w == 200) {
            const Ndc ndc = toNdc(vp, {3, 1.5, 2});
            EXPECT_NEAR(ndc.x, 0.5, 1e-12);
            EXPECT_NEAR(ndc.y, 0.5, 1e-12);
        }
    }
}

TEST(CameraOrthographic, LookingStraightDownUsesXForUp) {
    const Bounds bounds = boxBounds({-1, -1, -1}, {3, 1, 1});
    const glm::dvec3 dir(0, -1, 0);
    const glm::dvec3 right = glm::normalize(glm::cross(dir, glm::dvec3(1, 0, 0)));
    const glm::dvec3 up = glm::cross(right, dir);
    // By hand: right = (0, 0, 1), up = (1, 0, 0).
    EXPECT_NEAR(glm::length(right - glm::dvec3(0, 0, 1)), 0, 1e-15);
    EXPECT_NEAR(glm::length(up - glm::dvec3(1, 0, 0)), 0, 1e-15);
    const ViewProjection vp = frameCamera(orthographicCamera(fromGlm(dir)), bounds, 30, 20);
    expectOrthographicFrame(vp, bounds, right, up);
    // Straight up: right = normalize((0,1,0) x (1,0,0)) = (0, 0, -1), up = (1, 0, 0).
    const ViewProjection vp_up = frameCamera(orthographicCamera({0, 2, 0}), bounds, 30, 20);
    expectOrthographicFrame(vp_up, bounds, {0, 0, -1}, {1, 0, 0});
}

TEST(CameraOrthographic, GeneralDirections) {
    const Bounds bounds = boxBounds({-1, 2, -3}, {2, 4, 1});
    for (const glm::dvec3 raw : {glm::dvec3(1, -0.5, -2), glm::dvec3(0.3, -0.95, 0.1),
                                 glm::dvec3(-0.2, 3, 0.1), glm::dvec3(5, 0, 0)}) {
        const glm::dvec3 dir = glm::normalize(raw);
        const glm::dvec3 up0 = std::abs(dir.y) > 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
        const glm::dvec3 right = glm::normalize(glm::cross(dir, up0));
        const glm::dvec3 up = glm::cross(right, dir);
        const ViewProjection vp = frameCamera(orthographicCamera(fromGlm(raw)), bounds, 40, 25);
        EXPECT_NEAR(glm::length(toGlm(vp.forward) - dir), 0, 1e-12);
        expectOrthographicFrame(vp, bounds, right, up);
    }
}

TEST(CameraOrthographic, DepthEnclosesSphereAndIsLinear) {
    const Bounds bounds = boxBounds({-1, 2, -3}, {2, 4, 1});
    const glm::dvec3 c = toGlm(bounds.centre());
    const double r = bounds.radius();
    for (const glm::dvec3 raw :
         {glm::dvec3(0, 0, -1), glm::dvec3(1, -0.5, -2), glm::dvec3(0, -1, 0)}) {
        const glm::dvec3 dir = glm::normalize(raw);
        const ViewProjection vp = frameCamera(orthographicCamera(fromGlm(raw)), bounds, 32, 32);
        EXPECT_LT(vp.near, vp.far);
        for (const Vec3& p : spherePoints(bounds.centre(), r)) {
            const double d = vp.depthOf(p);
            EXPECT_GE(d, 0.0);
            EXPECT_LE(d, 1.0);
            const auto clip = vp.toClip(p);
            EXPECT_NEAR(clip[2] / clip[3], d, 1e-12);
        }
        // The nearest and farthest points of the sphere are strictly inside.
        EXPECT_GT(vp.depthOf(fromGlm(c - r * dir)), 0.0);
        EXPECT_LT(vp.depthOf(fromGlm(c + r * dir)), 1.0);
        // d = (z - near) / (far - near), with z the distance along dir.
        const double d_centre = vp.depthOf(fromGlm(c));
        const glm::dvec3 lateral = glm::normalize(glm::cross(dir, glm::dvec3(0.3, 0.7, 0.2)));
        for (double t : {-1.5, -1.0, -0.3, 0.0, 0.4, 1.0, 1.5}) {
            const double expected = d_centre + t * r / (vp.far - vp.near);
            EXPECT_NEAR(vp.depthOf(fromGlm(c + t * r * dir)), expected, 1e-12);
            // Moving sideways changes nothing.
            EXPECT_NEAR(vp.depthOf(fromGlm(c + t * r * dir + 0.7 * r * lateral)), expected, 1e-12);
        }
        // Along a pixel's ray, depth grows by 1 over the distance far - near.
        Vec3 origin, direction;
        vp.pixelRay(16, 16, origin, direction);
        const double d_origin = vp.depthOf(origin);
        for (double s : {0.5, 1.0, 2.0, 3.0})
            EXPECT_NEAR(vp.depthOf(fromGlm(toGlm(origin) + s * r * toGlm(direction))),
                        d_origin + s * r / (vp.far - vp.near), 1e-12);
    }
}

// ---------------------------------------------------------------------------------------------
// validateCamera

TEST(CameraValidate, RejectsDegenerateCameras) {
    const CameraSpec good = perspectiveCamera({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 45);
    EXPECT_EQ(validateCamera(good).error, "");
    EXPECT_EQ(validateCamera(CameraSpec{}).error, "");
    EXPECT_EQ(validateCamera(perspectiveCamera({1, 2, 3}, {-1, 0.5, 2}, {0.2, 3, 0}, 179.5)).error,
              "");
    EXPECT_EQ(validateCamera(perspectiveCamera({1, 2, 3}, {-1, 0.5, 2}, {0, 1, 0}, 0.5)).error, "");

    const double nan = std::nan(""), inf = INFINITY;
    std::vector<CameraSpec> bad;
    bad.push_back(perspectiveCamera({1, 2, 3}, {1, 2, 3}, {0, 1, 0}, 45));  // eye == target
    bad.push_back(perspectiveCamera({0, 0, 5}, {0, 0, 0}, {0, 0, 0}, 45));  // zero up
    bad.push_back(perspectiveCamera({0, 0, 5}, {0, 0, 0}, {0, 0, -3}, 45)); // up along the view
    bad.push_back(perspectiveCamera({0, 0, 5}, {0, 0, 0}, {0, 0, 2}, 45));  // up against the view
    bad.push_back(perspectiveCamera({1, 1, 1}, {0, 0, 0}, {2, 2, 2}, 45));  // parallel, diagonal
    bad.push_back(perspectiveCamera({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 0));
    bad.push_back(perspectiveCamera({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 180));
    bad.push_back(perspectiveCamera({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, -30));
    bad.push_back(perspectiveCamera({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, nan));
    bad.push_back(perspectiveCamera({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, inf));
    bad.push_back(perspectiveCamera({inf, 0, 5}, {0, 0, 0}, {0, 1, 0}, 45));
    bad.push_back(perspectiveCamera({0, nan, 5}, {0, 0, 0}, {0, 1, 0}, 45));
    bad.push_back(perspectiveCamera({0, 0, 5}, {0, 0, nan}, {0, 1, 0}, 45));
    bad.push_back(perspectiveCamera({0, 0, 5}, {0, 0, 0}, {0, -inf, 0}, 45));
    bad.push_back(orthographicCamera({0, 0, 0}));
    bad.push_back(orthographicCamera({nan, 0, -1}));
    bad.push_back(orthographicCamera({0, inf, -1}));
    for (std::size_t i = 0; i < bad.size(); ++i) {
        const std::string message = validateCamera(bad[i]).error;
        EXPECT_FALSE(message.empty()) << "camera " << i;
        EXPECT_EQ(message.find('\n'), std::string::npos) << "camera " << i;
    }

    EXPECT_EQ(validateCamera(orthographicCamera({0, 0, -1})).error, "");
    EXPECT_EQ(validateCamera(orthographicCamera({0, -1, 0})).error, "");
    EXPECT_EQ(validateCamera(orthographicCamera({1e-3, 2, -7})).error, "");
}

// ---------------------------------------------------------------------------------------------
// defaultCamera

TEST(CameraDefault, FramesTheWholeBoundingSphere) {
    const Bounds scenes[] = {
        boxBounds({-1, -1, -1}, {1, 1, 1}),
        boxBounds({10, -3, 100}, {14, 5, 101}), // off the origin, flat
        boxBounds({0, 0, 0}, {1e-3, 50, 2e-3}), // a thin needle
        boxBounds({2, 3, 4}, {2, 3, 4}),        // a single point (radius 0)
    };
    for (const Bounds& bounds : scenes) {
        const CameraSpec camera = defaultCamera(bounds);
        EXPECT_EQ(camera.projection, Projection::perspective);
        EXPECT_EQ(camera.fov_degrees, 45.0);
        EXPECT_EQ(validateCamera(camera).error, "");
        const glm::dvec3 c = toGlm(bounds.centre());
        EXPECT_NEAR(glm::length(toGlm(camera.target) - c), 0.0, 1e-12);
        EXPECT_EQ(camera.up.x, 0);
        EXPECT_EQ(camera.up.y, 1);
        EXPECT_EQ(camera.up.z, 0);
        // The eye sits in the direction (0.6, 0.5, 1) from the centre, outside the sphere.
        const glm::dvec3 offset = toGlm(camera.eye) - c;
        const double r = bounds.radius() > 0 ? bounds.radius() : 1.0;
        EXPECT_NEAR(glm::length(glm::normalize(offset) - glm::normalize(glm::dvec3(0.6, 0.5, 1))),
                    0, 1e-12);
        EXPECT_GT(glm::length(offset), r);

        for (auto [w, h] : {std::pair<uint32_t, uint32_t>{1024, 1024}, {640, 480}, {64, 64}}) {
            const ViewProjection vp = frameCamera(camera, bounds, w, h);
            std::vector<Vec3> points = boxCorners(bounds);
            if (bounds.radius() > 0) {
                const auto sphere = spherePoints(bounds.centre(), bounds.radius());
                points.insert(points.end(), sphere.begin(), sphere.end());
            }
            for (const Vec3& p : points) {
                const auto clip = vp.toClip(p);
                ASSERT_GT(clip[3], 0.0);
                const Ndc ndc = toNdc(vp, p);
                EXPECT_GE(ndc.x, -1.0);
                EXPECT_LE(ndc.x, 1.0);
                EXPECT_GE(ndc.y, -1.0);
                EXPECT_LE(ndc.y, 1.0);
                EXPECT_GE(ndc.d, 0.0);
                EXPECT_LT(ndc.d, 1.0);
                EXPECT_NEAR(vp.depthOf(p), ndc.d, 1e-12);
            }
        }
    }
}

TEST(CameraDefault, SinglePointIsInTheMiddle) {
    const Bounds bounds = boxBounds({2, 3, 4}, {2, 3, 4});
    const ViewProjection vp = frameCamera(defaultCamera(bounds), bounds, 33, 33);
    const Ndc ndc = toNdc(vp, {2, 3, 4});
    EXPECT_NEAR(ndc.x, 0.0, 1e-12);
    EXPECT_NEAR(ndc.y, 0.0, 1e-12);
    EXPECT_GT(ndc.d, 0.0);
    EXPECT_LT(ndc.d, 1.0);
}

} // namespace
} // namespace vissort

namespace vissort {
namespace {

// A portrait image is narrower than it is tall: the sphere must fit the horizontal field.
TEST(CameraDefault, PortraitImageStillFitsTheSphere) {
    Bounds bounds;
    bounds.add({-1, -1, -1});
    bounds.add({1, 1, 1});
    const uint32_t width = 480, height = 640;
    const CameraSpec camera = defaultCamera(bounds, double(width) / height);
    const ViewProjection view = frameCamera(camera, bounds, width, height);
    for (int i = 0; i < 8; ++i) {
        const Vec3 corner{(i & 1) ? 1.0 : -1.0, (i & 2) ? 1.0 : -1.0, (i & 4) ? 1.0 : -1.0};
        const auto clip = view.toClip(corner);
        EXPECT_LE(std::abs(clip[0] / clip[3]), 1.0) << "corner " << i;
        EXPECT_LE(std::abs(clip[1] / clip[3]), 1.0) << "corner " << i;
    }
}

} // namespace
} // namespace vissort

// ---------------------------------------------------------------------------------------------
// framingCamera

namespace vissort {
namespace {

// The largest |NDC x| and |NDC y| over the points, checking each is in front of the eye.
std::pair<double, double> ndcExtent(const CameraSpec& camera, std::span<const Vec3> points,
                                    uint32_t width, uint32_t height) {
    Bounds bounds;
    for (const Vec3& p : points)
        bounds.add(p);
    const ViewProjection vp = frameCamera(camera, bounds, width, height);
    double max_x = 0, max_y = 0;
    for (const Vec3& p : points) {
        const Ndc ndc = toNdc(vp, p);
        EXPECT_GT(vp.toClip(p)[3], 0.0);
        EXPECT_GE(ndc.d, 0.0);
        EXPECT_LT(ndc.d, 1.0);
        max_x = std::max(max_x, std::abs(ndc.x));
        max_y = std::max(max_y, std::abs(ndc.y));
    }
    return {max_x, max_y};
}

// Every point inside the 5% margin, and the binding extent on it: tighter than the sphere.
TEST(CameraFraming, FitsThePointsWithAFivePercentMargin) {
    const std::vector<std::vector<Vec3>> shapes = {
        spherePoints({0, 0, 0}, 1.0),
        spherePoints({10, -3, 100}, 0.5),
        {{0, 0, 0}, {4, 0, 0}, {0, 1, 0}, {4, 1, 0.5}}, // a flat wide quad
        {{-1, -1, -1}, {1, -1, -1}, {0, 2, 1}},         // one triangle
    };
    for (std::size_t s = 0; s < shapes.size(); ++s)
        for (auto [w, h] : {std::pair<uint32_t, uint32_t>{1024, 1024}, {640, 480}, {480, 640}}) {
            const CameraSpec camera = framingCamera(shapes[s], double(w) / h);
            EXPECT_EQ(validateCamera(camera).error, "");
            EXPECT_EQ(camera.fov_degrees, 45.0);
            const auto [x, y] = ndcExtent(camera, shapes[s], w, h);
            EXPECT_LE(x, 0.95 + 1e-9) << "shape " << s << ' ' << w << 'x' << h;
            EXPECT_LE(y, 0.95 + 1e-9) << "shape " << s << ' ' << w << 'x' << h;
            EXPECT_NEAR(std::max(x, y), 0.95, 1e-9) << "shape " << s << ' ' << w << 'x' << h;
            // The eye looks from (0.6, 0.5, 1).
            const glm::dvec3 view = toGlm(camera.eye) - toGlm(camera.target);
            EXPECT_NEAR(glm::length(glm::normalize(view) - glm::normalize(glm::dvec3(0.6, 0.5, 1))),
                        0, 1e-12);
        }
}

// The box of the points' projections in NDC, through camera over their bounds.
struct NdcBox {
    double lo_x = 1, hi_x = -1, lo_y = 1, hi_y = -1;
};
NdcBox ndcBox(const CameraSpec& camera, std::span<const Vec3> points, uint32_t size) {
    Bounds bounds;
    for (const Vec3& p : points)
        bounds.add(p);
    const ViewProjection vp = frameCamera(camera, bounds, size, size);
    NdcBox box;
    for (const Vec3& p : points) {
        const Ndc ndc = toNdc(vp, p);
        box.lo_x = std::min(box.lo_x, ndc.x);
        box.hi_x = std::max(box.hi_x, ndc.x);
        box.lo_y = std::min(box.lo_y, ndc.y);
        box.hi_y = std::max(box.hi_y, ndc.y);
    }
    return box;
}

// The share of the picture the points' projections span: (max - min) of x times that of y / 4.
double filledFraction(const CameraSpec& camera, std::span<const Vec3> points) {
    const NdcBox box = ndcBox(camera, points, 512);
    return (box.hi_x - box.lo_x) * (box.hi_y - box.lo_y) / 4;
}

// The bounding sphere's framing leaves a round model (a sphere of points) and a long flat one
// small in the picture; the points' framing fills more of it.
TEST(CameraFraming, IsTighterThanTheBoundingSphere) {
    const std::vector<Vec3> quad = {{0, 0, 0}, {4, 0, 0}, {0, 1, 0}, {4, 1, 0}};
    const std::vector<Vec3> ball = spherePoints({1, 2, 3}, 2.0);
    for (const std::vector<Vec3>& points : {quad, ball}) {
        Bounds bounds;
        for (const Vec3& p : points)
            bounds.add(p);
        const double sphere = filledFraction(defaultCamera(bounds), points);
        const double tight = filledFraction(framingCamera(points), points);
        EXPECT_GT(tight, sphere * 1.2) << sphere << " " << tight;
    }
}

// The extent that does not bind is centred: the same margin on both sides.
TEST(CameraFraming, CentresThePicture) {
    const std::vector<Vec3> points = {{0, 0, 0}, {3, 0, 0}, {3, 0.2, 0}, {0, 0.2, 0}};
    const NdcBox box = ndcBox(framingCamera(points, 1.0), points, 256);
    EXPECT_NEAR(box.lo_x + box.hi_x, 0.0, 1e-9);
    EXPECT_NEAR(box.lo_y + box.hi_y, 0.0, 1e-9);
}

// A needle seen end-on, a single point, no points: the eye stays outside the bounding sphere
// and the camera is usable.
TEST(CameraFraming, DegenerateShapesKeepTheEyeOutside) {
    const glm::dvec3 d = glm::normalize(glm::dvec3(0.6, 0.5, 1));
    const std::vector<Vec3> needle = {{0, 0, 0}, fromGlm(d * 10.0)};
    const std::vector<Vec3> point = {{2, 3, 4}};
    for (const std::vector<Vec3>& points : {needle, point, std::vector<Vec3>{}}) {
        const CameraSpec camera = framingCamera(points, 1.0);
        EXPECT_EQ(validateCamera(camera).error, "");
        Bounds bounds;
        for (const Vec3& p : points)
            bounds.add(p);
        const double r = bounds.isEmpty() || bounds.radius() == 0 ? 1.0 : bounds.radius();
        const glm::dvec3 centre = bounds.isEmpty() ? glm::dvec3(0) : toGlm(bounds.centre());
        EXPECT_GE(glm::length(toGlm(camera.eye) - centre), 1.1 * r - 1e-9);
        if (!points.empty())
            ndcExtent(camera, points, 64, 64);
    }
}

// The same points give the same camera, bit for bit, whichever container holds them.
TEST(CameraFraming, PositionsAndPointsAgree) {
    TrianglePositions positions;
    positions.x = {0, 1, 0, 2, 3, 2};
    positions.y = {0, 0, 1, 5, 5, 6};
    positions.z = {0, 0, 0, -1, -1, -2};
    std::vector<Vec3> points;
    for (std::size_t i = 0; i < positions.x.size(); ++i)
        points.push_back(positions.view().corner(i));
    const CameraSpec a = framingCamera(positions, 1.5), b = framingCamera(points, 1.5);
    EXPECT_TRUE(toGlm(a.eye) == toGlm(b.eye));
    EXPECT_TRUE(toGlm(a.target) == toGlm(b.target));
}

} // namespace
} // namespace vissort

namespace vissort {
namespace {

TEST(ImageSize, LimitsEachSideAndThePixelCount) {
    EXPECT_TRUE(validateImageSize(1, 1));
    EXPECT_TRUE(validateImageSize(kMaxImageSide, kMaxImagePixels / kMaxImageSide));
    EXPECT_FALSE(validateImageSize(0, 10));
    EXPECT_FALSE(validateImageSize(10, 0));
    EXPECT_FALSE(validateImageSize(kMaxImageSide + 1, 1));
    const Status too_many = validateImageSize(kMaxImageSide, kMaxImageSide);
    ASSERT_FALSE(too_many);
    EXPECT_EQ(too_many.error,
              "16384x16384 is out of range: each side 1..16384, at most 67108864 pixels");
}

} // namespace
} // namespace vissort

namespace vissort {
namespace {

TEST(DescribeCamera, OneLineWithFourDigits) {
    CameraSpec camera;
    camera.eye = {1.23456, 2, -3};
    camera.target = {0, 0.5, 0};
    camera.fov_degrees = 47.51234;
    EXPECT_EQ(describeCamera(camera),
              "perspective from 1.235,2,-3 towards 0,0.5,0, up 0,1,0, fov 47.51 degrees");
    camera.projection = Projection::orthographic;
    camera.ortho_direction = {0, 0, -1};
    EXPECT_EQ(describeCamera(camera), "orthographic along 0,0,-1");
}

} // namespace
} // namespace vissort
