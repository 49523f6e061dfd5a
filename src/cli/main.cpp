// vissort: visibility orderings of 3D geometry from the command line.

#include <iostream>

#include "cli/commands.h"
#include "cli/environment.h"

int main(int argc, char** argv) {
    using namespace vissort::cli;
    CLI::App app{"vissort: visibility ordering of 3D geometry with occlusion queries (Vis-sort)"};
    app.require_subcommand(1);
    app.footer(
        "Run 'vissort order --help' for the camera, --size, --level, --oracle, --frames and\n"
        "output options; docs/ and README.md explain the algorithm and the scene formats.");
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
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        // One line, not CLI11's multi-line report.
        return fail(kExitUsage, std::string(e.what()) + " (run 'vissort --help')");
    }
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
        if (view_command->parsed()) {
            view.frames_given = view_command->count("--frames") > 0;
            return runView(view);
        }
    } catch (const std::bad_alloc&) {
        return fail(kExitFailure, "out of memory (try a smaller --size or scene)");
    } catch (const std::exception& e) {
        return fail(kExitFailure, e.what());
    }
    return kExitUsage;
}
