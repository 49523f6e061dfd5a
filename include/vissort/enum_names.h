#pragma once
// One table of names per enum: parsing, naming and the list for help text all come from it, so
// a new value is added in one place and every "unknown name" message reads the same.
//
// Layer: vissort::core (the package's `order` component; docs/architecture.md).

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "vissort/closest_name.h"
#include "vissort/result.h"

namespace vissort {

template <class E> struct EnumName {
    E value;
    const char* name;
};

/// The value named `text` in table, or "unknown WHAT 'TEXT' (expected A, B or C)", with "did
/// you mean" when one name is near.
template <class E>
Result<E> parseEnum(std::span<const EnumName<E>> table, std::string_view text,
                    std::string_view what);

/// The name of value in table; "?" when it has none (a programming mistake).
template <class E> const char* enumName(std::span<const EnumName<E>> table, E value) {
    for (const EnumName<E>& entry : table)
        if (entry.value == value)
            return entry.name;
    return "?";
}

/// Every name of table: "a, b, c" (for help text).
template <class E> std::string enumNames(std::span<const EnumName<E>> table) {
    std::string names;
    for (const EnumName<E>& entry : table) {
        if (!names.empty())
            names += ", ";
        names += entry.name;
    }
    return names;
}

template <class E>
Result<E> parseEnum(std::span<const EnumName<E>> table, std::string_view text,
                    std::string_view what) {
    for (const EnumName<E>& entry : table)
        if (text == entry.name)
            return {entry.value, {}};
    std::string expected;
    std::vector<std::string_view> names;
    for (std::size_t i = 0; i < table.size(); ++i) {
        if (i > 0)
            expected += i + 1 == table.size() ? " or " : ", ";
        expected += table[i].name;
        names.push_back(table[i].name);
    }
    return Result<E>::failure("unknown " + std::string(what) + " '" + std::string(text) + "' (" +
                              didYouMeanFirst(text, names) + "expected " + expected + ")");
}

} // namespace vissort
