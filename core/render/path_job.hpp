// A path-traced still (`fraktal render --mode path`): the GL path tracer over the whole image,
// optionally denoised, written atomically to an EXR with the compositing passes (R G B A, Z, and
// diffuse_direct.R/G/B, diffuse_indirect.*, specular.*, emission.*, albedo.*, N.x/y/z) and to the
// PNG preview. Needs a current GL context.
#pragma once

#include "core/render/path_image.hpp"
#include "core/render/still_job.hpp"

namespace fraktal {

struct PathJob {
    StillJob still;          // preset, outputs; preset.render.spp samples per pixel
    std::string presetFile;  // where relative environment paths start, and errors name
    bool denoise = false;
};

// Loads the environment map (errors name the preset file and field) and checks the outputs.
void renderPathJob(const PathJob& job, const ColorPipeline& color);
// The EXR writing alone (atomic: temp file then rename).
void writePathExr(const std::filesystem::path& path, const PathImage& image, const std::string& presetJson,
                  const std::string& workingSpace);

}  // namespace fraktal
