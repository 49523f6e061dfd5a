// The exact ground truth (exact_ground_truth.h, ground_truth.h): hand-made cases whose answer is
// known by construction, exactly (ties, touching faces, centres on edges, 1-ulp offsets), and a
// brute force in exact rationals over every pixel and triangle, without the filter.

#include "ground_truth.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include <CGAL/Gmpq.h>
#include <gtest/gtest.h>

#include "exact_ground_truth.h"
#include "tarjan_scc.h"
#include "test_scenes.h"

namespace vissort {
namespace {

using test::addQuad;
using test::addTriangle;
using test::checkVisibilityOrder;
using test::ExactFragments;
using test::exactFragments;
using test::occlusionGraph;
using test::range;

using Graph = std::vector<std::vector<uint32_t>>;
using Exact = CGAL::Gmpq;

TrianglePositions twoParallelQuads() {
    TrianglePositions positions;
    addQuad(positions, 1.0, 0.0);  // primitive 0, front
    addQuad(positions, 2.0, -1.0); // primitive 1, behind
    return positions;
}

const std::vector<PrimitiveRange> kTwoQuads = {range(0, 2), range(2, 2)};

// Three long sticks along the sides of a triangle, each high at its start and low at its end, so
// that at every corner the next stick lies over the previous one: 1 over 0, 2 over 1, 0 over 2.
TrianglePositions cyclicSticks() {
    TrianglePositions positions;
    const double pi = std::acos(-1.0);
    Vec3 corners[3];
    for (int i = 0; i < 3; ++i)
        corners[i] = {std::cos(pi / 2 + 2 * pi * i / 3), std::sin(pi / 2 + 2 * pi * i / 3), 0};
    for (int i = 0; i < 3; ++i) {
        const Vec3 a = corners[i], b = corners[(i + 1) % 3];
        const double length = std::hypot(b.x - a.x, b.y - a.y);
        const double dx = (b.x - a.x) / length, dy = (b.y - a.y) / length;
        const double nx = -dy * 0.1, ny = dx * 0.1;
        const Vec3 start{a.x - dx * 0.3, a.y - dy * 0.3, 1},
            end{b.x + dx * 0.3, b.y + dy * 0.3, -1};
        const Vec3 s0{start.x - nx, start.y - ny, 1}, s1{start.x + nx, start.y + ny, 1};
        const Vec3 e0{end.x - nx, end.y - ny, -1}, e1{end.x + nx, end.y + ny, -1};
        addTriangle(positions, s0, e0, e1);
        addTriangle(positions, s0, e1, s1);
    }
    return positions;
}

const std::vector<PrimitiveRange> kThreeSticks = {range(0, 2), range(2, 2), range(4, 2)};

ViewProjection topView(const TrianglePositions& positions) {
    return test::orthographicView(positions, {0, 0, -1}, 64, 64);
}

// An orthographic view along -z whose pixel centres are exact: pixel (px, py) samples the line
// x = px + 0.5 - width / 2, y = height / 2 - py - 0.5 (unit pixels), from z = eye_z downwards;
// width and height powers of two. Eye distance eye_z - z; near 1, far 2 eye_z.
ViewProjection exactOrthographicView(uint32_t width, uint32_t height, double eye_z = 8) {
    ViewProjection view;
    view.projection = Projection::orthographic;
    view.width = width;
    view.height = height;
    view.view = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, -eye_z, 1};
    view.near = 1;
    view.far = 2 * eye_z;
    view.projection_matrix = {2.0 / width,
                              0,
                              0,
                              0,
                              0,
                              2.0 / height,
                              0,
                              0,
                              0,
                              0,
                              -1 / (view.far - view.near),
                              0,
                              0,
                              0,
                              -view.near / (view.far - view.near),
                              1};
    view.eye_position = {0, 0, eye_z};
    view.forward = {0, 0, -1};
    return view;
}

// Asserts that exactOrthographicView's pixel rays are the exact lines it promises.
void expectExactRays(const ViewProjection& view) {
    for (uint32_t py = 0; py < view.height; ++py) {
        for (uint32_t px = 0; px < view.width; ++px) {
            Vec3 origin, direction;
            view.pixelRay(px + 0.5, py + 0.5, origin, direction);
            ASSERT_EQ(origin.x, px + 0.5 - view.width / 2.0);
            ASSERT_EQ(origin.y, view.height / 2.0 - py - 0.5);
            ASSERT_EQ(direction.x, 0.0);
            ASSERT_EQ(direction.y, 0.0);
            ASSERT_EQ(direction.z, -1.0);
        }
    }
}

// A perspective view from the origin along -z, 90 degrees, square: the ray through screen point
// (sx, sy) has the direction (x_ndc, y_ndc, -1), normalised.
ViewProjection perspectiveFromOrigin(uint32_t size, double near) {
    ViewProjection view;
    view.projection = Projection::perspective;
    view.width = view.height = size;
    view.view = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    view.near = near;
    view.far = INFINITY;
    view.projection_matrix = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1, -1, 0, 0, -near, 0};
    view.eye_position = {0, 0, 0};
    view.forward = {0, 0, -1};
    return view;
}

