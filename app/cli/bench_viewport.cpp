// `fraktal bench viewport PRESET [--path orbit|dolly|pan] [--frames N] [--size WxH]
// [--no-reproject] [--json]`: flies a scripted camera path headlessly through the real-time
// viewport (core/viewport) and prints per-frame work (DE evaluations per pixel), pixel shares
// (reprojected / restarted / converged), frame time and each frame's error against a converged
// render of the same view, then what happens after the camera stops. bench/README.md has the
// table this produces.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "core/gl/context.hpp"
#include "core/preset.hpp"
#include "core/viewport/flight.hpp"

namespace fraktal::cli {

namespace {

struct BenchViewportArgs {
    std::string preset;
    std::string path = "orbit";
    std::string size = "640x360";
    std::string motionSize;  // empty: the moving frames keep --size
    int frames = 30;
    int steps = 30;
    int deferAfter = viewport::ViewportOptions{}.deferAfterSteps;
    int samples = 16;
    int coneTile = 0;
    int maxCarry = viewport::ViewportOptions{}.maxCarryFrames;
    double degrees = 0.5;
    double filterRadius = viewport::ViewportOptions{}.motionFilterRadius;
    std::string dump;
    bool noReproject = false, noOverRelaxation = false, noMotionFilter = false, noCoarseHits = false, noError = false,
         noRest = false, fromRest = false, json = false, timePasses = false;
};

std::pair<int, int> parseSize(const std::string& option, const std::string& text) {
    int w = 0, h = 0;
    char x = 0, extra = 0;
    if (std::sscanf(text.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || x != 'x' || w < 2 || h < 2 ||
        w > kMaxImageSide || h > kMaxImageSide)
        throw std::runtime_error(option + ": expected WxH (e.g. 640x360), got '" + text + "'");
    return {w, h};
}

nlohmann::json number(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

int run(const BenchViewportArgs& a) {
    const Preset preset = loadPreset(a.preset);
    const auto path = viewport::parseCameraPath(a.path);
    if (!path) throw std::runtime_error("--path: expected orbit, dolly or pan, got '" + a.path + "'");
    viewport::FlightSettings fs;
    fs.path = *path;
    fs.frames = a.frames;
    fs.degreesPerFrame = a.degrees;
    std::tie(fs.width, fs.height) = parseSize("--size", a.size);
    if (!a.motionSize.empty()) {
        if (!a.noError)
            throw std::runtime_error(
                "--motion-size: the moving frames' error needs references of their size; add --no-error");
        std::tie(fs.motionWidth, fs.motionHeight) = parseSize("--motion-size", a.motionSize);
    }
    fs.options.stepsPerFrame = a.steps;
    fs.options.deferAfterSteps = a.deferAfter;
    fs.options.maxSamples = a.samples;
    fs.options.reproject = !a.noReproject;
    fs.options.overRelaxation = !a.noOverRelaxation;
    fs.options.motionFilter = !a.noMotionFilter;
    fs.options.motionFilterRadius = a.filterRadius;
    fs.options.coarseHits = !a.noCoarseHits;
    fs.options.coneTile = a.coneTile;
    fs.options.maxCarryFrames = a.maxCarry;
    fs.options.timePasses = a.timePasses;
    fs.measureError = !a.noError;
    fs.restAfterPath = !a.noRest;
    fs.fromRest = a.fromRest;
    fs.dumpDirectory = a.dump;
    if (!a.dump.empty()) {
        if (a.noError) throw std::runtime_error("--dump needs the per-frame reference renders (drop --no-error)");
        std::filesystem::create_directories(a.dump);
    }

    auto context = gl::HeadlessContext::create();
    const viewport::FlightResult r = viewport::fly(preset, fs);

    if (a.json) {
        nlohmann::json out;
        out["preset"] = a.preset;
        out["renderer"] = context->renderer();
        out["path"] = a.path;
        out["width"] = fs.width;
        out["height"] = fs.height;
        out["motion_width"] = fs.motionWidth > 0 ? fs.motionWidth : fs.width;
        out["motion_height"] = fs.motionHeight > 0 ? fs.motionHeight : fs.height;
        out["steps_per_frame"] = a.steps;
        out["defer_after_steps"] = a.deferAfter;
        out["reproject"] = fs.options.reproject;
        out["over_relaxation"] = fs.options.overRelaxation;
        out["motion_filter"] = fs.options.motionFilter;
        out["motion_filter_radius"] = fs.options.motionFilterRadius;
        out["coarse_hits"] = fs.options.coarseHits;
        out["from_rest"] = fs.fromRest;
        out["cone_tile"] = fs.options.coneTile;
        out["max_carry_frames"] = fs.options.maxCarryFrames;
        out["frames"] = fs.frames;
        out["mean_de_evals_per_pixel_per_frame"] = r.meanDeEvalsPerPixel;
        out["mean_shade_de_evals_per_pixel_per_frame"] = r.meanShadeDeEvalsPerPixel;
        out["mean_ms_per_frame"] = r.meanMilliseconds;
        out["mean_psnr_db"] = number(r.meanPsnrDb);
        out["final_psnr_db"] = number(r.frames.empty() ? NAN : r.frames.back().psnrDb);
        out["mean_psnr_centre_db"] = number(r.meanPsnrCentreDb);
        out["final_psnr_centre_db"] = number(r.frames.empty() ? NAN : r.frames.back().psnrCentreDb);
        out["rest_frames_to_40db"] = r.restFramesToThreshold;
        out["rest_frames_to_settle"] = r.restFramesToSettle;
        out["rest_ms_to_settle"] = r.restMillisecondsToSettle;
        out["settled_de_evals_per_pixel"] = r.settledDeEvalsPerPixel;
        nlohmann::json frames = nlohmann::json::array();
        for (size_t i = 0; i < r.frames.size(); ++i) {
            const auto& f = r.frames[i];
            frames.push_back({{"frame", i},
                              {"action", viewport::toString(f.stats.action)},
                              {"ms", f.stats.milliseconds},
                              {"de_evals_per_pixel", f.stats.deEvalsPerPixel},
                              {"shade_de_evals_per_pixel", f.stats.shadeDeEvalsPerPixel},
                              {"reprojected", f.stats.shareReprojected},
                              {"restarted", f.stats.shareRestarted},
                              {"converged", f.stats.shareConverged},
                              {"shaded", f.stats.shareShaded},
                              {"march_listed", f.stats.shareMarchListed},
                              {"psnr_db", number(f.psnrDb)},
                              {"psnr_centre_db", number(f.psnrCentreDb)}});
            if (a.timePasses) {
                nlohmann::json passes = nlohmann::json::object();
                for (const auto& p : f.stats.passTimes) passes[p.name] = p.milliseconds;
                frames.back()["pass_ms"] = passes;
            }
        }
        out["per_frame"] = frames;
        std::printf("%s\n", out.dump(2).c_str());
        return 0;
    }
    std::printf("%s, %s path, %dx%d, %d steps/frame, reprojection %s (%s)\n", a.preset.c_str(), a.path.c_str(),
                fs.width, fs.height, a.steps, fs.options.reproject ? "on" : "off", context->renderer().c_str());
    std::printf(
        "frame  action     ms      DE/px  shadeDE  reproj  restart  conv   shaded  PSNR dB (AA ref, centre ref)\n");
    for (size_t i = 0; i < r.frames.size(); ++i) {
        const auto& s = r.frames[i].stats;
        std::printf("%5zu  %-9s %7.1f %8.2f %8.2f  %5.2f  %6.2f  %5.2f  %6.2f  %6.1f %6.1f\n", i,
                    viewport::toString(s.action), s.milliseconds, s.deEvalsPerPixel, s.shadeDeEvalsPerPixel,
                    s.shareReprojected, s.shareRestarted, s.shareConverged, s.shareShaded, r.frames[i].psnrDb,
                    r.frames[i].psnrCentreDb);
        if (a.timePasses) {
            std::printf("       GPU ms:");
            for (const auto& p : s.passTimes) std::printf(" %s %.1f", p.name, p.milliseconds);
            std::printf("\n");
        }
    }
    std::printf(
        "mean: %.1f ms/frame, %.2f DE evals/pixel/frame (%.2f shading), %.1f dB (%.1f dB against the centre sample)\n",
        r.meanMilliseconds, r.meanDeEvalsPerPixel, r.meanShadeDeEvalsPerPixel, r.meanPsnrDb, r.meanPsnrCentreDb);
    std::printf(
        "after the stop: %d frames to within 40 dB of the settled image, %d to settle (%.0f ms); settled frame "
        "%.3f DE evals/pixel\n",
        r.restFramesToThreshold, r.restFramesToSettle, r.restMillisecondsToSettle, r.settledDeEvalsPerPixel);
    return 0;
}

}  // namespace

void addBenchViewportCommand(CLI::App& app, Action& action) {
    CLI::App* bench = nullptr;
    try {
        bench = app.get_subcommand("bench");
    } catch (const CLI::OptionNotFound&) {
        bench = app.add_subcommand("bench", "benchmarks");
        bench->require_subcommand(1);
    }
    auto args = std::make_shared<BenchViewportArgs>();
    CLI::App* cmd =
        bench->add_subcommand("viewport", "fly a camera path through the real-time viewport and measure it");
    cmd->add_option("preset", args->preset, "preset file")->required();
    cmd->add_option("--path", args->path, "camera path: orbit, dolly or pan")->capture_default_str();
    cmd->add_option("--frames", args->frames, "moving frames")->capture_default_str()->check(CLI::Range(1, 100000));
    cmd->add_option("--size", args->size, "viewport size WxH")->capture_default_str();
    cmd->add_option("--motion-size", args->motionSize,
                    "grid of the moving frames WxH, as the editor's dynamic resolution moves on a smaller one "
                    "(default: --size; needs --no-error)");
    cmd->add_option("--steps", args->steps, "march steps per ray per frame")
        ->capture_default_str()
        ->check(CLI::Range(1, 10000));
    cmd->add_option("--defer-after", args->deferAfter,
                    "steps of the full-screen march pass before a ray moves to the compacted march list (0: never)")
        ->capture_default_str()
        ->check(CLI::Range(0, 10000));
    cmd->add_option("--samples", args->samples, "AA cap, samples per pixel")
        ->capture_default_str()
        ->check(CLI::Range(1, kMaxSpp));
    cmd->add_option("--cone-tile", args->coneTile, "cone pre-pass tile in pixels (0: off)")
        ->capture_default_str()
        ->check(CLI::Range(0, 64));
    cmd->add_option("--max-carry", args->maxCarry,
                    "frames a reprojected hit may keep its carried colour before it is shaded again (0: always shade)")
        ->capture_default_str()
        ->check(CLI::Range(0, 1000));
    cmd->add_option("--degrees", args->degrees, "camera turn per frame, degrees")->capture_default_str();
    cmd->add_flag("--no-reproject", args->noReproject, "restart every ray on camera motion");
    cmd->add_flag("--no-over-relaxation", args->noOverRelaxation, "plain sphere tracing (omega = 1)");
    cmd->add_flag("--no-motion-filter", args->noMotionFilter,
                  "under motion show each pixel's one sample, not a reconstruction from its neighbours'");
    cmd->add_option("--filter-radius", args->filterRadius, "radius of the motion filter's tent, pixels")
        ->capture_default_str()
        ->check(CLI::Range(viewport::ViewportOptions::kMinFilterRadius, viewport::ViewportOptions::kMaxFilterRadius));
    cmd->add_flag("--no-coarse-hits", args->noCoarseHits,
                  "under motion march rays that keep a carried colour on to the hit threshold");
    cmd->add_flag("--no-error", args->noError, "skip the per-frame reference renders (faster)");
    cmd->add_flag("--from-rest", args->fromRest,
                  "start moving from the settled view (as a user's orbit does), not from an empty viewport");
    cmd->add_flag("--no-rest", args->noRest, "stop after the path (no frames at rest until settled)");
    cmd->add_flag("--time-passes", args->timePasses, "GPU timestamps around each pass (per-frame pass_ms)");
    cmd->add_option("--dump", args->dump, "write each moving frame and its reference as PNGs into this folder");
    cmd->add_flag("--json", args->json, "one JSON object on stdout");
    cmd->callback([args, &action] { action = [args] { return run(*args); }; });
}

}  // namespace fraktal::cli
