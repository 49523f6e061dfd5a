// `vissort bench WHAT`: the benchmarks behind docs/benchmarks.md, each measuring every contender
// in the same run so that the figures are ratios on one machine.

#include "cli/commands.h"

namespace vissort::cli {

CLI::App* addBenchCommand(CLI::App& app, BenchOptions& options) {
    CLI::App* command = app.add_subcommand(
        "bench",
        "Measure the oracles, the transparency methods, the collision methods or the paper's "
        "figures (figures for docs/benchmarks.md)");
    command
        ->add_option("what", options.what,
                     "What to measure: oracle, transparency, collision, paper (the paper's "
                     "figures 5 and 6, files under --out) or volume (the volume rendering "
                     "methods on grids)")
        ->required();
    command->add_option("--repeat", options.repeat, "Runs per synthetic case (best is kept)")
        ->capture_default_str();
    command->add_option("--frames", options.frames,
                        "Frames of the real workloads (oracle: 11), of each method and scene "
                        "(transparency: 3), of each count (collision: 30, after one "
                        "untimed), of each path (paper: 60, quick 6) or of each grid's orbit "
                        "(volume: 5, after one untimed); the first is not timed");
    command->add_option("--gl-frames", options.gl_frames,
                        "Frames through the gl oracle, at most --frames (oracle: 5; paper: 3 on "
                        "a GPU, 0 on a software renderer, quick 2)");
    command->add_option("--size", options.size,
                        "Image size WxH (transparency: 1024x1024; paper: 1600x1200, the "
                        "paper's, quick 320x240; volume: 512x512)");
    command
        ->add_option("--level", options.level,
                     "transparency: vissort's level, object, triangle or multistage")
        ->capture_default_str();
    command
        ->add_option("--depths", options.depths,
                     "transparency: depth complexities to measure, comma-separated")
        ->capture_default_str();
    command
        ->add_option("--samples", options.samples,
                     "transparency: also measure every method at 2, 4 or 8 samples a pixel, "
                     "next to 1, in the same run")
        ->capture_default_str();
    command
        ->add_option("--counts", options.counts,
                     "collision: numbers of bodies (the scene's n) to measure, comma-separated")
        ->capture_default_str();
    command
        ->add_option("--scene", options.collision_scene,
                     "collision: builtin:bunnies (the paper's deforming bunnies) or builtin:pile "
                     "(thousands of small bodies settling), given as bunnies or pile")
        ->capture_default_str();
    command
        ->add_option("--methods", options.methods,
                     "collision: methods to measure besides brute (the ground truth, always "
                     "run), comma-separated: vissort, bullet, fcl")
        ->capture_default_str();
    command
        ->add_option("--threads", options.threads,
                     "collision: thread counts of vissort and bullet, comma-separated, each "
                     "measured")
        ->capture_default_str();
    command
        ->add_option("--cells", options.cells,
                     "volume: about how many tetrahedra each grid has (a cube and a knot of "
                     "each), comma-separated")
        ->capture_default_str();
    command->add_option("--plot", options.plot_path,
                        "collision: write ms against N as a PNG; volume: ms against cells");
    addJsonOptions(*command, options.json, "Write the figures as JSON");
    command
        ->add_option("--out", options.out_dir,
                     "paper: the folder for paper.json, paper.csv, figure6.csv and the plots")
        ->capture_default_str();
    command
        ->add_option("--lod-error", options.lod_error,
                     "paper: the ten-times plant's levels of detail, within PX pixels (0: every "
                     "triangle); the paper's own paths are at full detail")
        ->option_text("PX")
        ->capture_default_str();
    command->add_flag("--quick", options.quick,
                      "paper: a small power plant, 320x240, 6 frames a path, figure 6 at two "
                      "depths (under two minutes)");
    return command;
}

int runBench(const BenchOptions& options) {
    if (options.what == "oracle")
        return runOracleBench(options);
    if (options.what == "transparency") {
#if VISSORT_WITH_GL
        return runTransparencyBench(options);
#else
        return failWithoutGl("bench transparency");
#endif
    }
    if (options.what == "collision")
        return runCollisionBench(options);
    if (options.what == "paper")
        return runPaperBench(options);
    if (options.what == "volume")
        return runVolumeBench(options);
    return fail(kExitUsage, "bench: unknown benchmark '" + options.what +
                                "' (try: oracle, transparency, collision, paper, volume)");
}

} // namespace vissort::cli
