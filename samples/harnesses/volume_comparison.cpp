// compareVolumeMethods (volume_comparison.h).

#include "harnesses/volume_comparison.h"

#include <iomanip>
#include <sstream>

namespace vissort::bench {

Result<VolumeComparison> compareVolumeMethods(const TetGrid& grid, const VolumeSettings& settings,
                                              const ViewProjection& view, OracleKind oracle) {
    using R = Result<VolumeComparison>;
    VolumeComparison comparison;
    for (const auto& [method, name] : kVolumeMethodNames) {
        VolumeRenderer renderer(grid, method, oracle);
        Result<Image> image = renderer.render(settings, view);
        if (!image)
            return R::failure(image.error);
        comparison.methods.push_back({method, image.value->toRgba8(), renderer.stats(), {}});
    }
    const std::vector<uint8_t> reference = comparison.methods.back().rgba; // raycast
    std::vector<samples::StripTile> tiles, maps;
    for (VolumePicture& picture : comparison.methods) {
        picture.error = compareImages(picture.rgba, reference);
        std::ostringstream caption, map_caption;
        caption << volumeMethodName(picture.method) << '\n'
                << std::fixed << std::setprecision(1)
                << picture.stats.order_ms + picture.stats.composite_ms << " ms";
        map_caption << "against raycast:\nmax " << picture.error.max_abs << "/255, "
                    << picture.error.pixels_over_one << " px > 1";
        tiles.push_back({picture.rgba, caption.str()});
        maps.push_back({errorMap(picture.rgba, reference), map_caption.str()});
    }
    tiles.insert(tiles.end(), maps.begin(), maps.end());
    comparison.strip =
        samples::composeStrip(tiles, view.width, view.height, uint32_t(comparison.methods.size()));
    return R{std::move(comparison), {}};
}

} // namespace vissort::bench
