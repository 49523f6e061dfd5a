// `vissort bench transparency`: the paper's figure 6, extended. Frame time against depth
// complexity for vissort and the methods it is measured against (depth peeling, dual depth
// peeling, per-pixel linked lists, weighted blended OIT, and centroid sorting), on builtin:slabs
// (depth complexity = layers) and the CAD-like builtin:plant (about 2 x layers), with each
// method's error against linked-list, every method in the same run through the same renderer.

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cli/bench_common.h"
#include "cli/commands.h"
#include "cli/json_output.h"
#include "vissort/camera_path.h"
#include "vissort/transparency_renderer.h"

namespace vissort::cli {
namespace {

// In the order shown. linked-list is rendered first: the reference of the others' errors.
constexpr BlendMethod kMethods[] = {BlendMethod::vissort,   BlendMethod::peel,
                                    BlendMethod::dual_peel, BlendMethod::linked_list,
                                    BlendMethod::weighted,  BlendMethod::centroid};
constexpr std::size_t kVissort = 0, kPeel = 1, kLinkedList = 3;
constexpr std::size_t kRenderOrder[] = {kLinkedList, 0, 1, 2, 4, 5};

struct Family {
    const char* name;
    const char* description;
    std::string (*scene)(uint32_t depth);
};

const Family kFamilies[] = {
    {"slabs", "builtin:slabs?layers=D, seen down the stack",
     [](uint32_t depth) { return "builtin:slabs?layers=" + std::to_string(depth); }},
    {"plant", "builtin:plant?layers=D/2, CAD-like, opaque steel and transparent pipes and tanks",
     [](uint32_t depth) {
         return "builtin:plant?layers=" + std::to_string(std::max<uint32_t>(1, depth / 2));
     }},
};

struct Measured {
    double ms = 0; // median over the timed frames
    double order_ms = 0;
    uint32_t passes = 0; // the most in a frame
    uint64_t fragments = 0;
    int max_abs = 0; // against linked-list, the worst frame
    double rmse = 0;
};

} // namespace

int runTransparencyBench(const BenchOptions& options) {
    const int frames = options.frames.value_or(3);
    if (frames < 2 || frames > 100)
        return fail(kExitUsage, "--frames must be 2..100");
    uint32_t width = 0, height = 0;
    if (auto error = parseSize(options.size, width, height); !error.empty())
        return fail(kExitUsage, error);
    const Result<OrderLevel> parsed_level = parseOrderLevel(options.level);
    if (!parsed_level) return fail(kExitUsage, "--level: " + parsed_level.error);
    const OrderLevel level = *parsed_level.value;
    std::vector<uint32_t> depths;
    if (!parseCounts(options.depths, depths))
        return fail(kExitUsage, "--depths expects depth complexities of 1 to 1000 separated by "
                                "commas, got '" +
                                    options.depths + "'");
    Result<std::shared_ptr<GlContext>> context = GlContext::shared();
    if (!context)
        return fail(kExitFailure, context.error);
    const GlContextInfo& gl = (*context.value)->info();

    std::cout << "vissort bench transparency on " << machineName() << "\n  OpenGL: " << gl.renderer
              << " (" << gl.version << ")\n  " << width << 'x' << height << ", vissort at "
              << orderLevelName(level) << " level with the cpu oracle; milliseconds per frame, "
              << "median of " << frames - 1 << " frame(s) on an orbit after an untimed first\n";
    nlohmann::json rows = nlohmann::json::array();
    for (const Family& family : kFamilies) {
        std::cout << '\n'
                  << family.name << ": " << family.description << '\n'
                  << "     D  seen" << std::right;
        for (BlendMethod method : kMethods)
            std::cout << std::setw(19) << blendMethodName(method);
        std::cout << "   errors against linked-list (max/255)\n";
        for (uint32_t depth : depths) {
            const std::string spec = family.scene(depth);
            Result<Scene> loaded = loadScene(spec);
            if (!loaded)
                return fail(kExitFailure, loaded.error);
            const Scene& scene = *loaded.value;
            const Bounds bounds = scene.positions.bounds();
            const CameraSpec base =
                scene.camera.value_or(defaultCamera(bounds, double(width) / height));
            std::vector<std::vector<uint8_t>> reference(static_cast<std::size_t>(frames));
            std::vector<Measured> measured(std::size(kMethods));
            for (std::size_t index : kRenderOrder) {
                const BlendMethod method = kMethods[index];
                RenderSettings settings;
                settings.method = method;
                settings.level = level;
                TransparencyRenderer renderer(*context.value, scene, settings);
                Measured m;
                std::vector<double> ms, order_ms;
                for (int f = 0; f < frames; ++f) {
                    const ViewProjection view = frameCamera(
                        cameraOnPath(base, CameraPath::orbit, f, bounds), bounds, width, height);
                    RenderStats stats;
                    std::vector<uint8_t> image =
                        renderer.render(scene.positions, view, stats).toRgba8();
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
                measured[index] = m;
            }
            // Depth peeling takes one pass a layer and one more: the depth complexity the frames
            // really had, in front of the opaque surfaces.
            const uint32_t seen = measured[kPeel].passes - 1;
            std::cout << std::setw(6) << depth << std::setw(6) << seen;
            const double vissort_ms = measured[kVissort].ms;
            for (std::size_t i = 0; i < measured.size(); ++i) {
                std::ostringstream cell;
                cell << std::fixed << std::setprecision(1) << measured[i].ms;
                if (i != kVissort)
                    cell << " (" << measured[i].ms / vissort_ms << "x)";
                std::cout << std::setw(19) << cell.str();
            }
            std::cout << "   ";
            for (std::size_t i = 0; i < measured.size(); ++i)
                if (i != kLinkedList)
                    std::cout << (i > 0 ? ", " : "") << blendMethodName(kMethods[i]) << ' '
                              << measured[i].max_abs;
            std::cout << std::endl; // a row at a time: a long run shows its progress
            for (std::size_t i = 0; i < measured.size(); ++i) {
                const Measured& m = measured[i];
                nlohmann::json row = {{"scene", family.name},
                                      {"specification", spec},
                                      {"depth", depth},
                                      {"depth_seen", seen},
                                      {"method", blendMethodName(kMethods[i])},
                                      {"ms", m.ms},
                                      {"order_ms", m.order_ms},
                                      {"passes", m.passes},
                                      {"fragments", m.fragments},
                                      {"ms_over_vissort", m.ms / vissort_ms}};
                if (kMethods[i] != BlendMethod::linked_list)
                    row["error"] = {{"max_abs", m.max_abs}, {"rmse", m.rmse}};
                rows.push_back(std::move(row));
            }
        }
    }
    std::cout << "\n(x): a method's time over vissort's; seen: the most transparent layers at a "
                 "pixel, from depth peeling's passes\n";
    if (!options.json_path.empty()) {
        const nlohmann::json document = {
            {"machine", machineName()}, {"gl_renderer", gl.renderer},
            {"size", {width, height}},  {"level", orderLevelName(level)},
            {"frames", frames},         {"rows", rows}};
        if (const int code = writeJsonFile(options.json_path, document); code != kExitOk)
            return code;
    }
    return kExitOk;
}

} // namespace vissort::cli
