// The exact fragment model evaluated by OpenGL with error bounds (bounded_fragments.h).
//
// This work is based on: Jonathan Richard Shewchuk. Adaptive Precision Floating-Point Arithmetic
// and Fast Robust Geometric Predicates. Discrete & Computational Geometry 18(3):305-363, 1997
// (a determinant's sign settled by a floating-point evaluation and a bound on its error, as
// geometry/exact_fragments.cpp does on the CPU; here nothing follows when the bound cannot
// settle it: the fragment is kept), and on Jon Hasselgren, Tomas Akenine-Moeller, Lennart
// Ohlsson. Conservative Rasterization. GPU Gems 2, chapter 42, 2005 (a triangle's edges pushed
// out, or its bounding box, so that rasterization covers every pixel the triangle could).
//
// Number formats: corners are IEEE binary32 and read exactly; every shader computation that
// decides is binary64 (GLSL 4.50 doubles), the ray as PixelRays computes it. The driver may
// round in other orders than the CPU (fused multiply-adds, a division a few units off), so
// every bound assumes 2^-46 per operation where IEEE gives 2^-53, and the ray's direction and
// origin carry a slack for their difference from the CPU's (setView). The coverage polygon is
// rasterized from float positions with the driver's sub-pixel snapping (GL_SUBPIXEL_BITS: 8 on
// Mesa and the GPUs, at least 4): pushed out by twice what both can move an edge (setView).

#include "gl/bounded_fragments.h"

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "gl/gl_program.h"

