#pragma once
// Transfer functions of volume rendering: colour and extinction as piecewise-linear functions of
// a grid's scalar (docs/volume.md, "The rendering law").
//
// Layer: vissort::volume (the package's `volume` component; docs/architecture.md).

#include <string>
#include <vector>

#include "vissort/result.h"

namespace vissort {

/// One control point: at `scalar`, colour (r, g, b) in [0, 1] and extinction (>= 0, per unit of
/// length as VolumeSettings measures it).
struct TransferPoint {
    double scalar = 0;
    double r = 0, g = 0, b = 0;
    double extinction = 0;
    friend bool operator==(const TransferPoint&, const TransferPoint&) = default;
};

/// Piecewise linear between its points (scalars strictly increasing), constant beyond the first
/// and the last.
struct TransferFunction {
    std::vector<TransferPoint> points;
    /// Whether the points' scalars are fractions of the grid's scalar range (0 its minimum, 1 its
    /// maximum) rather than the grid's own values.
    bool normalized = true;

    /// The colour and extinction at scalar s (already normalized when `normalized`).
    TransferPoint at(double s) const;
    friend bool operator==(const TransferFunction&, const TransferFunction&) = default;
};

/// Empty when tf can be used, else a one-line problem: at least one point, every number finite,
/// scalars strictly increasing, colours within [0, 1], extinctions non-negative.
Status validateTransferFunction(const TransferFunction& tf);

/// The named transfer functions, each with a one-line description.
struct TransferPreset {
    const char* name;
    const char* description;
};
std::vector<TransferPreset> transferPresets();

/// A preset by name, or a JSON file: {"range": "normalized"|"absolute", "points": [[scalar, r,
/// g, b, extinction], ...]} ("range" defaults to normalized). Errors name the file or the preset
/// and the problem in one line, with a "did you mean" for a mistyped preset.
Result<TransferFunction> loadTransferFunction(const std::string& name_or_path);

/// The same JSON text, parsed (what loadTransferFunction reads from a file).
Result<TransferFunction> parseTransferFunction(const std::string& json_text);

/// The JSON text of tf, as parseTransferFunction reads it.
std::string transferFunctionJson(const TransferFunction& tf);

} // namespace vissort
