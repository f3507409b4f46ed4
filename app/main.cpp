// fraktal: the command line. Without a subcommand it will open the editor (or, with no display,
// render the default preset); subcommands do headless work.
#include <cstdio>
#include <exception>

#include "cli/commands.hpp"
#include "core/preset.hpp"

int main(int argc, char** argv) {
    CLI::App app{"fraktal: compose, explore and render 3D fractals"};
    app.require_subcommand(0, 1);
    fraktal::cli::Action action;
    fraktal::cli::addCheckCommand(app, action);
    fraktal::cli::addEditCommand(app, action);
    fraktal::cli::addRenderCommand(app, action);
    fraktal::cli::addInfoCommand(app, action);
    fraktal::cli::addBenchViewportCommand(app, action);
    fraktal::cli::addMergeCommand(app, action);
    fraktal::cli::addEncodeCommand(app, action);
    fraktal::cli::addFarmCommand(app, action);
    fraktal::cli::addImportCommand(app, action);
    fraktal::cli::addMeshCommand(app, action);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    }
    if (!action) action = fraktal::cli::defaultEditorAction();
    try {
        return action();
    } catch (const fraktal::PresetError& e) {
        std::fprintf(stderr, "fraktal: error: %s\n", e.what());
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "fraktal: error: %s\n", e.what());
        return 2;
    }
}
