// `fraktal render PRESET -o OUT.exr [--png OUT.png] ...`: a print-quality still, headless.
// PRESET may also be an EXR written by fraktal: its embedded preset (3D or 2D) is rendered again.
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <regex>

#include "cli/cancel.hpp"
#include "cli/commands.hpp"
#include "cli/plane_render.hpp"
#include "cli/render_options.hpp"
#include "cli/render_sequence.hpp"
#include "core/color/color_pipeline.hpp"
#include "core/gl/context.hpp"
#include "core/image/exr_writer.hpp"
#include "core/plane/plane_preset.hpp"
#include "core/plane/plane_still.hpp"
#include "core/preset.hpp"
#include "core/render/path_job.hpp"
#include "core/render/still_job.hpp"
#include "core/scene/scene_import.hpp"

namespace fraktal::cli {

namespace {

struct RenderOptions {
    std::string input;
    std::string output;
    std::string png;
    std::string size;
    int spp = 0;
    int maxSteps = 0;
    double detail = 0.0;
    double maxStepGrowth = 0.0;
    std::optional<double> exposure;
    std::string view, display, workingSpace;
    bool fullFloat = false;
    int threads = 0;
    int tile = 256;
    std::string tileOrPart;  // --tile: "i/n" is a part of the still (as --part), a number the tile size
    std::optional<double> adaptiveTolerance;
    bool quiet = false;
    std::string frames;  // an image sequence of an animated preset: FIRST-LAST[:STEP]
    std::string part;    // one part of a still: "i/n"
    std::string mode = "fast";
    bool denoise = false;
    bool noDiskCheck = false;
};

bool isExrPath(const std::string& input) {
    std::string ext = std::filesystem::path(input).extension().string();
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    return ext == ".exr";
}

Preset loadInput(const std::string& input) {
    if (isExrPath(input)) {
        std::error_code ec;
        if (!std::filesystem::is_regular_file(input, ec)) throw PresetError(input, "", "no such file");
        return parsePreset(readExrPreset(input), input + " (embedded preset)");
    }
    return loadSceneFile(input, headlessGlslSampler());
}

// A 2D preset (presets/2d) or a 2D still's EXR (its embedded 2D preset); nullopt for 3D input.
std::optional<PlanePreset> loadPlaneInput(const std::string& input) {
    if (isExrPath(input)) {
        std::error_code ec;
        if (!std::filesystem::is_regular_file(input, ec)) return std::nullopt;  // loadInput says so
        const std::optional<std::string> text = readExrPlanePreset(input);
        if (!text) return std::nullopt;
        return parsePlanePreset(*text, input + " (embedded 2D preset)");
    }
    if (isPlanePresetFile(input)) return loadPlanePreset(input);
    return std::nullopt;
}

}  // namespace

namespace {

std::string formatSeconds(double s) {
    char buf[32];
    if (s < 60)
        std::snprintf(buf, sizeof buf, "%.1fs", s);
    else
        std::snprintf(buf, sizeof buf, "%dm%02ds", int(s) / 60, int(s) % 60);
    return buf;
}

// A bar with ETA on a terminal; plain lines at every 10% otherwise (logs, CI).
struct ProgressPrinter {
    bool tty = ::isatty(STDERR_FILENO) != 0;
    int lastDecile = -1;
    void operator()(const StillProgress& p) {
        const double f = double(p.tilesDone) / double(std::max(1, p.tilesTotal));
        const double eta = p.tilesDone > 0 ? p.secondsElapsed * (1.0 - f) / f : 0.0;
        if (tty) {
            constexpr int width = 30;
            std::string bar(size_t(f * width), '#');
            bar.resize(width, ' ');
            std::fprintf(stderr, "\r[%s] %3d%%  tile %d/%d  %s elapsed  ETA %s   ", bar.c_str(), int(f * 100),
                         p.tilesDone, p.tilesTotal, formatSeconds(p.secondsElapsed).c_str(),
                         formatSeconds(eta).c_str());
            if (p.tilesDone == p.tilesTotal) std::fputc('\n', stderr);
        } else if (int decile = int(f * 10); decile != lastDecile) {
            lastDecile = decile;
            std::fprintf(stderr, "progress: %d/%d tiles (%d%%), %s elapsed, ETA %s\n", p.tilesDone, p.tilesTotal,
                         int(f * 100), formatSeconds(p.secondsElapsed).c_str(), formatSeconds(eta).c_str());
        }
        std::fflush(stderr);
    }
};

// The command line's overrides of the preset's render and colour settings.
void applyRenderOptions(const RenderOptions& o, RenderSettings& r) {
    if (!o.size.empty()) parseSize(o.size, r);
    if (o.spp) r.spp = o.spp;
    if (o.maxSteps) r.maxSteps = o.maxSteps;
    if (o.detail > 0) r.detail = o.detail;
    if (o.maxStepGrowth > 0) r.maxStepGrowth = o.maxStepGrowth;
    if (o.exposure) r.exposure = *o.exposure;
    if (!o.view.empty()) r.view = o.view;
    if (!o.display.empty()) r.display = o.display;
    if (!o.workingSpace.empty()) r.workingSpace = o.workingSpace;
}

// --tile i/n is --part i/n (the name a farm uses); --tile N keeps meaning the tile size in pixels.
void resolveTileOption(RenderOptions& o) {
    if (o.tileOrPart.empty()) return;
    if (o.tileOrPart.find('/') != std::string::npos) {
        if (!o.part.empty() && o.part != o.tileOrPart)
            throw std::runtime_error("--tile " + o.tileOrPart + " and --part " + o.part + " name different parts");
        o.part = o.tileOrPart;
        return;
    }
    std::smatch m;
    if (!std::regex_match(o.tileOrPart, m, std::regex(R"(\d{1,6})")) || std::stoi(m[0]) < 16 || std::stoi(m[0]) > 4096)
        throw std::runtime_error("--tile '" + o.tileOrPart +
                                 "': expected i/n (part i of n of the still) or a tile size in pixels (16..4096)");
    o.tile = std::stoi(m[0]);
}

int runRender(RenderOptions o) {
    resolveTileOption(o);
    if (std::optional<PlanePreset> plane = loadPlaneInput(o.input)) {  // 2D: the 2D renderer, same options
        PlaneRenderRequest q{o.input,
                             o.output,
                             o.png,
                             0,
                             0,
                             o.spp,
                             o.exposure,
                             o.view,
                             o.display,
                             o.workingSpace,
                             o.fullFloat,
                             o.threads,
                             std::min(o.tile, 4096),
                             o.quiet};
        if (!o.size.empty()) {
            RenderSettings size;
            parseSize(o.size, size);
            q.width = size.width;
            q.height = size.height;
        }
        return runPlaneRender(q, std::move(*plane));
    }
    StillJob job;
    job.preset = loadInput(o.input);
    RenderSettings& r = job.preset.render;
    applyRenderOptions(o, r);
    job.exr = o.output;
    if (!o.png.empty()) job.png = std::filesystem::path(o.png);
    job.fullFloat = o.fullFloat;
    job.tileSize = o.tile;
    if (!o.part.empty()) {
        std::smatch m;
        if (!std::regex_match(o.part, m, std::regex(R"((\d{1,6})/(\d{1,6}))")))
            throw std::runtime_error("--tile '" + o.part + "': expected i/n, e.g. 2/8 (part i of n, from 1)");
        job.partIndex = std::stoi(m[1]) - 1;
        job.partCount = std::stoi(m[2]);
    }
    if (o.adaptiveTolerance) job.adaptiveTolerance = *o.adaptiveTolerance;
    job.checkDisk = !o.noDiskCheck;

    if (o.denoise && o.mode != "path") throw std::runtime_error("--denoise needs --mode path");
    if (o.mode == "path" && !o.part.empty())
        throw std::runtime_error("--mode path renders a whole image: not with --tile/--part");
    const ColorPipeline color = ColorPipeline::fromEnvironment();
    std::optional<SequenceJob> sequence;
    if (!o.frames.empty()) {
        if (job.png) throw std::runtime_error("--png is for stills, not with --frames");
        sequence = SequenceJob{job.preset, o.input, o.output, parseFrameRange(o.frames), o.fullFloat, o.tile, o.quiet};
        sequence->pathTraced = o.mode == "path";
        sequence->denoise = o.denoise;
        validateSequenceJob(*sequence, color);
    } else {
        validateStillJob(job, color);  // before the (slow) GL start-up: bad input fails fast
    }

    // llvmpipe reads its thread count when the context is made.
    if (o.threads > 0) ::setenv("LP_NUM_THREADS", std::to_string(o.threads).c_str(), 1);
    // Before the context: a Ctrl+C while the driver starts (seconds on a loaded machine) is then a
    // request the render sees at its first check, not the default action's abrupt end.
    job.cancel = &cancelOnSignal();
    auto context = gl::HeadlessContext::create();
    if (sequence) {
        sequence->cancel = job.cancel;
        if (!o.quiet)
            std::fprintf(stderr, "rendering frames %s of %s: %dx%d, %d spp, %s\n", o.frames.c_str(), o.input.c_str(),
                         r.width, r.height, r.spp, context->renderer().c_str());
        return renderSequence(*sequence, color);
    }

    ProgressPrinter printer;
    if (!o.quiet) job.onProgress = [&printer](const StillProgress& p) { printer(p); };
    if (!o.quiet)
        std::fprintf(stderr, "rendering %s: %dx%d, %d spp, %s, OCIO config %s\n", o.input.c_str(), r.width, r.height,
                     r.spp, context->renderer().c_str(), color.configPath().c_str());
    if (o.mode != "path" && !o.quiet)
        if (const std::string note = lightingIgnoredByFastMode(job.preset.lighting); !note.empty())
            std::fprintf(stderr, "note: %s\n", note.c_str());
    try {
        if (o.mode == "path")
            renderPathJob(PathJob{job, o.input, o.denoise}, color);
        else
            renderStillJob(job, color);
    } catch (const RenderCancelled&) {
        std::fprintf(stderr, "\nfraktal: render cancelled; no file written\n");
        return kCancelledExitCode;
    }
    if (!o.quiet) {
        std::fprintf(stderr, "wrote %s", job.exr.c_str());
        if (job.png) std::fprintf(stderr, " and %s", job.png->c_str());
        std::fprintf(stderr, "\n");
    }
    return 0;
}

}  // namespace

void addRenderCommand(CLI::App& app, Action& action) {
    auto o = std::make_shared<RenderOptions>();
    CLI::App* cmd = app.add_subcommand("render", "Render a print-quality still to EXR (and a PNG preview)");
    cmd->add_option("preset", o->input,
                    "Preset (JSON), an EXR written by fraktal (its embedded preset), a Mandelbulber2 settings file "
                    "(.fract) or a Fragmentarium frag (.frag), imported")
        ->required();
    cmd->add_option("-o,--output", o->output, "Output EXR (scene-linear, with AOVs)")->required();
    cmd->add_option("--png", o->png, "Also write a PNG through the OCIO display/view transform");
    cmd->add_option("--size", o->size, "Image size WIDTHxHEIGHT (default: the preset's, else 1280x720)");
    cmd->add_option("--spp", o->spp, "Samples per pixel")->check(CLI::Range(1, kMaxSpp));
    cmd->add_option("--max-steps", o->maxSteps, "March steps per camera ray")->check(CLI::Range(1, kMaxMarchSteps));
    cmd->add_option("--detail", o->detail, "Hit threshold in pixel footprints (smaller: finer)")
        ->check(CLI::Range(1e-3, 100.0));
    cmd->add_option("--max-step-growth", o->maxStepGrowth,
                    "The longest step a ray's adaptive march may take, in multiples of the safe one (1: never longer)")
        ->check(CLI::Range(1.0, kMaxStepGrowth));
    cmd->add_option("--exposure", o->exposure, "Exposure of the PNG preview, in stops")->check(CLI::Range(-20.0, 20.0));
    cmd->add_option("--view", o->view, "OCIO view of the PNG preview (shipped config: Standard, ACES, Raw)");
    cmd->add_option("--display", o->display, "OCIO display of the PNG preview (default sRGB)");
    cmd->add_option("--working-space", o->workingSpace,
                    "Scene-linear working space: an OCIO colour space or role (shipped: scene_linear = Linear "
                    "Rec.709 (sRGB), ACEScg)");
    cmd->add_flag("--float", o->fullFloat, "32-bit float EXR channels (default: half)");
    cmd->add_option("--threads", o->threads, "Rendering threads (llvmpipe; default: all cores)")
        ->check(CLI::Range(1, 1024));
    cmd->add_option("--tile-size", o->tile, "Tile size in pixels")->check(CLI::Range(16, 4096));
    cmd->add_option("--tile", o->tileOrPart,
                    "i/n: render only part i of n of the still (horizontal bands, from 1) for `fraktal merge`; "
                    "a number N: the tile size in pixels (as --tile-size)");
    cmd->add_option("--adaptive-tolerance", o->adaptiveTolerance,
                    "A pixel stops sampling when its samples agree within this (sqrt colour); 0: all spp")
        ->check(CLI::Range(0.0, 1.0));
    cmd->add_flag("-q,--quiet", o->quiet, "No progress output");
    cmd->add_flag("--no-disk-check", o->noDiskCheck,
                  "Render even when the output's disk has less free space than the EXR may take uncompressed");
    cmd->add_option("--part", o->part, "Same as --tile i/n");
    cmd->add_option("--frames", o->frames,
                    "Render frames FIRST-LAST[:STEP] of an animated preset; -o is then a pattern whose run of # is "
                    "the frame number (out/frame_####.exr); frames already complete are skipped");
    cmd->add_option("--mode", o->mode,
                    "fast (the default still renderer) or path (progressive path tracing: lights, "
                    "environment, depth of field, compositing passes)")
        ->check(CLI::IsMember({"fast", "path"}));
    cmd->add_flag("--denoise", o->denoise, "With --mode path: joint bilateral denoise guided by albedo and normal");
    cmd->callback([&action, o] { action = [o] { return runRender(*o); }; });
}

}  // namespace fraktal::cli
