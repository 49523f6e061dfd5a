#pragma once
// Reads the key=value parameters of a built-in scene (`builtin:NAME?key=value&...`): decimal
// integers and numbers with a range, and 64-bit seeds. Errors name the scene, the key and the
// problem.

#include <cstdint>
#include <set>
#include <string>

#include "scenes/scene_library.h"

namespace vissort::detail {

/// Reads typed values for one scene and keeps the first problem found. Read every key the scene
/// accepts, then call `error()`: it also reports keys that were never read (unknown keys).
class ParameterReader {
public:
    /// `scene` names the scene in messages, e.g. "builtin:bunnies".
    ParameterReader(std::string scene, const SceneParameters& parameters);

    /// The value of `key` (default_value when absent), a decimal integer in [min, max].
    /// On a problem, records it and returns default_value.
    int64_t integer(const std::string& key, int64_t default_value, int64_t min, int64_t max);
    /// The value of `key` (default_value when absent), a decimal number in [min, max] written
    /// with digits and at most one point ("0.25", "3", "2."): no sign, exponent or spaces.
    /// On a problem, records it and returns default_value.
    double number(const std::string& key, double default_value, double min, double max);
    /// The value of `key` (default_value when absent), any decimal integer in [0, 2^64).
    uint64_t seed(const std::string& key, uint64_t default_value);

    /// Empty when every parameter was known and valid, else a one-line message.
    std::string error() const;

private:
    const std::string* find(const std::string& key);
    void fail(std::string message);

    std::string scene_;
    const SceneParameters& parameters_;
    std::set<std::string> known_keys_;
    std::string first_error_;
};

} // namespace vissort::detail
