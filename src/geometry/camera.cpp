#include "vissort/camera.h"

#include "geometry/pixel_rays.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

namespace vissort {
namespace {

glm::dvec3 toGlm(const Vec3& v) {
    return {v.x, v.y, v.z};
}
Vec3 fromGlm(const glm::dvec3& v) {
    return {v.x, v.y, v.z};
}

glm::dmat4 toMat(const std::array<double, 16>& m) {
    return glm::make_mat4(m.data());
}

std::array<double, 16> fromMat(const glm::dmat4& m) {
    std::array<double, 16> out{};
    const double* p = glm::value_ptr(m);
    std::copy(p, p + 16, out.begin());
    return out;
}

// Beyond this, squared lengths overflow and the camera maths gives no meaningful answer.
constexpr double kMaxCoordinate = 1e30;

bool isFinite(const Vec3& v) {
    return std::abs(v.x) <= kMaxCoordinate && std::abs(v.y) <= kMaxCoordinate &&
           std::abs(v.z) <= kMaxCoordinate;
}

// The default view direction, from the target towards the eye.
glm::dvec3 defaultViewDirection() {
    return glm::normalize(glm::dvec3(0.6, 0.5, 1.0));
}

// A sphere of radius 0 (one point) still gets a usable frame.
double framingRadius(const Bounds& b) {
    return b.radius() > 0 ? b.radius() : 1.0;
}

} // namespace

static std::string cameraProblem(const CameraSpec& camera) {
    if (camera.projection == Projection::orthographic) {
        if (!isFinite(camera.ortho_direction))
            return "orthographic direction must be finite and below 1e30";
        if (glm::length(toGlm(camera.ortho_direction)) < 1e-12)
            return "orthographic direction is zero";
        return {};
    }
    if (!isFinite(camera.eye) || !isFinite(camera.target) || !isFinite(camera.up))
        return "camera eye, target and up must be finite and below 1e30";
    if (!(camera.fov_degrees > 0 && camera.fov_degrees < 180))
        return "field of view must be between 0 and 180 degrees (exclusive)";
    const glm::dvec3 forward = toGlm(camera.target) - toGlm(camera.eye);
    if (glm::length(forward) < 1e-12)
        return "camera eye and target coincide";
    const glm::dvec3 up = toGlm(camera.up);
    if (glm::length(up) < 1e-12)
        return "camera up vector is zero";
    if (glm::length(glm::cross(glm::normalize(forward), glm::normalize(up))) < 1e-9)
        return "camera up vector is parallel to the view direction";
    return {};
}

CameraSpec defaultCamera(const Bounds& scene_bounds, double aspect) {
    CameraSpec camera;
    camera.projection = Projection::perspective;
    camera.fov_degrees = 45.0;
    const glm::dvec3 centre = toGlm(scene_bounds.centre());
    const double r = framingRadius(scene_bounds);
    // Far enough that the bounding sphere fits in the narrower of the two fields of view.
    const double half_vertical = glm::radians(camera.fov_degrees) / 2;
    const double half_horizontal = std::atan(std::tan(half_vertical) * (aspect > 0 ? aspect : 1.0));
    const double distance = r / std::sin(std::min(half_vertical, half_horizontal)) * 1.05;
    camera.eye = fromGlm(centre + defaultViewDirection() * distance);
    camera.target = fromGlm(centre);
    camera.up = {0, 1, 0};
    return camera;
}

namespace {

// framingCamera over corner(0..count-1). In the camera's frame (right, up, and d towards the
// eye), a point (x, y, z) relative to the box centre is inside the margin when
// |x - sx| <= tx (D - z) and |y - sy| <= ty (D - z), for an eye D along d and a target shifted
// by (sx, sy). Per axis the two sides give D >= A - sx / tx and D >= B + sx / tx with
// A = max(x / tx + z), B = max(-x / tx + z): the least D is (A + B) / 2, at sx = tx (A - B) / 2,
// where both sides touch the margin. The axis that does not bind is then centred (centredShift).

// The shift s in [lo, hi] of a non-binding axis that centres the picture: the largest and the
// smallest slope (x - s) / (D - z) over the points are opposite. Each slope is a line in s, so
// g(s) = largest + smallest decreases, piecewise linear: Newton's step on the two lines active
// at s lands on the root as soon as they are the ones active there (a few passes over the
// points), with a bisection of the bracket whenever the step leaves it.
template <typename Local>
double centredShift(std::size_t count, const Local& local, int axis, double distance, double lo,
                    double hi) {
    double s = (lo + hi) / 2;
    for (int pass = 0; pass < 200 && lo < hi; ++pass) {
        double most = -INFINITY, least = INFINITY;
        double most_x = 0, most_depth = 1, least_x = 0, least_depth = 1;
        for (std::size_t i = 0; i < count; ++i) {
            const glm::dvec3 p = local(i);
            const double depth = distance - p.z, slope = (p[axis] - s) / depth;
            if (slope > most) {
                most = slope;
                most_x = p[axis];
                most_depth = depth;
            }
            if (slope < least) {
                least = slope;
                least_x = p[axis];
                least_depth = depth;
            }
        }
        const double g = most + least;
        if (g == 0)
            return s;
        (g > 0 ? lo : hi) = s;
        // Where (most_x - s) / most_depth + (least_x - s) / least_depth = 0.
        const double next =
            (most_x / most_depth + least_x / least_depth) / (1 / most_depth + 1 / least_depth);
        if (next == s)
            return s;
        s = next > lo && next < hi ? next : (lo + hi) / 2;
    }
    return s;
}

template <typename Corner>
CameraSpec framePoints(std::size_t count, Corner corner, double aspect,
                       const CameraSpec& orientation) {
    Bounds bounds;
    for (std::size_t i = 0; i < count; ++i)
        bounds.add(corner(i));
    if (bounds.isEmpty())
        return defaultCamera(Bounds{{-1, -1, -1}, {1, 1, 1}}, aspect);
    const bool usable = orientation.projection == Projection::perspective &&
                        validateCamera(orientation).error.empty();
    CameraSpec camera = usable ? orientation : defaultOrientation();
    const glm::dvec3 centre = toGlm(bounds.centre());
    const glm::dvec3 towards_eye = glm::normalize(toGlm(camera.eye) - toGlm(camera.target));
    const glm::dvec3 right = glm::normalize(glm::cross(-towards_eye, toGlm(camera.up)));
    const glm::dvec3 up = glm::cross(right, -towards_eye);
    const auto local = [&](std::size_t i) {
        const glm::dvec3 p = toGlm(corner(i)) - centre;
        return glm::dvec3(glm::dot(p, right), glm::dot(p, up), glm::dot(p, towards_eye));
    };
    constexpr double kMargin = 0.05;
    const double ty = std::tan(glm::radians(camera.fov_degrees) / 2) * (1 - kMargin);
    const double t[2] = {ty * (aspect > 0 ? aspect : 1.0), ty};
    double a[2] = {-INFINITY, -INFINITY}, b[2] = {-INFINITY, -INFINITY};
    for (std::size_t i = 0; i < count; ++i) {
        const glm::dvec3 p = local(i);
        for (int axis = 0; axis < 2; ++axis) {
            a[axis] = std::max(a[axis], p[axis] / t[axis] + p.z);
            b[axis] = std::max(b[axis], -p[axis] / t[axis] + p.z);
        }
    }
    const double distance =
        std::max({(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, 1.1 * framingRadius(bounds)});
    double shift[2];
    for (int axis = 0; axis < 2; ++axis) {
        shift[axis] = t[axis] * (a[axis] - b[axis]) / 2;
        if ((a[axis] + b[axis]) / 2 == distance)
            continue; // this axis binds: both sides already on the margin
        shift[axis] = centredShift(count, local, axis, distance, t[axis] * (a[axis] - distance),
                                   t[axis] * (distance - b[axis]));
    }
    const glm::dvec3 target = centre + right * shift[0] + up * shift[1];
    camera.target = fromGlm(target);
    camera.eye = fromGlm(target + towards_eye * distance);
    return camera;
}

} // namespace

CameraSpec defaultOrientation() {
    CameraSpec camera;
    camera.projection = Projection::perspective;
    camera.fov_degrees = 45.0;
    camera.target = {0, 0, 0};
    camera.eye = fromGlm(defaultViewDirection());
    camera.up = {0, 1, 0};
    return camera;
}

CameraSpec orbitOrientation(double azimuth_degrees, double elevation_degrees) {
    const double az = glm::radians(azimuth_degrees), el = glm::radians(elevation_degrees);
    CameraSpec camera = defaultOrientation();
    camera.eye = {std::sin(az) * std::cos(el), std::sin(el), std::cos(az) * std::cos(el)};
    camera.up = {-std::sin(el) * std::sin(az), std::cos(el), -std::sin(el) * std::cos(az)};
    return camera;
}

CameraSpec framingCamera(std::span<const Vec3> points, double aspect,
                         const CameraSpec& orientation) {
    return framePoints(
        points.size(), [&](std::size_t i) { return points[i]; }, aspect, orientation);
}

CameraSpec framingCamera(PositionsView positions, double aspect, const CameraSpec& orientation) {
    return framePoints(
        positions.x.size(), [&](std::size_t i) { return positions.corner(i); }, aspect,
        orientation);
}

ViewProjection frameCamera(const CameraSpec& camera, const Bounds& scene_bounds, uint32_t width,
                           uint32_t height) {
    ViewProjection vp;
    vp.projection = camera.projection;
    vp.width = std::max<uint32_t>(width, 1);
    vp.height = std::max<uint32_t>(height, 1);
    const double aspect = double(vp.width) / double(vp.height);
    const glm::dvec3 centre = toGlm(scene_bounds.centre());
    const double r = framingRadius(scene_bounds);

    glm::dmat4 view, projection(0.0);
    if (camera.projection == Projection::perspective) {
        const glm::dvec3 eye = toGlm(camera.eye);
        view = glm::lookAt(eye, toGlm(camera.target), toGlm(camera.up));
        const double distance = glm::length(eye - centre);
        vp.near = std::max(distance - r, r * 1e-3) * 0.99;
        vp.far = INFINITY;
        const glm::dmat4 gl = glm::perspective(glm::radians(camera.fov_degrees), aspect, 1.0, 2.0);
        projection[0][0] = gl[0][0];
        projection[1][1] = gl[1][1];
        // z_clip = z - near and w_clip = z, with z = -z_eye the distance along the view
        // direction: z_clip / w_clip = 1 - near / z.
        projection[2][2] = -1.0;
        projection[3][2] = -vp.near;
        projection[2][3] = -1.0;
        vp.eye_position = camera.eye;
        vp.forward = fromGlm(glm::normalize(toGlm(camera.target) - eye));
    } else {
        const glm::dvec3 dir = glm::normalize(toGlm(camera.ortho_direction));
        const glm::dvec3 up0 = std::abs(dir.y) > 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
        const glm::dvec3 right = glm::normalize(glm::cross(dir, up0));
        const glm::dvec3 up = glm::cross(right, dir);
        const glm::dvec3 eye = centre - dir * (2.0 * r);
        view = glm::lookAt(eye, centre, up);
        // The sphere spans distances [r, 3r] from the eye; keep a margin on both sides.
        vp.near = 0.5 * r;
        vp.far = 3.5 * r;
        projection[0][0] = 1.0 / (r * aspect);
        projection[1][1] = 1.0 / r;
        projection[2][2] = -1.0 / (vp.far - vp.near);
        projection[3][2] = -vp.near / (vp.far - vp.near);
        projection[3][3] = 1.0;
        vp.eye_position = fromGlm(eye);
        vp.forward = fromGlm(dir);
    }
    vp.view = fromMat(view);
    vp.projection_matrix = fromMat(projection);
    return vp;
}

std::array<double, 4> ViewProjection::toClip(const Vec3& world) const {
    const glm::dvec4 clip = toMat(projection_matrix) * toMat(view) * glm::dvec4(toGlm(world), 1.0);
    return {clip.x, clip.y, clip.z, clip.w};
}

bool boxOutsideView(const Bounds& box, const ViewProjection& view) {
    if (box.isEmpty())
        return true;
    const glm::dmat4 clip = toMat(view.projection_matrix) * toMat(view.view);
    glm::dvec4 corners[8];
    for (unsigned i = 0; i < 8; ++i)
        corners[i] = clip * glm::dvec4(toGlm(box.corner(i)), 1.0);
    // Inside each plane: w - x, w + x, w - y, w + y, z all >= 0.
    const auto outside = [&](auto distance) {
        for (const glm::dvec4& c : corners)
            if (distance(c) >=
                -1e-5 * (std::abs(c.x) + std::abs(c.y) + std::abs(c.z) + std::abs(c.w)))
                return false;
        return true;
    };
    return outside([](const glm::dvec4& c) { return c.w - c.x; }) ||
           outside([](const glm::dvec4& c) { return c.w + c.x; }) ||
           outside([](const glm::dvec4& c) { return c.w - c.y; }) ||
           outside([](const glm::dvec4& c) { return c.w + c.y; }) ||
           outside([](const glm::dvec4& c) { return c.z; });
}

double ViewProjection::depthOf(const Vec3& world) const {
    const double z = -(toMat(view) * glm::dvec4(toGlm(world), 1.0)).z;
    if (projection == Projection::perspective)
        return 1.0 - near / z;
    return (z - near) / (far - near);
}

void ViewProjection::pixelRay(double px, double py, Vec3& origin, Vec3& direction) const {
    const detail::PixelRay ray = detail::PixelRays(*this).at(px, py);
    origin = ray.origin;
    direction = ray.direction;
}

Status validateCamera(const CameraSpec& camera) {
    return Status{cameraProblem(camera)};
}

Status validateImageSize(uint64_t width, uint64_t height) {
    if (width == 0 || height == 0 || width > kMaxImageSide || height > kMaxImageSide ||
        width * height > kMaxImagePixels)
        return Status::failure(std::to_string(width) + "x" + std::to_string(height) +
                               " is out of range: each side 1.." + std::to_string(kMaxImageSide) +
                               ", at most " + std::to_string(kMaxImagePixels) + " pixels");
    return Status::ok();
}

namespace {

std::string point(const Vec3& p) {
    std::ostringstream text;
    text << std::setprecision(4) << p.x << ',' << p.y << ',' << p.z;
    return text.str();
}

} // namespace

std::string describeCamera(const CameraSpec& camera) {
    if (camera.projection == Projection::orthographic)
        return "orthographic along " + point(camera.ortho_direction);
    std::ostringstream fov;
    fov << std::setprecision(4) << camera.fov_degrees;
    return "perspective from " + point(camera.eye) + " towards " + point(camera.target) + ", up " +
           point(camera.up) + ", fov " + fov.str() + " degrees";
}

} // namespace vissort
