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

namespace {

// Whether any member of group g is behind (queries change nothing: asking them one by one is
// asking before any is drawn), and drawing them all.
bool anyMemberBehind(OcclusionOracle& oracle, std::span<const uint32_t> members,
                     std::span<const uint32_t> first, std::size_t g) {
    for (uint32_t k = first[g]; k < first[g + 1]; ++k)
        if (oracle.anyBehind(members[k]))
            return true;
    return false;
}

void drawMembers(OcclusionOracle& oracle, std::span<const uint32_t> members,
                 std::span<const uint32_t> first, std::size_t g) {
    for (uint32_t k = first[g]; k < first[g + 1]; ++k)
        oracle.draw(members[k]);
}

} // namespace

void OcclusionOracle::backToFrontGroupPass(std::span<const uint32_t> members,
                                           std::span<const uint32_t> first,
                                           std::span<const uint8_t> query,
                                           std::span<uint8_t> behind) {
    assert(first.size() == query.size() + 1 && behind.size() == query.size());
    clear();
    for (std::size_t g = query.size(); g-- > 0;) {
        if (query[g])
            behind[g] = anyMemberBehind(*this, members, first, g) ? 1 : 0;
        drawMembers(*this, members, first, g);
    }
}

void OcclusionOracle::frontToBackGroupPass(std::span<const uint32_t> members,
                                           std::span<const uint32_t> first,
                                           std::span<const uint8_t> query,
                                           std::span<uint8_t> behind) {
    assert(first.size() == query.size() + 1 && behind.size() == query.size());
    clear();
    for (std::size_t g = 0; g < query.size(); ++g) {
        if (query[g]) {
            behind[g] = anyMemberBehind(*this, members, first, g) ? 1 : 0;
            if (behind[g])
                drawMembers(*this, members, first, g);
        } else {
            drawMembers(*this, members, first, g);
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

bool OcclusionOracle::occlusionGraph(std::span<const uint32_t>, std::vector<Occlusion>&) {
    return false;
}

} // namespace vissort
