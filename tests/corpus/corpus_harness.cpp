#include "corpus_harness.h"

#include <algorithm>
#include <memory>
#include <set>
#include <sstream>

#include "ground_truth.h"
#include "scenes/scene_library.h"
#include "vissort/oracles.h"
#include "vissort/scene.h"
#if VISSORT_WITH_GL
#include "vissort/transparency_renderer.h"
#endif

namespace vissort::test {
namespace {

using Cycles = std::vector<std::vector<uint32_t>>;

CameraSpec orthographic(Vec3 direction) {
    CameraSpec camera;
    camera.projection = Projection::orthographic;
    camera.ortho_direction = direction;
    return camera;
}

// "3 cycles of 71, 125, 19 primitives" or "no cycle".
std::string cycleSizes(const Cycles& cycles) {
    if (cycles.empty())
        return "no cycle";
    std::vector<std::size_t> sizes;
    for (const auto& cycle : cycles)
        sizes.push_back(cycle.size());
    std::sort(sizes.begin(), sizes.end());
    std::ostringstream out;
    out << cycles.size() << (cycles.size() == 1 ? " cycle of " : " cycles of ");
    for (std::size_t i = 0; i < sizes.size(); ++i)
        out << (i ? ", " : "") << sizes[i];
    out << " primitives";
    return out.str();
}

// Cycles as a set, each ascending (FrameOrder's are; sorted again to compare regardless).
std::set<std::vector<uint32_t>> cycleSet(Cycles cycles) {
    for (auto& cycle : cycles)
        std::sort(cycle.begin(), cycle.end());
    return {cycles.begin(), cycles.end()};
}

struct OrderOutcome {
    FrameOrder frame;
    std::string error; // the oracle could not be made
};

OrderOutcome orderWith(OracleKind kind, const Scene& scene, OrderLevel level,
                       const ViewProjection& view) {
    Result<std::unique_ptr<GeometryOracle>> oracle = makeOracle(kind);
    if (!oracle)
        return {{}, oracle.error};
    SceneOrderer orderer(scene.objectPrimitives(), uint32_t(scene.triangleCount()), level,
                         **oracle.value);
    return {orderer.orderFrame(scene.positions, view), {}};
}

#if VISSORT_WITH_GL
std::shared_ptr<GlContext> sharedContext(std::string& error) {
    static const Result<std::shared_ptr<GlContext>> shared = GlContext::shared();
    if (!shared)
        error = shared.error;
    return shared ? *shared.value : nullptr;
}

std::vector<uint8_t> renderAllTransparent(const Scene& scene, const ViewProjection& view,
                                          BlendMethod method, OrderLevel level, float alpha,
                                          const std::shared_ptr<GlContext>& context) {
    RenderSettings settings;
    settings.method = method;
    settings.level = level;
    settings.all_transparent = true;
    settings.alpha = alpha;
    settings.list_bytes = uint64_t(256) << 20; // more fragments are drawn in bands
    TransparencyRenderer renderer(context, scene, settings);
    RenderStats stats;
    return renderer.render(scene.positions, view, stats).toRgba8();
}
#endif

} // namespace

std::vector<CorpusView> corpusViews() {
    std::vector<CorpusView> views = {
        {"ortho(-0.3,-0.5,-1)", orthographic({-0.3, -0.5, -1})},
        {"ortho(0.9,-0.12,-0.4)", orthographic({0.9, -0.12, -0.4})},
        {"perspective", {}}, // the default view of each file's bounds (defaultCamera)
    };
    return views;
}

std::string refusalProblem(const std::string& path, const std::string& error) {
    if (error.empty())
        return "empty error message";
    if (error.find('\n') != std::string::npos || error.find('\r') != std::string::npos)
        return "error message of more than one line: " + error;
    if (error.find(path) == std::string::npos)
        return "error message does not name the file: " + error;
    return {};
}

namespace {

// Fills report; what it found stays there if a later step throws.
void runChecks(const std::string& path, const CorpusSettings& settings, CorpusReport& report) {
    Result<Scene> loaded = samples::loadScene(path);
    if (!loaded) {
        report.load_error = loaded.error;
        if (const std::string problem = refusalProblem(path, loaded.error); !problem.empty())
            report.failures.push_back("refusal: " + problem);
        return;
    }
    const Scene& scene = *loaded.value;
    report.loaded = true;
    report.objects = scene.objects.size();
    report.triangles = scene.triangleCount();
    if (Status valid = validateScene(scene); !valid)
        report.failures.push_back("loaded scene is invalid: " + valid.error);

    const Bounds bounds = scene.positions.bounds();
    const double aspect = double(settings.width) / settings.height;
    for (const CorpusView& corpus_view : settings.views) {
        const CameraSpec camera = corpus_view.camera.projection == Projection::perspective
                                      ? defaultCamera(bounds, aspect)
                                      : corpus_view.camera;
        const ViewProjection view = frameCamera(camera, bounds, settings.width, settings.height);
        for (OrderLevel level : settings.levels) {
            const std::string where = corpus_view.name + " " + orderLevelName(level) + ": ";
            const std::vector<PrimitiveRange> primitives = primitivesOf(scene, level);
            const Cycles truth = occlusionCycles(scene.positions, view, primitives);
            for (const auto& cycle : truth)
                report.max_cycle = std::max(report.max_cycle, uint32_t(cycle.size()));

            for (const Cycles::value_type& cycle : truth)
                report.true_cycle_members += cycle.size();
            std::vector<OracleKind> kinds = settings.oracles;
#if VISSORT_WITH_GL
            if (settings.gl)
                kinds.push_back(OracleKind::gl);
#endif
            for (OracleKind kind : kinds) {
                const std::string who = where + oracleName(kind) + " oracle: ";
                const OrderOutcome outcome = orderWith(kind, scene, level, view);
                if (!outcome.error.empty()) {
                    report.failures.push_back(who + outcome.error);
                    continue;
                }
                const FrameOrder& frame = outcome.frame;
                // (a) the ground truth, outside the reported cycles.
                const OrderCheck check = checkVisibilityOrder(scene.positions, view, primitives,
                                                              frame.order, frame.cycles, 1);
                if (kind == OracleKind::cpu)
                    report.pairs_checked += check.pairs_checked;
                if (!check.valid_permutation) {
                    report.failures.push_back(who + "the order is not a permutation of " +
                                              std::to_string(primitives.size()) + " primitives");
                } else if (check.violation_count > 0) {
                    const OrderViolation& first = check.violations.front();
                    std::ostringstream line;
                    line << who << check.violation_count << " ground-truth violations of "
                         << check.pairs_checked << " occlusions; first: " << first.front
                         << " in front of " << first.behind << " at pixel (" << first.pixel_x
                         << ", " << first.pixel_y << ") but ordered after it";
                    report.failures.push_back(line.str());
                }
                // (b) the cycles are the exact graph's strongly connected components (gl: its
                // cycles hold them).
                if (kind == OracleKind::gl) {
                    report.gl_ran = true;
                    for (const std::vector<uint32_t>& cycle : frame.cycles)
                        report.gl_cycle_members += cycle.size();
                    const std::set<std::vector<uint32_t>> held = cycleSet(frame.cycles);
                    for (const std::vector<uint32_t>& component : cycleSet(truth))
                        if (std::none_of(held.begin(), held.end(), [&](const auto& cycle) {
                                return std::includes(cycle.begin(), cycle.end(), component.begin(),
                                                     component.end());
                            }))
                            report.failures.push_back(
                                who + "a component of " + std::to_string(component.size()) +
                                " lies in no cycle gl reports (" + cycleSizes(frame.cycles) + ")");
                } else if (cycleSet(frame.cycles) != cycleSet(truth))
                    report.failures.push_back(who + "reports " + cycleSizes(frame.cycles) +
                                              ", the ground truth's components are " +
                                              cycleSizes(truth));
            }
        }

#if VISSORT_WITH_GL
        // (c) vissort against the per-pixel linked-list reference, every object transparent.
        if (!settings.render)
            continue;
        std::string context_error;
        const std::shared_ptr<GlContext> context = sharedContext(context_error);
        if (!context) {
            report.failures.push_back(corpus_view.name + " render: " + context_error);
            continue;
        }
        const std::vector<uint8_t> reference = renderAllTransparent(
            scene, view, BlendMethod::linked_list, OrderLevel::object, settings.alpha, context);
        for (OrderLevel level : settings.levels) {
            const std::vector<uint8_t> image = renderAllTransparent(
                scene, view, BlendMethod::vissort, level, settings.alpha, context);
            const ImageError error = compareImages(image, reference);
            if (error.max_abs > 1)
                report.failures.push_back(corpus_view.name + " " + orderLevelName(level) +
                                          ": render: vissort differs from linked-list by " +
                                          std::to_string(error.max_abs) + "/255, " +
                                          std::to_string(error.pixels_over_one) +
                                          " pixels off by more than 1/255");
        }
#endif
    }
}

} // namespace

CorpusReport checkCorpusFile(const std::string& path, const CorpusSettings& settings) {
    CorpusReport report;
    report.path = path;
    try {
        runChecks(path, settings, report);
    } catch (const std::exception& e) {
        report.failures.push_back(std::string("exception: ") + e.what());
    }
    return report;
}

std::string describe(const CorpusReport& report) {
    std::ostringstream out;
    out << report.path << ": ";
    if (!report.loaded)
        out << "refused: " << report.load_error;
    else
        out << report.objects << " objects, " << report.triangles << " triangles, "
            << report.pairs_checked << " occlusions checked, largest cycle " << report.max_cycle
            << ", cycle members " << report.true_cycle_members
            << (report.gl_ran ? " (gl's: " + std::to_string(report.gl_cycle_members) + ")" : "");
    for (const std::string& failure : report.failures)
        out << "\n  FAIL " << failure;
    return out.str();
}

} // namespace vissort::test
