// vissort.render and vissort.Renderer: exact order-independent transparency (and its peer
// methods) as (H, W, 4) uint8 images, through the process's shared OpenGL context.

#include <cmath>
#include <memory>
#include <mutex>

#include <pybind11/stl.h>

#include "arrays.h"
#include "bindings.h"
#include "frame_input.h"
#include "gl_turn.h"
#include "python_camera.h"
#include "stats_dict.h"

#if VISSORT_WITH_GL
#include "vissort/frame_pipeline.h"
#endif

namespace vissort::python {
namespace {

#if VISSORT_WITH_GL
FramePipelineDef pipelineDefOf(const std::string& method, const std::string& level,
                               const std::string& oracle, bool all_transparent, double alpha,
                               const std::string& shading, int samples, const std::string& check,
                               const py::handle& background, bool highlight_collisions,
                               double lod_error, uint32_t threads) {
    FramePipelineDef def;
    def.highlight_collisions = highlight_collisions;
    RenderSettings& settings = def.settings;
    const Result<BlendMethod> parsed_method = parseBlendMethod(method);
    if (!parsed_method)
        throw py::value_error(parsed_method.error);
    settings.method = *parsed_method.value;
    const Result<OrderLevel> parsed_level = parseOrderLevel(level);
    if (!parsed_level)
        throw py::value_error(parsed_level.error);
    settings.level = *parsed_level.value;
    const Result<OracleKind> parsed_oracle = parseOracleKind(oracle);
    if (!parsed_oracle)
        throw py::value_error(parsed_oracle.error);
    settings.oracle = *parsed_oracle.value;
    settings.oracle_options.threads = threads;
    settings.all_transparent = all_transparent;
    settings.alpha = float(alpha);
    const Result<Shading> parsed_shading = parseShading(shading);
    if (!parsed_shading)
        throw py::value_error(parsed_shading.error);
    settings.shading = *parsed_shading.value;
    if (const Result<SampleGrid> grid = sampleGridOf(samples); !grid)
        throw py::value_error(grid.error);
    settings.samples = uint32_t(samples);
    const Result<RenderSettings::OrderCheck> parsed_check = parseOrderCheck(check);
    if (!parsed_check)
        throw py::value_error(parsed_check.error);
    settings.check = *parsed_check.value;
    settings.background = readColour(background, "background");
    if (!(lod_error >= 0 && lod_error <= 1e6))
        throw py::value_error("lod_error must be 0 (every triangle) or a number of pixels up to "
                              "1e6, got " +
                              std::to_string(lod_error));
    settings.lod_error = float(lod_error);
    return def;
}

// The frame's statistics (the same table as the command line's) and the ordering's counts,
// as Orderer.order's stats; with highlights, the collisions'.
py::dict statsDict(const PipelineFrame& frame, bool highlighting) {
    py::dict d;
    addStats(d, frame.stats);
    addStats(d, frame.stats.order);
    if (highlighting) {
        d["colliding_pairs"] = frame.colliding_pairs;
        d["colliding_triangles"] = frame.colliding_triangles;
        d["collision_ms"] = frame.collision_ms;
    }
    return d;
}

// A FramePipeline of one scene: successive frames reuse the last order (coherence).
class Renderer {
public:
    Renderer(std::shared_ptr<Scene> scene, const FramePipelineDef& def) : scene_(std::move(scene)) {
        Result<std::shared_ptr<GlContext>> context;
        {
            py::gil_scoped_release unlocked;
            context = sharedGlContext();
            if (context) {
                GlTurn turn(*context.value);
                renderer_ = std::make_unique<FramePipeline>(*context.value, *scene_, def);
            }
        }
        if (!context)
            throw std::runtime_error(context.error);
        context_ = *context.value;
    }

    ~Renderer() {
        GlTurn turn(context_); // its GL objects are deleted in the context
        renderer_.reset();
    }

    py::array_t<uint8_t> render(const py::object& camera, const py::object& size,
                                const py::object& time, const py::object& positions,
                                const py::object& triangles) {
        const auto [width, height] = readSize(size);
        const std::unique_lock<std::mutex> lock = lockWithoutGil(mutex_);
        std::shared_ptr<Scene> used_scene;
        const PositionsView frame =
            readFrame(positions, triangles, time, scene_, buffer_, used_scene);
        const PythonCamera used_camera = cameras_.choose(camera, scene_, frame, width, height);
        PipelineFrame rendered;
        {
            py::gil_scoped_release unlocked;
            GlTurn turn(context_);
            renderer_->render(frame, viewOf(used_camera, frame, width, height), rendered);
        }
        stats_ = statsDict(rendered, renderer_->def().highlight_collisions);
        return toArray(std::move(rendered.rgba))
            .reshape(std::vector<py::ssize_t>{py::ssize_t(height), py::ssize_t(width), 4});
    }

