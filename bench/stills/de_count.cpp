// Counts the work of a still: DE evaluations per pixel (camera rays, normals, shadows, AO: all of
// them, and the shading's part of them) and march steps per camera ray, averaged over the image,
// from the still renderer's stats target. The same setup as renderStillJob
// (core/render/still_job.cpp) without writing files. Built and run by bench/stills/run.sh.
// Usage: de_count PRESET WxH SPP [ADAPTIVE_TOLERANCE]
#include <cstdio>
#include <cstdlib>

#include "core/color/color_pipeline.hpp"
#include "core/gl/context.hpp"
#include "core/preset.hpp"
#include "core/render/still_job.hpp"
#include "core/render/still_renderer.hpp"
#include "core/render/tiles.hpp"

int main(int argc, char** argv) {
    using namespace fraktal;
    int width = 0, height = 0;
    if ((argc != 4 && argc != 5) || std::sscanf(argv[2], "%dx%d", &width, &height) != 2) {
        std::fprintf(stderr, "usage: %s PRESET WxH SPP [ADAPTIVE_TOLERANCE]\n", argv[0]);
        return 2;
    }
    Preset preset = loadPreset(argv[1]);
    RenderSettings& r = preset.render;
    r.width = width;
    r.height = height;
    r.spp = std::atoi(argv[3]);
    const double adaptiveTolerance = argc == 5 ? std::atof(argv[4]) : kDefaultAdaptiveTolerance;
    const ColorPipeline color = ColorPipeline::fromFile(shippedOcioConfigPath());
    const std::string space = color.resolveSpace(r.workingSpace);
    const ShadingParams shading = resolveShading(preset.shading, r, preset.formula,
                                                 [&](const vec3& c) { return color.fromLinearRec709(c, space); });
    auto context = gl::HeadlessContext::create();
    constexpr int tileSize = 256;
    gl::StillRenderer renderer(preset.formula, tileSize);
    renderer.setScene(preset.formula, preset.camera, r, shading, adaptiveTolerance);
    double deEvalsOverSpp = 0.0, stepsPerRay = 0.0, samples = 0.0, shadeEvalsOverSpp = 0.0;
    ImageStrip strip;
    for (const TileRect& s : stripsOf(r.width, r.height, stillStripRows(r.width, tileSize))) {
        strip.resize(r.width, s.y, s.height);
        for (const TileRect& tile : tilesOf(s, tileSize)) renderer.renderTile(tile, strip);
        for (size_t i = 0; i < strip.stats.size(); i += 4) {
            deEvalsOverSpp += strip.stats[i];
            stepsPerRay += strip.stats[i + 1];
            samples += strip.stats[i + 2];
            shadeEvalsOverSpp += strip.stats[i + 3];
        }
    }
    const double pixels = double(r.width) * r.height;
    std::printf(
        "%.1f DE evaluations per pixel (%.1f per sample), %.1f march steps per camera ray, %.2f samples per pixel, "
        "%.1f of the DE evaluations per pixel shading\n",
        deEvalsOverSpp / pixels * r.spp, deEvalsOverSpp * r.spp / samples, stepsPerRay / pixels, samples / pixels,
        shadeEvalsOverSpp / pixels * r.spp);
    return 0;
}
