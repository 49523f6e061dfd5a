// compareEveryMethod (method_comparison.h).

#include "harnesses/method_comparison.h"

#include <iomanip>
#include <sstream>

namespace vissort::bench {
namespace {

constexpr BlendMethod kShown[] = {
    BlendMethod::vissort,   BlendMethod::unsorted,    BlendMethod::centroid, BlendMethod::peel,
    BlendMethod::dual_peel, BlendMethod::linked_list, BlendMethod::weighted};
constexpr std::size_t kReference = 5; // linked-list

} // namespace

MethodComparison compareEveryMethod(const std::shared_ptr<GlContext>& context, const Scene& scene,
                                    RenderSettings settings, const ViewProjection& view) {
    MethodComparison comparison;
    for (BlendMethod method : kShown) {
        settings.method = method;
        TransparencyRenderer renderer(context, scene, settings);
        MethodPicture picture;
        picture.method = method;
        renderer.render(scene.positions, view, picture.stats); // compiles the programs
        picture.rgba = renderer.render(scene.positions, view, picture.stats).toRgba8();
        comparison.methods.push_back(std::move(picture));
    }
    const std::vector<uint8_t>& reference = comparison.methods[kReference].rgba;
    std::vector<samples::StripTile> tiles, maps;
    for (MethodPicture& picture : comparison.methods) {
        picture.error = compareImages(picture.rgba, reference);
        std::ostringstream caption, map_caption;
        caption << blendMethodName(picture.method) << '\n'
                << std::fixed << std::setprecision(1) << picture.stats.total_ms << " ms, "
                << picture.stats.passes << (picture.stats.passes == 1 ? " pass" : " passes");
        map_caption << "against linked-list:\nmax " << picture.error.max_abs << "/255, "
                    << picture.error.pixels_over_one << " px > 1";
        tiles.push_back({picture.rgba, caption.str()});
        maps.push_back({errorMap(picture.rgba, reference), map_caption.str()});
    }
    tiles.insert(tiles.end(), maps.begin(), maps.end());
    comparison.strip =
        samples::composeStrip(tiles, view.width, view.height, uint32_t(std::size(kShown)));
    return comparison;
}

} // namespace vissort::bench