namespace vissort::detail {
namespace {

// The corners pass through unchanged: the geometry shader sees all three of a triangle.
constexpr const char* kVertexShader = R"(#version 450 core
layout(location = 0) in float x;
layout(location = 1) in float y;
layout(location = 2) in float z;
out vec3 world;
void main() {
    world = vec3(x, y, z);
}
)";

// Per triangle: culls what can have no fragment (a non-finite or repeated corner, or all of it
// certainly before the near plane or, orthographic, beyond the far one), bounds the depth of any
// fragment it can have by its corners' (a fragment lies in the triangle), and emits a polygon
// covering every pixel centre of the viewport the model could give it: the triangle with its
// edges pushed out by coverage_margin pixels, or its bounding box grown by the margin and cut to
// the viewport where that is smaller (slivers, whose pushed-out corners go far) or where the
// triangle is not surely in front of the eye or reaches far off-screen (where float positions
// would lose the margin). A triangle crossing the plane at half the near distance is boxed by
// its part beyond that plane (its fragments are beyond the near plane). The polygon's z is 0.5
// (never clipped); the fragment shader writes the depth.
constexpr const char* kGeometryShader = R"(#version 450 core
layout(triangles) in;
layout(triangle_strip, max_vertices = 4) out;
in vec3 world[];
flat out vec3 corner_a;
flat out vec3 corner_b;
flat out vec3 corner_c;
flat out vec2 depth_keys; // bounds of the depth of any fragment of the triangle: [lower, upper]
uniform dmat4 view_projection;
uniform dvec4 view_row; // the view matrix's third row: eye-space z = row . (x, y, z, 1)
uniform double near_plane;
uniform double far_plane;
uniform int orthographic;
uniform dvec2 viewport;
uniform double coverage_margin; // pixels: more than float positions and snapping move an edge

const double kStep = 1.0e-14lf;    // one operation's relative rounding, with margin
const double kLargest = 16.0lf;    // farthest normalized device coordinate drawn as such
const double kSmallest = 1.0e-30lf;

// x rounded down (up) to a float in [0, 1]: the depth bounds stay bounds.
float floatBelow(double x) {
    if (x <= kSmallest)
        return 0.0;
    float f = float(x);
    if (double(f) > x)
        f = uintBitsToFloat(floatBitsToUint(f) - 1u);
    return f;
}
float floatAbove(double x) {
    if (x >= 1.0lf)
        return 1.0;
    if (x <= kSmallest)
        return 1.0e-29;
    float f = float(x);
    if (double(f) < x)
        f = uintBitsToFloat(floatBitsToUint(f) + 1u);
    return f;
}

double depthOf(double z) {
    return orthographic != 0 ? (z - near_plane) / (far_plane - near_plane)
                             : 1.0lf - near_plane / z;
}

bool finite(vec3 v) {
    uvec3 exponent = floatBitsToUint(v) & 0x7f800000u;
    return all(notEqual(exponent, uvec3(0x7f800000u)));
}

double cross2(dvec2 p, dvec2 q) {
    return p.x * q.y - p.y * q.x;
}

void emitCorner(dvec2 pixel, vec2 keys) {
    corner_a = world[0];
    corner_b = world[1];
    corner_c = world[2];
    depth_keys = keys;
    gl_Position = vec4(float(2.0lf * pixel.x / viewport.x - 1.0lf),
                       float(1.0lf - 2.0lf * pixel.y / viewport.y), 0.5, 1.0);
    EmitVertex();
}

void emitBox(dvec2 low, dvec2 high, vec2 keys) {
    emitCorner(low, keys);
    emitCorner(dvec2(high.x, low.y), keys);
    emitCorner(dvec2(low.x, high.y), keys);
    emitCorner(high, keys);
    EndPrimitive();
}

// Where the point projects, in pixels from the top-left corner of the viewport; false when it is
// not surely in front of the eye.
bool project(dvec3 p, out dvec2 pixel) {
    dvec4 clip = view_projection * dvec4(p, 1.0lf);
    dvec2 ndc = clip.xy / clip.w;
    pixel = dvec2((ndc.x + 1.0lf) * 0.5lf * viewport.x, (1.0lf - ndc.y) * 0.5lf * viewport.y);
    return clip.w > 0.0lf && !any(isnan(pixel)) && !any(isinf(pixel));
}

void main() {
    if (!finite(world[0]) || !finite(world[1]) || !finite(world[2]))
        return; // never drawn (exact_fragments.h)
    if (world[0] == world[1] || world[1] == world[2] || world[2] == world[0])
        return; // Q = 0 for every ray
    double z[3], z_low = 1.0e300lf, z_high = -1.0e300lf;
    dvec2 pixel[3];
    bool in_front = true; // every corner surely in front of the eye, projected as drawn
    bool near_clip = false; // some corner maybe before the plane at half the near distance
    for (int k = 0; k < 3; ++k) {
        dvec3 p = dvec3(world[k]);
        z[k] = -(dot(view_row.xyz, p) + view_row.w);
        double bound = kStep * (dot(abs(view_row.xyz), abs(p)) + abs(view_row.w));
        z_low = min(z_low, z[k] - bound);
        z_high = max(z_high, z[k] + bound);
        in_front = project(p, pixel[k]) && (orthographic != 0 || z[k] - bound > 0.0lf) &&
                   in_front;
        near_clip = near_clip || (orthographic == 0 && !(z[k] - bound > 0.5lf * near_plane));
    }
    if (z_high < near_plane || (orthographic != 0 && z_low > far_plane))
        return;
    double low = max(z_low, near_plane);
    double high = orthographic != 0 ? min(z_high, far_plane) : z_high;
    vec2 keys = vec2(floatBelow(depthOf(low) - kStep), floatAbove(depthOf(high) + kStep));
    // The box of the pixels the triangle can cover: of its projection or, crossing the plane at
    // half the near distance, of its part beyond (a fragment is at least near away: the half
    // leaves room for the cut's rounding); grown by the margin, cut to the viewport.
    dvec2 box_low = dvec2(1.0e300lf), box_high = dvec2(-1.0e300lf);
    bool boxed = true;
    for (int k = 0; k < 3; ++k) {
        int next = (k + 1) % 3;
        double cut = 0.5lf * near_plane;
        dvec2 at = pixel[k];
        if (!near_clip || z[k] >= cut) {
            boxed = (near_clip ? project(dvec3(world[k]), at) : in_front) && boxed;
            box_low = min(box_low, at);
            box_high = max(box_high, at);
        }
        if (near_clip && (z[k] < cut) != (z[next] < cut)) {
            dvec3 p = dvec3(world[k]), q = dvec3(world[next]);
            boxed = project(p + (cut - z[k]) / (z[next] - z[k]) * (q - p), at) && boxed;
            box_low = min(box_low, at);
            box_high = max(box_high, at);
        }
    }
    if (!boxed) {
        box_low = dvec2(0.0lf);
        box_high = viewport;
    }
    box_low = max(box_low - coverage_margin, dvec2(0.0lf));
    box_high = min(box_high + coverage_margin, viewport);
    if (!(box_low.x < box_high.x && box_low.y < box_high.y))
        return; // no pixel centre of the viewport
    bool small = true;
    for (int k = 0; k < 3; ++k)
        small = small && all(lessThanEqual(abs(pixel[k] / viewport * 2.0lf - 1.0lf),
                                           dvec2(kLargest)));
    if (!in_front || !small) {
        emitBox(box_low, box_high, keys);
        return;
    }
    double box_area = (box_high.x - box_low.x) * (box_high.y - box_low.y);
    double twice_area = cross2(pixel[1] - pixel[0], pixel[2] - pixel[0]);
    if (twice_area != 0.0lf) {
        // Edge k runs from corner k to corner k + 1; its outward unit normal.
        double orientation = twice_area > 0.0lf ? 1.0lf : -1.0lf;
        dvec2 normal[3];
        bool pushed = true;
        for (int k = 0; k < 3; ++k) {
            dvec2 e = pixel[(k + 1) % 3] - pixel[k];
            double len = length(e);
            pushed = pushed && len > 0.0lf;
            normal[k] = orientation * dvec2(e.y, -e.x) / max(len, 1.0e-300lf);
        }
        // Corner k moves to where the two pushed-out edges meeting there cross; at an angle
        // below about 8 degrees that is more than 3.5 pixels away: the box then.
        dvec2 grown[3];
        for (int k = 0; k < 3; ++k) {
            dvec2 before = normal[(k + 2) % 3], after = normal[k];
            double c = 1.0lf + dot(before, after);
            pushed = pushed && c > 0.01lf;
            grown[k] = pixel[k] + coverage_margin * (before + after) / max(c, 0.01lf);
        }
        if (pushed && 0.5lf * abs(cross2(grown[1] - grown[0], grown[2] - grown[0])) < box_area) {
            for (int k = 0; k < 3; ++k)
                emitCorner(grown[k], keys);
            EndPrimitive();
            return;
        }
    }
    emitBox(box_low, box_high, keys);
}
)";

