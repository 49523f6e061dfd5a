#pragma once
// Per-frame statistics as CSV (--csv FILE): a header row naming the columns, then one row a
// frame, for spreadsheets and plotting scripts.

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace vissort::cli {

/// Adds --csv FILE (FILE, or - for standard output); columns says what a row holds.
void addCsvOption(CLI::App& command, std::string& path, const std::string& columns);

/// A table of numbers, written as CSV once the frames are done.
class CsvTable {
public:
    explicit CsvTable(std::vector<std::string> columns) : columns_(std::move(columns)) {}
    /// One row, a value per column (shortest text that reads back the same double).
    void addRow(const std::vector<double>& values);
    /// Writes the table to path ("-": standard output, see reserveStandardOutputFor). Returns
    /// kExitOk, or prints "cannot write PATH" and returns kExitFailure.
    int write(const std::string& path) const;

private:
    std::vector<std::string> columns_;
    std::vector<std::vector<double>> rows_;
};

} // namespace vissort::cli
