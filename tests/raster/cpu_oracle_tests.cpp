// CpuOracle against the reference CpuReferenceOracle: the same answer to every query and the same
// depth buffer, bit for bit, after the same clears and draws, on random soups, slabs, shared-edge
// grids and real meshes, through both projections, at many viewport sizes; and the same Vis-sort
// order. Every comparison runs with the AVX2 row walk (where the CPU has it) and with the scalar
// one; the pass-level batches also with 1, 2 and 3 screen bands, against the default sequential
// implementations over CpuReferenceOracle.

#include "vissort/cpu_oracle.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "scenes/scene_library.h"
#include "vissort/cpu_reference_oracle.h"
#include "vissort/scene.h"
#include "vissort/vis_sort.h"
#include "vissort/worker_pool.h"

namespace vissort {
namespace {

// A negative tolerance, as the transparency renderer sets (kBlendingDepthTolerance): near ties
// count as occlusion.
constexpr float kNegativeTolerance = -1.0f / (1 << 16);

bool sameBits(std::span<const float> a, std::span<const float> b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

// The row walks: SIMD allowed (AVX2 where the CPU has it), and the scalar fallback (compared
// with CpuReferenceOracle), each drawing and querying triangle by triangle and through depth
// images of every primitive (however small).
std::vector<CpuOracleOptions> rowWalks() {
    std::vector<CpuOracleOptions> all;
    for (bool simd : {true, false})
        for (uint32_t image_min_triangles : {0u, 1u}) {
            CpuOracleOptions options;
            options.allow_simd = simd;
            options.threads = 1;
            options.image_min_triangles = image_min_triangles;
            all.push_back(options);
        }
    return all;
}

// Both row walks with 1, 2 and 3 threads, every pass split into bands however small.
std::vector<CpuOracleOptions> rowWalksAndThreads() {
    std::vector<CpuOracleOptions> all;
    for (CpuOracleOptions options : rowWalks())
        for (uint32_t threads : {1u, 2u, 3u}) {
            options.threads = threads;
            options.parallel_threshold = 0;
            all.push_back(options);
        }
    return all;
}

std::string describe(const CpuOracleOptions& options) {
    return std::string(options.allow_simd ? "simd" : "scalar") + ", " +
           std::to_string(options.threads) + " threads, images from " +
           std::to_string(options.image_min_triangles) + " triangles";
}

// Random clears, draws and queries, in the same order on both oracles; every answer and, after
// The same random clears, draws and queries on two bound oracles: every answer and the depth
// buffer after every draw must be the same bits. Returns how many queries found a fragment behind.
std::size_t interleave(CpuReferenceOracle& reference, CpuOracle& fast, uint32_t seed,
                       int operations) {
    EXPECT_EQ(fast.primitiveCount(), reference.primitiveCount());
    EXPECT_EQ(fast.width(), reference.width());
    EXPECT_EQ(fast.height(), reference.height());
    EXPECT_TRUE(sameBits(fast.depthBuffer(), reference.depthBuffer()));
    if (reference.primitiveCount() == 0)
        return 0;
    std::mt19937 rng(seed);
    std::uniform_int_distribution<uint32_t> pick(0, reference.primitiveCount() - 1);
    std::uniform_real_distribution<double> action(0, 1);
    std::size_t behind = 0;
    for (int op = 0; op < operations; ++op) {
        const double a = action(rng);
        const uint32_t id = pick(rng);
        if (a < 0.03) {
            reference.clear();
            fast.clear();
        } else if (a < 0.5) {
            reference.draw(id);
            fast.draw(id);
            if (!sameBits(fast.depthBuffer(), reference.depthBuffer())) {
                ADD_FAILURE() << "depth buffers differ after draw " << id << " (operation " << op
                              << ", seed " << seed << ")";
                return behind;
            }
        } else {
            const bool expected = reference.anyBehind(id);
            const bool got = fast.anyBehind(id);
            if (expected != got) {
                ADD_FAILURE() << "anyBehind(" << id << ") = " << got << ", reference " << expected
                              << " (operation " << op << ", seed " << seed << ")";
                return behind;
            }
            behind += expected;
        }
    }
    EXPECT_TRUE(sameBits(fast.depthBuffer(), reference.depthBuffer()));
    return behind;
}

// every draw, the depth buffers compared. Returns how many queries answered true (so that a test
// can check it exercised both answers); adds the fast oracle's tile counts to totals if given.
std::size_t compareInterleavingWith(const CpuOracleOptions& options, const TrianglePositions& p,
                                    const ViewProjection& view,
                                    std::span<const PrimitiveRange> primitives, uint32_t seed,
                                    int operations, CpuOracleStats* totals,
                                    float tolerance = kDepthTolerance) {
    SCOPED_TRACE(describe(options) + ", tolerance " + std::to_string(tolerance));
    CpuReferenceOracle reference;
    CpuOracle fast(options);
    reference.setDepthTolerance(tolerance);
    fast.setDepthTolerance(tolerance);
    reference.bind(p, view, primitives);
    fast.bind(p, view, primitives);
    const std::size_t behind = interleave(reference, fast, seed, operations);
    if (totals != nullptr) {
        totals->tiles_visited += fast.stats().tiles_visited;
        totals->tiles_culled += fast.stats().tiles_culled;
        totals->tiles_accepted += fast.stats().tiles_accepted;
        totals->images_built += fast.stats().images_built;
        totals->arbitrations += fast.stats().arbitrations;
    }
    return behind;
}

// compareInterleavingWith for both row walks, with the default tolerance and the blending one
// (negative: the tile shortcuts must hold for both signs); returns the true answers of the first.
std::size_t compareInterleaving(const TrianglePositions& p, const ViewProjection& view,
                                std::span<const PrimitiveRange> primitives, uint32_t seed,
                                int operations, CpuOracleStats* totals = nullptr) {
    std::size_t behind = 0;
    bool first = true;
    for (float tolerance : {kDepthTolerance, kNegativeTolerance})
        for (const CpuOracleOptions& options : rowWalks()) {
            const std::size_t b = compareInterleavingWith(options, p, view, primitives, seed,
                                                          operations, totals, tolerance);
            if (first)
                behind = b;
            first = false;
        }
    return behind;
}

// The pixels where any of targets has a fragment: where a group test's depth buffer is defined
// (occlusion_oracle.h).
std::vector<uint8_t> pixelsOf(const TrianglePositions& p, const ViewProjection& view,
                              std::span<const PrimitiveRange> primitives,
                              std::span<const uint32_t> targets) {
    CpuReferenceOracle oracle;
    oracle.bind(p, view, primitives);
    oracle.clear();
    for (uint32_t t : targets)
        oracle.draw(t);
    std::vector<uint8_t> covered;
    for (float d : oracle.depthBuffer())
        covered.push_back(std::isfinite(d) ? 1 : 0);
    return covered;
}

// Equal bit for bit where mask is set.
bool sameBitsWhere(std::span<const float> a, std::span<const float> b,
                   std::span<const uint8_t> mask) {
    if (a.size() != b.size() || a.size() != mask.size())
        return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (mask[i] && std::memcmp(&a[i], &b[i], sizeof(float)) != 0)
            return false;
    return true;
}

// The pass-level batches against the default sequential ones over CpuReferenceOracle, with random
// sequences and query flags: every answer, and the depth buffer after each pass, bit for bit.
// behind is filled with a marker first, so an entry a pass must not touch is checked too.
void comparePasses(const TrianglePositions& p, const ViewProjection& view,
                   std::span<const PrimitiveRange> primitives, uint32_t seed) {
    if (primitives.empty())
        return;
    for (const CpuOracleOptions& options : rowWalksAndThreads()) {
        SCOPED_TRACE(describe(options));
        CpuReferenceOracle reference;
        reference.bind(p, view, primitives);
        CpuOracle fast(options);
        fast.bind(p, view, primitives);
        std::mt19937 rng(seed);
        for (int round = 0; round < 6; ++round) {
            std::vector<uint32_t> sequence(primitives.size());
            for (uint32_t i = 0; i < sequence.size(); ++i)
                sequence[i] = i;
            std::shuffle(sequence.begin(), sequence.end(), rng);
            sequence.resize(1 + rng() % sequence.size());
            std::vector<uint8_t> query(sequence.size());
            for (uint8_t& q : query)
                q = uint8_t(rng() % 4 != 0);
            std::vector<uint8_t> expected(sequence.size(), 7), got(sequence.size(), 7);
            const int kind = round % 3;
            if (kind == 0) {
                reference.backToFrontPass(sequence, query, expected);
                fast.backToFrontPass(sequence, query, got);
            } else if (kind == 1) {
                reference.frontToBackPass(sequence, query, expected);
                fast.frontToBackPass(sequence, query, got);
            } else {
                const std::size_t split = rng() % (sequence.size() + 1);
                const std::span<const uint32_t> occluders(sequence.data(), split);
                const std::span<const uint32_t> targets(sequence.data() + split,
                                                        sequence.size() - split);
                expected.resize(targets.size());
                got.resize(targets.size());
                reference.queryAgainst(occluders, targets, expected);
                fast.queryAgainst(occluders, targets, got);
                ASSERT_EQ(got, expected) << "group test, round " << round;
                // The buffer is defined where the targets have fragments; elsewhere the fast
                // oracle leaves out occluders that cannot change an answer.
                ASSERT_TRUE(sameBitsWhere(fast.depthBuffer(), reference.depthBuffer(),
                                          pixelsOf(p, view, primitives, targets)))
                    << "group test, round " << round;
                continue;
            }
            ASSERT_EQ(got, expected) << "pass kind " << kind << ", round " << round;
            ASSERT_TRUE(sameBits(fast.depthBuffer(), reference.depthBuffer()))
                << "pass kind " << kind << ", round " << round;
        }
    }
}

// Every primitive drawn in order, then every primitive queried: the pass-like access pattern;
// then the pass-level batches.
void compareDrawAllThenQueryAll(const TrianglePositions& p, const ViewProjection& view,
                                std::span<const PrimitiveRange> primitives) {
    for (const CpuOracleOptions& options : rowWalks()) {
        SCOPED_TRACE(describe(options));
        CpuReferenceOracle reference;
        CpuOracle fast(options);
        reference.bind(p, view, primitives);
        fast.bind(p, view, primitives);
        for (uint32_t i = 0; i < primitives.size(); ++i) {
            reference.draw(i);
            fast.draw(i);
        }
        ASSERT_TRUE(sameBits(fast.depthBuffer(), reference.depthBuffer()));
        for (uint32_t i = 0; i < primitives.size(); ++i)
            ASSERT_EQ(fast.anyBehind(i), reference.anyBehind(i)) << "primitive " << i;
    }
    comparePasses(p, view, primitives, uint32_t(primitives.size()));
}

// Random triangles in [-1, 1]^3 with legs between min_size and max_size.
TrianglePositions randomSoup(uint32_t seed, std::size_t count, double min_size, double max_size) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(-1, 1);
    std::uniform_real_distribution<double> size(min_size, max_size);
    TrianglePositions p;
    for (std::size_t t = 0; t < count; ++t) {
        const double cx = unit(rng), cy = unit(rng), cz = unit(rng), s = size(rng);
        for (int k = 0; k < 3; ++k) {
            p.x.push_back(float(cx + s * unit(rng)));
            p.y.push_back(float(cy + s * unit(rng)));
            p.z.push_back(float(cz + s * unit(rng)));
        }
    }
    return p;
}

// A (cells + 1)^2 vertex grid of layers at different depths, slightly tilted: every interior edge
// is shared by two triangles of a layer.
TrianglePositions sharedEdgeGrid(int cells, int layers) {
    TrianglePositions p;
    const auto vertex = [&](int i, int j, int layer) {
        const double x = -1 + 2.0 * i / cells, y = -1 + 2.0 * j / cells;
        // Irrational-looking offsets keep vertices off pixel centres but shared exactly.
        const double jitter = 0.3 / cells * std::sin(7.1 * i + 3.3 * j);
        p.x.push_back(float(x + jitter));
        p.y.push_back(float(y - jitter));
        p.z.push_back(float(-0.5 * layer + 0.05 * x + 0.02 * y));
    };
    for (int layer = 0; layer < layers; ++layer)
        for (int i = 0; i < cells; ++i)
            for (int j = 0; j < cells; ++j) {
                vertex(i, j, layer), vertex(i + 1, j, layer), vertex(i + 1, j + 1, layer);
                vertex(i, j, layer), vertex(i + 1, j + 1, layer), vertex(i, j + 1, layer);
            }
    return p;
}

ViewProjection viewOf(const Bounds& bounds, Projection projection, uint32_t width, uint32_t height,
                      Vec3 eye = {0.7, 0.5, 4}) {
    CameraSpec spec;
    spec.projection = projection;
    spec.eye = eye;
    spec.target = {0, 0, 0};
    spec.ortho_direction = {-0.2, -0.1, -1};
    return frameCamera(spec, bounds, width, height);
}

struct Case {
    Projection projection;
    uint32_t width, height;
};

std::string caseName(const ::testing::TestParamInfo<Case>& info) {
    return std::string(info.param.projection == Projection::perspective ? "Perspective" : "Ortho") +
           std::to_string(info.param.width) + "x" + std::to_string(info.param.height);
}

class CpuOracleMatches : public ::testing::TestWithParam<Case> {};

TEST_P(CpuOracleMatches, RandomSoupOfSingleTriangles) {
    const Case c = GetParam();
    std::size_t behind = 0;
    for (uint32_t seed = 1; seed <= 3; ++seed) {
        const TrianglePositions p = randomSoup(seed, 200, 0.02, 0.6);
        const std::vector<PrimitiveRange> primitives = [&] {
            std::vector<PrimitiveRange> r;
            for (uint32_t t = 0; t < p.triangleCount(); ++t)
                r.push_back({t, 1});
            return r;
        }();
        const ViewProjection view = viewOf(p.bounds(), c.projection, c.width, c.height);
        behind += compareInterleaving(p, view, primitives, seed, 1500);
        compareDrawAllThenQueryAll(p, view, primitives);
    }
    if (c.width * c.height >= 17 * 13) {
        EXPECT_GT(behind, 0u); // both answers exercised
    }
}

TEST_P(CpuOracleMatches, SoupSeenFromInsideCrossesTheNearPlaneAndScreenEdges) {
    const Case c = GetParam();
    const TrianglePositions p = randomSoup(11, 300, 0.1, 1.0);
    std::vector<PrimitiveRange> primitives;
    for (uint32_t t = 0; t + 3 <= p.triangleCount(); t += 3)
        primitives.push_back({t, 3});
    // The eye inside the soup: many triangles cross the near plane or lie behind the eye.
    const ViewProjection view =
        viewOf(p.bounds(), c.projection, c.width, c.height, {0.1, 0.05, 0.2});
    compareInterleaving(p, view, primitives, 5, 1500);
    compareDrawAllThenQueryAll(p, view, primitives);
}

TEST_P(CpuOracleMatches, SharedEdgeGridLayers) {
    const Case c = GetParam();
    const TrianglePositions p = sharedEdgeGrid(9, 3);
    std::vector<PrimitiveRange> per_triangle, per_layer;
    for (uint32_t t = 0; t < p.triangleCount(); ++t)
        per_triangle.push_back({t, 1});
    const uint32_t per = uint32_t(p.triangleCount() / 3);
    for (uint32_t l = 0; l < 3; ++l)
        per_layer.push_back({l * per, per});
    const ViewProjection view = viewOf(p.bounds(), c.projection, c.width, c.height);
    compareInterleaving(p, view, per_triangle, 7, 2000);
    compareInterleaving(p, view, per_layer, 8, 200);
    compareDrawAllThenQueryAll(p, view, per_triangle);
    compareDrawAllThenQueryAll(p, view, per_layer);
}

TEST_P(CpuOracleMatches, BuiltinSlabsAndSoup) {
    const Case c = GetParam();
    for (const char* spec : {"builtin:slabs?layers=6", "builtin:soup?n=300"}) {
        const Result<Scene> loaded = samples::loadScene(spec);
        ASSERT_TRUE(loaded) << loaded.error;
        const Scene& scene = *loaded.value;
        const ViewProjection view = frameCamera(
            [&] {
                CameraSpec s = defaultCamera(scene.positions.bounds());
                s.projection = c.projection;
                return s;
            }(),
            scene.positions.bounds(), c.width, c.height);
        const auto triangles = scene.trianglePrimitives();
        const auto objects = scene.objectPrimitives();
        compareInterleaving(scene.positions, view, triangles, 21, 1500);
        compareInterleaving(scene.positions, view, objects, 22, 300);
        compareDrawAllThenQueryAll(scene.positions, view, triangles);
    }
}

INSTANTIATE_TEST_SUITE_P(
    ProjectionsAndSizes, CpuOracleMatches,
    ::testing::Values(Case{Projection::perspective, 1, 1}, Case{Projection::orthographic, 1, 1},
                      Case{Projection::perspective, 3, 5}, Case{Projection::orthographic, 3, 5},
                      Case{Projection::perspective, 17, 13}, Case{Projection::orthographic, 17, 13},
                      Case{Projection::perspective, 64, 48}, Case{Projection::orthographic, 64, 48},
                      Case{Projection::perspective, 203, 111}),
    caseName);

TEST(CpuOracle, SpotMeshBothProjections) {
    const Result<Scene> loaded =
        samples::loadScene(std::string(VISSORT_SOURCE_DIR) + "/assets/models/spot.obj");
    ASSERT_TRUE(loaded) << loaded.error;
    const TrianglePositions& p = loaded.value->positions;
    std::vector<PrimitiveRange> triangles;
    for (uint32_t t = 0; t < p.triangleCount(); ++t)
        triangles.push_back({t, 1});
    CpuOracleStats totals;
    std::size_t behind = 0;
    for (Projection projection : {Projection::perspective, Projection::orthographic})
        for (auto [w, h] : {std::pair<uint32_t, uint32_t>{17, 13}, {160, 120}, {640, 480}}) {
            CameraSpec spec = defaultCamera(p.bounds(), double(w) / h);
            spec.projection = projection;
            const ViewProjection view = frameCamera(spec, p.bounds(), w, h);
            behind += compareInterleaving(p, view, triangles, w, 3000, &totals);
            compareDrawAllThenQueryAll(p, view, triangles);
            // The whole mesh as one primitive.
            const PrimitiveRange whole{0, uint32_t(p.triangleCount())};
            behind += compareInterleaving(p, view, std::span(&whole, 1), 3, 20, &totals);
        }
    EXPECT_GT(behind, 0u);
    EXPECT_GT(totals.tiles_culled, 0u);
}

// Faces that meet where the floats cannot tell them apart, as CAD assemblies' parts do: boxes
// sharing faces, coplanar overlapping squares, stacks of copies of one face, squares crossing
// along a line, all on a lattice of quarters so that the ties are exact; and squares apart by a
// few units in the last place, or crossing at such an angle, which the exact model finds nearer.
// Every pixel they share is arbitrated by the exact model from the pixel's own list of covering
// set-ups (and, through depth images, the primitive's set-ups from the tile's index); the answers
// must be the reference's, which arbitrates against every drawn triangle.
TrianglePositions touchingCoplanarAndCrossingFaces(uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> lattice(-4, 3);
    TrianglePositions p;
    const auto corner = [&](double x, double y, double z) {
        p.x.push_back(float(x));
        p.y.push_back(float(y));
        p.z.push_back(float(z));
    };
    // The square [x0, x0 + s] x [y0, y0 + s] at depth z (axis 2), or its turns onto the other axes.
    const auto square = [&](double a0, double b0, double c, double s, int axis) {
        const auto at = [&](double a, double b) {
            if (axis == 2)
                corner(a, b, c);
            else if (axis == 1)
                corner(a, c, b);
            else
                corner(c, a, b);
        };
        at(a0, b0), at(a0 + s, b0), at(a0 + s, b0 + s);
        at(a0, b0), at(a0 + s, b0 + s), at(a0, b0 + s);
    };
    for (int i = 0; i < 24; ++i) {
        const double a = lattice(rng) * 0.25, b = lattice(rng) * 0.25, c = lattice(rng) * 0.25;
        const double s = 0.25 * (1 + rng() % 4);
        // A few units in the last place: apart by less than the floats can see at a pixel.
        const double nudge = double(std::nextafter(std::nextafter(float(c), 9.0f), 9.0f)) - c;
        switch (rng() % 6) {
        case 0: // a box: its six faces, sharing planes with the boxes beside it
            for (int axis = 0; axis < 3; ++axis) {
                square(a, b, c, s, axis);
                square(a, b, c + s, s, axis);
            }
            break;
        case 1: // coplanar squares overlapping
            square(a, b, c, s, 2);
            square(a + 0.25, b + 0.25, c, s, 2);
            break;
        case 2: // a stack of copies of one square
            for (int copy = 0; copy < 5; ++copy)
                square(a, b, c, s, 2);
            break;
        case 3: // two squares apart by a nudge, the second nearer or farther by the camera
            square(a, b, c, s, 2);
            square(a + 0.25, b, c + nudge, s, 2);
            break;
        case 4: // two squares crossing at an angle too shallow for the floats
            square(a, b, c, s, 2);
            corner(a, b, c - nudge), corner(a + s, b, c + nudge), corner(a + s, b + s, c + nudge);
            corner(a, b, c - nudge), corner(a + s, b + s, c + nudge), corner(a, b + s, c - nudge);
            break;
        default: // two squares crossing along a line
            square(a, b, c, s, 2);
            corner(a, b, c - s / 2), corner(a + s, b, c + s / 2), corner(a + s, b + s, c + s / 2);
            corner(a, b, c - s / 2), corner(a + s, b + s, c + s / 2), corner(a, b + s, c - s / 2);
            break;
        }
    }
    return p;
}

TEST(CpuOracle, TiesOfTouchingCoplanarAndCrossingFacesAreDecidedAsTheReferenceDoes) {
    for (uint32_t seed : {1u, 2u, 3u}) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        const TrianglePositions p = touchingCoplanarAndCrossingFaces(seed);
        std::vector<PrimitiveRange> per_triangle, per_group;
        for (uint32_t t = 0; t < p.triangleCount(); ++t)
            per_triangle.push_back({t, 1});
        for (uint32_t t = 0; t < p.triangleCount(); t += 12)
            per_group.push_back({t, std::min<uint32_t>(12, uint32_t(p.triangleCount()) - t)});
        for (Projection projection : {Projection::perspective, Projection::orthographic}) {
            const ViewProjection view = viewOf(p.bounds(), projection, 157, 93);
            CpuOracleStats totals;
            compareInterleaving(p, view, per_triangle, seed, 1500, &totals);
            compareInterleaving(p, view, per_group, seed + 10, 300, &totals);
            EXPECT_GT(totals.arbitrations, 0u); // the ties were the exact model's to decide
            comparePasses(p, view, per_group, seed + 20);
            compareDrawAllThenQueryAll(p, view, per_triangle);
            compareDrawAllThenQueryAll(p, view, per_group);
        }
    }
}

TEST(CpuOracle, LargeViewportWithBigTriangles) {
    const TrianglePositions p = randomSoup(99, 12, 0.8, 2.0);
    std::vector<PrimitiveRange> primitives;
    for (uint32_t t = 0; t < p.triangleCount(); ++t)
        primitives.push_back({t, 1});
    for (Projection projection : {Projection::perspective, Projection::orthographic}) {
        const ViewProjection view = viewOf(p.bounds(), projection, 1600, 1200);
        CpuOracleStats totals;
        const std::size_t behind = compareInterleaving(p, view, primitives, 4, 120, &totals);
        EXPECT_GT(behind, 0u);
        EXPECT_GT(totals.tiles_culled, 0u);
        compareDrawAllThenQueryAll(p, view, primitives);
        const ViewProjection inside = viewOf(p.bounds(), projection, 1600, 1200, {0.1, 0, 0.3});
        compareInterleaving(p, inside, primitives, 6, 120);
    }
}

TEST(CpuOracle, WholeTilesAreCulledAndAcceptedWithTheReferenceAnswers) {
    // 0 and 1: squares of half-side 1 at height z, two triangles each, inside the screen.
    // 2 and 3: one triangle each, much larger than the screen: it covers every tile.
    TrianglePositions p;
    const auto square = [&](double r, double z) {
        const double c[6][2] = {{-r, -r}, {r, -r}, {r, r}, {-r, -r}, {r, r}, {-r, r}};
        for (const auto& v : c) {
            p.x.push_back(float(v[0]));
            p.y.push_back(float(v[1]));
            p.z.push_back(float(z));
        }
    };
    square(1, 0.5);
    square(1, -0.5);
    for (double z : {0.5, -0.5})
        for (const auto& v : {std::array<double, 2>{-20, -20}, {40, -20}, {-20, 40}}) {
            p.x.push_back(float(v[0]));
            p.y.push_back(float(v[1]));
            p.z.push_back(float(z));
        }
    const std::vector<PrimitiveRange> primitives{{0, 2}, {2, 2}, {4, 1}, {5, 1}};
    Bounds b;
    b.add({-3, -3, -1});
    b.add({3, 3, 1});
    const ViewProjection view = viewOf(b, Projection::orthographic, 256, 192, {0, 0, 4});
    for (const CpuOracleOptions& options : rowWalks()) {
        if (options.image_min_triangles != 0)
            continue; // the triangle-by-triangle walk's tile shortcuts are the subject here
        SCOPED_TRACE(describe(options));
        CpuReferenceOracle reference;
        CpuOracle fast(options);
        reference.bind(p, view, primitives);
        fast.bind(p, view, primitives);
        const auto both_draw = [&](uint32_t id) {
            reference.draw(id);
            fast.draw(id);
            EXPECT_TRUE(sameBits(fast.depthBuffer(), reference.depthBuffer()))
                << "after draw " << id;
        };
        const auto both_query = [&](uint32_t id) {
            const bool expected = reference.anyBehind(id);
            EXPECT_EQ(fast.anyBehind(id), expected) << "query " << id;
            return expected;
        };

        // The view is tilted, so the squares are sloped in depth.
        both_draw(0);
        EXPECT_TRUE(both_query(1));
        EXPECT_FALSE(both_query(0)); // itself: coplanar tiles culled by depth bounds
        EXPECT_GT(fast.stats().tiles_culled, 0u);
        fast.resetStats();
        both_draw(1); // entirely behind: the tiles inside square 0 culled by depth bounds
        EXPECT_GT(fast.stats().tiles_culled, 0u);

        // The screen-filling near triangle makes every tile's bounds exact; the far one is then
        // behind in the first tile, which is wholly covered: accepted without per-pixel work.
        reference.clear();
        fast.clear();
        both_draw(2);
        fast.resetStats();
        EXPECT_TRUE(both_query(3));
        EXPECT_EQ(fast.stats().tiles_accepted, 1u);
        EXPECT_FALSE(both_query(2));
        EXPECT_FALSE(both_query(0)); // on the plane of 2
        EXPECT_TRUE(both_query(1));
        both_draw(3);
        both_draw(1);
    }
}

TEST(CpuOracle, EmptyPrimitivesAndRebind) {
    TrianglePositions p = randomSoup(3, 20, 0.1, 0.5);
    std::vector<PrimitiveRange> primitives{{0, 0}, {0, 20}, {5, 0}, {19, 1}};
    const ViewProjection view = viewOf(p.bounds(), Projection::perspective, 40, 30);
    compareInterleaving(p, view, primitives, 1, 200);
    CpuOracle fast;
    fast.bind(p, view, primitives);
    fast.draw(1);
    fast.bind(p, viewOf(p.bounds(), Projection::orthographic, 7, 9), primitives); // clears
    EXPECT_EQ(fast.depthBuffer().size(), 63u);
    for (float d : fast.depthBuffer())
        EXPECT_EQ(d, std::numeric_limits<float>::infinity());
    EXPECT_FALSE(fast.anyBehind(1));
    fast.bind(p, view, {});
    EXPECT_EQ(fast.primitiveCount(), 0u);
}

// rebind (multi-stage ordering's groups after the frame's objects) copies the bind's set-ups:
// the reference answers for groups of triangles in shuffled order, clipped fans included (the eye
// inside the soup), in both modes; a view, triangle or positions the bind did not set up binds.
TEST(CpuOracle, RebindReusesTheSetUpsOfTheBindWithTheReferenceAnswers) {
    TrianglePositions p = randomSoup(11, 300, 0.1, 1.0);
    std::vector<PrimitiveRange> objects;
    for (uint32_t t = 0; t + 10 <= 290; t += 10) // triangles 290..299 in no object
        objects.push_back({t, 10});
    const ViewProjection view =
        viewOf(p.bounds(), Projection::perspective, 67, 45, {0.1, 0.05, 0.2});
    std::mt19937 rng(4);
    const auto shuffledTriangles = [&](uint32_t first, uint32_t end) {
        std::vector<PrimitiveRange> group;
        for (uint32_t t = first; t < end; ++t)
            group.push_back({t, 1});
        std::shuffle(group.begin(), group.end(), rng);
        return group;
    };
    for (const CpuOracleOptions& options : rowWalks()) {
        SCOPED_TRACE(describe(options));
        CpuOracle fast(options);
        CpuReferenceOracle reference;
        fast.bind(p, view, objects);
        reference.bind(p, view, objects);
        interleave(reference, fast, 1, 300);
        // Groups of the bound triangles, one after another, and a group of two objects.
        // The whole group also with empty ranges, one where the positions end.
        std::vector<PrimitiveRange> with_empty = shuffledTriangles(0, 290);
        with_empty.insert(with_empty.begin() + 20, PrimitiveRange{300, 0});
        with_empty.push_back({7, 0});
        const std::vector<std::vector<PrimitiveRange>> groups{shuffledTriangles(0, 40),
                                                              shuffledTriangles(120, 150),
                                                              with_empty,
                                                              {{40, 10}, {10, 10}}};
        for (std::size_t g = 0; g < groups.size(); ++g) {
            SCOPED_TRACE("group " + std::to_string(g));
            fast.rebind(p, view, groups[g]);
            reference.bind(p, view, groups[g]);
            EXPECT_GT(interleave(reference, fast, uint32_t(10 + g), 400), 0u);
        }
        // Triangles the bind did not set up; another view: each binds afresh.
        const std::vector<PrimitiveRange> unbound = shuffledTriangles(280, 300);
        fast.rebind(p, view, unbound);
        reference.bind(p, view, unbound);
        interleave(reference, fast, 20, 300);
        const ViewProjection other =
            viewOf(p.bounds(), Projection::orthographic, 31, 52, {0.3, -0.2, 0.1});
        fast.rebind(p, other, groups[2]);
        reference.bind(p, other, groups[2]);
        interleave(reference, fast, 21, 300);
        // Positions changed in place and bound again: the rebind after it sees them.
        const TrianglePositions original = p;
        for (float& x : p.x)
            x = x * 0.5f + 0.1f;
        fast.bind(p, view, objects);
        fast.rebind(p, view, groups[1]);
        reference.bind(p, view, groups[1]);
        interleave(reference, fast, 22, 300);
        p = original; // the same arrays, as a dynamic scene's frames are
    }
}

// Primitives of many overlapping triangles (a primitive then occludes itself: its image must
// hold its nearest and farthest fragments per pixel, not its last), in random groups.
TEST(CpuOracle, DepthImagesOfPrimitivesOfManyTriangles) {
    const TrianglePositions p = randomSoup(21, 240, 0.1, 0.9);
    std::vector<PrimitiveRange> primitives;
    std::mt19937 rng(5);
    for (uint32_t t = 0; t < p.triangleCount();) {
        const uint32_t n = std::min<uint32_t>(1 + rng() % 40, uint32_t(p.triangleCount()) - t);
        primitives.push_back({t, n});
        t += n;
    }
    for (Projection projection : {Projection::perspective, Projection::orthographic}) {
        const ViewProjection view = viewOf(p.bounds(), projection, 203, 111);
        CpuOracleStats totals;
        EXPECT_GT(compareInterleaving(p, view, primitives, 8, 400, &totals), 0u);
        EXPECT_GT(totals.images_built, 0u); // the configurations with images used them
        comparePasses(p, view, primitives, 9);
        compareDrawAllThenQueryAll(p, view, primitives);
        // The camera among the triangles: clipped fans, primitives crossing the screen's edges.
        compareInterleaving(p, viewOf(p.bounds(), projection, 203, 111, {0.1, 0, 0.3}), primitives,
                            10, 400);
    }
}

TEST(CpuOracle, DepthImagesAreMadeOncePerBindWithinTheirBudget) {
    const Result<Scene> loaded = samples::loadScene("builtin:bunnies?n=4");
    ASSERT_TRUE(loaded) << loaded.error;
    const Scene& scene = *loaded.value;
    const auto objects = scene.objectPrimitives();
    const ViewProjection view = frameCamera(defaultCamera(scene.positions.bounds(), 4.0 / 3),
                                            scene.positions.bounds(), 320, 240);
    CpuReferenceOracle reference;
    reference.bind(scene.positions, view, objects);
    CpuOracle fast; // the defaults: every bunny has far more triangles than the threshold
    fast.bind(scene.positions, view, objects);
    CpuOracleOptions no_room;
    no_room.image_budget_bytes = 1000; // three covered tiles: less than any bunny covers
    CpuOracle direct(no_room);
    direct.bind(scene.positions, view, objects);
    std::size_t answers[2] = {0, 0}; // false, true: both must be compared
    for (int round = 0; round < 3; ++round)
        for (uint32_t id = 0; id < objects.size(); ++id) {
            // Blending's negative tolerance on the last round: images made for the other one
            // must not answer for it.
            const float tolerance = round == 2 ? kNegativeTolerance : kDepthTolerance;
            for (GeometryOracle* o :
                 std::initializer_list<GeometryOracle*>{&reference, &fast, &direct})
                o->setDepthTolerance(tolerance);
            const bool expected = reference.anyBehind(id);
            ++answers[expected];
            EXPECT_EQ(fast.anyBehind(id), expected) << "round " << round << ", object " << id;
            EXPECT_EQ(direct.anyBehind(id), expected) << "round " << round << ", object " << id;
            reference.draw(id);
            fast.draw(id);
            direct.draw(id);
            EXPECT_TRUE(sameBits(fast.depthBuffer(), reference.depthBuffer()));
            EXPECT_TRUE(sameBits(direct.depthBuffer(), reference.depthBuffer()));
        }
    EXPECT_GT(answers[0], 0u);
    EXPECT_GT(answers[1], 0u);
    // A near and a far image per object for each tolerance, each made once.
    EXPECT_EQ(fast.stats().images_built, 2 * 2 * objects.size());
    EXPECT_EQ(direct.stats().images_built, 0u);
    fast.bind(scene.positions, view, objects); // a new bind: new images
    fast.resetStats();
    fast.draw(0);
    fast.draw(0);
    EXPECT_EQ(fast.stats().images_built, 1u);
}

TEST(CpuOracle, OptionsChooseTheRowWalkAndThreads) {
    CpuOracleOptions options;
    options.allow_simd = false;
    options.threads = 3;
    const CpuOracle scalar(options);
    EXPECT_FALSE(scalar.usesSimd());
    EXPECT_EQ(scalar.threadCount(), 3u);
    const CpuOracle defaults;
    EXPECT_EQ(defaults.threadCount(), 1u); // all work on the calling thread unless asked
    options.threads = 0;                   // one per core
    const CpuOracle per_core(options);
    EXPECT_EQ(per_core.threadCount(), std::clamp(std::thread::hardware_concurrency(), 1u, 256u));
    options.threads = 1000;
    EXPECT_EQ(CpuOracle(options).threadCount(), 256u);
}

TEST(CpuOracle, PassesOnALargeViewportMatchWithEveryBandCount) {
    const TrianglePositions p = randomSoup(5, 400, 0.05, 0.8);
    std::vector<PrimitiveRange> primitives;
    for (uint32_t t = 0; t < p.triangleCount(); ++t)
        primitives.push_back({t, 1});
    for (Projection projection : {Projection::perspective, Projection::orthographic})
        comparePasses(p, viewOf(p.bounds(), projection, 803, 611), primitives, 17);
}

// The one-pass occlusion graph's strips split over 1, 2 and 3 threads give the same edges, in
// the same order (here, in the raster tests, so that ThreadSanitizer runs its bands; its edges
// are checked against the exact ground truth in tests/order/occlusion_graph_tests.cpp).
TEST(CpuOracle, OcclusionGraphIsTheSameOnEveryThreadCount) {
    const TrianglePositions p = randomSoup(4, 160, 0.2, 0.6);
    std::vector<PrimitiveRange> primitives;
    for (uint32_t t = 0; t < p.triangleCount(); ++t)
        primitives.push_back({t, 1});
    const ViewProjection view = frameCamera({}, p.bounds(), 160, 120);
    std::vector<uint32_t> members(primitives.size());
    for (uint32_t i = 0; i < members.size(); ++i)
        members[i] = uint32_t(members.size()) - 1 - i;
    std::vector<std::vector<Occlusion>> graphs;
    for (uint32_t threads : {1u, 2u, 3u}) {
        CpuOracleOptions options;
        options.threads = threads;
        options.parallel_threshold = 0;
        CpuOracle oracle(options);
        oracle.bind(p, view, primitives);
        graphs.emplace_back();
        EXPECT_TRUE(oracle.occlusionGraph(members, graphs.back()));
    }
    EXPECT_GT(graphs[0].size(), 50u);
    EXPECT_EQ(graphs[1], graphs[0]);
    EXPECT_EQ(graphs[2], graphs[0]);
}

TEST(CpuOracle, VisSortOrderMatchesReferenceOnBunnies) {
    const Result<Scene> loaded = samples::loadScene("builtin:bunnies?n=6");
    ASSERT_TRUE(loaded) << loaded.error;
    const Scene& scene = *loaded.value;
    const auto primitives = scene.trianglePrimitives();
    for (Projection projection : {Projection::perspective, Projection::orthographic}) {
        CameraSpec spec = scene.camera ? *scene.camera : defaultCamera(scene.positions.bounds());
        spec.projection = projection;
        const ViewProjection view = frameCamera(spec, scene.positions.bounds(), 256, 192);
        {
            std::vector<uint32_t> start(primitives.size());
            for (uint32_t i = 0; i < start.size(); ++i)
                start[i] = uint32_t(start.size()) - 1 - i;
            CpuReferenceOracle reference;
            reference.bind(scene.positions, view, primitives);
            const VisibilityOrder expected = visSort(reference, start);
            // Determinism: the same order, cycles and counts for every row walk and thread count.
            // (Not the final buffer: a call that ends in the cycle search ends with a group
            // test, whose buffer is defined only where its targets are; comparePasses checks
            // the buffers.)
            for (const CpuOracleOptions& options : rowWalksAndThreads()) {
                SCOPED_TRACE(describe(options));
                CpuOracle fast(options);
                fast.bind(scene.positions, view, primitives);
                const VisibilityOrder got = visSort(fast, start);
                EXPECT_EQ(got.order, expected.order);
                EXPECT_EQ(got.cycles, expected.cycles);
                EXPECT_EQ(got.stats.queries, expected.stats.queries);
                EXPECT_EQ(got.stats.iterations, expected.stats.iterations);
                EXPECT_EQ(fast.stats().queries, reference.stats().queries);
                EXPECT_EQ(fast.stats().draws, reference.stats().draws);
            }
        }
    }
}

// What one oracle leaves after Vis-sort over a scene: for comparing runs.
struct SortRun {
    VisibilityOrder order;
    std::vector<float> depths;
    uint64_t draws = 0, queries = 0;
};

SortRun sortWith(const CpuOracleOptions& options, const Scene& scene, const ViewProjection& view,
                 std::span<const PrimitiveRange> primitives, std::span<const uint32_t> start) {
    CpuOracle fast(options);
    fast.bind(scene.positions, view, primitives);
    SortRun run;
    run.order = visSort(fast, start);
    const std::span<const float> depths = fast.depthBuffer();
    run.depths.assign(depths.begin(), depths.end());
    run.draws = fast.stats().draws;
    run.queries = fast.stats().queries;
    return run;
}

void expectSameRun(const SortRun& got, const SortRun& expected) {
    EXPECT_EQ(got.order.order, expected.order.order);
    EXPECT_EQ(got.order.cycles, expected.order.cycles);
    EXPECT_EQ(got.order.stats.queries, expected.order.stats.queries);
    EXPECT_EQ(got.draws, expected.draws);
    EXPECT_EQ(got.queries, expected.queries);
    EXPECT_TRUE(sameBits(got.depths, expected.depths));
}

// Two oracles with 2 threads each, sorting from two threads at once (they share
// WorkerPool::shared(), whose runs take turns): the same orders, counts and depth buffers as the
// same sorts one after the other. Run under ThreadSanitizer in CI (scripts/test.sh --tsan).
TEST(CpuOracleThreads, TwoOraclesOnTwoThreadsMatchSequentialRuns) {
    const Result<Scene> loaded = samples::loadScene("builtin:bunnies?n=2");
    ASSERT_TRUE(loaded) << loaded.error;
    const Scene& scene = *loaded.value;
    const auto primitives = scene.trianglePrimitives();
    std::vector<uint32_t> start(primitives.size());
    for (uint32_t i = 0; i < start.size(); ++i)
        start[i] = uint32_t(start.size()) - 1 - i;
    CpuOracleOptions options;
    options.threads = 2;
    options.parallel_threshold = 0;
    CameraSpec spec = scene.camera ? *scene.camera : defaultCamera(scene.positions.bounds());
    std::array<ViewProjection, 2> views;
    for (int k = 0; k < 2; ++k) {
        spec.projection = k == 0 ? Projection::perspective : Projection::orthographic;
        views[k] = frameCamera(spec, scene.positions.bounds(), 96 + 32 * k, 80);
    }
    std::array<SortRun, 2> sequential;
    for (int k = 0; k < 2; ++k)
        sequential[k] = sortWith(options, scene, views[k], primitives, start);
    ASSERT_GT(sequential[0].queries, 0u);

    constexpr int kRounds = 3;
    std::array<std::vector<SortRun>, 2> concurrent;
    std::array<std::thread, 2> threads;
    for (int k = 0; k < 2; ++k)
        threads[k] = std::thread([&, k] {
            for (int round = 0; round < kRounds; ++round)
                concurrent[k].push_back(sortWith(options, scene, views[k], primitives, start));
        });
    for (std::thread& t : threads)
        t.join();
    for (int k = 0; k < 2; ++k)
        for (int round = 0; round < kRounds; ++round) {
            SCOPED_TRACE("oracle " + std::to_string(k) + ", round " + std::to_string(round));
            expectSameRun(concurrent[k][round], sequential[k]);
        }
}

// A pool passed in options is the one used: its thread count is the oracle's, its runs count the
// banded passes, and the shared pool is left alone; the answers stay the reference's.
TEST(CpuOracleThreads, CallerPoolIsUsed) {
    const TrianglePositions p = randomSoup(11, 300, 0.05, 0.8);
    std::vector<PrimitiveRange> primitives;
    for (uint32_t t = 0; t < p.triangleCount(); ++t)
        primitives.push_back({t, 1});
    const ViewProjection view = viewOf(p.bounds(), Projection::perspective, 200, 150);
    WorkerPool pool(3);
    EXPECT_EQ(pool.threadCount(), 3u);
    CpuOracleOptions options;
    options.threads = 2; // ignored: the pool's count is used
    options.parallel_threshold = 0;
    options.pool = &pool;
    CpuOracle fast(options);
    EXPECT_EQ(fast.threadCount(), 3u);
    CpuReferenceOracle reference;
    fast.bind(p, view, primitives);
    reference.bind(p, view, primitives);
    std::vector<uint32_t> sequence(primitives.size());
    for (uint32_t i = 0; i < sequence.size(); ++i)
        sequence[i] = i;
    const std::vector<uint8_t> query(sequence.size(), 1);
    std::vector<uint8_t> expected(sequence.size()), got(sequence.size());
    const uint64_t shared_runs = WorkerPool::shared().runCount();
    reference.backToFrontPass(sequence, query, expected);
    fast.backToFrontPass(sequence, query, got);
    EXPECT_EQ(got, expected);
    EXPECT_TRUE(sameBits(fast.depthBuffer(), reference.depthBuffer()));
    const std::span<const uint32_t> occluders(sequence.data(), sequence.size() / 2);
    const std::span<const uint32_t> targets(sequence.data() + sequence.size() / 2,
                                            sequence.size() - sequence.size() / 2);
    expected.resize(targets.size());
    got.resize(targets.size());
    reference.queryAgainst(occluders, targets, expected);
    fast.queryAgainst(occluders, targets, got);
    EXPECT_EQ(got, expected);
    EXPECT_EQ(pool.runCount(), 2u);
    EXPECT_EQ(WorkerPool::shared().runCount(), shared_runs);
}

// The pool itself: every task runs once per run, on as many threads as asked, when runs come from
// several threads at once and the pool grows between them.
TEST(CpuOracleThreads, WorkerPoolRunsFromSeveralThreadsTakeTurns) {
    WorkerPool pool(2);
    constexpr int kRuns = 200;
    constexpr uint32_t kCallers = 3;
    std::array<std::array<uint32_t, 4>, kCallers> counts{}; // per caller, per task index
    std::array<std::thread, kCallers> callers;
    for (uint32_t c = 0; c < kCallers; ++c)
        callers[c] = std::thread([&, c] {
            if (c == 2)
                pool.reserve(4);
            for (int r = 0; r < kRuns; ++r) {
                const uint32_t tasks = std::min<uint32_t>(1 + uint32_t(r) % 4, pool.threadCount());
                // Each task writes its own counter: another caller's run never overlaps.
                pool.run(
                    tasks,
                    [](void* context, uint32_t index) {
                        ++(*static_cast<std::array<uint32_t, 4>*>(context))[index];
                    },
                    &counts[c]);
            }
        });
    for (std::thread& t : callers)
        t.join();
    EXPECT_EQ(pool.threadCount(), 4u);
    EXPECT_EQ(pool.runCount(), uint64_t(kRuns) * kCallers);
    for (uint32_t c = 0; c < kCallers; ++c)
        EXPECT_EQ(counts[c][0], uint32_t(kRuns));
    pool.reserve(2); // never shrinks
    EXPECT_EQ(pool.threadCount(), 4u);
}

} // namespace
} // namespace vissort