// Per fragment, the model at the pixel centre's ray O + t D in double: the three edge
// determinants and Q = det[B - A, C - A, D] with bounds on their errors (against the CPU's
// exact values, the slack for the ray included). Discarded only where the model certainly has
// no fragment: two sides certainly of opposite signs, a side certainly against Q's, or the hit
// certainly outside the depth range. Otherwise the hit t = N / Q bounds the depth d (camera.h)
// from both sides, within the triangle's depth keys; where Q's sign is uncertain (the ray nearly
// in the triangle's plane) the keys alone. Draws write the lower bound, queries the upper.
constexpr const char* kFragmentShader = R"(#version 450 core
flat in vec3 corner_a;
flat in vec3 corner_b;
flat in vec3 corner_c;
flat in vec2 depth_keys;
uniform int query;
uniform int orthographic;
uniform dvec4 pixel_to_eye; // the eye-space ray at window (x, y): (x * [0] + [1], y * [2] + [3])
uniform dmat4 inverse_view;
uniform dvec3 eye_position;
uniform dvec3 forward;
uniform dvec4 view_row;
uniform double near_plane;
uniform double far_plane;
uniform double direction_slack; // |this driver's D - the CPU's D| per component, scaled alike
uniform double origin_slack;    // |this driver's O - the CPU's O| per component

const double kDifference = 1.0e-15lf;  // relative error of a rounded difference, with margin
const double kDeterminant = 1.5e-14lf; // relative to its largest term, a 3x3 determinant's
const double kStep = 1.0e-14lf;        // one operation's relative rounding, with margin
const double kTiny = 1.0e-270lf;       // a value below this may have underflowed: unsettled
const double kSmallest = 1.0e-30lf;

double largest(dvec3 v) {
    return max(max(abs(v.x), abs(v.y)), abs(v.z));
}

// +1 or -1 where the bound settles the sign, else 0 (NaN included).
int certainSign(double value, double bound) {
    if (!(abs(value) >= kTiny))
        return 0;
    return value > bound ? 1 : (value < -bound ? -1 : 0);
}

// A bound on |det[p, q, r] - det[p*, q*, r*]|, the first computed in double from columns within
// dp, dq and dr of the exact ones in every component, whose largest components are np, nq, nr:
// the three differences det[p - p*, q*, r*] + det[p, q - q*, r*] + det[p, q, r - r*], and the
// evaluation's rounding; six terms each.
double determinantBound(double np, double dp, double nq, double dq, double nr, double dr) {
    return 6.0lf *
           (dp * (nq + dq) * (nr + dr) + np * dq * (nr + dr) + np * nq * dr +
            kDeterminant * np * nq * nr) *
           (1.0lf + kStep);
}

