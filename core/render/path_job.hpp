// A path-traced still (`fraktal render --mode path`): the GL path tracer over the whole image,
// optionally denoised, written atomically to an EXR with the compositing passes (R G B A, Z, and
// diffuse_direct.R/G/B, diffuse_indirect.*, specular.*, emission.*, albedo.*, N.x/y/z) and to the
// PNG preview. Needs a current GL context.
#pragma once

#include "core/cpu_render/cpu_path_tracer.hpp"
#include "core/image/path_image.hpp"
#include "core/render/still_job.hpp"

namespace fraktal {

namespace gl {
class PathTracer;
}

struct PathJob {
    StillJob still;          // preset, outputs; preset.render.spp samples per pixel
    std::string presetFile;  // where relative environment paths start, and errors name
    bool denoise = false;
};

// What a preset's path-traced image depends on beyond the preset itself, resolved into the working
// space: the shading, the lights and the environment map. The still (renderPathJob) and the
// editor's viewport at rest both build their scene through this, so the two draw the same samples.
struct PathSceneData {
    std::string workingSpace, presetFile;
    ShadingParams shading;
    Lighting lighting;
    EnvironmentMap environment;
    // The scene of `preset` (which must outlive it), at size `render` (the preset's own render
    // settings, or a copy of them at another size, such as the viewport's).
    PathScene scene(const Preset& preset, const RenderSettings& render) const {
        return PathScene{preset.formula, preset.camera, render, shading, lighting, environment};
    }
};

// Loads the environment map (errors name the preset file and field) and resolves the colours.
// `previous`: an earlier result whose environment map is reused when it was loaded with the same
// environment settings, preset file and working space (the editor resolves the scene every time
// its view comes to rest; an HDR map can take a second to load).
PathSceneData resolvePathScene(const Preset& preset, const std::string& presetFile, const ColorPipeline& color,
                               const PathSceneData* previous = nullptr);
// Adds path-traced samples to `tracer` (set to `scene` from sample index 0) in draws of 4, as the
// still does, until it holds `spp`; polls `cancel` and reports to `onProgress` between draws.
void accumulatePathSamples(gl::PathTracer& tracer, int spp, const StillJob& job);

// Loads the environment map (errors name the preset file and field) and checks the outputs.
void renderPathJob(const PathJob& job, const ColorPipeline& color);
// The EXR writing alone (atomic: temp file then rename).
void writePathExr(const std::filesystem::path& path, const PathImage& image, const std::string& presetJson,
                  const std::string& workingSpace);

}  // namespace fraktal
