#include "cli/csv_output.h"

#include <cassert>
#include <cerrno>
#include <charconv>
#include <fstream>
#include <iostream>

#include "cli/cli_common.h"
#include "cli/json_output.h"
#include "cli/output_paths.h"

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
    std::ofstream file;
    errno = 0;
    if (path != "-")
        file.open(path);
    std::ostream out(path == "-" ? standardOutputBuffer() : file.rdbuf());
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
    if (!out || (path != "-" && !file))
        return fail(kExitFailure, cannotWrite(path));
    return kExitOk;
}

} // namespace vissort::cli