    py::dict stats() const { return stats_; }

private:
    std::shared_ptr<Scene> scene_; // kept alive while the renderer is
    std::shared_ptr<GlContext> context_;
    std::unique_ptr<FramePipeline> renderer_;
    TrianglePositions buffer_;
    CameraChoice cameras_;
    py::dict stats_;
    std::mutex mutex_;
};
#endif

[[maybe_unused]] [[noreturn]] void withoutGl() {
    throw std::runtime_error("this vissort was built without OpenGL (VISSORT_WITH_GL=OFF): "
                             "render is not available");
}

constexpr const char* kSettingsDoc =
    "method: vissort, unsorted, centroid, peel, dual-peel, linked-list or weighted. level and "
    "oracle: vissort's ordering (centroid's unit). all_transparent with alpha: every object "
    "transparent. shading: lit, flat or membrane. samples: 1, 2, 4 or 8 a pixel, averaged "
    "(anti-aliasing). check: auto, on or off (vissort's per-pixel check and repair). "
    "background: (r, g, b[, a]) in [0, 1], a dark slate grey by default. highlight_collisions: "
    "the triangles that intersect another object's in opaque magenta, the rest dimmed, each "
    "frame (stats then count the collisions). lod_error: levels of detail within that many "
    "pixels, objects out of view left out (0: every triangle; stats count the triangles "
    "drawn). threads: the cpu oracle's, the calling one included (default 1; 0: one per "
    "core; the picture never depends on it). As the command line's render options.";

} // namespace

void bindRender(py::module_& m) {
#if VISSORT_WITH_GL
    const auto make = [](const std::shared_ptr<Scene>& scene, const std::string& method,
                         const std::string& level, const std::string& oracle, bool all_transparent,
                         double alpha, const std::string& shading, int samples,
                         const std::string& check, const py::object& background,
                         bool highlight_collisions, double lod_error, uint32_t threads) {
        if (!scene)
            throw py::value_error("render needs a Scene (vissort.load or vissort.builtin)");
        return std::make_unique<Renderer>(
            scene, pipelineDefOf(method, level, oracle, all_transparent, alpha, shading, samples,
                                 check, background, highlight_collisions, lod_error, threads));
    };
    py::class_<Renderer>(m, "Renderer",
                         "Renders frames of one scene with transparency; each frame starts "
                         "from the last one's order")
        .def(py::init(make), py::arg("scene"), py::kw_only(), py::arg("method") = "vissort",
             py::arg("level") = "object", py::arg("oracle") = "cpu",
             py::arg("all_transparent") = false, py::arg("alpha") = 0.5, py::arg("shading") = "lit",
             py::arg("samples") = 1, py::arg("check") = "auto",
             py::arg("background") = defaultBackground(), py::arg("highlight_collisions") = false,
             py::arg("lod_error") = 0.0, py::arg("threads") = 1u, kSettingsDoc)
        .def("render", &Renderer::render, py::arg("camera") = py::none(),
             py::arg("size") = py::make_tuple(1024, 1024), py::kw_only(),
             py::arg("time") = py::none(), py::arg("positions") = py::none(),
             py::arg("triangles") = py::none(),
             "An (H, W, 4) uint8 RGBA image, row 0 at the top: the scene at time (default 0), "
             "or at positions ((T, 3, 3), or (V, 3) with triangles) of its triangle count. "
             "camera: default the scene's default (Camera.default). Releases the GIL.")
        .def_property_readonly("stats", &Renderer::stats, "The last frame's costs");
    m.def(
        "render",
        [make](const std::shared_ptr<Scene>& scene, const py::object& camera,
               const py::object& size, const std::string& method, const std::string& level,
               const std::string& oracle, bool all_transparent, double alpha,
               const std::string& shading, int samples, const std::string& check,
               const py::object& background, bool highlight_collisions, double lod_error,
               uint32_t threads, const py::object& time, const py::object& positions,
               const py::object& triangles) {
            auto renderer =
                make(scene, method, level, oracle, all_transparent, alpha, shading, samples, check,
                     background, highlight_collisions, lod_error, threads);
            return renderer->render(camera, size, time, positions, triangles);
        },
        py::arg("scene"), py::arg("camera") = py::none(),
        py::arg("size") = py::make_tuple(1024, 1024), py::kw_only(), py::arg("method") = "vissort",
        py::arg("level") = "object", py::arg("oracle") = "cpu", py::arg("all_transparent") = false,
        py::arg("alpha") = 0.5, py::arg("shading") = "lit", py::arg("samples") = 1,
        py::arg("check") = "auto", py::arg("background") = defaultBackground(),
        py::arg("highlight_collisions") = false, py::arg("lod_error") = 0.0,
        py::arg("threads") = 1u, py::arg("time") = py::none(), py::arg("positions") = py::none(),
        py::arg("triangles") = py::none(),
        ("One frame as an (H, W, 4) uint8 RGBA image (Renderer renders many). " +
         std::string(kSettingsDoc))
            .c_str());
#else
    m.def("Renderer", [](py::args, py::kwargs) { withoutGl(); });
    m.def("render", [](py::args, py::kwargs) { withoutGl(); });
#endif
}

} // namespace vissort::python
