#pragma once
// "Did you mean": the known name nearest to a mistyped one, so that one-line errors about an
// unknown command, option, method or JSON key can point at the likely intent ('ordr' -> 'order',
// 'color' -> 'colour', '--levle' -> '--level').
//
// Layer: vissort::core (the package's `order` component; docs/architecture.md).

#include <algorithm>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace vissort {

/// Levenshtein distance with adjacent swaps counting one edit (optimal string alignment).
inline std::size_t editDistance(std::string_view a, std::string_view b) {
    std::vector<std::size_t> before(b.size() + 1), previous(b.size() + 1), current(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j)
        previous[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        current[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t substitution = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
            current[j] = std::min({previous[j] + 1, current[j - 1] + 1, substitution});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                current[j] = std::min(current[j], before[j - 2] + 1);
        }
        before.swap(previous);
        previous.swap(current);
    }
    return previous[b.size()];
}

/// The name of `names` nearest to text, if it is near enough to be a typing mistake (at most a
/// third of text's letters changed, at least one allowed); else the name that shares the
/// longest beginning with text, if that beginning is at least 4 letters and two thirds of text
/// (a singular for a plural: 'bunny' for 'bunnies'); empty otherwise. Ties: the first.
template <class Names> std::string closestName(std::string_view text, const Names& names) {
    const std::size_t allowed = std::max<std::size_t>(1, text.size() / 3);
    std::string best, best_prefix;
    std::size_t best_distance = allowed + 1;
    std::size_t longest_prefix = std::max<std::size_t>(3, (2 * text.size() + 2) / 3 - 1);
    for (const auto& name : names) {
        const std::string_view candidate(name);
        const std::size_t distance = editDistance(text, candidate);
        if (distance < best_distance && distance > 0) {
            best = std::string(candidate);
            best_distance = distance;
        }
        std::size_t prefix = 0;
        while (prefix < text.size() && prefix < candidate.size() &&
               text[prefix] == candidate[prefix])
            ++prefix;
        if (prefix > longest_prefix && candidate != text) {
            best_prefix = std::string(candidate);
            longest_prefix = prefix;
        }
    }
    return best.empty() ? best_prefix : best;
}

/// "did you mean 'PREFIXNAME'? " for closestName's answer, or "" when there is none: the start
/// of a parenthesis that goes on to list what is known ("(did you mean 'object'? expected
/// object, triangle or multistage)"). `shown_prefix` is written before the name
/// ("builtin:").
template <class Names>
std::string didYouMeanFirst(std::string_view text, const Names& names,
                            std::string_view shown_prefix = {}) {
    const std::string best = closestName(text, names);
    return best.empty() ? std::string()
                        : "did you mean '" + std::string(shown_prefix) + best + "'? ";
}

/// " (did you mean 'NAME'?)" for closestName's answer, or "" when there is none.
template <class Names> std::string didYouMean(std::string_view text, const Names& names) {
    const std::string best = closestName(text, names);
    return best.empty() ? std::string() : " (did you mean '" + best + "'?)";
}

} // namespace vissort
