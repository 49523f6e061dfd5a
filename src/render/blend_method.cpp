// The blending methods' names and the order check's (transparency_renderer.h).

#include <array>
#include <utility>

#include "vissort/transparency_renderer.h"

namespace vissort {
namespace {

constexpr std::array<std::pair<BlendMethod, const char*>, 7> kNames{{
    {BlendMethod::vissort, "vissort"},
    {BlendMethod::unsorted, "unsorted"},
    {BlendMethod::centroid, "centroid"},
    {BlendMethod::peel, "peel"},
    {BlendMethod::dual_peel, "dual-peel"},
    {BlendMethod::linked_list, "linked-list"},
    {BlendMethod::weighted, "weighted"},
}};

} // namespace

bool parseBlendMethod(const std::string& name, BlendMethod& method) {
    for (const auto& [m, n] : kNames)
        if (name == n) {
            method = m;
            return true;
        }
    return false;
}

const char* blendMethodName(BlendMethod method) {
    for (const auto& [m, n] : kNames)
        if (m == method)
            return n;
    return "?";
}

std::string blendMethodNames() {
    std::string names;
    for (const auto& [m, n] : kNames)
        names += (names.empty() ? "" : ", ") + std::string(n);
    return names;
}

bool parseOrderCheck(const std::string& name, RenderSettings::OrderCheck& check) {
    if (name == "auto")
        check = RenderSettings::OrderCheck::automatic;
    else if (name == "on")
        check = RenderSettings::OrderCheck::on;
    else if (name == "off")
        check = RenderSettings::OrderCheck::off;
    else
        return false;
    return true;
}

} // namespace vissort
