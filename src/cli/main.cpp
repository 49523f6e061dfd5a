// vissort: visibility orderings of 3D geometry from the command line.

#include <algorithm>
#include <csignal>
#include <filesystem>
#include <iostream>

#include "cli/command_files.h"
#include "cli/command_line_errors.h"
#include "cli/commands.h"
#include "cli/environment.h"
#include "cli/json_output.h"
#include "cli/output_paths.h"
#include "cli/progress.h"
#include "vissort/atomic_file.h"
#include "vissort/collision_peers.h"

namespace {

// Ctrl-C or a kill during a write: the temporary file goes too (the target was never touched),
// then the signal ends the process as it would have.
extern "C" void removeTemporaryFilesAndStop(int signal_number) {
    vissort::removeTemporaryFilesOfWritesInProgress();
    std::signal(signal_number, SIG_DFL);
    std::raise(signal_number);
}

} // namespace

int main(int argc, char** argv) {
    using namespace vissort::cli;
    for (int signal_number : {SIGINT, SIGTERM, SIGHUP})
        std::signal(signal_number, removeTemporaryFilesAndStop);
    // Each line as it is printed, also into a pipe: long runs report as they go.
    std::cout << std::unitbuf;
    // `collide --method bullet|fcl` and `bench collision` measure the peers beside vissort.
    vissort::registerPeerColliders();
    CLI::App app{"vissort: visibility ordering of 3D geometry with occlusion queries (Vis-sort)",
                 "vissort"};
    app.require_subcommand(1);
    app.set_version_flag("--version", std::string("vissort ") + VISSORT_VERSION);
    OrderOptions order;
    InfoOptions info;
    CLI::App* order_command = addOrderCommand(app, order);
    CLI::App* info_command = addInfoCommand(app, info);
    BenchOptions bench;
    CLI::App* bench_command = addBenchCommand(app, bench);
    RenderOptions render;
    CLI::App* render_command = addRenderCommand(app, render);
    CollideOptions collide;
    CLI::App* collide_command = addCollideCommand(app, collide);
    ViewerOptions view;
    CLI::App* view_command = addViewCommand(app, view);
    VolumeOptions volume;
    CLI::App* volume_command = addVolumeCommand(app, volume);
    for (CLI::App* command : {order_command, info_command, bench_command, render_command,
                              collide_command, view_command, volume_command})
        addQuietOption(*command);
    // After the commands: each would inherit it, and it speaks of them all.
    app.footer("Run 'vissort COMMAND --help' for a command's options. docs/cli.md documents\n"
               "every command, option, output and exit code; README.md and docs/ explain the\n"
               "algorithm and the scene formats.");
    // `vissort help [COMMAND]`: what people type after git and cargo.
    // `vissort` alone: the help, as `vissort help` and `vissort --help` print it.
    if (argc == 1 || (argc >= 2 && std::string(argv[1]) == "help")) {
        if (argc <= 2) {
            std::cout << app.help();
            return kExitOk;
        }
        try {
            // Named as `vissort order --help` names it: "Usage: vissort order ...".
            std::cout << app.get_subcommand(argv[2])->help(app.get_name());
            return kExitOk;
        } catch (const CLI::OptionNotFound&) {
            // Reported below, as any unknown command.
            argv[1] = argv[2];
        }
    }
    if (const std::string error = checkCommandLine(app, argc, argv); !error.empty())
        return fail(kExitUsage, error);
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        // One line, not CLI11's multi-line report.
        return fail(kExitUsage, explainParseError(app, e));
    }
    // One document on standard output: the people's text then goes to standard error.
    for (const auto& [json, csv] : {std::pair{&order.json, &order.csv},
                                    {&render.json, &render.csv},
                                    {&collide.json, &collide.csv}})
        if (json->path == "-" && *csv == "-")
            return fail(kExitUsage, "--json - and --csv - both want standard output: send one of "
                                    "them to a file");
    // Every file the command will write, checked before any work. A frame pattern (render's
    // and volume's -o and --error-map) names its command's frames.
    const struct {
        const CLI::App* command;
        const char* option;
        const std::string* path;
        const int* frames = nullptr;
    } outputs[] = {{order_command, "--json", &order.json.path},
                   {order_command, "--csv", &order.csv},
                   {order_command, "--dump-primitives", &order.dump_path},
                   {info_command, "--json", &info.json.path},
                   {bench_command, "--json", &bench.json.path},
                   {bench_command, "--plot", &bench.plot_path},
                   {render_command, "-o", &render.output, &render.view.frames},
                   {render_command, "--json", &render.json.path},
                   {render_command, "--csv", &render.csv},
                   {render_command, "--error-map", &render.error_map, &render.view.frames},
                   {collide_command, "--json", &collide.json.path},
                   {collide_command, "--csv", &collide.csv},
                   {collide_command, "--pairs-out", &collide.pairs_path},
                   {collide_command, "--dump-primitives", &collide.dump_path},
                   {view_command, "--screenshot", &view.screenshot},
                   {volume_command, "-o", &volume.output, &volume.view.frames},
                   {volume_command, "--json", &volume.json.path},
                   {volume_command, "--error-map", &volume.error_map, &volume.view.frames}};
    std::vector<vissort::FileUse> written;
    for (const auto& output : outputs)
        if (output.command->parsed()) {
            if (const std::string reason = unwritableReason(*output.path); !reason.empty())
                return fail(kExitFailure, std::string(output.option) + ": " + reason);
            const bool pattern = output.frames && vissort::isFramePattern(*output.path);
            written.push_back(
                {output.option, *output.path, pattern ? std::max(1, *output.frames) : 0});
        }
    if (bench_command->parsed() && bench.what == "paper")
        for (const std::string& name : paperBenchFileNames())
            written.push_back({"--out", (std::filesystem::path(bench.out_dir) / name).string()});
    // No output is an input or another output (output_files.h): the files known from the
    // command line now, a scene's own files once it is loaded (loadSceneOrReport).
    const std::vector<vissort::FileUse> read =
        commandInputs({{order_command, order.scene},
                       {info_command, info.scene},
                       {render_command, render.scene},
                       {collide_command, collide.scene},
                       {view_command, view.scene},
                       {volume_command, volume.grid}},
                      {{volume_command, "--tf", volume.tf},
                       {view_command, "--tf", view.tf},
                       {view_command, "--script", view.script}});
    vissort::OutputFiles output_files(std::move(written));
    if (std::string clash = output_files.clashWith(read); !clash.empty())
        return fail(kExitFailure, clash);
    if (std::string clash = output_files.clashAmongThemselves(); !clash.empty())
        return fail(kExitFailure, clash);
    declareOutputs(std::move(output_files));
    for (const JsonOutput* json :
         {&order.json, &info.json, &bench.json, &render.json, &collide.json, &volume.json})
        reserveStandardOutputFor(*json);
    for (const std::string* csv : {&order.csv, &render.csv, &collide.csv})
        reserveStandardOutputFor(*csv);
    applyQuiet();
    if (vissort::Status environment = applyEnvironment(); !environment)
        return fail(kExitFailure, environment.error);
    try {
        if (order_command->parsed())
            return runOrder(order);
        if (info_command->parsed())
            return runInfo(info);
        if (bench_command->parsed())
            return runBench(bench);
        if (render_command->parsed())
            return runRender(render);
        if (collide_command->parsed())
            return runCollide(collide);
        if (volume_command->parsed())
            return runVolume(volume);
        if (view_command->parsed()) {
            view.frames_given = view_command->count("--frames") > 0;
            view.given = [view_command](const std::string& name) {
                return view_command->count(name) > 0;
            };
            return runView(view);
        }
    } catch (const std::bad_alloc&) {
        return fail(kExitFailure, "out of memory (try a smaller --size or scene)");
    } catch (const std::exception& e) {
        return fail(kExitFailure, e.what());
    }
    return kExitUsage;
}
