// --tf, --density and --background of the volume commands (volume_options.h).

#include "cli/volume_options.h"

#include <cmath>

#include "cli/colour_options.h"
#include "cli/command_line_errors.h"

namespace vissort::cli {

std::string resolveVolumeSettings(const std::string& tf, double density,
                                  const std::string& background, VolumeSettings& settings) {
    if (!std::isfinite(density) || density < 0)
        return "--density must be a finite number >= 0, got " + formatNumber(density);
    const Result<Rgba> colour = parseBackground(background);
    if (!colour)
        return "--background " + colour.error;
    Result<TransferFunction> transfer = loadTransferFunction(tf);
    if (!transfer)
        return "--tf " + transfer.error;
    settings.transfer = std::move(*transfer.value);
    settings.density = density;
    settings.background = *colour.value;
    return {};
}

} // namespace vissort::cli