float floatBelow(double x) {
    if (x <= kSmallest)
        return 0.0;
    float f = float(x);
    if (double(f) > x)
        f = uintBitsToFloat(floatBitsToUint(f) - 1u);
    return f;
}
float floatAbove(double x) {
    if (x >= 1.0lf)
        return 1.0;
    if (x <= kSmallest)
        return 1.0e-29;
    float f = float(x);
    if (double(f) < x)
        f = uintBitsToFloat(floatBitsToUint(f) + 1u);
    return f;
}

void main() {
    // PixelRays::at for the pixel's centre, whose window coordinates these are: (x_ndc / p00,
    // y_ndc / p11) in eye space, then to world space.
    double ex = double(gl_FragCoord.x) * pixel_to_eye.x + pixel_to_eye.y;
    double ey = double(gl_FragCoord.y) * pixel_to_eye.z + pixel_to_eye.w;
    dvec3 across = ex * inverse_view[0].xyz + ey * inverse_view[1].xyz;
    dvec3 origin, direction;
    if (orthographic != 0) {
        origin = across + inverse_view[3].xyz;
        direction = forward;
    } else {
        // Not normalized: no sign, order or depth here depends on D's length.
        origin = eye_position;
        direction = across - inverse_view[2].xyz;
    }
    dvec3 a = dvec3(corner_a), b = dvec3(corner_b), c = dvec3(corner_c);
    dvec3 u = a - origin, v = b - origin, w = c - origin;
    double nd = largest(direction), dd = direction_slack;
    double nu = largest(u), du = origin_slack + kDifference * nu;
    double nv = largest(v), dv = origin_slack + kDifference * nv;
    double nw = largest(w), dw = origin_slack + kDifference * nw;
    dvec3 uv = cross(u, v);
    int side0 = certainSign(dot(direction, uv), determinantBound(nd, dd, nu, du, nv, dv));
    int side1 = certainSign(dot(direction, cross(v, w)), determinantBound(nd, dd, nv, dv, nw, dw));
    int side2 = certainSign(dot(direction, cross(w, u)), determinantBound(nd, dd, nw, dw, nu, du));
    bool positive = side0 > 0 || side1 > 0 || side2 > 0;
    bool negative = side0 < 0 || side1 < 0 || side2 < 0;
    if (positive && negative)
        discard;
    dvec3 ab = b - a, ac = c - a;
    double nab = largest(ab), nac = largest(ac);
    double q = dot(direction, cross(ab, ac));
    double q_bound = determinantBound(nd, dd, nab, kDifference * nab, nac, kDifference * nac);
    int facing = certainSign(q, q_bound);
    if ((facing > 0 && negative) || (facing < 0 && positive))
        discard;
    float lower = depth_keys.x, upper = depth_keys.y;
    if (facing != 0) {
        double n = dot(w, uv); // det[A - O, B - O, C - O]
        double n_bound = determinantBound(nw, dw, nu, du, nv, dv);
        double t = n / q;
        double t_bound =
            ((n_bound + abs(t) * q_bound) / (abs(q) - q_bound) + kStep * abs(t)) * (1.0lf + kStep);
        // The hit's eye-space distance z = zO + t zD.
        dvec3 row = view_row.xyz;
        double row_sum = abs(row.x) + abs(row.y) + abs(row.z);
        double z_origin = -(dot(row, origin) + view_row.w);
        double z_origin_bound =
            kStep * (dot(abs(row), abs(origin)) + abs(view_row.w)) + origin_slack * row_sum;
        double z_direction = -dot(row, direction);
        double z_direction_bound =
            kStep * dot(abs(row), abs(direction)) + direction_slack * row_sum;
        double z = z_origin + t * z_direction;
        double z_bound = (z_origin_bound + abs(t) * z_direction_bound +
                          t_bound * (abs(z_direction) + z_direction_bound) +
                          kStep * (abs(t * z_direction) + abs(z))) *
                         (1.0lf + kStep);
        if (abs(z) + z_bound < 1.0e300lf) { // else the keys alone
            if (z + z_bound < near_plane)
                discard;
            if (orthographic != 0 && z - z_bound > far_plane)
                discard;
            double z_low = max(z - z_bound, near_plane);
            double z_high = z + z_bound;
            double d_low, d_high;
            if (orthographic != 0) {
                z_high = min(z_high, far_plane);
                d_low = (z_low - near_plane) / (far_plane - near_plane);
                d_high = (z_high - near_plane) / (far_plane - near_plane);
            } else {
                d_low = 1.0lf - near_plane / z_low;
                d_high = 1.0lf - near_plane / z_high;
            }
            lower = max(lower, floatBelow(d_low - kStep));
            upper = min(upper, floatAbove(d_high + kStep));
        }
    }
    gl_FragDepth = query != 0 ? upper : lower;
}
)";

