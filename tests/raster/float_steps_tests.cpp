// detail::nextDown and nextUp against std::nextafter: zeros of both signs, subnormals, the
// largest finite floats, infinities, and random bit patterns.
#include "raster/float_steps.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

namespace vissort::detail {
namespace {

using Limits = std::numeric_limits<float>;

void expectSteps(float f) {
    const float down = std::nextafter(f, -Limits::infinity());
    const float up = std::nextafter(f, Limits::infinity());
    // Bit patterns, so that -0.0 and +0.0 differ.
    EXPECT_EQ(std::bit_cast<uint32_t>(nextDown(f)), std::bit_cast<uint32_t>(down)) << f;
    EXPECT_EQ(std::bit_cast<uint32_t>(nextUp(f)), std::bit_cast<uint32_t>(up)) << f;
}

TEST(FloatSteps, MatchNextafterAtTheEdges) {
    const std::vector<float> edges = {0.0f, -0.0f, Limits::denorm_min(), -Limits::denorm_min(),
                                      Limits::min(), -Limits::min(), Limits::max(), -Limits::max(),
                                      Limits::infinity(), -Limits::infinity(), 1.0f, -1.0f,
                                      1e-30f, 0.99f};
    for (float f : edges) expectSteps(f);
}

TEST(FloatSteps, MatchNextafterOnRandomFloats) {
    std::mt19937 rng(3);
    for (int i = 0; i < 100000; ++i) {
        const float f = std::bit_cast<float>(uint32_t(rng()));
        if (std::isnan(f)) continue;
        expectSteps(f);
    }
}

} // namespace
} // namespace vissort::detail
