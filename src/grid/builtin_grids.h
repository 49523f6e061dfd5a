#pragma once
// The built-in grids (builtin:cube, builtin:torus, builtin:knot): hexahedral lattices clipped to
// a shape, split into tetrahedra, with an analytic scalar per point. Internal to src/grid/.

#include <string>

#include "vissort/tet_grid.h"

namespace vissort::detail {

/// Makes the grid that "NAME?key=value&..." (after "builtin:") names, or says why it cannot.
Result<TetGrid> makeBuiltinGrid(const std::string& name_and_parameters);

/// The built-in grids' names, comma-separated, for messages.
std::string builtinGridList();

/// Every built-in grid's name and description.
std::vector<BuiltinGridInfo> builtinGrids();

} // namespace vissort::detail
