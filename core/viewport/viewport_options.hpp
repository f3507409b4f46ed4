// How the viewport renders (the editor's viewport panel and `fraktal bench viewport` set these).
#pragma once

#include "core/render_settings.hpp"

namespace fraktal::viewport {

struct ViewportOptions {
    int stepsPerFrame = 30;  // march steps per ray per frame (the seed's 30)
    // On a reprojected frame the full-screen march pass takes at most this many of them; rays
    // still marching then take the rest in a dispatch over a compacted list
    // (shaders/viewport_march.comp: why). The same steps either way; 0: all in the full-screen
    // pass. A reset or a frame at rest marches in one pass: there most rays need many steps, and
    // the list only adds its loads and stores (bench/README.md has the measurements).
    int deferAfterSteps = 8;
    int maxSamples = 16;    // progressive AA cap, samples per pixel
    bool reproject = true;  // carry distances over on camera motion (seed 4.2); off: restart
    // Under motion a reprojected hit on the same surface keeps its carried colour for at most this
    // many frames in a row before it is shaded again (0: always shade). A carried colour keeps its
    // own surface point, so its error does not grow with age; the cap bounds how stale the
    // view-dependent part (specular, fog) gets. bench/README.md has the trade of DE against error.
    int maxCarryFrames = 16;
    // Under motion, show each pixel as a reconstruction from the samples scattered around it
    // (shaders/viewport_resolve.comp) rather than its one sample.
    bool motionFilter = true;
    // Its tent's radius in pixels. 1 leaves samples on the pixel grid (restarted rays) as they are;
    // wider blurs more, which scores higher against the converged anti-aliased image in both modes
    // (bench/README.md, "What we tried in the viewport"). In [kMinFilterRadius, kMaxFilterRadius].
    double motionFilterRadius = 1.0;
    static constexpr double kMinFilterRadius = 0.5, kMaxFilterRadius = 2.0;
    // Under motion, a ray that keeps its carried colour stops within the reprojection margin of the
    // surface instead of marching on to the hit threshold (isCoarseHit, shaders/viewport_common.glsl):
    // fewer DE, for thin parts that look up to the margin thicker while the camera moves.
    bool coarseHits = true;
    bool overRelaxation = true;  // over-relaxed sphere tracing (RenderSettings::overRelaxation); off: omega = 1
    int coneTile = 0;            // low-resolution cone pre-pass tile in pixels (0: off; 8 is typical)
    int coneSteps = 64;          // DE steps of a pre-pass cone
    bool timePasses = false;     // GPU timestamps around each pass into FrameStats::passTimes
    // Sliced refinement: a continued frame (the camera at rest) and a reset advance only one slice
    // of the view, every slices-th tile of 32x8 pixels, a different slice each frame
    // (sliceOfFrame); the other pixels keep what they show. A pixel takes the same steps, shading
    // and samples as with the whole view a frame, so the settled image is the same; it comes in
    // about `slices` times as many frames, each costing about a slices-th. Reprojected frames
    // (motion) always march the whole view. 1: the whole view every frame.
    int slices = 1;
};

}  // namespace fraktal::viewport
