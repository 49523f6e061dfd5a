#pragma once
// `vissort bench volume`: every volume rendering method on convex and non-convex grids of several
// sizes, over coherent frames of an orbit, in the same run: ms per frame, cells per second, the
// vissort order's queries per cell, and each method's error against raycast (the exact ray
// caster), frame by frame (docs/volume.md).

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "vissort/volume.h"

namespace vissort::bench {

struct VolumeBenchSettings {
    std::vector<uint64_t> cells = {10000, 100000}; // tetrahedra, about: each grid's n is chosen
    uint32_t width = 512, height = 512;
    int frames = 5; // timed frames of the orbit, after one untimed (vissort's first, from depth)
    std::string tf = "bands";
    double density = 4.0;
    OracleKind oracle = OracleKind::cpu;
};

/// One method on one grid over the timed frames.
struct VolumeBenchRow {
    std::string grid;   // builtin:cube?n=N or builtin:knot?n=N
    uint64_t cells = 0; // its tetrahedra
    bool convex = false;
    std::string method;
    double median_ms = 0, median_order_ms = 0, median_composite_ms = 0;
    double cells_per_second = 0;       // cells / median_ms
    double queries_per_cell = 0;       // vissort: the median over the timed frames
    double list_segments_per_cell = 0; // the most a frame held in per-pixel lists, per cell
    int max_error = 0;                 // against raycast, the largest over every frame, 1/255 units
    uint64_t pixels_over_one = 0;      // against raycast, the most in one frame
};

/// The grids measured for a number of cells: a cube (convex) and a trefoil knot (not), each at
/// the lattice size n that gives about that many tetrahedra.
std::vector<std::string> volumeBenchGrids(uint64_t cells);

/// Measures every method on each grid; methods take turns within each frame (raycast first, the
/// reference) so that none always runs on a cold cache. on_grid runs before each grid, on_row
/// after each row; both may be empty. Throws std::runtime_error when a grid cannot be made.
std::vector<VolumeBenchRow>
runVolumeBench(const VolumeBenchSettings& settings,
               const std::function<void(const std::string& grid)>& on_grid = {},
               const std::function<void(const VolumeBenchRow&)>& on_row = {});

} // namespace vissort::bench
