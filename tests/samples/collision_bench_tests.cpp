// The collision bench's ratios (samples/harnesses/collision_bench.h): bullet's median over
// vissort's at each n and thread count, from rows made here (nothing is measured).

#include <gtest/gtest.h>

#include "harnesses/collision_bench.h"

namespace vissort::bench {
namespace {

CollisionBenchRow row(uint32_t n, const std::string& method, double median_ms) {
    CollisionBenchRow r;
    r.n = n;
    r.method = method;
    r.median_ms = median_ms;
    return r;
}

TEST(CollisionBench, BulletOverVissortPairsTheSameThreadsAndN) {
    CollisionBenchSettings settings;
    settings.counts = {18, 144};
    settings.threads = {1, 2};
    const std::vector<CollisionBenchRow> rows = {
        row(18, "vissort-1t", 2.0),  row(18, "vissort-2t", 1.0),  row(18, "brute", 20.0),
        row(18, "bullet-1t", 3.0),   row(18, "bullet-2t", 1.25),  row(144, "vissort-1t", 10.0),
        row(144, "bullet-1t", 15.0), row(144, "vissort-2t", 0.0), row(144, "bullet-2t", 4.0)};
    const std::vector<CollisionSpeedup> speedups = bulletOverVissort(rows, settings);
    ASSERT_EQ(speedups.size(), 4u);
    EXPECT_EQ(speedups[0].n, 18u);
    EXPECT_EQ(speedups[0].threads, 1u);
    EXPECT_DOUBLE_EQ(speedups[0].bullet_over_vissort, 1.5);
    EXPECT_EQ(speedups[1].threads, 2u);
    EXPECT_DOUBLE_EQ(speedups[1].bullet_over_vissort, 1.25);
    EXPECT_EQ(speedups[2].n, 144u);
    EXPECT_DOUBLE_EQ(speedups[2].bullet_over_vissort, 1.5);
    EXPECT_DOUBLE_EQ(speedups[3].bullet_over_vissort, 0.0); // vissort's median of 0: no ratio
}

TEST(CollisionBench, NoRatioWithoutBothMethods) {
    CollisionBenchSettings settings;
    settings.counts = {18};
    settings.threads = {1, 2};
    const std::vector<CollisionBenchRow> rows = {row(18, "vissort-1t", 2.0), row(18, "brute", 20.0),
                                                 row(18, "bullet-2t", 1.0)};
    EXPECT_TRUE(bulletOverVissort(rows, settings).empty());
}

} // namespace
} // namespace vissort::bench
