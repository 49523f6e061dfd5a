#pragma once
// `vissort bench paper`: the figures of Govindaraju, Henson, Lin and Manocha, "Interactive
// Visibility Ordering and Transparency Computations among Geometric Primitives in Complex
// Environments" (I3D 2005), section 5.4, measured on this machine in one run:
//  - figure 5 (left): the power plant walkthrough (builtin:powerplant, its own camera path),
//    ordering queries and milliseconds per frame through the cpu and gl oracles, and the frame
//    time with transparency (vissort's renderer: its ordering and blending);
//  - figure 5 (right): the deforming bunnies with a stationary and with a moving viewer: the same,
//    and the collision time per frame (vissort's detector);
//  - figure 6: frame time against depth complexity, vissort against depth peeling and the other
//    methods (transparency_bench.h);
//  - queries per primitive per coherent frame on each path (the paper's "almost linear" claim);
//  - the power plant ten times over (builtin:powerplant?scale=10, 7.9M triangles) along the same
//    walkthrough with levels of detail (levels_of_detail.h, issue 37): the paper's future work.

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "harnesses/transparency_bench.h"
#include "vissort/camera_path.h"
#include "vissort/result.h"
#include "vissort/scene_orderer.h"

namespace vissort {
class GlContext;
}

namespace vissort::bench {

/// What the paper reports for its paths (GeForce 6800, 1600x1200), and the project's targets,
/// drawn on the plots.
struct PaperReported {
    const char* what;
    double low_ms, high_ms; // a range of frame times; equal when one value is reported
};

/// One frame of one path: its ordering through each oracle, its render, its collisions.
struct PaperFrame {
    int frame = 0;
    uint64_t cpu_queries = 0;
    uint64_t cpu_cycle_queries = 0; // of cpu_queries, those the cycle search and its hints spent
    uint64_t cpu_cycles = 0;        // the cycles the cpu oracle's order reported
    double cpu_order_ms = 0;
    std::optional<uint64_t> gl_queries; // the first gl_frames frames only
    std::optional<double> gl_order_ms;
    std::optional<double> render_ms;  // vissort's transparency renderer, whole frame (OpenGL)
    std::optional<double> collide_ms; // vissort's collision detector (PaperPath::collide)
    uint64_t triangles_drawn = 0;     // ordered and drawn: every triangle, or the levels chosen
};

/// A scene walked frame by frame along a camera path.
struct PaperPath {
    std::string name;          // "plant-walkthrough", "bunnies-static", "bunnies-moving"
    std::string figure;        // "5 left", "5 right"
    std::string specification; // the scene
    CameraPath path = CameraPath::fixed;
    OrderLevel level = OrderLevel::object;
    uint32_t width = 0, height = 0;
    uint64_t primitives = 0; // of the ordering level (objects, or triangles)
    uint64_t triangles = 0;
    std::vector<PaperReported> reported;
    bool collide = false; // measure vissort's collision detector too (a dynamic scene)
    /// Levels of detail within this many pixels (0: every triangle); the ordering's time then
    /// includes choosing the levels and gathering their triangles.
    float lod_error = 0.0f;
    double levels_ms = 0;  // building the levels of detail, once
    bool gl_oracle = true; // ordered through the gl oracle too (its first gl_frames frames)
    std::vector<PaperFrame> frames;
};

struct PaperBenchSettings {
    std::shared_ptr<GlContext> context; // null: no gl oracle, no rendering, no figure 6
    bool quick = false;                 // small scenes and images, few frames: under two minutes
    int frames = 0;                     // per path; 0: 60 (quick: 6)
    int gl_frames = -1;                 // of those through the gl oracle; -1: paperGlFrames's
    uint32_t width = 0, height = 0;     // 0: 1600x1200, the paper's (quick: 320x240)
    /// The scale-10 plant's level of detail error in pixels (0: every triangle, slow); the
    /// paper's own paths are measured at full detail, as the paper's were.
    float lod_error = 1.0f;
};

struct PaperBenchResult {
    std::vector<PaperPath> paths;
    std::vector<TransparencyBenchRow> figure6; // empty without an OpenGL context
    TransparencyBenchSettings figure6_settings;
};

/// The frames of each path ordered through the gl oracle: settings.gl_frames when set (at most
/// the path's frames); else 2 with quick, 3 on a GPU and none on a software renderer (llvmpipe:
/// the plant's first frame at 1600x1200 takes more than ten minutes there); none without a
/// context.
int paperGlFrames(const PaperBenchSettings& settings);

/// Progress: what is being measured, and steps done of the run's total.
using PaperProgress = std::function<void(const std::string& what, int done, int total)>;

/// Measures every path frame by frame (each oracle's orderer starting from its own previous
/// frame), then figure 6 when there is a context. A one-line message when a scene cannot be made.
Result<PaperBenchResult> runPaperBench(const PaperBenchSettings& settings,
                                       const PaperProgress& progress = {});

/// What a frame measured, one value each: the summaries, the tables and the plots read them
/// through metricOf.
enum class PaperMetric {
    cpu_order_ms,
    cpu_queries,
    cpu_cycle_queries,
    gl_order_ms,
    gl_queries,
    render_ms,
    collide_ms
};
/// The frame's value of a metric; none when the frame did not measure it.
std::optional<double> metricOf(const PaperFrame& frame, PaperMetric metric);

/// A path's medians over the coherent frames (every frame but the first, which starts from the
/// depth-key order); none where no coherent frame measured the value.
struct PaperSummary {
    std::optional<double> cpu_order_ms, cpu_queries, cpu_cycle_queries, gl_order_ms, gl_queries,
        render_ms, collide_ms;
    std::optional<double> cpu_queries_per_primitive, gl_queries_per_primitive;
};
PaperSummary summarize(const PaperPath& path);

} // namespace vissort::bench
