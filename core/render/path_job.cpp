#include "core/render/path_job.hpp"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIntAttribute.h>
#include <ImfOutputFile.h>
#include <ImfStringAttribute.h>

#include <chrono>

#include "core/atomic_file.hpp"
#include "core/image/exr_writer.hpp"
#include "core/image/png_writer.hpp"
#include "core/render/denoise.hpp"
#include "core/render/path_tracer.hpp"

namespace fraktal {

void writePathExr(const std::filesystem::path& path, const PathImage& image, const std::string& presetJson,
                  const std::string& workingSpace) {
    AtomicFile file(path);
    {
        Imf::Header header(image.width, image.height);
        header.compression() = Imf::ZIP_COMPRESSION;
        header.insert(kExrSppAttribute, Imf::IntAttribute(image.spp));
        header.insert(kExrWorkingSpaceAttribute, Imf::StringAttribute(workingSpace));
        header.insert(kExrPresetAttribute, Imf::StringAttribute(presetJson));
        header.insert("software", Imf::StringAttribute("fraktal"));
        Imf::FrameBuffer fb;
        const size_t xStride = 4 * sizeof(float), yStride = xStride * size_t(image.width);
        auto add = [&](const std::string& name, int pass, int component) {
            header.channels().insert(name, Imf::Channel(Imf::FLOAT));
            fb.insert(name, Imf::Slice(Imf::FLOAT, (char*)(image.passes[pass].data() + component), xStride, yStride));
        };
        const char* rgba[] = {"R", "G", "B", "A"};
        for (int c = 0; c < 4; ++c) add(rgba[c], kBeauty, c);
        add("Z", kNormal, 3);
        for (int pass = kDiffuseDirect; pass < kPassCount; ++pass) {
            static const char* const kXyz[] = {"x", "y", "z"};
            static const char* const kRgb[] = {"R", "G", "B"};
            const char* const* names = pass == kNormal ? kXyz : kRgb;
            for (int c = 0; c < 3; ++c) add(std::string(kPathPassNames[pass]) + "." + names[c], pass, c);
        }
        Imf::OutputFile out(file.tempPath().c_str(), header);
        out.setFrameBuffer(fb);
        out.writePixels(image.height);
    }
    file.commit();
}

PathSceneData resolvePathScene(const Preset& preset, const std::string& presetFile, const ColorPipeline& color,
                               const PathSceneData* previous) {
    const RenderSettings& r = preset.render;
    PathSceneData d;
    d.workingSpace = color.resolveSpace(r.workingSpace);
    d.presetFile = presetFile;
    const auto toWorking = [&](const vec3& c) { return color.fromLinearRec709(c, d.workingSpace); };
    d.shading = resolveShading(preset.shading, r, preset.formula, toWorking);
    d.lighting = preset.lighting;
    d.lighting.lights = resolveLights(d.lighting.lights, toWorking);
    if (previous && previous->lighting.environment == d.lighting.environment && previous->presetFile == presetFile &&
        previous->workingSpace == d.workingSpace)
        d.environment = previous->environment;
    else if (d.lighting.environment.active())
        d.environment = loadEnvironmentMap(resolveEnvironmentPath(d.lighting.environment.map, presetFile),
                                           d.lighting.environment, color, d.workingSpace, presetFile);
    return d;
}

void accumulatePathSamples(gl::PathTracer& tracer, int spp, const StillJob& job) {
    const auto start = std::chrono::steady_clock::now();
    while (tracer.samplesTaken() < spp) {
        tracer.addSamples(std::min(4, spp - tracer.samplesTaken()));
        if (job.cancel && job.cancel->load()) throw RenderCancelled();
        if (job.onProgress)
            job.onProgress(
                StillProgress{tracer.samplesTaken(), spp,
                              std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()});
    }
}

void renderPathJob(const PathJob& job, const ColorPipeline& color) {
    validateStillJob(job.still, color);
    const Preset& preset = job.still.preset;
    const RenderSettings& r = preset.render;
    const PathSceneData data = resolvePathScene(preset, job.presetFile, color);
    const DisplayTransform display(color, data.workingSpace, r.display, r.view, r.exposure);

    gl::PathTracer tracer(preset.formula, r.width, r.height);
    tracer.setScene(data.scene(preset, r));
    accumulatePathSamples(tracer, r.spp, job.still);
    PathImage image = tracer.image();
    if (job.denoise) denoisePathImage(image);
    writePathExr(job.still.exr, image, serializePreset(preset), data.workingSpace);
    if (job.still.png) {
        std::vector<uint8_t> rgb8(size_t(r.width) * r.height * 3);
        display.toDisplay8(image.passes[kBeauty], rgb8);
        writePngAtomic(*job.still.png, r.width, r.height, rgb8);
    }
}

}  // namespace fraktal
