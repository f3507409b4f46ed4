// fraktal: the command line. Without a subcommand it will open the editor (or, with no display,
// render the default preset); subcommands do headless work.
#include <cstdio>
#include <exception>

#include "cli/commands.hpp"
#include "core/preset.hpp"

#if defined(__SANITIZE_ADDRESS__)
#include <sanitizer/lsan_interface.h>
#endif

namespace {

int run(int argc, char** argv) {
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

}  // namespace

int main(int argc, char** argv) {
    const int status = run(argc, argv);
#if defined(__SANITIZE_ADDRESS__)
    // Under the sanitizers, look for leaks here, before exit tears down the worker threads of
    // OpenEXR's pool, rather than in LeakSanitizer's at-exit check. That check's thread tracer
    // crashed once on CI ("Tracer caught signal 11", a known intermittent failure of the tracer:
    // google/sanitizers#1353) in a re-render from an EXR; it did not reproduce here. At this point
    // every other thread is either joined or parked. The call replaces the at-exit check and exits
    // non-zero on a leak, as that check does.
    __lsan_do_leak_check();
#endif
    return status;
}
