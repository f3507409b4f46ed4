// Counts the work of a still: DE evaluations per pixel (camera rays, normals, shadows, AO: all of
// them) and march steps per camera ray, averaged over the image, from the still renderer's stats
// target. The same setup as renderStillJob (core/render/still_job.cpp) without writing files.
// Built and run by bench/stills/run.sh. Usage: de_count PRESET WxH SPP
#include <cstdio>
#include <cstdlib>

#include "core/color/color_pipeline.hpp"
#include "core/gl/context.hpp"
#include "core/preset.hpp"
#include "core/render/still_renderer.hpp"
#include "core/render/tiles.hpp"

int main(int argc, char** argv) {
    using namespace fraktal;
    int width = 0, height = 0;
    if (argc != 4 || std::sscanf(argv[2], "%dx%d", &width, &height) != 2) {
        std::fprintf(stderr, "usage: %s PRESET WxH SPP\n", argv[0]);
        return 2;
    }
    Preset preset = loadPreset(argv[1]);
    RenderSettings& r = preset.render;
    r.width = width;
    r.height = height;
    r.spp = std::atoi(argv[3]);
    const ColorPipeline color = ColorPipeline::fromFile(shippedOcioConfigPath());
    const std::string space = color.resolveSpace(r.workingSpace);
    const ShadingParams shading = resolveShading(preset.shading, r, preset.formula,
                                                 [&](const vec3& c) { return color.fromLinearRec709(c, space); });
    auto context = gl::HeadlessContext::create();
    constexpr int tileSize = 256;
    gl::StillRenderer renderer(preset.formula, tileSize);
    renderer.setScene(preset.formula, preset.camera, r, shading);
    double deEvalsPerSample = 0.0, stepsPerRay = 0.0;
    ImageStrip strip;
    for (const TileRect& s : stripsOf(r.width, r.height, stillStripRows(r.width, tileSize))) {
        strip.resize(r.width, s.y, s.height);
        for (const TileRect& tile : tilesOf(s, tileSize)) renderer.renderTile(tile, strip);
        for (size_t i = 0; i < strip.stats.size(); i += 4) {
            deEvalsPerSample += strip.stats[i];
            stepsPerRay += strip.stats[i + 1];
        }
    }
    const double pixels = double(r.width) * r.height;
    std::printf("%.1f DE evaluations per pixel (%.1f per sample), %.1f march steps per camera ray\n",
                deEvalsPerSample / pixels * r.spp, deEvalsPerSample / pixels, stepsPerRay / pixels);
    return 0;
}
