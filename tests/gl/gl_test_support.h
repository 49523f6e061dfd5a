#pragma once
// What the OpenGL tests share: the process's context, views of a scene, random scenes, and the
// comparison of the gl oracle's answers with the exact oracle's (depth tolerance 0: every exact
// "behind" must be a gl "behind"; the extra ones are counted).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <random>
#include <span>
#include <string>
#include <vector>

#include "vissort/camera.h"
#include "vissort/exact_oracle.h"
#include "vissort/gl_context.h"
#include "vissort/gl_oracle.h"
#include "vissort/scene.h"

namespace vissort::test {

inline std::shared_ptr<GlContext> glContext() {
    static const Result<std::shared_ptr<GlContext>> shared = GlContext::shared();
    if (!shared)
        ADD_FAILURE() << shared.error;
    return shared ? *shared.value : nullptr;
}

/// The scene's camera (or the default one) in either projection: orthographic along the
/// perspective camera's direction, so that the same overlaps are seen.
inline ViewProjection sceneView(const Scene& scene, Projection projection, uint32_t width,
                                uint32_t height) {
    CameraSpec camera =
        scene.camera.value_or(defaultCamera(scene.positions.bounds(), double(width) / height));
    if (projection == Projection::orthographic) {
        camera.ortho_direction = camera.target - camera.eye;
        camera.projection = Projection::orthographic;
    }
    return frameCamera(camera, scene.positions.bounds(), width, height);
}

/// A view from eye towards the origin (orthographic: along a fixed oblique direction).
inline ViewProjection obliqueView(const Bounds& bounds, Projection projection, uint32_t width,
                                  uint32_t height, Vec3 eye = {0.7, 0.5, 4}) {
    CameraSpec spec;
    spec.projection = projection;
    spec.eye = eye;
    spec.target = {0, 0, 0};
    spec.ortho_direction = {-0.2, -0.1, -1};
    return frameCamera(spec, bounds, width, height);
}

/// Random triangles in [-1, 1]^3 with legs between min_size and max_size.
inline TrianglePositions randomSoup(uint32_t seed, std::size_t count, double min_size,
                                    double max_size) {
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

/// A (cells + 1)^2 vertex grid of layers at different depths, slightly tilted: every interior
/// edge is shared by two triangles of a layer.
inline TrianglePositions sharedEdgeGrid(int cells, int layers) {
    TrianglePositions p;
    const auto vertex = [&](int i, int j, int layer) {
        const double x = -1 + 2.0 * i / cells, y = -1 + 2.0 * j / cells;
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

/// One range per triangle.
inline std::vector<PrimitiveRange> eachTriangle(const TrianglePositions& p) {
    std::vector<PrimitiveRange> r;
    for (uint32_t t = 0; t < p.triangleCount(); ++t)
        r.push_back({t, 1});
    return r;
}

/// The gl oracle's answers against the exact oracle's. A query of a primitive drawn since the
/// last clear (which Vis-sort never makes: each pass draws an element after its query) meets its
/// own fragments, an exact tie that gl counts as behind: such answers are tallied apart.
struct Tally {
    uint64_t answers = 0;      // queries answered by both, of primitives not drawn since a clear
    uint64_t exact_behind = 0; // of those, behind in the exact model
    uint64_t missed = 0;       // behind exactly, not for gl, of all answers: must stay 0
    uint64_t extra = 0;        // behind for gl, not exactly: the cost of deciding in the driver
    uint64_t self_answers = 0; // queries of a primitive drawn since the last clear
    uint64_t self_extra = 0;   // of those, behind for gl, not exactly

    void add(bool exact, bool gl, bool drawn_itself = false) {
        missed += exact && !gl ? 1 : 0;
        if (drawn_itself) {
            ++self_answers;
            self_extra += gl && !exact ? 1 : 0;
            return;
        }
        ++answers;
        exact_behind += exact ? 1 : 0;
        extra += gl && !exact ? 1 : 0;
    }
    /// Of the answers that are "not behind" exactly, the share gl called behind.
    double extraRate() const {
        const uint64_t not_behind = answers - exact_behind;
        return not_behind == 0 ? 0.0 : double(extra) / double(not_behind);
    }
    std::string describe() const {
        return std::to_string(answers) + " answers, " + std::to_string(exact_behind) +
               " behind exactly, " + std::to_string(missed) + " missed by gl, " +
               std::to_string(extra) + " extra gl behind (" + std::to_string(100 * extraRate()) +
               "% of the exact not-behind); queries of a drawn primitive: " +
               std::to_string(self_extra) + " extra of " + std::to_string(self_answers);
    }
};

/// The same random clears, draws and queries on both bound oracles; every answer tallied, and
/// a failure added at the first exact "behind" that gl does not report.
inline void interleave(ExactOracle& exact, GlOracle& gl, uint32_t seed, int operations,
                       Tally& tally) {
    if (exact.primitiveCount() == 0)
        return;
    std::mt19937 rng(seed);
    std::uniform_int_distribution<uint32_t> pick(0, exact.primitiveCount() - 1);
    std::uniform_real_distribution<double> action(0, 1);
    std::vector<uint8_t> drawn(exact.primitiveCount(), 0); // since the last clear
    for (int op = 0; op < operations; ++op) {
        const double a = action(rng);
        const uint32_t id = pick(rng);
        if (a < 0.03) {
            exact.clear();
            gl.clear();
            drawn.assign(drawn.size(), 0);
        } else if (a < 0.5) {
            exact.draw(id);
            gl.draw(id);
            drawn[id] = 1;
        } else {
            const bool expected = exact.anyBehind(id);
            const bool got = gl.anyBehind(id);
            tally.add(expected, got, drawn[id] != 0);
            if (expected && !got) {
                ADD_FAILURE() << "anyBehind(" << id << "): exactly behind, not for gl (operation "
                              << op << ", seed " << seed << ")";
                return;
            }
        }
    }
}

/// The pass-level batches (both passes, plain and over random groups, and the group test) on
/// random sequences and query flags, both oracles: every exact "behind" must be gl's. In pass 2
/// gl then draws whatever exact draws, and more: its later answers stay a superset. Entries not
/// queried must be left alone.
inline void comparePasses(ExactOracle& exact, GlOracle& gl, uint32_t seed, int rounds,
                          Tally& tally) {
    const uint32_t n = exact.primitiveCount();
    if (n == 0)
        return;
    std::mt19937 rng(seed);
    const auto compare = [&](std::span<const uint8_t> expected, std::span<const uint8_t> got,
                             std::span<const uint8_t> query, const char* pass) {
        for (std::size_t i = 0; i < expected.size(); ++i) {
            if (!query.empty() && !query[i]) {
                EXPECT_EQ(got[i], 7) << pass << ": entry " << i << " was not queried";
                continue;
            }
            tally.add(expected[i] == 1, got[i] == 1);
            EXPECT_FALSE(expected[i] == 1 && got[i] != 1)
                << pass << ": entry " << i << " exactly behind, not for gl (seed " << seed << ")";
        }
    };
    for (int round = 0; round < rounds; ++round) {
        std::vector<uint32_t> sequence(n);
        for (uint32_t i = 0; i < n; ++i)
            sequence[i] = i;
        std::shuffle(sequence.begin(), sequence.end(), rng);
        std::vector<uint8_t> query(n);
        for (uint8_t& q : query)
            q = uint8_t(rng() % 3 != 0);
        std::vector<uint8_t> expected(n, 7), got(n, 7);
        exact.backToFrontPass(sequence, query, expected);
        gl.backToFrontPass(sequence, query, got);
        compare(expected, got, query, "pass 1");
        expected.assign(n, 7);
        got.assign(n, 7);
        exact.frontToBackPass(sequence, query, expected);
        gl.frontToBackPass(sequence, query, got);
        compare(expected, got, query, "pass 2");
        const std::span<const uint32_t> occluders(sequence.data(), n / 2);
        const std::span<const uint32_t> targets(sequence.data() + n / 2, n - n / 2);
        std::vector<uint8_t> expected_group(targets.size()), got_group(targets.size());
        exact.queryAgainst(occluders, targets, expected_group);
        gl.queryAgainst(occluders, targets, got_group);
        compare(expected_group, got_group, {}, "group test");
        // The passes over groups: the sequence cut into groups of 1 to 4 members, against the
        // exact oracle's, which are the definitions in primitive operations.
        std::vector<uint32_t> first{0};
        while (first.back() < n)
            first.push_back(std::min<uint32_t>(n, first.back() + 1 + rng() % 4));
        const std::size_t groups = first.size() - 1;
        std::vector<uint8_t> group_query(groups);
        for (uint8_t& q : group_query)
            q = uint8_t(rng() % 3 != 0);
        expected.assign(groups, 7);
        got.assign(groups, 7);
        exact.backToFrontGroupPass(sequence, first, group_query, std::span(expected).first(groups));
        gl.backToFrontGroupPass(sequence, first, group_query, std::span(got).first(groups));
        compare(std::span(expected).first(groups), std::span(got).first(groups), group_query,
                "group pass 1");
        expected.assign(groups, 7);
        got.assign(groups, 7);
        exact.frontToBackGroupPass(sequence, first, group_query, std::span(expected).first(groups));
        gl.frontToBackGroupPass(sequence, first, group_query, std::span(got).first(groups));
        compare(std::span(expected).first(groups), std::span(got).first(groups), group_query,
                "group pass 2");
    }
}

/// Whether every cycle of `inner` lies inside one cycle of `outer` (both lists of id sets).
inline bool cyclesContained(const std::vector<std::vector<uint32_t>>& inner,
                            const std::vector<std::vector<uint32_t>>& outer) {
    for (const std::vector<uint32_t>& cycle : inner) {
        bool found = false;
        for (const std::vector<uint32_t>& candidate : outer) {
            std::vector<uint32_t> a = cycle, b = candidate;
            std::sort(a.begin(), a.end());
            std::sort(b.begin(), b.end());
            if (std::includes(b.begin(), b.end(), a.begin(), a.end()))
                found = true;
        }
        if (!found)
            return false;
    }
    return true;
}

} // namespace vissort::test