// ---------------------------------------------------------------------------------------------
// The brute force: rules 1 to 6 of exact_ground_truth.h written out in exact rationals for every
// pixel and triangle, no filter, no candidate boxes.

struct ExactVec {
    Exact x, y, z;
};

ExactVec exactOf(const Vec3& v) {
    return {Exact(v.x), Exact(v.y), Exact(v.z)};
}
ExactVec minus(const ExactVec& a, const ExactVec& b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
// The determinant of the matrix with columns u, v, w (rule of Sarrus).
Exact determinant(const ExactVec& u, const ExactVec& v, const ExactVec& w) {
    return u.x * v.y * w.z + v.x * w.y * u.z + w.x * u.y * v.z - w.x * v.y * u.z - v.x * u.y * w.z -
           u.x * w.y * v.z;
}

struct BruteLine {
    ExactVec origin, direction;
};

BruteLine bruteLine(const ViewProjection& view, uint32_t px, uint32_t py) {
    Vec3 origin, direction;
    view.pixelRay(px + 0.5, py + 0.5, origin, direction);
    return {exactOf(origin), exactOf(direction)};
}

// The three edge determinants s1, s2, s3 of triangle t and a line.
std::array<Exact, 3> edgeDeterminants(const TrianglePositions& positions, uint32_t t,
                                      const BruteLine& line) {
    const ExactVec a = exactOf(positions.corner(3 * t)), b = exactOf(positions.corner(3 * t + 1)),
                   c = exactOf(positions.corner(3 * t + 2));
    const ExactVec& o = line.origin;
    return {determinant(minus(a, o), minus(b, o), line.direction),
            determinant(minus(b, o), minus(c, o), line.direction),
            determinant(minus(c, o), minus(a, o), line.direction)};
}

// t of triangle t's fragment on the line, or false.
bool bruteHit(const TrianglePositions& positions, const ViewProjection& view, uint32_t t,
              const BruteLine& line, Exact& hit) {
    for (int i = 0; i < 3; ++i) {
        const Vec3 corner = positions.corner(3 * t + i);
        if (!std::isfinite(corner.x) || !std::isfinite(corner.y) || !std::isfinite(corner.z))
            return false;
    }
    const ExactVec a = exactOf(positions.corner(3 * t)), b = exactOf(positions.corner(3 * t + 1)),
                   c = exactOf(positions.corner(3 * t + 2));
    const ExactVec& o = line.origin;
    const Exact q = determinant(minus(b, a), minus(c, a), line.direction);
    if (q == 0)
        return false;
    const std::array<Exact, 3> s = edgeDeterminants(positions, t, line);
    const bool all_nonnegative = s[0] >= 0 && s[1] >= 0 && s[2] >= 0;
    const bool all_nonpositive = s[0] <= 0 && s[1] <= 0 && s[2] <= 0;
    if (!all_nonnegative && !all_nonpositive)
        return false;
    hit = determinant(minus(a, o), minus(b, o), minus(c, o)) / q;
    const ExactVec r = exactOf({view.view[2], view.view[6], view.view[10]});
    const Exact r3(view.view[14]);
    const ExactVec x = {o.x + hit * line.direction.x, o.y + hit * line.direction.y,
                        o.z + hit * line.direction.z};
    const Exact z = -(r.x * x.x + r.y * x.y + r.z * x.z + r3);
    if (z < Exact(view.near))
        return false;
    return !(view.projection == Projection::orthographic && z > Exact(view.far));
}

// Each pixel's (triangle, rank), nearest first, ties by triangle id.
using PixelFragments = std::vector<std::vector<std::pair<uint32_t, uint32_t>>>;

PixelFragments bruteForce(const TrianglePositions& positions, const ViewProjection& view) {
    PixelFragments pixels(std::size_t(view.width) * view.height);
    std::vector<std::pair<Exact, uint32_t>> hits;
    for (uint32_t py = 0; py < view.height; ++py) {
        for (uint32_t px = 0; px < view.width; ++px) {
            const BruteLine line = bruteLine(view, px, py);
            hits.clear();
            for (uint32_t t = 0; t < positions.triangleCount(); ++t) {
                Exact hit;
                if (bruteHit(positions, view, t, line, hit))
                    hits.emplace_back(hit, t);
            }
            std::sort(hits.begin(), hits.end());
            auto& out = pixels[std::size_t(py) * view.width + px];
            uint32_t rank = 0;
            for (std::size_t i = 0; i < hits.size(); ++i) {
                if (i > 0 && hits[i].first != hits[i - 1].first)
                    ++rank;
                out.emplace_back(hits[i].second, rank);
            }
        }
    }
    return pixels;
}

PixelFragments fragmentsByPixel(const ExactFragments& fragments) {
    PixelFragments pixels(fragments.pixelCount());
    for (std::size_t pixel = 0; pixel < pixels.size(); ++pixel) {
        for (uint64_t f = fragments.firstFragment(pixel); f < fragments.endFragment(pixel); ++f)
            pixels[pixel].emplace_back(fragments.triangles[f], fragments.ranks[f]);
    }
    return pixels;
}

// The fast path, with its filter and without (every test exact), against the brute force at
// every pixel; returns the number of fragments.
uint64_t expectSameAsBruteForce(const TrianglePositions& positions, const ViewProjection& view) {
    const PixelFragments expected = bruteForce(positions, view);
    uint64_t fragment_count = 0;
    for (const bool filter : {true, false}) {
        const ExactFragments fast = exactFragments(positions, view, {.filter = filter});
        const PixelFragments actual = fragmentsByPixel(fast);
        EXPECT_EQ(fast.offsets.size(), expected.size() + 1);
        uint64_t mismatches = 0;
        for (std::size_t pixel = 0; pixel < expected.size() && pixel < actual.size(); ++pixel) {
            if (expected[pixel] != actual[pixel] && ++mismatches <= 5) {
                ADD_FAILURE() << "filter " << filter << ", pixel " << pixel % view.width << ","
                              << pixel / view.width << ": " << actual[pixel].size()
                              << " fragments, expected " << expected[pixel].size();
            }
        }
        EXPECT_EQ(mismatches, 0u);
        fragment_count = fast.triangles.size();
    }
    return fragment_count;
}

// The fragments of one pixel as (triangle, rank).
std::vector<std::pair<uint32_t, uint32_t>> at(const ExactFragments& fragments, uint32_t px,
                                              uint32_t py) {
    std::vector<std::pair<uint32_t, uint32_t>> out;
    const std::size_t pixel = std::size_t(py) * fragments.width + px;
    for (uint64_t f = fragments.firstFragment(pixel); f < fragments.endFragment(pixel); ++f)
        out.emplace_back(fragments.triangles[f], fragments.ranks[f]);
    return out;
}

// ---------------------------------------------------------------------------------------------

TEST(GroundTruth, CorrectOrderHasNoViolation) {
    const TrianglePositions positions = twoParallelQuads();
    const ViewProjection view = test::perspectiveView(positions, {0, 0, 5}, 32, 32);
    const std::vector<uint32_t> order = {0, 1};
    const test::OrderCheck check = checkVisibilityOrder(positions, view, kTwoQuads, order, {});
    EXPECT_TRUE(check.valid_permutation);
    EXPECT_EQ(check.violation_count, 0u);
    EXPECT_TRUE(check.violations.empty());
    EXPECT_GT(check.pairs_checked, 50u);
    EXPECT_EQ(check.max_depth_complexity, 2u);
}

TEST(GroundTruth, SwappedPairIsReportedWithItsDepths) {
    const TrianglePositions positions = twoParallelQuads();
    const uint32_t size = 32;
    const ViewProjection view = test::perspectiveView(positions, {0, 0, 5}, size, size);
    const std::vector<uint32_t> order = {1, 0};
    const test::OrderCheck check = checkVisibilityOrder(positions, view, kTwoQuads, order, {}, 5);
    EXPECT_TRUE(check.valid_permutation);
    // Every pair found is the front quad over the back one, and every one is violated.
    EXPECT_GT(check.violation_count, 50u);
    EXPECT_EQ(check.violation_count, check.pairs_checked);
    ASSERT_EQ(check.violations.size(), 5u);
    // Depths by hand: planes at distances 5 and 6 from the eye, d = 1 - near / distance.
    for (const test::OrderViolation& violation : check.violations) {
        EXPECT_EQ(violation.front, 0u);
        EXPECT_EQ(violation.behind, 1u);
        EXPECT_NEAR(violation.front_depth, 1 - view.near / 5, 1e-12);
        EXPECT_NEAR(violation.behind_depth, 1 - view.near / 6, 1e-12);
        // The front quad's half-size 1 at distance 5 spans the middle of the image.
        const double x_ndc = 2.0 * (violation.pixel_x + 0.5) / size - 1;
        EXPECT_LT(std::abs(x_ndc) * 5 * std::tan(std::acos(-1.0) / 8), 1.0);
    }
}

TEST(GroundTruth, PairInsideADeclaredCycleIsNotReported) {
    const TrianglePositions positions = twoParallelQuads();
    const ViewProjection view = test::perspectiveView(positions, {0, 0, 5}, 32, 32);
    const std::vector<uint32_t> order = {1, 0};
    const test::OrderCheck check =
        checkVisibilityOrder(positions, view, kTwoQuads, order, {{0, 1}});
    EXPECT_EQ(check.violation_count, 0u);
    EXPECT_GT(check.pairs_checked, 50u);
}

TEST(GroundTruth, NonPermutationsAreDetected) {
    const TrianglePositions positions = twoParallelQuads();
    const ViewProjection view = test::perspectiveView(positions, {0, 0, 5}, 8, 8);
    const std::vector<std::vector<uint32_t>> bad_orders = {{0, 0}, {0}, {0, 1, 1}, {0, 2}, {}};
    for (const std::vector<uint32_t>& order : bad_orders) {
        EXPECT_FALSE(checkVisibilityOrder(positions, view, kTwoQuads, order, {}).valid_permutation);
    }
}

// The front quad is in front at every pixel where both show, in both projections, and the back
// one never in front of it.
TEST(GroundTruth, ParallelQuadsFrontOneInFrontEverywhere) {
    const TrianglePositions positions = twoParallelQuads();
    for (const ViewProjection& view :
         {test::perspectiveView(positions, {0.4, -0.3, 5}, 40, 40), topView(positions),
          test::orthographicView(positions, {0.3, 0.2, -1}, 40, 40)}) {
        EXPECT_EQ(occlusionGraph(positions, view, kTwoQuads), (Graph{{1}, {}}));
        const ExactFragments fragments = exactFragments(positions, view);
        uint64_t both = 0;
        for (std::size_t pixel = 0; pixel < fragments.pixelCount(); ++pixel) {
            uint32_t front_rank = UINT32_MAX, back_rank = UINT32_MAX;
            for (uint64_t f = fragments.firstFragment(pixel); f < fragments.endFragment(pixel);
                 ++f) {
                uint32_t& rank = fragments.triangles[f] < 2 ? front_rank : back_rank;
                rank = std::min(rank, fragments.ranks[f]);
            }
            if (front_rank != UINT32_MAX && back_rank != UINT32_MAX) {
                ++both;
                EXPECT_LT(front_rank, back_rank);
            }
        }
        EXPECT_GT(both, 100u);
    }
}

TEST(GroundTruth, CoplanarQuadsHaveNoOcclusion) {
    TrianglePositions positions;
    addQuad(positions, 1.0, 0.0);
    addQuad(positions, 1.0, 0.0);
    const ViewProjection view = test::perspectiveView(positions, {0.3, 0.2, 5}, 32, 32);
    for (const std::vector<uint32_t>& order : {std::vector<uint32_t>{0, 1}, {1, 0}}) {
        const test::OrderCheck check = checkVisibilityOrder(positions, view, kTwoQuads, order, {});
        EXPECT_EQ(check.pairs_checked, 0u);
        EXPECT_EQ(check.violation_count, 0u);
        EXPECT_EQ(check.max_depth_complexity, 2u);
    }
    EXPECT_EQ(occlusionGraph(positions, view, kTwoQuads), (Graph{{}, {}}));
}

// Two quads in the plane z = 0.3f with different corners and diagonals: wherever both show they
// tie exactly, also seen at a grazing angle; raised by one float ulp, the second is in front.
TEST(GroundTruth, CoplanarOverlappingQuadsTieExactly) {
    const float z = 0.3f;
    const auto scene = [z](float z_second) {
        TrianglePositions positions;
        addTriangle(positions, {-1, -1, z}, {0.5, -1, z}, {0.5, 0.5, z});
        addTriangle(positions, {-1, -1, z}, {0.5, 0.5, z}, {-1, 0.5, z});
        addTriangle(positions, {-0.5, -0.5, z_second}, {1, -0.5, z_second},
                    {-0.5, 1, z_second}); // the other diagonal
        addTriangle(positions, {1, -0.5, z_second}, {1, 1, z_second}, {-0.5, 1, z_second});
        return positions;
    };
    const TrianglePositions flat = scene(z);
    const TrianglePositions raised = scene(std::nextafter(z, 1.0f));
    const std::vector<ViewProjection> views = {
        test::perspectiveView(flat, {0.3, 0.2, 5}, 64, 64),
        test::perspectiveView(flat, {5, 1, 0.8}, 64, 64), // about 5 degrees above the plane
        test::orthographicView(flat, {-1, -0.2, -0.08}, 64, 64)};
    for (const ViewProjection& view : views) {
        const ExactFragments fragments = exactFragments(flat, view);
        uint64_t ties = 0;
        for (std::size_t pixel = 0; pixel < fragments.pixelCount(); ++pixel) {
            bool first = false, second = false;
            for (uint64_t f = fragments.firstFragment(pixel); f < fragments.endFragment(pixel);
                 ++f) {
                EXPECT_EQ(fragments.ranks[f], 0u); // one plane: every fragment at one t
                (fragments.triangles[f] < 2 ? first : second) = true;
            }
            ties += first && second;
        }
        EXPECT_GT(ties, 10u);
        EXPECT_EQ(occlusionGraph(fragments, flat.triangleCount(), kTwoQuads), (Graph{{}, {}}));
        EXPECT_EQ(occlusionGraph(raised, view, kTwoQuads), (Graph{{}, {0}}));
    }
}

// A primitive of 12 triangles: the closed box [lo, hi].
void addBoxPrimitive(TrianglePositions& positions, std::vector<PrimitiveRange>& primitives,
                     const Vec3& lo, const Vec3& hi) {
    const uint32_t first = uint32_t(positions.triangleCount());
    const auto corner = [&](int i) {
        return Vec3{i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z};
    };
    const int faces[6][4] = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1},
                             {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
    for (const auto& f : faces) {
        addTriangle(positions, corner(f[0]), corner(f[1]), corner(f[2]));
        addTriangle(positions, corner(f[0]), corner(f[2]), corner(f[3]));
    }
    primitives.push_back({first, 12});
}

// A box standing on a slab: the box's bottom lies on the slab's top. Seen from above, the box is
// in front of the slab and the touching faces tie (the slab never in front of the box); from
// below, the other way round.
TEST(GroundTruth, BoxOnSlabTouchingFacesTie) {
    TrianglePositions positions;
    std::vector<PrimitiveRange> primitives;
    addBoxPrimitive(positions, primitives, {-2, -0.25, -2}, {2, 0, 2});     // 0: slab
    addBoxPrimitive(positions, primitives, {-0.7, 0, -0.5}, {0.5, 1, 0.6}); // 1: box
    const std::vector<ViewProjection> from_above = {
        test::perspectiveView(positions, {3, 2, 4}, 48, 48),
        test::perspectiveView(positions, {-4, 0.4, 1}, 48, 48),
        test::perspectiveView(positions, {0.3, 6, 0.2}, 48, 48),
        test::orthographicView(positions, {-0.3, -0.6, -1}, 48, 48),
        test::orthographicView(positions, {1, -0.2, 0.3}, 48, 48)};
    for (const ViewProjection& view : from_above) {
        const ExactFragments fragments = exactFragments(positions, view);
        EXPECT_EQ(occlusionGraph(fragments, positions.triangleCount(), primitives),
                  (Graph{{}, {0}}));
        // Somewhere the box's bottom (triangles 16, 17) and the slab's top (triangles 6, 7)
        // both have fragments, at one rank: the tie that keeps the slab behind.
        uint64_t ties = 0;
        for (std::size_t pixel = 0; pixel < fragments.pixelCount(); ++pixel) {
            uint32_t bottom = UINT32_MAX, top = UINT32_MAX;
            for (uint64_t f = fragments.firstFragment(pixel); f < fragments.endFragment(pixel);
                 ++f) {
                const uint32_t t = fragments.triangles[f];
                if (t == 16 || t == 17)
                    bottom = fragments.ranks[f];
                if (t == 6 || t == 7)
                    top = fragments.ranks[f];
            }
            if (bottom != UINT32_MAX && top != UINT32_MAX) {
                ++ties;
                EXPECT_EQ(bottom, top);
            }
        }
        EXPECT_GT(ties, 0u);
    }
    for (const ViewProjection& view : {test::perspectiveView(positions, {3, -2, 4}, 48, 48),
                                       test::orthographicView(positions, {0.2, 0.7, -1}, 48, 48)}) {
        EXPECT_EQ(occlusionGraph(positions, view, primitives), (Graph{{1}, {}}));
    }
}

// Two triangles of different planes folded along a shared edge on the line x = 0.5, where a
// column of pixel centres lies: both have fragments there, tied; neither is in front.
TEST(GroundTruth, CentreOnASharedEdgeIsCoveredByBoth) {
    const ViewProjection view = exactOrthographicView(8, 8);
    expectExactRays(view);
    TrianglePositions positions;
    addTriangle(positions, {0.5, -3, 0}, {0.5, 3, 0}, {-2.5, 0, 1});   // 0: rises to the left
    addTriangle(positions, {0.5, 3, 0}, {0.5, -3, 0}, {3.5, 0, -0.5}); // 1: falls to the right
    const std::vector<PrimitiveRange> primitives = {range(0, 1), range(1, 1)};
    const ExactFragments fragments = exactFragments(positions, view);
    // Centre x = 0.5 is pixel column 4; y = 2.5 .. -2.5 rows 1 .. 6.
    for (uint32_t py = 1; py <= 6; ++py) {
        const BruteLine line = bruteLine(view, 4, py);
        for (uint32_t t = 0; t < 2; ++t) {
            const std::array<Exact, 3> s = edgeDeterminants(positions, t, line);
            EXPECT_EQ(s[0], 0) << "the centre lies on the shared edge";
            EXPECT_NE(s[1], 0);
            EXPECT_NE(s[2], 0);
        }
        EXPECT_EQ(at(fragments, 4, py),
                  (std::vector<std::pair<uint32_t, uint32_t>>{{0, 0}, {1, 0}}));
    }
    // Off the edge, one each: column 3 (x = -0.5) the first, column 5 (x = 1.5) the second.
    EXPECT_EQ(at(fragments, 3, 4), (std::vector<std::pair<uint32_t, uint32_t>>{{0, 0}}));
    EXPECT_EQ(at(fragments, 5, 4), (std::vector<std::pair<uint32_t, uint32_t>>{{1, 0}}));
    EXPECT_EQ(occlusionGraph(fragments, positions.triangleCount(), primitives), (Graph{{}, {}}));
    expectSameAsBruteForce(positions, view);
}

// The same with a slanted shared edge whose corners use all 24 bits of a float: the centre
// (0.5, -0.5) of pixel (4, 4) is the edge's midpoint.
TEST(GroundTruth, CentreOnASlantedSharedEdgeIsCoveredByBoth) {
    const ViewProjection view = exactOrthographicView(8, 8);
    expectExactRays(view);
    // Half the edge, (0.1, 0.7) to within 2^-24: 0.5 -+ it and -0.5 -+ it are floats.
    const double half_x = std::ldexp(1677721.0, -24), half_y = std::ldexp(5872025.0, -23);
    const Vec3 a{0.5 - half_x, -0.5 - half_y, 0}, b{0.5 + half_x, -0.5 + half_y, 0};
    ASSERT_EQ(double(float(a.x)), a.x);
    ASSERT_EQ(double(float(a.y)), a.y);
    ASSERT_EQ(double(float(b.x)), b.x);
    ASSERT_EQ(double(float(b.y)), b.y);
    TrianglePositions positions;
    addTriangle(positions, a, b, {-2.5, 1.5, 1});    // 0: left of the edge, rising
    addTriangle(positions, b, a, {3.5, -2.5, -0.5}); // 1: right of it, falling
    const BruteLine line = bruteLine(view, 4, 4);
    for (uint32_t t = 0; t < 2; ++t) {
        const std::array<Exact, 3> s = edgeDeterminants(positions, t, line);
        EXPECT_EQ(s[0], 0) << "the centre lies on the shared edge";
        EXPECT_NE(s[1], 0);
        EXPECT_NE(s[2], 0);
    }
    const ExactFragments fragments = exactFragments(positions, view);
    EXPECT_EQ(at(fragments, 4, 4), (std::vector<std::pair<uint32_t, uint32_t>>{{0, 0}, {1, 0}}));
    EXPECT_EQ(occlusionGraph(fragments, positions.triangleCount(),
                             std::vector<PrimitiveRange>{range(0, 1), range(1, 1)}),
              (Graph{{}, {}}));
    expectSameAsBruteForce(positions, view);
}

// An edge through a pixel centre covers it (closed triangle); moved one float ulp away it does
// not, moved one ulp the other way it still does. A slanted and a vertical edge.
TEST(GroundTruth, EdgeOneUlpFromACentre) {
    const ViewProjection view = exactOrthographicView(8, 8);
    expectExactRays(view);
    const auto covers = [&](const TrianglePositions& positions, uint32_t px, uint32_t py) {
        return !at(exactFragments(positions, view), px, py).empty();
    };
    // The edge from (-1.5, -2.5) to (x_end, 1.5); at x_end = 2.5 it passes through the centre
    // (0.5, -0.5) of pixel (4, 4), the triangle lying above it.
    const auto slanted = [](float x_end) {
        TrianglePositions positions;
        addTriangle(positions, {-1.5, -2.5, 0}, {x_end, 1.5, 0}, {-1.5, 1.5, 0});
        return positions;
    };
    EXPECT_TRUE(covers(slanted(2.5f), 4, 4));
    EXPECT_TRUE(covers(slanted(std::nextafter(2.5f, 3.0f)), 4, 4));  // edge just below the centre
    EXPECT_FALSE(covers(slanted(std::nextafter(2.5f, 2.0f)), 4, 4)); // edge just above it
    // The vertical edge x = x_edge, the triangle to its right; centres at x = 0.5 in column 4.
    const auto vertical = [](float x_edge) {
        TrianglePositions positions;
        addTriangle(positions, {x_edge, -3, 0}, {3.5, 0, 0}, {x_edge, 3, 0});
        return positions;
    };
    for (uint32_t py = 1; py <= 6; ++py) {
        EXPECT_TRUE(covers(vertical(0.5f), 4, py));
        EXPECT_TRUE(covers(vertical(std::nextafter(0.5f, 0.0f)), 4, py));
        EXPECT_FALSE(covers(vertical(std::nextafter(0.5f, 1.0f)), 4, py));
    }
}

// Two parallel quads 1e-6 apart relative to their distance, and one float ulp apart: the higher
// one is in front at every pixel, whichever is listed first; any depth tolerance of that size
// would call them a tie.
TEST(GroundTruth, TinyDepthDifferenceIsOrdered) {
    const float low = 0.3f;
    for (const float high : {low * (1 + 1e-6f), std::nextafter(low, 1.0f)}) {
        ASSERT_GT(high, low);
        for (const bool high_first : {false, true}) {
            TrianglePositions positions;
            addQuad(positions, 1.0, high_first ? high : low);
            addQuad(positions, 1.0, high_first ? low : high);
            const Graph expected = high_first ? Graph{{1}, {}} : Graph{{}, {0}};
            for (const ViewProjection& view :
                 {test::perspectiveView(positions, {0.2, 0.1, 5}, 32, 32),
                  test::orthographicView(positions, {0.1, -0.2, -1}, 32, 32)}) {
                EXPECT_EQ(occlusionGraph(positions, view, kTwoQuads), expected);
                const std::vector<uint32_t> high_then_low =
                    high_first ? std::vector<uint32_t>{0, 1} : std::vector<uint32_t>{1, 0};
                const std::vector<uint32_t> low_then_high = {high_then_low[1], high_then_low[0]};
                EXPECT_EQ(checkVisibilityOrder(positions, view, kTwoQuads, high_then_low, {})
                              .violation_count,
                          0u);
                EXPECT_GT(checkVisibilityOrder(positions, view, kTwoQuads, low_then_high, {})
                              .violation_count,
                          100u);
            }
        }
    }
}

TEST(GroundTruth, OcclusionGraphOfPartialOverlap) {
    TrianglePositions positions;
    addQuad(positions, 1.0, -0.5);                                              // 0
    addTriangle(positions, {-0.5, -0.5, 0.5}, {0.5, -0.5, 0.5}, {0, 0.5, 0.5}); // 1: over 0
    addTriangle(positions, {1.5, 1.5, 0.8}, {1.9, 1.5, 0.8}, {1.7, 1.9, 0.8});  // 2: beside
    const std::vector<PrimitiveRange> primitives = {range(0, 2), range(2, 1), range(3, 1)};
    for (const ViewProjection& view :
         {test::perspectiveView(positions, {0.1, 0.2, 5}, 48, 48), topView(positions)}) {
        EXPECT_EQ(occlusionGraph(positions, view, primitives), (Graph{{}, {0}, {}}));
    }
}

TEST(GroundTruth, TrianglesOutsideEveryPrimitiveAreIgnored) {
    TrianglePositions positions = twoParallelQuads();
    addQuad(positions, 3.0, 0.5); // triangles 4, 5 over both: in no primitive
    const ViewProjection view = test::perspectiveView(positions, {0, 0, 5}, 32, 32);
    EXPECT_EQ(occlusionGraph(positions, view, kTwoQuads), (Graph{{1}, {}}));
    const std::vector<PrimitiveRange> three = {range(0, 2), range(2, 2), range(4, 2)};
    EXPECT_EQ(occlusionGraph(positions, view, three), (Graph{{1}, {}, {0, 1}}));
}

TEST(GroundTruth, CyclicSticks) {
    const TrianglePositions positions = cyclicSticks();
    const ViewProjection view = topView(positions);
    const Graph graph = occlusionGraph(positions, view, kThreeSticks);
    EXPECT_EQ(graph, (Graph{{2}, {0}, {1}}));
    EXPECT_EQ(test::cyclicComponents(graph), (Graph{{0, 1, 2}}));
    EXPECT_EQ(test::occlusionCycles(positions, view, kThreeSticks), (Graph{{0, 1, 2}}));

    // Every order breaks the cycle somewhere, unless the cycle is declared.
    std::vector<uint32_t> order = {0, 1, 2};
    do {
        EXPECT_GT(checkVisibilityOrder(positions, view, kThreeSticks, order, {}).violation_count,
                  0u);
        EXPECT_EQ(
            checkVisibilityOrder(positions, view, kThreeSticks, order, {{0, 1, 2}}).violation_count,
            0u);
    } while (std::next_permutation(order.begin(), order.end()));
    // A cycle that leaves out one stick excuses only the pairs inside it.
    const std::vector<uint32_t> two_one_zero = {2, 1, 0}; // violates 0 over 2 only
    const test::OrderCheck check =
        checkVisibilityOrder(positions, view, kThreeSticks, two_one_zero, {{0, 1}});
    ASSERT_FALSE(check.violations.empty());
    for (const test::OrderViolation& violation : check.violations) {
        EXPECT_EQ(violation.front, 0u);
        EXPECT_EQ(violation.behind, 2u);
        EXPECT_LT(violation.front_depth, violation.behind_depth);
    }
}

// A floor y = -1 reaching behind the eye, seen from the origin with near = 2: the rows whose
// line meets the floor nearer than the near plane have no fragment, though the line meets the
// triangle there; the rows beyond have them.
TEST(GroundTruth, TriangleCrossingTheNearPlane) {
    const uint32_t size = 32;
    const ViewProjection view = perspectiveFromOrigin(size, 2.0);
    TrianglePositions positions;
    addTriangle(positions, {-6, -1, 1}, {6, -1, 1}, {0, -1, -12});
    const ExactFragments fragments = exactFragments(positions, view);
    EXPECT_EQ(fragments.statistics.clipped_triangles, 1u);
    // Row py has y_ndc = 1 - (2 py + 1) / 32 and meets the floor at distance 1 / |y_ndc|:
    // beyond the near plane (2) for rows 16 .. 23, nearer for rows 24 .. 31.
    for (uint32_t py = 20; py < size; ++py) {
        for (uint32_t px = 0; px < size; ++px) {
            const BruteLine line = bruteLine(view, px, py);
            const std::array<Exact, 3> s = edgeDeterminants(positions, 0, line);
            ASSERT_TRUE((s[0] > 0 && s[1] > 0 && s[2] > 0) || (s[0] < 0 && s[1] < 0 && s[2] < 0))
                << "the line meets the triangle at " << px << "," << py;
            EXPECT_EQ(at(fragments, px, py).size(), py < 24 ? 1u : 0u) << px << "," << py;
        }
    }
    for (uint64_t f = 0; f < fragments.triangles.size(); ++f)
        EXPECT_GE(fragments.depths[f], 0.0); // d = 1 - near / z >= 0 where z >= near
    EXPECT_GT(expectSameAsBruteForce(positions, view), 100u);
}

// Random triangles that cross each other, of random sizes, in general position and on a grid
// where centres fall on edges and faces coincide: the fast path against the exact brute force.
TrianglePositions randomTriangles(uint32_t count, uint32_t seed, bool on_grid) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::uniform_int_distribution<int> cell(-20, 20), level(-4, 4);
    TrianglePositions positions;
    for (uint32_t i = 0; i < count; ++i) {
        Vec3 corners[3];
        for (Vec3& v : corners) {
            v = on_grid ? Vec3{0.5 * cell(rng), 0.5 * cell(rng), 0.5 * level(rng)}
                        : Vec3{unit(rng), unit(rng), unit(rng)};
        }
        addTriangle(positions, corners[0], corners[1], corners[2]);
    }
    if (on_grid) {
        // Exact copies and a degenerate triangle.
        for (uint32_t t : {0u, 3u, 7u}) {
            addTriangle(positions, positions.corner(3 * t + 1), positions.corner(3 * t + 2),
                        positions.corner(3 * t));
        }
        addTriangle(positions, {-3, -3, 0}, {0, 0, 0}, {3, 3, 0});
    }
    return positions;
}

