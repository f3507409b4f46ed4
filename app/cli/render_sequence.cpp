#include "cli/render_sequence.hpp"

#include <chrono>
#include <cstdio>

#include "cli/cancel.hpp"
#include "core/render/path_job.hpp"
#include "core/render/still_job.hpp"

namespace fraktal::cli {

namespace {

StillJob frameJob(const SequenceJob& job, int frame) {
    StillJob still;
    still.preset = sequenceFramePreset(job.animated, frame);
    still.exr = framePath(job.pattern, frame);
    still.fullFloat = job.fullFloat;
    still.tileSize = job.tileSize;
    still.cancel = job.cancel;
    return still;
}

}  // namespace

void validateSequenceJob(const SequenceJob& job, const ColorPipeline& color) {
    checkFrameRangeWithin(job.range, job.animated.animation, job.source);
    checkFramePattern(job.pattern);
    validateStillJob(frameJob(job, job.range.first), color);
}

int renderSequence(const SequenceJob& job, const ColorPipeline& color) {
    validateSequenceJob(job, color);
    const std::vector<int> frames = job.range.frames();
    const int n = int(frames.size());
    int rendered = 0, skipped = 0;
    double renderSeconds = 0.0;
    for (int i = 0; i < n; ++i) {
        const StillJob still = frameJob(job, frames[size_t(i)]);
        std::string why;
        const FrameFileState state = checkFrameFile(still.exr, still.preset, &why);
        if (state == FrameFileState::Complete) {
            ++skipped;
            if (!job.quiet)
                std::fprintf(stderr, "frame %d/%d (%d): %s is complete, skipped\n", i + 1, n, frames[size_t(i)],
                             still.exr.c_str());
            continue;
        }
        if (state == FrameFileState::Broken && !job.quiet)
            std::fprintf(stderr, "frame %d/%d (%d): %s is incomplete (%s), rendering it again\n", i + 1, n,
                         frames[size_t(i)], still.exr.c_str(), why.c_str());
        const auto start = std::chrono::steady_clock::now();
        try {
            if (job.pathTraced)
                renderPathJob(PathJob{still, job.source, job.denoise}, color);
            else
                renderStillJob(still, color);
        } catch (const RenderCancelled&) {
            std::fprintf(stderr,
                         "\nfraktal: render cancelled at frame %d; %d frames written, the frame under way "
                         "is not\n",
                         frames[size_t(i)], rendered);
            return kCancelledExitCode;
        }
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        renderSeconds += seconds;
        ++rendered;
        // Remaining: the frames still to check, at the mean time of the frames rendered so far.
        const double remaining = renderSeconds / rendered * (n - i - 1);
        if (!job.quiet)
            std::fprintf(stderr, "frame %d/%d (%d): %.2fs, %.1fs elapsed, about %.1fs remaining: %s\n", i + 1, n,
                         frames[size_t(i)], seconds, renderSeconds, remaining, still.exr.c_str());
    }
    if (!job.quiet) std::fprintf(stderr, "%d frames rendered, %d already complete\n", rendered, skipped);
    return 0;
}

}  // namespace fraktal::cli
