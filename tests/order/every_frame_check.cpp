#include "every_frame_check.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <sstream>

#include "exact_ground_truth.h"
#include "ground_truth.h"
#include "tarjan_scc.h"

namespace vissort::test {

std::string EveryFrameTally::describe() const {
    std::ostringstream out;
    out << frames << " frames, " << orders << " orders, " << pairs_checked
        << " occlusions checked, " << violations << " out of order, " << true_cycles
        << " true cycles; gl cycle members " << gl_cycle_members << " (" << extra_gl_members
        << " beyond the true components), " << hinted_cycles << " confirmed from the last frame";
    return out.str();
}

struct EveryFrameCheck::Runner {
    OrderedPair pair;
    double seconds = 0; // ordering, summed over the frames
    std::unique_ptr<GeometryOracle> oracle;
    std::unique_ptr<SceneOrderer> orderer;
};

EveryFrameCheck::EveryFrameCheck(std::span<const PrimitiveRange> objects, uint32_t triangle_count,
                                 const std::vector<OrderedPair>& pairs)
    : objects_(objects.begin(), objects.end()), triangle_count_(triangle_count) {
    for (const OrderedPair& pair : pairs) {
        Result<std::unique_ptr<GeometryOracle>> oracle = makeOracle(pair.oracle);
        if (!oracle) {
            ADD_FAILURE() << oracleName(pair.oracle) << ": " << oracle.error;
            continue;
        }
        auto runner = std::make_unique<Runner>();
        runner->pair = pair;
        runner->oracle = std::move(*oracle.value);
        runner->orderer =
            std::make_unique<SceneOrderer>(objects_, triangle_count_, pair.level, *runner->oracle);
        runners_.push_back(std::move(runner));
    }
}

EveryFrameCheck::~EveryFrameCheck() = default;

namespace {

// The cycles of a level's exact occlusion graph.
std::vector<std::vector<uint32_t>> trueCycles(const ExactFragments& fragments,
                                              std::size_t triangle_count,
                                              std::span<const PrimitiveRange> primitives) {
    return cyclicComponents(occlusionGraph(fragments, triangle_count, primitives));
}

} // namespace

void EveryFrameCheck::checkFrame(PositionsView positions, const ViewProjection& view,
                                 const std::string& where) {
    const ExactFragments fragments = exactFragments(positions, view);
    const std::vector<PrimitiveRange> object_level =
        levelPrimitives(objects_, triangle_count_, OrderLevel::object);
    const std::vector<PrimitiveRange> triangle_level =
        levelPrimitives(objects_, triangle_count_, OrderLevel::triangle);
    // Per level, made on first need: the true components.
    std::vector<std::vector<uint32_t>> object_cycles, triangle_cycles;
    bool have_object_cycles = false, have_triangle_cycles = false;
    const auto cyclesOf = [&](OrderLevel level) -> const std::vector<std::vector<uint32_t>>& {
        if (level == OrderLevel::object) {
            if (!have_object_cycles)
                object_cycles = trueCycles(fragments, triangle_count_, object_level);
            have_object_cycles = true;
            return object_cycles;
        }
        if (!have_triangle_cycles)
            triangle_cycles = trueCycles(fragments, triangle_count_, triangle_level);
        have_triangle_cycles = true;
        return triangle_cycles;
    };

    ++tally_.frames;
    for (const std::unique_ptr<Runner>& runner : runners_) {
        const OrderLevel level = runner->pair.level;
        const std::string name = where + ", " + oracleName(runner->pair.oracle) + " at " +
                                 orderLevelName(level) + " level";
        SCOPED_TRACE(name);
        const auto start = std::chrono::steady_clock::now();
        const FrameOrder frame = runner->orderer->orderFrame(positions, view);
        runner->seconds +=
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const std::vector<PrimitiveRange>& primitives =
            level == OrderLevel::object ? object_level : triangle_level;
        const OrderCheck check =
            checkVisibilityOrder(fragments, triangle_count_, primitives, frame.order, frame.cycles);
        ++tally_.orders;
        tally_.hinted_cycles += frame.stats.hinted_cycles;
        ASSERT_TRUE(check.valid_permutation);
        tally_.pairs_checked += check.pairs_checked;
        tally_.violations += check.violation_count;
        if (check.violation_count != 0) {
            const OrderViolation& v = check.violations.front();
            ADD_FAILURE() << check.violation_count << " occlusions out of order; first: " << v.front
                          << " in front of " << v.behind << " at pixel (" << v.pixel_x << ", "
                          << v.pixel_y << "), depths " << v.front_depth << " and "
                          << v.behind_depth;
        }
        const std::vector<std::vector<uint32_t>>& truth = cyclesOf(level);
        tally_.true_cycles += truth.size();
        if (runner->pair.oracle != OracleKind::gl) {
            std::vector<std::vector<uint32_t>> reported = frame.cycles; // in output order
            std::sort(reported.begin(), reported.end());
            std::vector<std::vector<uint32_t>> expected = truth;
            std::sort(expected.begin(), expected.end());
            EXPECT_EQ(reported, expected)
                << reported.size() << " cycles reported, " << expected.size() << " true components";
            continue;
        }
        // gl: each component inside one reported cycle; the extra members counted.
        uint64_t held = 0;
        for (const std::vector<uint32_t>& component : truth) {
            const bool inside =
                std::any_of(frame.cycles.begin(), frame.cycles.end(), [&](const auto& c) {
                    return std::includes(c.begin(), c.end(), component.begin(), component.end());
                });
            EXPECT_TRUE(inside) << "a true cycle of " << component.size() << " (first "
                                << component.front() << ") is in no reported cycle";
            held += component.size();
        }
        uint64_t members = 0;
        for (const std::vector<uint32_t>& c : frame.cycles)
            members += c.size();
        tally_.gl_cycle_members += members;
        tally_.extra_gl_members += members > held ? members - held : 0;
    }
}

void checkPairAnswers(OracleKind kind, PositionsView positions, const ViewProjection& view,
                      std::span<const PrimitiveRange> primitives, const std::string& where,
                      PairAnswerTally& tally) {
    SCOPED_TRACE(where + ", " + oracleName(kind));
    Result<std::unique_ptr<GeometryOracle>> made = makeOracle(kind);
    ASSERT_TRUE(made) << made.error;
    GeometryOracle& oracle = **made.value;
    oracle.bind(positions, view, primitives);
    const ExactFragments fragments = exactFragments(positions, view);
    const std::vector<std::vector<uint32_t>> graph =
        occlusionGraph(fragments, positions.triangleCount(), primitives);
    const uint32_t n = uint32_t(primitives.size());
    for (uint32_t b = 0; b < n; ++b) {
        oracle.clear();
        oracle.draw(b);
        for (uint32_t a = 0; a < n; ++a) {
            if (a == b)
                continue;
            const bool truth = std::binary_search(graph[b].begin(), graph[b].end(), a);
            const bool answer = oracle.anyBehind(a);
            ++tally.pairs;
            tally.occluding += truth ? 1 : 0;
            if (kind == OracleKind::gl && answer && !truth) {
                ++tally.extra_gl;
                continue;
            }
            ASSERT_EQ(answer, truth) << "primitive " << a << " after drawing " << b;
        }
    }
}

std::string EveryFrameCheck::timings() const {
    std::ostringstream out;
    out.precision(3);
    for (const std::unique_ptr<Runner>& runner : runners_)
        out << (&runner == &runners_.front() ? "" : ", ") << oracleName(runner->pair.oracle) << ' '
            << orderLevelName(runner->pair.level) << ' ' << runner->seconds << " s";
    return out.str();
}

std::vector<OrderedPair> everyOracleAndLevel() {
    std::vector<OrderedPair> pairs;
    for (OracleKind oracle : {
             OracleKind::cpu, OracleKind::cpu_reference, OracleKind::exact,
#if VISSORT_TEST_WITH_GL
                 OracleKind::gl
#endif
         })
        for (OrderLevel level : {OrderLevel::object, OrderLevel::triangle, OrderLevel::multistage})
            pairs.push_back({oracle, level});
    return pairs;
}

} // namespace vissort::test
