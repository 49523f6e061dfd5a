#pragma once
// How the commands write for people: counts with their noun ("1 object", "2 objects"),
// durations with their unit, warnings on one line.

#include <cstdint>
#include <string>

namespace vissort::cli {

/// "1 object", "2 objects", "0 passes": noun's plural is noun + "s", or plural when given.
std::string counted(uint64_t count, const std::string& noun, const std::string& plural = "");

/// Milliseconds as people read them: "0.02 ms", "8.68 ms", "24.7 ms", "1593 ms" (two decimals
/// below 10, one below 100, whole beyond).
std::string milliseconds(double ms);

/// Prints "vissort: warning: MESSAGE" on one line to standard error (in yellow on a terminal,
/// unless NO_COLOR is set).
void warn(const std::string& message);

/// Whether standard error is a terminal that colour may be used on (NO_COLOR unset).
bool colourOnStandardError();

} // namespace vissort::cli
