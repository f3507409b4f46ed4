// `fraktal render ANIM.json --frames A-B[:STEP] -o out/frame_####.exr`: an image sequence.
#pragma once

#include <atomic>
#include <string>

#include "core/anim/sequence.hpp"
#include "core/color/color_pipeline.hpp"

namespace fraktal::cli {

struct SequenceJob {
    Preset animated;  // its render settings hold the size, spp and colour settings of every frame
    std::string source;
    std::string pattern;
    FrameRange range;
    bool fullFloat = false;
    int tileSize = 256;
    bool quiet = false;
    const std::atomic<bool>* cancel = nullptr;
    bool pathTraced = false;  // --mode path: each frame path-traced with the preset's lights and lens
    bool denoise = false;     // with pathTraced: --denoise on each frame
};

// Fails fast on a bad range, pattern or folder, before any GL work.
void validateSequenceJob(const SequenceJob& job, const ColorPipeline& color);

// Renders the frames that are not already complete on disk (each written atomically; a broken
// one is rendered again), with progress per frame. Needs a current GL context. Returns the exit
// status (130 when cancelled: the frame under way is not written).
int renderSequence(const SequenceJob& job, const ColorPipeline& color);

}  // namespace fraktal::cli
