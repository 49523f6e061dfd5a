#pragma once
// The tests' exact visibility model: which triangles each pixel's centre ray meets and in which
// order, every decision exact (no tolerance), computed without the library's oracles,
// rasterizers or ray caster. The definition:
//  1. Pixel (px, py) is sampled by the line L = {O + t D}, (O, D) the doubles that
//     view.pixelRay(px + 0.5, py + 0.5) returns, taken as exact values.
//  2. Triangle T = (A, B, C), its float corners exactly. Q = det[B - A, C - A, D]; Q == 0
//     (degenerate, or L parallel to its plane): no fragment. Non-finite corners: never one.
//  3. s1 = det[A - O, B - O, D], s2 = det[B - O, C - O, D], s3 = det[C - O, A - O, D]: L meets
//     the closed triangle iff all three are >= 0 or all are <= 0 (edges and corners count).
//  4. The hit is at t = N / Q, N = det[A - O, B - O, C - O].
//  5. Eye distance z(X) = -(r . X + r3), r = (view[2], view[6], view[10]), r3 = view[14]; the
//     hit's z = zO + t zD with zO = z(O), zD = -(r . D). A fragment needs z >= near and, for an
//     orthographic view, z <= far (the perspective far plane is infinite).
//  6. At a pixel, larger t is farther; exactly equal t is a tie.
//  7. (ground_truth.h) Primitive a is in front of b at a pixel iff a triangle of a and one of b
//     both have fragments there and t(a's) < t(b's), strictly.
// How: every sign is first taken from CGAL::Interval_nt<false> arithmetic on the exact doubles
// (under CGAL::Protect_FPU_rounding), and only where an interval contains zero (a centre on or
// within a few ulps of an edge, a tie, a hit at the near plane) recomputed with CGAL::Gmpq.
// Candidates: each triangle's projected bounding box grown by 2 pixels; for a triangle crossing
// the near plane (perspective), the box of its part beyond the plane (clipped in double, a plane
// 1e-9 relative nearer, far more than the rounding error); none for a triangle wholly out of the
// depth range by that margin; the whole image where nothing projects (non-finite).

#include <cstdint>
#include <vector>

#include "vissort/camera.h"
#include "vissort/geometry.h"

namespace vissort::test {

/// How much work the exact computation did, and how much of it needed exact arithmetic.
struct ExactFragmentStatistics {
    uint64_t candidates_tested = 0;     // (triangle, pixel) pairs whose coverage was decided
    uint64_t exact_coverage_tests = 0;  // of those, decided with Gmpq (the filter was unsure)
    uint64_t exact_depths = 0;          // fragments whose t was computed with Gmpq to order them
    uint64_t clipped_triangles = 0;     // crossing the near plane: boxed by their part beyond it
    uint64_t whole_image_triangles = 0; // tested at every pixel (no box: nothing projects)
};

/// Every pixel's fragments, rows of a compressed table: pixel p = py * width + px (row 0 at the
/// top) has its fragments at [offsets[p], offsets[p + 1]), nearest first (by exact t, then by
/// triangle id among exact ties).
struct ExactFragments {
    uint32_t width = 0, height = 0;
    std::vector<uint64_t> offsets;   // width * height + 1 entries
    std::vector<uint32_t> triangles; // the triangle of each fragment
    std::vector<uint32_t> ranks;     // exact depth rank at its pixel: 0 = nearest; fragments at
                                     // exactly equal t share one, the next distinct t gets + 1
    std::vector<double> depths;      // view.depthOf of the hit, approximate: for messages only
    ExactFragmentStatistics statistics;

    std::size_t pixelCount() const { return std::size_t(width) * height; }
    uint64_t firstFragment(std::size_t pixel) const { return offsets[pixel]; }
    uint64_t endFragment(std::size_t pixel) const { return offsets[pixel + 1]; }
};

struct ExactFragmentOptions {
    unsigned thread_count = 0; // 0: std::thread::hardware_concurrency(); the result is the same
    bool filter = true;        // false: every coverage test in exact rationals (to test the filter)
};

/// The exact fragments of every triangle at every pixel centre of view (the model above).
ExactFragments exactFragments(PositionsView positions, const ViewProjection& view,
                              const ExactFragmentOptions& options = {});

} // namespace vissort::test
