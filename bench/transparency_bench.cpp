// `vissort bench transparency`'s measurements (transparency_bench.h).

#include "transparency_bench.h"

#include <algorithm>

#include "support/measurement.h"
#include "vissort/frame_driver.h"

namespace vissort::bench {
namespace {

// linked-list is rendered first: the reference of the others' errors.
constexpr std::size_t kRenderOrder[] = {kTransparencyLinkedList, 0, 1, 2, 4, 5};

const TransparencyFamily kFamilies[] = {
    {"slabs", "builtin:slabs?layers=D, seen down the stack",
     [](uint32_t depth) { return "builtin:slabs?layers=" + std::to_string(depth); }},
    {"plant", "builtin:plant?layers=D/2, CAD-like, opaque steel and transparent pipes and tanks",
     [](uint32_t depth) {
         return "builtin:plant?layers=" + std::to_string(std::max<uint32_t>(1, depth / 2));
     }},
};

} // namespace

std::span<const TransparencyFamily> transparencyFamilies() {
    return kFamilies;
}

Result<std::vector<TransparencyBenchRow>>
runTransparencyBench(const TransparencyBenchSettings& settings,
                     const std::function<void(const TransparencyFamily&)>& on_family,
                     const std::function<void(const TransparencyBenchRow&)>& on_row) {
    using Rows = Result<std::vector<TransparencyBenchRow>>;
    const int frames = settings.frames;
    const uint32_t width = settings.width, height = settings.height;
    std::vector<TransparencyBenchRow> rows;
    for (const TransparencyFamily& family : kFamilies) {
        if (on_family)
            on_family(family);
        for (uint32_t depth : settings.depths) {
            TransparencyBenchRow row;
            row.family = family.name;
            row.specification = family.scene(depth);
            row.depth = depth;
            Result<Scene> loaded = loadScene(row.specification);
            if (!loaded)
                return Rows::failure(loaded.error);
            const Scene& scene = *loaded.value;
            const CameraSpec base = scene.camera.value_or(
                defaultCamera(scene.positions.bounds(), double(width) / height));
            std::vector<std::vector<uint8_t>> reference(static_cast<std::size_t>(frames));
            row.methods.resize(std::size(kTransparencyMethods));
            for (std::size_t index : kRenderOrder) {
                const BlendMethod method = kTransparencyMethods[index];
                RenderSettings render_settings;
                render_settings.method = method;
                render_settings.level = settings.level;
                TransparencyRenderer renderer(settings.context, scene, render_settings);
                FrameDriver driver(scene, base, CameraPath::orbit, width, height);
                TransparencyMeasured m;
                std::vector<double> ms, order_ms;
                for (int f = 0; f < frames; ++f) {
                    driver.seek(f);
                    RenderStats stats;
                    std::vector<uint8_t> image =
                        renderer.render(driver.positions(), driver.view(), stats).toRgba8();
                    if (f > 0) {
                        ms.push_back(stats.total_ms);
                        order_ms.push_back(stats.order_ms);
                    }
                    m.passes = std::max(m.passes, stats.passes);
                    m.fragments = std::max(m.fragments, stats.fragments);
                    if (method == BlendMethod::linked_list) {
                        reference[std::size_t(f)] = std::move(image);
                    } else {
                        const ImageError error = compareImages(image, reference[std::size_t(f)]);
                        m.max_abs = std::max(m.max_abs, error.max_abs);
                        m.rmse = std::max(m.rmse, error.rmse);
                    }
                }
                m.ms = median(ms);
                m.order_ms = median(order_ms);
                row.methods[index] = m;
            }
            // Depth peeling takes one pass a layer and one more: the depth complexity the frames
            // really had, in front of the opaque surfaces.
            row.seen = row.methods[kTransparencyPeel].passes - 1;
            rows.push_back(std::move(row));
            if (on_row)
                on_row(rows.back());
        }
    }
    return Rows{std::move(rows), {}};
}

} // namespace vissort::bench
