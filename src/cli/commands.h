#pragma once
// The vissort subcommands: each registers its options and runs when chosen.

#include <CLI/CLI.hpp>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "cli/cli_common.h"
#include "cli/json_output.h"

namespace vissort {
struct RenderSettings; // transparency_renderer.h: builds with OpenGL only
struct RenderStats;
class LevelsOfDetail;
} // namespace vissort

namespace vissort::cli {

struct OrderOptions {
    std::string scene;
    std::string objects; // --objects, empty when not given
    ViewOptions view;
    std::string level = "object";
    std::string oracle = "cpu";
    bool back_to_front = false;
    JsonOutput json;
    std::string csv;
    std::string dump_path;
    double lod_error = 0; // pixels; 0: every triangle
};
CLI::App* addOrderCommand(CLI::App& app, OrderOptions& options);
int runOrder(const OrderOptions& options);

struct InfoOptions {
    std::string scene;
    std::string objects; // --objects, empty when not given
    ViewOptions view;
    bool gl = false;
    bool all_objects = false; // list every object, not the first kListedObjects
    JsonOutput json;          // the facts as JSON, besides the printed ones
};
CLI::App* addInfoCommand(CLI::App& app, InfoOptions& options);
int runInfo(const InfoOptions& options);

struct BenchOptions {
    std::string what;
    int repeat = 3;
    std::optional<int> frames;       // each benchmark has its own default
    std::optional<int> gl_frames;    // each benchmark has its own default
    std::optional<std::string> size; // each benchmark has its own default
    std::string level = "multistage";
    std::string depths = "2,4,8,16,32,64";
    int samples = 1;                         // transparency: samples a pixel measured next to 1
    std::string counts = "18,36,72,144";     // collision: the scene's n
    std::string collision_scene = "bunnies"; // collision: bunnies or pile
    std::string methods = "vissort,bullet";  // collision: besides brute, the ground truth
    std::string threads = "1,2";             // collision: vissort's and bullet's
    std::string cells = "10000,100000";      // volume: about this many tetrahedra a grid
    std::string plot_path;
    JsonOutput json;
    std::string out_dir = "paper-bench"; // paper: where its files go
    bool quick = false;                  // paper: small scenes, few frames
    double lod_error = 1;                // paper: the scale-10 plant's levels of detail
};
CLI::App* addBenchCommand(CLI::App& app, BenchOptions& options);
int runBench(const BenchOptions& options);
int runOracleBench(const BenchOptions& options);
int runTransparencyBench(const BenchOptions& options);
int runCollisionBench(const BenchOptions& options);
int runPaperBench(const BenchOptions& options);
/// The files `bench paper` may write in its --out folder (bench_paper.cpp writes them).
std::vector<std::string> paperBenchFileNames();
int runVolumeBench(const BenchOptions& options);

struct CollideOptions {
    std::string scene;
    std::string objects; // --objects, empty when not given
    int frames = 1;
    std::string method = "vissort";
    std::string size = "64x64";
    int directions = 7;
    double min_cull = 0.25;
    std::string object_stage = "adaptive";
    int threads = 0;
    JsonOutput json;
    std::string csv;
    std::string pairs_path;
    std::string dump_path;
};
CLI::App* addCollideCommand(CLI::App& app, CollideOptions& options);
int runCollide(const CollideOptions& options);

/// The transparency renderer's settings, shared by render and view.
struct RendererOptions {
    std::string method = "vissort";
    std::string level = "object";
    std::string oracle = "cpu";
    bool all_transparent = false;
    double alpha = 0.5;
    std::string shading = "lit";
    int samples = 1;
    std::string check = "auto";
    double list_memory_mib = 3072;
    bool colour_cycles = false;
    std::string background; // empty: kDefaultBackground
    double lod_error = 0;   // pixels; 0: no levels of detail
};
/// Adds --method (its help: method_help) --level --oracle --all-transparent --alpha
/// --background --shading --samples --check --list-memory --colour-cycles --lod-error.
void addRendererOptions(CLI::App& command, RendererOptions& options,
                        const std::string& method_help);
/// Empty on success, else a one-line message naming the bad option. The method is left to the
/// caller when it is "all" and allow_all.
std::string resolveRendererOptions(const RendererOptions& options, bool allow_all,
                                   RenderSettings& settings);
/// The line before a render: the scene, its transparent objects, the method and the view; a
/// note when nothing is transparent, a warning when transparent objects have alpha 0 (unseen).
void printRenderHeader(const std::string& specification, const Scene& scene,
                       const RenderSettings& settings, const ChosenView& view);
/// The scene's levels of detail when --lod-error asks for them (lod_error > 0), built with a
/// progress bar; null otherwise.
std::shared_ptr<const LevelsOfDetail> buildLevels(const Scene& scene, double lod_error);
/// "313060 of 817948 triangles drawn (2 objects as boxes, 1164 out of view)" (verb: "drawn").
std::string levelsLine(uint64_t triangles, uint32_t boxed_objects, uint32_t culled_objects,
                       std::size_t scene_triangles, const std::string& verb);
/// Empty when --lod-error's value is usable (0 to 1e6 pixels), else why not.
std::string checkLodError(double lod_error);

struct RenderOptions {
    std::string scene;
    std::string objects; // --objects, empty when not given
    ViewOptions view;
    RendererOptions renderer;
    std::string output;
    JsonOutput json;
    std::string csv;
    std::string reference;
    std::string error_map;
    bool highlight_collisions = false;
};
CLI::App* addRenderCommand(CLI::App& app, RenderOptions& options);
int runRender(const RenderOptions& options);

struct ViewerOptions {
    std::string scene;
    std::string objects; // --objects, empty when not given
    ViewOptions view;
    RendererOptions renderer;
    std::string screenshot;
    std::string script;
    bool hide_ui = false;
    bool highlight_collisions = false;
    bool show_errors = false;
    bool frames_given = false; // --frames on the command line (else: until the window closes)
    // A grid's (vissort view GRID): its transfer function and density.
    std::string tf = "cool-warm";
    double density = 4.0;
    // Whether an option (by its long name, "--level") was on the command line: a grid's window
    // refuses a scene's options and a scene's a grid's, rather than ignoring them.
    std::function<bool(const std::string&)> given = [](const std::string&) { return false; };
};
CLI::App* addViewCommand(CLI::App& app, ViewerOptions& options);
int runView(const ViewerOptions& options);

struct VolumeOptions {
    std::string grid;
    std::string output;
    std::string tf = "cool-warm";
    double density = 4.0;
    std::string method = "vissort";
    std::string oracle = "cpu";
    std::string background; // empty: kDefaultBackground
    std::string reference;  // a method each frame is compared with, or empty
    std::string error_map;  // with reference: where the error maps go
    ViewOptions view;
    JsonOutput json;
};
CLI::App* addVolumeCommand(CLI::App& app, VolumeOptions& options);
int runVolume(const VolumeOptions& options);

/// `info` of a grid file or built-in grid (grid_info.cpp).
int runGridInfo(const InfoOptions& options);

} // namespace vissort::cli