TEST(GroundTruth, FastPathMatchesExactBruteForce) {
    const TrianglePositions general = randomTriangles(30, 7, false);
    for (const ViewProjection& view :
         {test::perspectiveView(general, {1.8, 1.5, 3}, 32, 32),
          test::orthographicView(general, {-0.3, -0.5, -1}, 32, 32),
          test::perspectiveView(general, {0.1, 0.2, 0.3}, 32, 32)}) { // eye inside the soup
        EXPECT_GT(expectSameAsBruteForce(general, view), 500u);
    }
    // From inside, some triangles cross the near plane: their candidates come from clipping.
    EXPECT_GT(exactFragments(general, test::perspectiveView(general, {0.1, 0.2, 0.3}, 32, 32))
                  .statistics.clipped_triangles,
              0u);
    const TrianglePositions grid = randomTriangles(30, 11, true);
    const ViewProjection exact_view = exactOrthographicView(32, 32);
    expectExactRays(exact_view);
    const ExactFragments fragments = exactFragments(grid, exact_view);
    EXPECT_GT(fragments.statistics.exact_depths, 0u); // the copies tie
    EXPECT_GT(expectSameAsBruteForce(grid, exact_view), 500u);
    EXPECT_GT(expectSameAsBruteForce(grid, test::perspectiveView(grid, {2, 3, 12}, 32, 32)), 500u);
}

// The same fragments, bit for bit, whatever the thread count.
TEST(GroundTruth, ResultDoesNotDependOnThreadCount) {
    TrianglePositions positions = test::randomLayeredSoup(1500, 5);
    const TrianglePositions crossing = randomTriangles(300, 9, false);
    for (std::size_t i = 0; i < crossing.x.size(); ++i) {
        positions.x.push_back(crossing.x[i]);
        positions.y.push_back(crossing.y[i]);
        positions.z.push_back(crossing.z[i]);
    }
    const ViewProjection view = test::perspectiveView(positions, {1, 2, 4}, 96, 80);
    const ExactFragments reference = exactFragments(positions, view, {.thread_count = 1});
    EXPECT_GT(reference.triangles.size(), 10000u);
    for (const unsigned threads : {1u, 2u, 3u, 8u}) {
        const ExactFragments fragments = exactFragments(positions, view, {.thread_count = threads});
        EXPECT_EQ(fragments.offsets, reference.offsets);
        EXPECT_EQ(fragments.triangles, reference.triangles);
        EXPECT_EQ(fragments.ranks, reference.ranks);
        EXPECT_EQ(fragments.depths, reference.depths);
    }
}

} // namespace
} // namespace vissort
