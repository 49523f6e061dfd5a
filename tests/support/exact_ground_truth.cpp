// The exact visibility model of exact_ground_truth.h. Filtered exact predicates after the
// practice of CGAL's Filtered_predicate (Brönnimann, Burnikel and Pion, "Interval arithmetic
// yields efficient dynamic filters for computational geometry", 2001): interval arithmetic
// with directed rounding first, exact rationals only where the interval cannot tell the sign.
// Coverage from Plücker coordinates of the edges and the pixel line.

#include "exact_ground_truth.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cassert>
#include <cmath>
#include <optional>
#include <thread>
#include <utility>

#include <CGAL/FPU.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Interval_nt.h>

namespace vissort::test {
namespace {

// Interval_nt<false> requires rounding towards +infinity: every use of it lies inside a
// CGAL::Protect_FPU_rounding<true> scope, and nothing else of consequence is computed there.
using Interval = CGAL::Interval_nt<false>;
using Exact = CGAL::Gmpq;

struct IntervalVec {
    Interval x, y, z;
};

IntervalVec toInterval(const Vec3& v) {
    return {Interval(v.x), Interval(v.y), Interval(v.z)};
}
IntervalVec operator-(const IntervalVec& a, const IntervalVec& b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
Interval dot(const IntervalVec& a, const IntervalVec& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
IntervalVec cross(const IntervalVec& a, const IntervalVec& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

struct ExactVec {
    Exact x, y, z;
};

ExactVec toExact(const Vec3& v) {
    return {Exact(v.x), Exact(v.y), Exact(v.z)};
}
ExactVec operator-(const ExactVec& a, const ExactVec& b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
Exact dot(const ExactVec& a, const ExactVec& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
// det[a, b, c] with a, b, c as columns: a . (b x c).
Exact det(const ExactVec& a, const ExactVec& b, const ExactVec& c) {
    return a.x * (b.y * c.z - b.z * c.y) + a.y * (b.z * c.x - b.x * c.z) +
           a.z * (b.x * c.y - b.y * c.x);
}

// A sign an interval is sure of, or kUnsure.
enum Sign : int { kNegative = -1, kZero = 0, kPositive = 1, kUnsure = 2 };

Sign signOf(const Interval& v) {
    if (v.inf() > 0)
        return kPositive;
    if (v.sup() < 0)
        return kNegative;
    if (v.inf() == 0 && v.sup() == 0)
        return kZero; // [0, 0] holds only zero
    return kUnsure;
}

// What every test at a pixel reads: the view's depth row and range, and the pixel rays.
struct Setup {
    uint32_t width = 0, height = 0;
    bool orthographic = false;
    double near = 0, far = 0;
    Vec3 depth_row; // r: z(X) = -(r . X + r3)
    double depth_offset = 0;
    std::vector<Vec3> origins, directions;
    std::vector<uint8_t> ray_finite;
};

// One pixel's line in the intervals of the filter: Plücker moment O x D and z(O), -(r . D).
struct PixelIntervals {
    IntervalVec moment;
    Interval z_origin, z_direction;
};

bool isFinite(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Rule 2 to 5 in exact rationals, literally: t of the fragment, or none.
std::optional<Exact> exactHit(const Vec3 corners[3], const Setup& setup, std::size_t pixel) {
    const ExactVec a = toExact(corners[0]), b = toExact(corners[1]), c = toExact(corners[2]);
    const ExactVec o = toExact(setup.origins[pixel]), d = toExact(setup.directions[pixel]);
    const Exact q = det(b - a, c - a, d);
    if (CGAL::sign(q) == CGAL::ZERO)
        return std::nullopt;
    const int s1 = CGAL::sign(det(a - o, b - o, d)), s2 = CGAL::sign(det(b - o, c - o, d)),
              s3 = CGAL::sign(det(c - o, a - o, d));
    if (!((s1 >= 0 && s2 >= 0 && s3 >= 0) || (s1 <= 0 && s2 <= 0 && s3 <= 0)))
        return std::nullopt;
    Exact t = det(a - o, b - o, c - o) / q;
    const ExactVec r = toExact(setup.depth_row);
    const Exact r3(setup.depth_offset);
    const Exact z = -(dot(r, o) + r3) - t * dot(r, d);
    if (z < Exact(setup.near) || (setup.orthographic && z > Exact(setup.far)))
        return std::nullopt;
    return t;
}

// A fragment found, before ordering: t lies in [t_low, t_high].
struct Candidate {
    uint32_t pixel, triangle;
    double t_low, t_high;
};

constexpr uint32_t kTrianglesPerBlock = 256;
constexpr uint32_t kRowsPerBlock = 4;

// Runs work(block) for every block in [0, block_count) on up to thread_count threads.
template <class Work>
void parallelBlocks(std::size_t block_count, unsigned thread_count, const Work& work) {
    const unsigned threads = unsigned(std::min<std::size_t>(thread_count, block_count));
    if (threads <= 1) {
        for (std::size_t b = 0; b < block_count; ++b)
            work(b);
        return;
    }
    std::atomic<std::size_t> next{0};
    std::vector<std::thread> pool;
    for (unsigned i = 0; i < threads; ++i) {
        pool.emplace_back([&] {
            for (std::size_t b = next++; b < block_count; b = next++)
                work(b);
        });
    }
    for (std::thread& thread : pool)
        thread.join();
}

// The pixel box [x0, x1] x [y0, y1] whose centre rays may meet triangle corners: the box of the
// projected corners grown by 2 pixels. Part of the triangle nearer than the near plane: the box
// of the part beyond it (perspective; orthographic projection is affine, the corners' box holds
// all). Wholly out of the depth range: empty. Nothing projects (non-finite, a plane at or behind
// the eye): the whole image.
struct PixelBox {
    uint32_t x0 = 1, x1 = 0, y0 = 1, y1 = 0; // empty
    bool clipped = false, whole_image = false;
};

PixelBox candidatePixels(const Vec3 corners[3], const ViewProjection& view, const Setup& setup) {
    PixelBox box;
    // Eye distances in double, and a margin far beyond their rounding error (a few ulps of the
    // terms): only a triangle out of range by more than the margin is dropped, so the exact test
    // decides every one that might reach the range.
    double z[3];
    double margin = std::abs(setup.depth_offset) + std::abs(setup.near);
    for (int i = 0; i < 3; ++i) {
        z[i] = -(dot(setup.depth_row, corners[i]) + setup.depth_offset);
        margin += std::abs(setup.depth_row.x * corners[i].x) +
                  std::abs(setup.depth_row.y * corners[i].y) +
                  std::abs(setup.depth_row.z * corners[i].z);
    }
    margin *= 1e-9;
    const double near = setup.near - margin;
    if (z[0] < near && z[1] < near && z[2] < near)
        return box; // every point of the triangle nearer than the near plane
    if (setup.orthographic) {
        const double far = setup.far + margin;
        if (z[0] > far && z[1] > far && z[2] > far)
            return box;
    }
    // The polygon to project: the triangle, or (perspective) its part at z >= near.
    Vec3 polygon[4];
    int count = 0;
    if (setup.orthographic || (z[0] >= near && z[1] >= near && z[2] >= near)) {
        for (int i = 0; i < 3; ++i)
            polygon[count++] = corners[i];
    } else {
        box.clipped = true;
        for (int i = 0; i < 3; ++i) {
            const int j = (i + 1) % 3;
            if (z[i] >= near)
                polygon[count++] = corners[i];
            if ((z[i] >= near) != (z[j] >= near))
                polygon[count++] =
                    corners[i] + (corners[j] - corners[i]) * ((near - z[i]) / (z[j] - z[i]));
        }
    }
    double min_x = INFINITY, max_x = -INFINITY, min_y = INFINITY, max_y = -INFINITY;
    bool projects = near > 0 || setup.orthographic;
    for (int i = 0; i < count && projects; ++i) {
        const std::array<double, 4> clip = view.toClip(polygon[i]);
        const double sx = (clip[0] / clip[3] + 1) * 0.5 * setup.width;
        const double sy = (1 - clip[1] / clip[3]) * 0.5 * setup.height;
        projects = clip[3] > 0 && std::isfinite(sx) && std::isfinite(sy);
        min_x = std::min(min_x, sx);
        max_x = std::max(max_x, sx);
        min_y = std::min(min_y, sy);
        max_y = std::max(max_y, sy);
    }
    if (!projects) {
        box = {0, setup.width - 1, 0, setup.height - 1, false, true};
        return box;
    }
    // Pixel px spans [px, px + 1): the pixels holding the box's corners, and 2 more each side.
    const double x0 = std::max(0.0, std::floor(min_x) - 2);
    const double x1 = std::min(double(setup.width) - 1, std::floor(max_x) + 2);
    const double y0 = std::max(0.0, std::floor(min_y) - 2);
    const double y1 = std::min(double(setup.height) - 1, std::floor(max_y) + 2);
    if (x0 > x1 || y0 > y1)
        return box;
    box = {uint32_t(x0), uint32_t(x1), uint32_t(y0), uint32_t(y1), box.clipped, false};
    return box;
}

// The fragments of the triangles of one block, in triangle order (orderPixel sorts them).
struct BlockResult {
    std::vector<Candidate> candidates;
    ExactFragmentStatistics statistics;
};

void findBlockFragments(PositionsView positions, const ViewProjection& view, const Setup& setup,
                        std::span<const PixelIntervals> pixel_intervals, bool filter,
                        uint32_t first, uint32_t end, BlockResult& out) {
    std::vector<uint32_t> unsure; // pixels the filter could not decide, for the exact test
    for (uint32_t t = first; t < end; ++t) {
        const Vec3 corners[3] = {positions.corner(3 * std::size_t(t)),
                                 positions.corner(3 * std::size_t(t) + 1),
                                 positions.corner(3 * std::size_t(t) + 2)};
        if (!isFinite(corners[0]) || !isFinite(corners[1]) || !isFinite(corners[2]))
            continue;
        // Two equal corners: Q = det[B - A, C - A, D] has a zero column or two equal ones at
        // every ray, so there is no fragment (rule 2); the interval filter cannot see that, and
        // would send every pixel of the box to the exact test.
        const auto same = [](const Vec3& u, const Vec3& v) {
            return u.x == v.x && u.y == v.y && u.z == v.z;
        };
        if (same(corners[0], corners[1]) || same(corners[1], corners[2]) ||
            same(corners[2], corners[0]))
            continue;
        const PixelBox box = candidatePixels(corners, view, setup);
        if (box.x0 > box.x1 || box.y0 > box.y1)
            continue;
        out.statistics.clipped_triangles += box.clipped;
        out.statistics.whole_image_triangles += box.whole_image;
        out.statistics.candidates_tested += uint64_t(box.x1 - box.x0 + 1) * (box.y1 - box.y0 + 1);
        unsure.clear();
        {
            CGAL::Protect_FPU_rounding<true> upward;
            const IntervalVec a = toInterval(corners[0]), b = toInterval(corners[1]),
                              c = toInterval(corners[2]);
            // Plücker coordinates (direction, moment) of the edges AB, BC, CA: for the line
            // (O, D), det[A - O, B - O, D] = D . (A x B) + (B - A) . (O x D).
            const IntervalVec edge[3] = {b - a, c - b, a - c};
            const IntervalVec edge_moment[3] = {cross(a, b), cross(b, c), cross(c, a)};
            const IntervalVec normal = cross(b - a, c - a);
            // Perspective far is infinite and unused; an Interval must be finite.
            const Interval near(setup.near), far(setup.orthographic ? setup.far : 0.0);
            for (uint32_t py = box.y0; py <= box.y1; ++py) {
                for (uint32_t px = box.x0; px <= box.x1; ++px) {
                    const uint32_t pixel = py * setup.width + px;
                    if (!setup.ray_finite[pixel])
                        continue;
                    if (!filter) {
                        unsure.push_back(pixel);
                        continue;
                    }
                    const IntervalVec d = toInterval(setup.directions[pixel]);
                    const PixelIntervals& line = pixel_intervals[pixel];
                    Interval s[3];
                    int positive = 0, negative = 0;
                    bool sure = true;
                    for (int e = 0; e < 3 && !(positive && negative); ++e) {
                        s[e] = dot(d, edge_moment[e]) + dot(edge[e], line.moment);
                        const Sign sign = signOf(s[e]);
                        positive += sign == kPositive;
                        negative += sign == kNegative;
                        sure = sure && sign != kUnsure;
                    }
                    if (positive && negative)
                        continue; // the line passes outside: sure whatever the others are
                    if (!sure) {
                        unsure.push_back(pixel);
                        continue;
                    }
                    if (!positive && !negative)
                        continue; // s1 = s2 = s3 = 0: Q = s1 + s2 + s3 = 0
                    // Q = s1 + s2 + s3 (multilinearity), of the sign of the nonzero ones.
                    const Interval q = s[0] + s[1] + s[2];
                    const Interval n = dot(normal, a - toInterval(setup.origins[pixel]));
                    // z >= near: sign(Q) ((zO - near) Q + N zD) >= 0; z <= far likewise.
                    const Interval q_signed = positive ? q : -q, n_signed = positive ? n : -n;
                    const Interval above_near =
                        (line.z_origin - near) * q_signed + n_signed * line.z_direction;
                    const Sign near_sign = signOf(above_near);
                    Sign far_sign = kPositive;
                    if (setup.orthographic)
                        far_sign =
                            signOf((far - line.z_origin) * q_signed - n_signed * line.z_direction);
                    if (near_sign == kNegative || far_sign == kNegative)
                        continue;
                    if (near_sign == kUnsure || far_sign == kUnsure) {
                        unsure.push_back(pixel);
                        continue;
                    }
                    const Interval hit = n / q;
                    out.candidates.push_back({pixel, t, hit.inf(), hit.sup()});
                }
            }
        }
        out.statistics.exact_coverage_tests += unsure.size();
        for (uint32_t pixel : unsure) {
            if (const std::optional<Exact> hit = exactHit(corners, setup, pixel)) {
                const std::pair<double, double> bounds = CGAL::to_interval(*hit);
                out.candidates.push_back({pixel, t, bounds.first, bounds.second});
            }
        }
    }
}

// A triangle's corners in a canonical order (sorted), to find copies: finite corners only (the
// fragments' triangles are).
using CornerKey = std::array<double, 9>;
CornerKey cornerKey(PositionsView positions, uint32_t t) {
    std::array<std::array<double, 3>, 3> corners;
    for (int k = 0; k < 3; ++k) {
        const Vec3 c = positions.corner(3 * std::size_t(t) + std::size_t(k));
        corners[std::size_t(k)] = {c.x, c.y, c.z};
    }
    std::sort(corners.begin(), corners.end());
    CornerKey key;
    for (std::size_t k = 0; k < 9; ++k)
        key[k] = corners[k / 3][k % 3];
    return key;
}

// Orders the candidates of one pixel (rule 6) into the output's fragment slots [first, end).
void orderPixel(PositionsView positions, const ViewProjection& view, const Setup& setup,
                std::size_t pixel, std::span<Candidate> candidates, uint32_t* triangles,
                uint32_t* ranks, double* depths, uint64_t& exact_depths) {
    // Intervals that overlap, transitively, form a cluster: clusters are strictly ordered and
    // only a cluster of two or more needs exact t.
    std::sort(candidates.begin(), candidates.end(), [](const Candidate& x, const Candidate& y) {
        if (x.t_low != y.t_low)
            return x.t_low < y.t_low;
        if (x.t_high != y.t_high)
            return x.t_high < y.t_high;
        return x.triangle < y.triangle;
    });
    const Vec3 origin = setup.origins[pixel], direction = setup.directions[pixel];
    const auto depthAt = [&](double t) { return view.depthOf(origin + direction * t); };
    uint32_t rank = 0;
    std::vector<std::pair<Exact, uint32_t>> cluster;   // exact t and triangle
    std::vector<std::pair<CornerKey, uint32_t>> keyed; // a cluster's corners and triangle
    for (std::size_t i = 0; i < candidates.size();) {
        std::size_t end = i + 1;
        double reach = candidates[i].t_high;
        while (end < candidates.size() && candidates[end].t_low <= reach) {
            reach = std::max(reach, candidates[end].t_high);
            ++end;
        }
        if (end == i + 1) {
            triangles[i] = candidates[i].triangle;
            ranks[i] = rank++;
            depths[i] = depthAt(0.5 * candidates[i].t_low + 0.5 * candidates[i].t_high);
            i = end;
            continue;
        }
        // Copies of a triangle (the same corners, in any order) lie in one plane and share t:
        // computed once for each set of corners (a file may stack hundreds of copies).
        keyed.clear();
        for (std::size_t k = i; k < end; ++k)
            keyed.emplace_back(cornerKey(positions, candidates[k].triangle),
                               candidates[k].triangle);
        std::sort(keyed.begin(), keyed.end());
        cluster.clear();
        for (std::size_t k = 0; k < keyed.size(); ++k) {
            const uint32_t t = keyed[k].second;
            if (k > 0 && keyed[k].first == keyed[k - 1].first) {
                Exact same = cluster.back().first; // a copy: emplace_back may reallocate
                cluster.emplace_back(std::move(same), t);
                continue;
            }
            const Vec3 corners[3] = {positions.corner(3 * std::size_t(t)),
                                     positions.corner(3 * std::size_t(t) + 1),
                                     positions.corner(3 * std::size_t(t) + 2)};
            std::optional<Exact> hit = exactHit(corners, setup, pixel);
            assert(hit); // every candidate is a fragment, decided exactly
            cluster.emplace_back(hit ? std::move(*hit) : Exact(0), t);
            ++exact_depths;
        }
        std::sort(cluster.begin(), cluster.end());
        for (std::size_t k = 0; k < cluster.size(); ++k) {
            if (k > 0 && cluster[k].first != cluster[k - 1].first)
                ++rank;
            triangles[i + k] = cluster[k].second;
            ranks[i + k] = rank;
            depths[i + k] = depthAt(CGAL::to_double(cluster[k].first));
        }
        ++rank;
        i = end;
    }
}

} // namespace

ExactFragments exactFragments(PositionsView positions, const ViewProjection& view,
                              const ExactFragmentOptions& options) {
    const unsigned thread_count = options.thread_count != 0
                                      ? options.thread_count
                                      : std::max(1u, std::thread::hardware_concurrency());
    ExactFragments out;
    out.width = view.width;
    out.height = view.height;
    const std::size_t pixel_count = out.pixelCount();
    out.offsets.assign(pixel_count + 1, 0);
    if (pixel_count == 0)
        return out;

    Setup setup;
    setup.width = view.width;
    setup.height = view.height;
    setup.orthographic = view.projection == Projection::orthographic;
    setup.near = view.near;
    setup.far = view.far;
    setup.depth_row = {view.view[2], view.view[6], view.view[10]};
    setup.depth_offset = view.view[14];
    setup.origins.resize(pixel_count);
    setup.directions.resize(pixel_count);
    setup.ray_finite.resize(pixel_count);
    // A view with non-finite numbers in the model's terms decides nothing: no fragments.
    const bool view_finite = isFinite(setup.depth_row) && std::isfinite(setup.depth_offset) &&
                             std::isfinite(setup.near) &&
                             (!setup.orthographic || std::isfinite(setup.far));
    std::vector<PixelIntervals> pixel_intervals(pixel_count);
    const std::size_t row_blocks = (view.height + kRowsPerBlock - 1) / kRowsPerBlock;
    parallelBlocks(row_blocks, thread_count, [&](std::size_t block) {
        const uint32_t y0 = uint32_t(block * kRowsPerBlock);
        const uint32_t y1 = std::min(view.height, y0 + kRowsPerBlock);
        for (uint32_t py = y0; py < y1; ++py) {
            for (uint32_t px = 0; px < view.width; ++px) {
                const std::size_t pixel = std::size_t(py) * view.width + px;
                view.pixelRay(px + 0.5, py + 0.5, setup.origins[pixel], setup.directions[pixel]);
                setup.ray_finite[pixel] = view_finite && isFinite(setup.origins[pixel]) &&
                                          isFinite(setup.directions[pixel]);
            }
        }
        CGAL::Protect_FPU_rounding<true> upward;
        const IntervalVec r = toInterval(setup.depth_row);
        const Interval r3(setup.depth_offset);
        for (std::size_t pixel = std::size_t(y0) * view.width; pixel < std::size_t(y1) * view.width;
             ++pixel) {
            if (!setup.ray_finite[pixel])
                continue;
            const IntervalVec o = toInterval(setup.origins[pixel]);
            const IntervalVec d = toInterval(setup.directions[pixel]);
            pixel_intervals[pixel] = {cross(o, d), -(dot(r, o) + r3), -dot(r, d)};
        }
    });

    // Coverage, by blocks of triangles; the blocks' results are merged in block order.
    const std::size_t triangle_count = positions.triangleCount();
    assert(triangle_count < UINT32_MAX);
    const std::size_t triangle_blocks =
        (triangle_count + kTrianglesPerBlock - 1) / kTrianglesPerBlock;
    std::vector<BlockResult> blocks(triangle_blocks);
    parallelBlocks(triangle_blocks, thread_count, [&](std::size_t block) {
        const uint32_t first = uint32_t(block * kTrianglesPerBlock);
        const uint32_t end =
            uint32_t(std::min<std::size_t>(triangle_count, first + kTrianglesPerBlock));
        findBlockFragments(positions, view, setup, pixel_intervals, options.filter, first, end,
                           blocks[block]);
    });
    std::vector<uint64_t>& offsets = out.offsets;
    for (const BlockResult& block : blocks) {
        for (const Candidate& candidate : block.candidates)
            ++offsets[candidate.pixel + 1];
        out.statistics.candidates_tested += block.statistics.candidates_tested;
        out.statistics.exact_coverage_tests += block.statistics.exact_coverage_tests;
        out.statistics.clipped_triangles += block.statistics.clipped_triangles;
        out.statistics.whole_image_triangles += block.statistics.whole_image_triangles;
    }
    for (std::size_t pixel = 0; pixel < pixel_count; ++pixel)
        offsets[pixel + 1] += offsets[pixel];
    const uint64_t fragment_count = offsets[pixel_count];
    std::vector<Candidate> by_pixel(fragment_count);
    {
        std::vector<uint64_t> fill(offsets.begin(), offsets.end() - 1);
        for (BlockResult& block : blocks) {
            for (const Candidate& candidate : block.candidates)
                by_pixel[fill[candidate.pixel]++] = candidate;
            block.candidates = {};
        }
    }

    // Order, by blocks of rows.
    out.triangles.resize(fragment_count);
    out.ranks.resize(fragment_count);
    out.depths.resize(fragment_count);
    std::vector<uint64_t> exact_depths(row_blocks, 0);
    parallelBlocks(row_blocks, thread_count, [&](std::size_t block) {
        const std::size_t first = block * kRowsPerBlock * view.width;
        const std::size_t end =
            std::min<std::size_t>(pixel_count, (block + 1) * kRowsPerBlock * view.width);
        for (std::size_t pixel = first; pixel < end; ++pixel) {
            const uint64_t begin = offsets[pixel], count = offsets[pixel + 1] - begin;
            if (count == 0)
                continue;
            orderPixel(positions, view, setup, pixel,
                       std::span<Candidate>(by_pixel.data() + begin, count),
                       out.triangles.data() + begin, out.ranks.data() + begin,
                       out.depths.data() + begin, exact_depths[block]);
        }
    });
    for (uint64_t count : exact_depths)
        out.statistics.exact_depths += count;
    return out;
}

} // namespace vissort::test
