// Path-traced convergence: renders PRESET with the GL path tracer to REF_SPP samples per pixel
// (the converged image), then again progressively from the start, and prints the samples and
// seconds at which the mean-image PSNR against the converged image first reaches 35 dB (and the
// PSNR at each power of two), plus the DE evaluations per sample. With --denoise the denoised
// image is measured too at each step.
// Usage: pathtrace PRESET WxH REF_SPP [--denoise]   (built and run by bench/stills/pathtrace.sh)
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "core/color/color_pipeline.hpp"
#include "core/gl/context.hpp"
#include "core/preset.hpp"
#include "core/render/denoise.hpp"
#include "core/render/path_tracer.hpp"

using namespace fraktal;

int main(int argc, char** argv) {
    if (argc < 4) {
        std::fprintf(stderr, "usage: %s PRESET WxH REF_SPP [--denoise]\n", argv[0]);
        return 2;
    }
    const bool denoise = argc > 4 && std::strcmp(argv[4], "--denoise") == 0;
    Preset preset = loadPreset(argv[1]);
    if (std::sscanf(argv[2], "%dx%d", &preset.render.width, &preset.render.height) != 2) return 2;
    const int refSpp = std::atoi(argv[3]);
    const ColorPipeline color = ColorPipeline::fromEnvironment();
    const std::string working = color.resolveSpace(preset.render.workingSpace);
    const auto toWorking = [&](const vec3& c) { return color.fromLinearRec709(c, working); };
    const ShadingParams shading = resolveShading(preset.shading, preset.render, preset.formula, toWorking);
    Lighting lighting = preset.lighting;
    lighting.lights = resolveLights(lighting.lights, toWorking);
    EnvironmentMap env;
    if (lighting.environment.active())
        env = loadEnvironmentMap(resolveEnvironmentPath(lighting.environment.map, argv[1]), lighting.environment, color,
                                 working, argv[1]);
    auto context = gl::HeadlessContext::create();
    const PathScene scene{preset.formula, preset.camera, preset.render, shading, lighting, env};
    gl::PathTracer tracer(preset.formula, preset.render.width, preset.render.height);
    using Clock = std::chrono::steady_clock;
    tracer.setScene(scene);
    auto t0 = Clock::now();
    tracer.addSamples(refSpp, 8);
    const double refSeconds = std::chrono::duration<double>(Clock::now() - t0).count();
    const PathImage reference = tracer.image();
    std::printf("reference: %d spp in %.1f s, %.0f DE evaluations per pixel per sample\n", refSpp, refSeconds,
                tracer.deEvaluationsPerSample());
    // A second, independent run: the reference's random numbers would flatter it, so its sample
    // indices start past the reference's.
    tracer.setScene(scene, refSpp);
    double seconds = 0.0, reached = -1.0, reachedDenoised = -1.0;
    int reachedSpp = 0, reachedDenoisedSpp = 0;
    for (int spp = 1; spp <= refSpp / 4; spp *= 2) {
        t0 = Clock::now();
        while (tracer.samplesTaken() < spp) tracer.addSamples(1, 1);
        seconds += std::chrono::duration<double>(Clock::now() - t0).count();
        PathImage image = tracer.image();
        const double p = meanImagePsnr(image, reference);
        double pd = 0.0, denoiseSeconds = 0.0;
        if (denoise) {
            const auto d0 = Clock::now();
            denoisePathImage(image);
            denoiseSeconds = std::chrono::duration<double>(Clock::now() - d0).count();
            pd = meanImagePsnr(image, reference);
        }
        std::printf("%5d spp %8.2f s  PSNR %.2f dB", spp, seconds, p);
        if (denoise) std::printf("  denoised %.2f dB (+%.2f s)", pd, denoiseSeconds);
        std::printf("\n");
        if (p >= 35.0 && reached < 0) reached = seconds, reachedSpp = spp;
        if (denoise && pd >= 35.0 && reachedDenoised < 0)
            reachedDenoised = seconds + denoiseSeconds, reachedDenoisedSpp = spp;
        if (reached >= 0 && (!denoise || reachedDenoised >= 0)) break;
    }
    std::printf("35 dB: %s", reached >= 0 ? "" : "not reached ");
    if (reached >= 0) std::printf("%d spp, %.2f s", reachedSpp, reached);
    if (denoise && reachedDenoised >= 0) std::printf("; denoised: %d spp, %.2f s", reachedDenoisedSpp, reachedDenoised);
    std::printf("\n");
    return 0;
}
