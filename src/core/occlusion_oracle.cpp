#include "vissort/occlusion_oracle.h"

#include <cassert>

namespace vissort {

void OcclusionOracle::backToFrontPass(std::span<const uint32_t> sequence,
                                      std::span<const uint8_t> query, std::span<uint8_t> behind) {
    assert(query.size() == sequence.size() && behind.size() == sequence.size());
    clear();
    for (std::size_t i = sequence.size(); i-- > 0;) {
        if (query[i])
            behind[i] = anyBehind(sequence[i]) ? 1 : 0;
        draw(sequence[i]);
    }
}

void OcclusionOracle::frontToBackPass(std::span<const uint32_t> sequence,
                                      std::span<const uint8_t> query, std::span<uint8_t> behind) {
    assert(query.size() == sequence.size() && behind.size() == sequence.size());
    clear();
    for (std::size_t i = 0; i < sequence.size(); ++i) {
        if (query[i]) {
            behind[i] = anyBehind(sequence[i]) ? 1 : 0;
            if (behind[i])
                draw(sequence[i]);
        } else {
            draw(sequence[i]);
        }
    }
}

void OcclusionOracle::queryAgainst(std::span<const uint32_t> occluders,
                                   std::span<const uint32_t> targets, std::span<uint8_t> behind) {
    assert(behind.size() == targets.size());
    clear();
    for (uint32_t p : occluders)
        draw(p);
    for (std::size_t i = 0; i < targets.size(); ++i)
        behind[i] = anyBehind(targets[i]) ? 1 : 0;
}

} // namespace vissort
