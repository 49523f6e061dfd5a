#pragma once
// The one error convention of vissort's public API (docs/architecture.md, "Errors"):
//  - an operation that can fail on its input or its environment (a file, a name, a GL driver)
//    returns a Result: a value, or a one-line message naming the problem;
//  - a caller's broken contract that a constructor cannot report otherwise (settings out of
//    range, positions of the wrong size) throws std::invalid_argument with the same kind of
//    one-line message; the matching validate function lets a caller check first;
//  - internal invariants are assertions.
// Standard library only: the core depends on nothing else.
//
// Layer: vissort::core (the package's `order` component; docs/architecture.md).

#include <optional>
#include <string>
#include <utility>

namespace vissort {

/// Either a value or a one-line error message naming the problem.
template <class T> struct Result {
    std::optional<T> value;
    std::string error;

    explicit operator bool() const { return value.has_value(); }
    static Result failure(std::string message) { return {std::nullopt, std::move(message)}; }
};

/// Success or a one-line error message: the Result of an operation with no value.
struct Status {
    std::string error; // empty on success

    explicit operator bool() const { return error.empty(); }
    static Status ok() { return {}; }
    static Status failure(std::string message) { return {std::move(message)}; }
};

} // namespace vissort
