#pragma once
// Statistics structs as Python dicts, from their field tables (forEachStat in vis_sort.h and
// collision.h): the same names as the command line's JSON and CSV, none listed here.

#include <string>
#include <string_view>

#include <pybind11/pybind11.h>

namespace vissort::python {

/// Each field of stats under its name, into d.
template <class Stats> void addStats(pybind11::dict& d, const Stats& stats) {
    forEachStat(stats,
                [&](std::string_view name, auto value) { d[std::string(name).c_str()] = value; });
}

} // namespace vissort::python
