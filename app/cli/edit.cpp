// `fraktal edit PRESET [--frames N --screenshot OUT.png]`: the editor. `fraktal` alone opens it
// with presets/mandelbulb.json. With no display it says so and points to `fraktal render`.
#include <cstdio>
#include <memory>

#include "cli/commands.hpp"

#ifdef FRAKTAL_HAVE_EDITOR
#include "editor/editor.hpp"
#endif

namespace fraktal::cli {

namespace {

struct EditOptions {
    std::string preset;
    int frames = 0;
    std::string screenshot;
    bool untilSettled = false;
    std::string tab;
    int width = 0, height = 0;  // 0: the editor's remembered size
    std::string stateFile;
    int slowFrameMs = 0;
    std::string frameLog;
    std::string exportSize;
    std::string dropReplay;
    bool fullUiRedraw = false;
    int aaCapLimit = 0;
};

int runEdit(const EditOptions& o) {
#ifdef FRAKTAL_HAVE_EDITOR
    editor::EditorOptions e;
    e.preset = o.preset;
    e.frames = o.frames;
    e.screenshot = o.screenshot;
    e.untilSettled = o.untilSettled;
    e.width = o.width;
    e.height = o.height;
    e.sidebarTab = o.tab;
    e.stateFile = o.stateFile;
    e.slowFrameMs = o.slowFrameMs;
    e.frameLog = o.frameLog;
    e.dropReplay = o.dropReplay;
    e.uiCache = !o.fullUiRedraw;
    e.aaCapLimit = o.aaCapLimit;
    if (!o.exportSize.empty() && std::sscanf(o.exportSize.c_str(), "%dx%d", &e.exportWidth, &e.exportHeight) != 2) {
        std::fprintf(stderr, "fraktal: --export-size: '%s' is not WIDTHxHEIGHT\n", o.exportSize.c_str());
        return 2;
    }
    // Scripted runs (tests, bug reports) must look the same everywhere: no personal ini.
    e.useIniFile = o.frames == 0;
    // Nor autosave or a restore prompt: a scripted run is not a session to recover.
    e.sessionRecovery = o.frames == 0 && o.stateFile.empty();
    return editor::runEditor(e);
#else
    std::fputs("fraktal: this build has no editor (FRAKTAL_BUILD_EDITOR=OFF); use `fraktal render`.\n", stderr);
    return 3;
#endif
}

}  // namespace

void addEditCommand(CLI::App& app, Action& action) {
    auto o = std::make_shared<EditOptions>();
    CLI::App* cmd = app.add_subcommand("edit", "Open the editor (needs a display; see `fraktal render` for headless)");
    cmd->add_option("preset", o->preset, "Preset file (JSON) or exported EXR to open")->check(CLI::ExistingFile);
    cmd->add_option("--frames", o->frames, "Draw this many frames, then exit")->check(CLI::Range(1, 100000));
    cmd->add_option("--screenshot", o->screenshot, "With --frames: save a PNG of the whole window at the end")
        ->needs("--frames");
    cmd->add_flag("--until-settled", o->untilSettled,
                  "With --frames: end at the first frame the view has finished refining (at most --frames)")
        ->needs("--frames");
    cmd->add_option("--tab", o->tab, "Scene panel tab to show first (2D documents: View, Render, Colouring, Presets)")
        ->check(CLI::IsMember({"Camera", "Render", "Shading", "Lights", "Presets", "View", "Colouring"}));
    cmd->add_option("--width", o->width, "Window width")->check(CLI::Range(320, 16384));
    cmd->add_option("--height", o->height, "Window height")->check(CLI::Range(240, 16384));
    cmd->add_option("--state-file", o->stateFile, "Write the editor's state as JSON after every frame (for tests)");
    cmd->add_option("--slow-frames", o->slowFrameMs, "Make every frame at least this many ms longer (for tests)")
        ->check(CLI::Range(0, 10000));
    cmd->add_option("--export-size", o->exportSize, "The export dialog's size at start, WIDTHxHEIGHT (Custom)");
    cmd->add_option("--frame-log", o->frameLog,
                    "Append one JSON line per frame (frame time and where it went, viewport scale and size, camera) "
                    "to this file");
    cmd->add_option("--replay-drops", o->dropReplay,
                    "When this file appears, drop the files it lists (one a line) on the window, through the "
                    "window's drop callback, and remove it (for tests)");
    cmd->add_option("--aa-cap", o->aaCapLimit,
                    "Stop the viewport's anti-aliasing at this many samples per pixel on this machine (the "
                    "document's own cap is kept and saved)")
        ->check(CLI::Range(1, 256));
    cmd->add_flag("--full-ui-redraw", o->fullUiRedraw,
                  "Draw every window on every frame, also during a camera drag (for comparisons)");
    cmd->callback([&action, o] { action = [o] { return runEdit(*o); }; });
}

Action defaultEditorAction() {
    return [] {
        EditOptions o;
        o.preset = std::string(FRAKTAL_SOURCE_DIR) + "/presets/mandelbulb.json";
        return runEdit(o);
    };
}

}  // namespace fraktal::cli
