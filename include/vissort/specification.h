#pragma once
// What the loaders of scenes and grids share about the specifications users type
// ("builtin:NAME?key=value&..."): the query's parameters, and messages kept to one line.
// Standard library only.
//
// Layer: vissort::core (the package's `order` component; docs/architecture.md).

#include <map>
#include <string>

#include "vissort/result.h"

namespace vissort {

/// A built-in's key=value parameters.
using SpecificationParameters = std::map<std::string, std::string>;

/// Splits "k=v&k2=v2" into parameters; an empty query gives none. Errors (an empty parameter, one
/// without a value or a key, a key given twice) start with `specification`.
inline Result<SpecificationParameters> parseSpecificationQuery(const std::string& query,
                                                               const std::string& specification) {
    using R = Result<SpecificationParameters>;
    SpecificationParameters parameters;
    std::size_t begin = 0;
    while (begin < query.size()) {
        std::size_t end = query.find('&', begin);
        if (end == std::string::npos)
            end = query.size();
        const std::string item = query.substr(begin, end - begin);
        const std::size_t equals = item.find('=');
        if (item.empty())
            return R::failure(specification + ": empty parameter between '&'");
        if (equals == std::string::npos)
            return R::failure(specification + ": parameter '" + item +
                              "' needs a value (key=value)");
        const std::string key = item.substr(0, equals);
        if (key.empty())
            return R::failure(specification + ": parameter '" + item + "' has no key");
        if (!parameters.emplace(key, item.substr(equals + 1)).second)
            return R::failure(specification + ": parameter '" + key + "' given twice");
        begin = end + 1;
        if (end + 1 == query.size())
            return R::failure(specification + ": empty parameter after the last '&'");
    }
    return {std::move(parameters), {}};
}

/// The message with control characters written as \xNN: messages quote what users typed (a file
/// name, a key, a value), and every error must stay one line. (The scene_parameters fuzzer found
/// "builtin:x?&" followed by line ends.)
inline std::string oneLine(const std::string& message) {
    static constexpr char kHex[] = "0123456789abcdef";
    std::string line;
    line.reserve(message.size());
    for (const char c : message) {
        const auto byte = static_cast<unsigned char>(c);
        if (byte < 0x20 || byte == 0x7f) {
            line += "\\x";
            line += kHex[byte >> 4];
            line += kHex[byte & 15];
        } else {
            line += c;
        }
    }
    return line;
}

} // namespace vissort
