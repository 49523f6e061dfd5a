// The named transfer functions, and loadTransferFunction (a name or a JSON file). Over the
// normalized scalar; their extinctions are chosen so that the built-in grids at the default
// density are translucent: the cells behind show through those in front, so an order's errors
// show.
#include <filesystem>
#include <fstream>
#include <sstream>

#include "vissort/closest_name.h"
#include "vissort/transfer_function.h"

namespace vissort {
namespace {

struct Preset {
    const char* name;
    const char* description;
    std::vector<TransferPoint> points;
};

const std::vector<Preset>& presets() {
    static const std::vector<Preset> list{
        {"cool-warm",
         "blue through white to red, extinction rising with the scalar (the default)",
         {{0.0, 0.23, 0.30, 0.75, 0.2},
          {0.5, 0.87, 0.87, 0.87, 1.0},
          {1.0, 0.71, 0.02, 0.15, 3.0}}},
        {"fire",
         "black, red, yellow, white; empty below a tenth of the range",
         {{0.0, 0.0, 0.0, 0.0, 0.0},
          {0.1, 0.2, 0.0, 0.0, 0.0},
          {0.4, 0.9, 0.1, 0.0, 1.5},
          {0.7, 1.0, 0.8, 0.1, 3.0},
          {1.0, 1.0, 1.0, 0.9, 5.0}}},
        {"grey",
         "grey ramp, extinction proportional to the scalar",
         {{0.0, 0.0, 0.0, 0.0, 0.0}, {1.0, 1.0, 1.0, 1.0, 3.0}}},
        {"bands",
         "three narrow opaque shells (at 0.25, 0.5, 0.75 of the range) in clear space: "
         "iso-surface-like, where an order's mistakes are plainest",
         {{0.0, 0.1, 0.1, 0.1, 0.0},
          {0.20, 0.1, 0.4, 0.9, 0.0},
          {0.25, 0.1, 0.4, 0.9, 12.0},
          {0.30, 0.1, 0.4, 0.9, 0.0},
          {0.45, 0.2, 0.9, 0.3, 0.0},
          {0.50, 0.2, 0.9, 0.3, 12.0},
          {0.55, 0.2, 0.9, 0.3, 0.0},
          {0.70, 0.95, 0.5, 0.1, 0.0},
          {0.75, 0.95, 0.5, 0.1, 12.0},
          {0.80, 0.95, 0.5, 0.1, 0.0},
          {1.0, 0.95, 0.5, 0.1, 0.0}}},
    };
    return list;
}

} // namespace

std::vector<TransferPreset> transferPresets() {
    std::vector<TransferPreset> names;
    for (const Preset& p : presets())
        names.push_back({p.name, p.description});
    return names;
}

Result<TransferFunction> loadTransferFunction(const std::string& name_or_path) {
    using R = Result<TransferFunction>;
    for (const Preset& p : presets())
        if (name_or_path == p.name)
            return R{TransferFunction{p.points, true}, {}};
    std::error_code error;
    if (!std::filesystem::is_regular_file(name_or_path, error)) {
        std::vector<std::string> names;
        for (const Preset& p : presets())
            names.push_back(p.name);
        std::string known;
        for (const std::string& n : names)
            known += (known.empty() ? "" : ", ") + n;
        return R::failure("'" + name_or_path + "' is neither a transfer function preset" +
                          didYouMean(name_or_path, names) + " nor a file; the presets are " +
                          known);
    }
    constexpr std::uintmax_t kMaxBytes = 16 << 20; // far beyond any hand-made function
    if (std::filesystem::file_size(name_or_path, error) > kMaxBytes)
        return R::failure(name_or_path + ": larger than a transfer function file may be (16 MB)");
    std::ifstream in(name_or_path);
    std::stringstream text;
    text << in.rdbuf();
    Result<TransferFunction> tf = parseTransferFunction(text.str());
    if (!tf)
        return R::failure(name_or_path + ": " + tf.error);
    return tf;
}

} // namespace vissort