// Relative slack for the driver's rounding of the ray against the CPU's: 2^-44, where IEEE
// doubles in the same order of operations differ by a few units of 2^-53.
constexpr double kRaySlack = 0x1p-44;

} // namespace

BoundedFragmentProgram BoundedFragmentProgram::link() {
    BoundedFragmentProgram p;
    p.program_ = linkProgram(kVertexShader, kGeometryShader, kFragmentShader);
    GLint bits = 8;
    glGetIntegerv(GL_SUBPIXEL_BITS, &bits);
    p.subpixel_bits_ = std::clamp(bits, 4, 16);
    p.query_location_ = glGetUniformLocation(p.program_.get(), "query");
    return p;
}

void BoundedFragmentProgram::setView(const ViewProjection& view) const {
    const GLuint p = program_.get();
    const auto at = [&](const char* name) { return glGetUniformLocation(p, name); };
    const bool orthographic = view.projection == Projection::orthographic;
    const glm::dmat4 view_matrix = glm::make_mat4(view.view.data());
    const glm::dmat4 view_projection = glm::make_mat4(view.projection_matrix.data()) * view_matrix;
    // PixelRays' inverse, computed as it computes it.
    const glm::dmat4 inverse = glm::inverse(view_matrix);
    const double scale_x = view.projection_matrix[0], scale_y = view.projection_matrix[5];
    double rotation = 0, translation = 0; // the inverse's largest entries
    for (int column = 0; column < 3; ++column)
        for (int row = 0; row < 3; ++row)
            rotation = std::max(rotation, std::abs(inverse[column][row]));
    for (int row = 0; row < 3; ++row)
        translation = std::max(translation, std::abs(inverse[3][row]));
    // The pixel centres' |x_ndc| and |y_ndc| are below 1: the ray's terms are at most these.
    const double screen = rotation * (1 / std::abs(scale_x) + 1 / std::abs(scale_y));
    const double forward_size =
        std::max({std::abs(view.forward.x), std::abs(view.forward.y), std::abs(view.forward.z)});
    const double direction_slack =
        orthographic ? kRaySlack * forward_size : kRaySlack * (rotation + screen);
    const double origin_slack = orthographic ? kRaySlack * (screen + translation) : 0.0;
    glProgramUniformMatrix4dv(p, at("view_projection"), 1, GL_FALSE,
                              glm::value_ptr(view_projection));
    glProgramUniformMatrix4dv(p, at("inverse_view"), 1, GL_FALSE, glm::value_ptr(inverse));
    glProgramUniform4d(p, at("view_row"), view.view[2], view.view[6], view.view[10], view.view[14]);
    glProgramUniform1d(p, at("near_plane"), view.near);
    glProgramUniform1d(p, at("far_plane"), orthographic ? view.far : 0.0); // unused: infinite
    glProgramUniform1i(p, at("orthographic"), orthographic ? 1 : 0);
    glProgramUniform2d(p, at("viewport"), view.width, view.height);
    glProgramUniform4d(p, at("pixel_to_eye"), 2 / (view.width * scale_x), -1 / scale_x,
                       -2 / (view.height * scale_y), 1 / scale_y);
    glProgramUniform3d(p, at("eye_position"), view.eye_position.x, view.eye_position.y,
                       view.eye_position.z);
    glProgramUniform3d(p, at("forward"), view.forward.x, view.forward.y, view.forward.z);
    glProgramUniform1d(p, at("direction_slack"), direction_slack);
    glProgramUniform1d(p, at("origin_slack"), origin_slack);
    // Snapping moves a corner by half a sub-pixel step, float positions (|ndc| <= 17) by 2^-20
    // of the viewport's size at most: the margin is twice both, and never below 1/64 pixel.
    const double size = std::max(view.width, view.height);
    const double margin = std::max(std::ldexp(1.0, -subpixel_bits_) + 0x1p-19 * size, 1.0 / 64);
    glProgramUniform1d(p, at("coverage_margin"), margin);
}

void BoundedFragmentProgram::setQuery(bool query) const {
    glProgramUniform1i(program_.get(), query_location_, query ? 1 : 0);
}

} // namespace vissort::detail
