#pragma once
// Editing a transfer function in the viewer's panel (and by its keys) without ever making an
// invalid one: scalars stay strictly increasing, colours in [0, 1], extinctions non-negative,
// at least two points. Pure functions, so the panel's rules are tested without a window.

#include <cstddef>
#include <string>

#include "vissort/transfer_function.h"

namespace vissort::viewer {

/// Moves point i to scalar s, held strictly between its neighbours' (a point may not pass
/// another: the panel's sliders would reorder them under the cursor). i must be a point's index.
void moveTransferPoint(TransferFunction& tf, std::size_t i, double s);

/// Inserts a point halfway between point i and the next (after the last: halfway to 1, or one
/// further in absolute ranges), with the function's colour and extinction there, so the picture
/// does not change until it is edited. Returns the new point's index.
std::size_t insertTransferPoint(TransferFunction& tf, std::size_t i);

/// Removes point i, unless only two are left; true when it was removed.
bool removeTransferPoint(TransferFunction& tf, std::size_t i);

/// Clamps colours to [0, 1] and the extinction to >= 0 (what the panel's widgets may overshoot).
void clampTransferPoint(TransferPoint& point);

/// The preset after `name` in transferPresets(), wrapping around; the first for a name that is
/// not a preset (a JSON file's).
std::string nextTransferPreset(const std::string& name);

} // namespace vissort::viewer
