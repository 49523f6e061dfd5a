#pragma once
// The colours the command line reads and prints: --background of render, view and volume.

#include <string>

#include "vissort/image.h"
#include "vissort/result.h"

namespace vissort::cli {

/// "R,G,B" with each channel's shortest form, as the help shows a default.
std::string backgroundText(const Rgba& colour);

/// "R,G,B", "R,G,B,A" (each in [0, 1]) or "#RRGGBB"; empty: kDefaultBackground. The error
/// completes "--background ...".
Result<Rgba> parseBackground(const std::string& text);

} // namespace vissort::cli
