// The export dialog's job: a still rendered by `fraktal render` (core/render) in a child process
// (export_process.hpp: the child, its progress, cancel and the Done rule, shared with the mesh
// export). `fraktal render` prints "progress: 3/10 tiles (30%)" lines when its stderr is not a
// terminal.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "app/editor/document/document.hpp"
#include "app/editor/document/export_process.hpp"
#include "core/preset.hpp"

namespace fraktal::editor {

struct ExportSize {
    const char* label;
    int width, height;  // 0: the window's viewport size
};

// A3 and A2 landscape at 300 dpi (ISO 216: 420x297 mm and 594x420 mm).
inline constexpr ExportSize kExportSizes[] = {
    {"Viewport size", 0, 0},
    {"HD 1920 x 1080", 1920, 1080},
    {"4K UHD 3840 x 2160", 3840, 2160},
    {"A3 300 dpi 4961 x 3508", 4961, 3508},
    {"A2 300 dpi 7016 x 4961", 7016, 4961},
    {"Custom", -1, -1},
};

struct ExportOptions {
    int sizeIndex = 1;
    int width = 1920, height = 1080;
    int spp = 16;  // samples per pixel of the fast renderer
    // The render mode: `--mode path` (the path tracer: the preset's lights, environment map and
    // lens, as the viewport shows it at rest in its path-traced mode) with its own samples per
    // pixel and `--denoise`; else the fast renderer. 3D documents only.
    bool pathTraced = false;
    int pathSpp = 256;
    bool denoise = false;
    // The view settings the mode and path samples were last taken from (followViewMode).
    bool followed = false;
    bool followedPathTraced = false;
    int followedPathSpp = 0;
    // OUT.exr is always written (scene-linear, with AOVs and the preset in its `fraktal.preset`
    // header attribute): it is the master. OUT.png goes through the preset's OCIO display/view
    // and exposure, as the viewport shows it.
    bool pngPreview = true;
    bool halfFloat = true;                 // EXR channels as half (else 32-bit float)
    std::string output = "fraktal_still";  // path without extension
};

// Its outputs: the EXR, then the PNG if chosen.
struct ExportJob : ExportProcess {
    ExportOptions options;
    bool pathTraced = false;  // the mode this job renders in
    int spp = 0;              // and its samples per pixel
};

// The export's default render mode is what the viewport shows: the view settings' render mode
// (pathTraceAtRest) and, for the path tracer, the samples the viewport accumulates (pathSppCap).
// Taken when the dialog first shows and again whenever the view's settings change; a choice made
// in the dialog stands until then.
void followViewMode(ExportOptions& o, bool pathTraceAtRest, int pathSppCap);
// The samples per pixel of the options' render mode.
int exportSpp(const ExportOptions& o);
// What the mode does with the preset's lighting, for the dialog: the lights and environment map
// the path tracer renders, or what the fast renderer leaves out ("" when nothing).
std::string exportLightsText(const Lighting& lighting, bool pathTraced);

// The command line for the still renderer (`fraktal render`), for the dialog to show.
std::vector<std::string> exportCommand(const std::filesystem::path& fraktalExe, const std::filesystem::path& preset,
                                       const ExportOptions& o);
// The document's file text for the renderer: a relative environment map is made absolute
// (resolved against `documentFile`'s folder, as the viewport does), since the renderer reads the
// preset from a temporary file next to the output.
std::string exportPresetText(const Document& d, const std::filesystem::path& documentFile);

// Writes the preset next to the output and starts the child; false with job.log saying why.
bool startExport(ExportJob& job, const Preset& preset, double now);
// The same for a preset's file text (a 2D preset too: `fraktal render` tells them apart).
bool startExport(ExportJob& job, const std::string& presetText, double now);
// The dialog's line for the job's state, e.g. "Done: out/still.exr and out/still.png (path traced,
// 64 spp)." (the files the job wrote, while they exist) or "Failed: ..." (the log's last line);
// "" while it runs (a progress bar).
std::string exportStatusText(const ExportJob& job);

}  // namespace fraktal::editor
