#pragma once
// Statistics structs as the command line writes them, from their field tables (forEachStat in
// vis_sort.h and collision.h): no field is named here, so the JSON, the CSV and the Python
// module's dicts list the same ones.

#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace vissort::cli {

/// A statistics struct as a JSON object: each count under its name, and the times (fields
/// ending in _ms) under "ms" by the rest of their name ({"ms": {"update": ..., "total": ...}}).
template <class Stats> nlohmann::json statsJson(const Stats& stats) {
    nlohmann::json out = nlohmann::json::object();
    forEachStat(stats, [&](std::string_view name, auto value) {
        if (name.ends_with("_ms"))
            out["ms"][std::string(name.substr(0, name.size() - 3))] = value;
        else
            out[std::string(name)] = value;
    });
    return out;
}

/// The CSV columns of a statistics struct, after `columns`: its field names.
template <class Stats> std::vector<std::string> withStatColumns(std::vector<std::string> columns) {
    forEachStat(Stats{}, [&](std::string_view name, auto) { columns.emplace_back(name); });
    return columns;
}

/// Column names as help text lists them: "a, b, c".
inline std::string columnList(const std::vector<std::string>& columns) {
    std::string text;
    for (const std::string& column : columns)
        text += (text.empty() ? "" : ", ") + column;
    return text;
}

/// A CSV row's values of a statistics struct, after `values`, in withStatColumns' order.
template <class Stats>
std::vector<double> withStatValues(std::vector<double> values, const Stats& stats) {
    forEachStat(stats, [&](std::string_view, auto value) { values.push_back(double(value)); });
    return values;
}

} // namespace vissort::cli
