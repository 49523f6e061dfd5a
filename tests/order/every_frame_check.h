#pragma once
// Orders every frame of a run with every (oracle, level) pair, each pair's orderer kept from frame
// to frame (coherence: a frame starts from the last frame's order), and checks every frame's
// order against the exact ground truth of that frame (ground_truth.h), never against another
// oracle: no (pixel, front, behind) out of order outside a reported cycle, and
//  - cpu, cpu-reference and exact: every reported cycle a strongly connected component of the
//    exact occlusion graph, and every such component reported (cycles equal to the components);
//  - gl (conservative where it cannot decide: an undecidable pixel counts both ways): every
//    component inside one reported cycle; the extra cycle members are counted, not failed.
// Failures are gtest failures naming the frame, oracle and level.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "vissort/geometry.h"
#include "vissort/oracles.h"
#include "vissort/scene_orderer.h"

namespace vissort::test {

struct OrderedPair {
    OracleKind oracle;
    OrderLevel level;
};

/// What the checks saw over a run.
struct EveryFrameTally {
    uint64_t frames = 0;           // frames checked (each with every pair)
    uint64_t orders = 0;           // orders checked: frames x pairs
    uint64_t pairs_checked = 0;    // (pixel, front, behind) occlusions the orders were held to
    uint64_t violations = 0;       // ... of them out of order outside a reported cycle
    uint64_t true_cycles = 0;      // components of two or more, summed over frames and levels
    uint64_t extra_gl_members = 0; // gl cycle members beyond the components they hold
    uint64_t gl_cycle_members = 0; // all gl cycle members
    uint64_t hinted_cycles = 0;    // cycles confirmed from the last frame's (VisSortStats)
    std::string describe() const;
};

class EveryFrameCheck {
public:
    /// objects: the scene's object ranges; the pairs to run (each gets its own oracle, made with
    /// makeOracle, and its own orderer).
    EveryFrameCheck(std::span<const PrimitiveRange> objects, uint32_t triangle_count,
                    const std::vector<OrderedPair>& pairs);
    ~EveryFrameCheck();

    /// Orders the frame with every pair and checks each order against the frame's ground truth;
    /// `where` names the frame in failure messages.
    void checkFrame(PositionsView positions, const ViewProjection& view, const std::string& where);

    const EveryFrameTally& tally() const { return tally_; }
    /// Each pair's ordering time over the frames so far, for the log.
    std::string timings() const;

private:
    struct Runner;
    std::vector<PrimitiveRange> objects_;
    uint32_t triangle_count_;
    std::vector<std::unique_ptr<Runner>> runners_;
    EveryFrameTally tally_;
};

/// What checkPairAnswers saw.
struct PairAnswerTally {
    uint64_t pairs = 0;     // ordered pairs asked
    uint64_t occluding = 0; // ... where the ground truth has the occlusion
    uint64_t extra_gl = 0;  // gl's "behind" answers beyond the ground truth's
};

/// The oracle's answer for every ordered pair (a, b) of primitives: after clear() and draw(b),
/// anyBehind(a) must be true exactly when b is in front of a at some pixel in the frame's exact
/// occlusion graph (gl: whenever it is; its extra answers counted). A direct check of the
/// oracle, which no ordering luck can hide.
void checkPairAnswers(OracleKind kind, PositionsView positions, const ViewProjection& view,
                      std::span<const PrimitiveRange> primitives, const std::string& where,
                      PairAnswerTally& tally);

/// Every oracle the build has (gl where it was built) at every level.
std::vector<OrderedPair> everyOracleAndLevel();

} // namespace vissort::test
