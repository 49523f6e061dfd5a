// `vissort bench transparency`'s measurements (transparency_bench.h).

#include "harnesses/transparency_bench.h"

#include <algorithm>
#include <memory>

#include "harnesses/measurement.h"
#include "scenes/scene_library.h"
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

// Every method on the scene at each count of samples a pixel, errors against linked-list's at as
// many: result[k][method] at sample_counts[k]. A method's counts take turns frame by frame, so
// that the machine's drift in a run weighs on each alike.
std::vector<std::vector<TransparencyMeasured>>
measureMethods(const TransparencyBenchSettings& settings, const Scene& scene,
               const CameraSpec& base, std::span<const uint32_t> sample_counts) {
    const std::size_t counts = sample_counts.size(), frames = std::size_t(settings.frames);
    // reference[k][f]: linked-list's image of frame f at sample_counts[k]
    std::vector<std::vector<std::vector<uint8_t>>> reference(
        counts, std::vector<std::vector<uint8_t>>(frames));
    std::vector<std::vector<TransparencyMeasured>> measured(
        counts, std::vector<TransparencyMeasured>(std::size(kTransparencyMethods)));
    for (std::size_t index : kRenderOrder) {
        const BlendMethod method = kTransparencyMethods[index];
        std::vector<std::unique_ptr<TransparencyRenderer>> renderers;
        for (uint32_t samples : sample_counts) {
            RenderSettings render_settings;
            render_settings.method = method;
            render_settings.level = settings.level;
            render_settings.samples = samples;
            renderers.push_back(
                std::make_unique<TransparencyRenderer>(settings.context, scene, render_settings));
        }
        FrameDriver driver(scene, base, CameraPath::orbit, settings.width, settings.height);
        std::vector<std::vector<double>> ms(counts), order_ms(counts);
        for (std::size_t f = 0; f < frames; ++f) {
            driver.seek(int(f));
            for (std::size_t k = 0; k < counts; ++k) {
                TransparencyMeasured& m = measured[k][index];
                RenderStats stats;
                std::vector<uint8_t> image =
                    renderers[k]->render(driver.positions(), driver.view(), stats).toRgba8();
                if (f > 0) {
                    ms[k].push_back(stats.total_ms);
                    order_ms[k].push_back(stats.order_ms);
                }
                m.passes = std::max(m.passes, stats.passes);
                m.fragments = std::max(m.fragments, stats.fragments);
                if (method == BlendMethod::linked_list) {
                    reference[k][f] = std::move(image);
                } else {
                    const ImageError error = compareImages(image, reference[k][f]);
                    m.max_abs = std::max(m.max_abs, error.max_abs);
                    m.rmse = std::max(m.rmse, error.rmse);
                }
            }
        }
        for (std::size_t k = 0; k < counts; ++k) {
            measured[k][index].ms = median(ms[k]);
            measured[k][index].order_ms = median(order_ms[k]);
        }
    }
    return measured;
}

} // namespace

std::span<const TransparencyFamily> transparencyFamilies() {
    return kFamilies;
}

Result<std::vector<TransparencyBenchRow>>
runTransparencyBench(const TransparencyBenchSettings& settings,
                     const std::function<void(const TransparencyFamily&)>& on_family,
                     const std::function<void(const TransparencyBenchRow&)>& on_row) {
    using Rows = Result<std::vector<TransparencyBenchRow>>;
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
            Result<Scene> loaded = samples::loadScene(row.specification);
            if (!loaded)
                return Rows::failure(loaded.error);
            const Scene& scene = *loaded.value;
            const CameraSpec base = scene.camera.value_or(
                defaultCamera(scene.positions.bounds(), double(width) / height));
            std::vector<uint32_t> sample_counts{1};
            if (settings.samples > 1)
                sample_counts.push_back(settings.samples);
            std::vector<std::vector<TransparencyMeasured>> measured =
                measureMethods(settings, scene, base, sample_counts);
            row.methods = std::move(measured[0]);
            if (settings.samples > 1) {
                row.sampled = std::move(measured[1]);
                row.samples = settings.samples;
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
