#pragma once
// One-line errors for a mistyped command line, better than CLI11's own: the command or option
// nearest to an unknown one ("did you mean"), a repeated option, a value that is not a number,
// and the help to run for the command at hand.

#include <string>

#include <CLI/CLI.hpp>

namespace vissort::cli {

/// Checked before CLI11 parses: no command, an unknown command, or an option the command does
/// not have. Empty when none of these; else the message (without "vissort: error: ").
std::string checkCommandLine(const CLI::App& app, int argc, const char* const* argv);

/// CLI11's parse error as one line: the option, what it expected and what it got, then the
/// help to run ("run 'vissort COMMAND --help'").
std::string explainParseError(const CLI::App& app, const CLI::ParseError& error);

/// A number as people write it: 0, 0.5, 1e+09 (std::to_string writes 0.000000).
std::string formatNumber(double value);

} // namespace vissort::cli
