#include "cli/csv_output.h"

#include <cassert>
#include <charconv>
#include <ostream>

#include "cli/json_output.h"

namespace vissort::cli {

void addCsvOption(CLI::App& command, std::string& path, const std::string& columns) {
    command.add_option("--csv", path,
                       "Write per-frame statistics as CSV, a row a frame: " + columns +
                           " (FILE, or - for standard output)");
}

void CsvTable::addRow(const std::vector<double>& values) {
    assert(values.size() == columns_.size());
    rows_.push_back(values);
}

int CsvTable::write(const std::string& path) const {
    const auto emit = [&](std::ostream& out) {
        for (std::size_t c = 0; c < columns_.size(); ++c)
            out << (c ? "," : "") << columns_[c];
        out << '\n';
        char text[32];
        for (const std::vector<double>& row : rows_) {
            for (std::size_t c = 0; c < row.size(); ++c) {
                const auto [end, ec] = std::to_chars(text, text + sizeof text, row[c]);
                out << (c ? "," : "") << std::string_view(text, ec == std::errc() ? end - text : 0);
            }
            out << '\n';
        }
        out.flush();
    };
    return writeTextOutput(path, emit);
}

} // namespace vissort::cli
