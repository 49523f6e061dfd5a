#pragma once
// The volume options `volume` and `view GRID` share: --tf, --density and --background, read into
// the volume renderer's settings.

#include <string>

#include "vissort/volume.h"

namespace vissort::cli {

/// Empty on success, else a one-line message naming the bad option (a usage error).
std::string resolveVolumeSettings(const std::string& tf, double density,
                                  const std::string& background, VolumeSettings& settings);

} // namespace vissort::cli
