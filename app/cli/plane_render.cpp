#include "cli/plane_render.hpp"

#include <cstdio>
#include <cstdlib>

#include "cli/cancel.hpp"
#include "core/gl/context.hpp"
#include "core/plane/plane_still.hpp"
#include "core/render/still_job.hpp"

namespace fraktal::cli {

int runPlaneRender(const PlaneRenderRequest& q, PlanePreset preset) {
    PlaneStillJob job;
    job.preset = std::move(preset);
    RenderSettings& r = job.preset.render;
    if (q.width > 0) r.width = q.width;
    if (q.height > 0) r.height = q.height;
    if (q.spp > 0) r.spp = q.spp;
    if (q.exposure) r.exposure = *q.exposure;
    if (!q.view.empty()) r.view = q.view;
    if (!q.display.empty()) r.display = q.display;
    if (!q.workingSpace.empty()) r.workingSpace = q.workingSpace;
    job.exr = q.output;
    if (!q.png.empty()) job.png = std::filesystem::path(q.png);
    job.fullFloat = q.fullFloat;
    job.tileSize = q.tile;
    job.precision = q.forceFloat ? PlanePrecision::Float : PlanePrecision::Auto;

    const ColorPipeline color = ColorPipeline::fromEnvironment();
    validatePlaneStillJob(job, color);  // before the GL start-up: bad input fails fast
    if (q.threads > 0) ::setenv("LP_NUM_THREADS", std::to_string(q.threads).c_str(), 1);
    job.cancel = &cancelOnSignal();  // before the driver starts, as render does
    auto context = gl::HeadlessContext::create();
    if (!q.quiet) {
        std::fprintf(stderr, "rendering %s (2D): %dx%d, %d spp, %s\n", q.input.c_str(), r.width, r.height, r.spp,
                     context->renderer().c_str());
        job.onProgress = [](int done, int total) {
            // "NN%" as the 3D renderer prints it: the editor's export dialog reads it.
            std::fprintf(stderr, "progress: %d/%d tiles (%d%%)\n", done, total, 100 * done / std::max(1, total));
        };
    }
    try {
        for (const std::string& w : renderPlaneStill(job, color))
            std::fprintf(stderr, "fraktal: warning: %s\n", w.c_str());
    } catch (const RenderCancelled&) {
        std::fprintf(stderr, "\nfraktal: render cancelled; no file written\n");
        return kCancelledExitCode;
    }
    if (!q.quiet) std::fprintf(stderr, "wrote %s%s%s\n", q.output.c_str(), q.png.empty() ? "" : " and ", q.png.c_str());
    return 0;
}

}  // namespace fraktal::cli
