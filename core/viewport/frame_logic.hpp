// The viewport's GPU-free decisions (seed chapter 4): what a frame does with the stored march
// state (reset, reproject, hold or continue), the progressive anti-aliasing schedule, the conservative
// stop distance of a coarse ray, and the per-frame statistics. Everything here is pure and
// unit-tested without a GL context (tests/viewport_logic_test.cpp); the GLSL passes mirror the
// functions marked "mirrored in shaders/viewport_common.glsl".
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/camera.hpp"
#include "core/formula.hpp"
#include "core/lighting.hpp"
#include "core/shading_params.hpp"

namespace fraktal::viewport {

// What the stored march state is worth for the next frame.
enum class FrameAction {
    Reset,      // nothing usable (first frame, new size, parameter or setting edit): every ray restarts
    Reproject,  // the camera moved: carry the rays' distances over to the new view (seed 4.2)
    Continue,   // nothing changed: keep marching unfinished rays, then raise the AA level (seed 4.1)
    Hold,       // the camera paused for one frame after a move: march on as Continue, but the next
                // still frame resets (see decideFrame)
};

const char* toString(FrameAction a);

// Everything a frame's image depends on, reduced to what the decision needs.
struct FrameKey {
    int width = 0, height = 0;
    std::string structure;  // Formula::structureKey(): a change recompiles
    std::string values;     // scene::SceneRevision::values, or formulaValuesKey(): every value a frame reads
    ShadingParams shading;  // shading, detail and over-relaxation: any change re-marches
    int maxSteps = 0;
    Camera camera;
    ThinLens lens;  // depth of field of the AA samples at rest: a change restarts them
};

// `values` of a formula alone, for callers without a whole scene: its preset section
// (formulaToJson: nodes, objects, combined fractals, placement, custom blocks), numbers printed
// exactly, so that any edit changes the string. The editor passes the whole scene's revision
// instead (core/scene/scene_revision.hpp).
std::string formulaValuesKey(const Formula& f);

// `previous` is null before the first frame. A camera move reprojects only when reprojection is
// enabled; otherwise it resets like an edit does. An edit and a move in the same frame reset
// (the carried distances belong to the old fractal). The first frame at rest after a reprojected
// one also resets: a ray's hit is only defined up to the hit threshold, so a ray that resumed from
// a reprojected start ends somewhere else in that band than a fresh ray, and on orbit-trap
// textures with sub-pixel detail that alone costs ~20 dB against a fresh render (measured: 22 dB
// on mandelbox). Re-marching the still view from the camera makes the settled image exactly the
// fresh one; the reprojected image stays on screen until each pixel's new sample replaces it.
// That reset waits one frame (Hold): during a drag, motion arrives unevenly (a hand pauses, the
// window system delivers no motion event before some frames), and a reset on every such frame
// cost a whole restart each time: in a 3 s orbit drag in the editor 50 of 175 frames reset, at
// about twice a reprojected frame's time. Held, the rays keep marching from their reprojected
// state; if the camera moves again the next frame reprojects from it.
// A new size (dynamic resolution changing the grid) with a moved camera reprojects too: the
// scatter works in world points, so the previous grid's points land in the new one. So does a
// new size while the camera pauses right after a move (held): the resolution controller raises
// the scale in such a pause, and a restart there cost 2-3 times a reprojected frame. A new size
// with the camera at rest (after a reset or a continued frame) resets.
FrameAction decideFrame(const FrameKey* previous, const FrameKey& current, bool reprojectEnabled,
                        FrameAction previousAction = FrameAction::Continue);

// Progressive anti-aliasing: sample 0 is the pixel centre, the others are spread over the pixel
// by the R2 low-discrepancy sequence (Roberts 2018, "The unreasonable effectiveness of
// quasirandom sequences"), so any prefix of the schedule covers the pixel evenly. Offsets are in
// pixels, in [-0.5, 0.5). Mirrored in shaders/viewport_common.glsl.
glm::dvec2 aaJitter(int sampleIndex);

// The AA level rises one sample per pixel at a time while the camera rests, up to the cap.
struct AASchedule {
    int maxSamples = 16;
    // The sample a pixel marches next once `finishedSample` has been shaded and accumulated, or -1
    // when the pixel is done (cap reached, or the camera moves: under motion only sample 0 runs).
    int next(int finishedSample, bool cameraAtRest) const;
};

// The seed's conservative stop (4.1), as cone coverage: a coarse ray carries the cone of half
// angle `tanHalfAngle` about it that contains the finer rays around it (AA samples within a
// pixel, or the full-resolution pixels of a cone pre-pass tile). A sphere-tracing point at
// distance t with distance estimate d proves the ball of radius d about it empty; the cone's
// cross-sections at axial distances s with |s - t| + s * tanHalfAngle <= d lie inside that ball,
// i.e. s in [(t - d) / (1 - tanHalfAngle), (t + d) / (1 + tanHalfAngle)]. If that interval
// reaches back to the distance already covered, the coverage extends to its far end. Every finer
// ray inside the cone is free of surface up to the returned distance, so it may start there and
// still meets its own first hit. Mirrored in shaders/viewport_common.glsl.
double extendConeCoverage(double covered, double t, double d, double tanHalfAngle);

// Reprojected starts are backed off toward the camera by this distance before the DE verifies
// them: the hit test accepts points up to `detail` pixel footprints in front of the surface (the
// refinement lands them half that), and the start is already the nearest of the 4x4 pixels'
// points around it (viewport_reproject.comp), so two footprints cover both. (It was four; two
// costs ~0.5 fewer DE evaluations per pixel per frame on the Mandelbulb orbit at 160x90, 22.4 and 22.5 dB; the
// no-holes test was written afterwards and has only run with two.)
// Mirrored in shaders/viewport_common.glsl.
double reprojectionMargin(double t, double pixelAngle, double detail);

// Where the march pass leaves a ray that found nothing inside the bound sphere (radius
// boundRadius about the origin; the camera cameraDistance from the origin): this far along the
// ray, past every point of the sphere. Reprojection then carries "nothing along here" into the
// next view as a start beyond the sphere's far side, which costs no DE, where a ray left just
// past the far side would be started a margin in front of it, verified and marched out again
// (about 1.4 DE per background pixel inside the sphere, every frame). The new far side is at
// most |c'| + R <= |c| + R + |c' - c| from the new camera c', this point at least
// |c| + 2R - |c' - c|: it stays beyond while the camera moves less than (R - margin) / 2 per
// frame. Being far, it never pulls reprojection's neighbourhood minimum toward the camera.
// Mirrored in shaders/viewport_common.glsl.
double parkedDistance(double cameraDistance, double boundRadius);

// pcg3d (Jarzynski and Olano, "Hash Functions for GPU Rendering", JCGT 9(3), 2020), to [0, 1).
// Mirrored in shaders/viewport_common.glsl.
double hash01(uint32_t x, uint32_t y, uint32_t z);

// Whether a colour reprojection has carried for carryAge frames is shaded afresh at pixel px
// (its specular and fog belong to the view it was shaded in). Colours shaded in the same frame
// (the whole view, when the camera starts moving from rest) would all reach maxCarryFrames
// together and be shaded again in one frame: on the Menger sponge at 320x180, a frame of 5.1 DE
// per pixel amid frames of 1.9. Each colour instead lives a number of frames spread evenly over
// the last quarter, [maxCarryFrames - maxCarryFrames / 4, maxCarryFrames]: there it expires at
// each age with the chance that spreads what is left evenly over the frames left
// (1 / (maxCarryFrames - age + 2)), drawn from a hash of its pixel and age; the march and shade
// passes ask with the same pixel and age, so they agree. (Spread over the second half, the spike
// went, but colours lived 12 frames instead of 16: 9 % more DE, and 0.2 dB worse on an orbit that
// starts from rest, whose carried colours are the settled anti-aliased ones.)
// Mirrored in shaders/viewport_common.glsl.
bool carriedColourExpires(int carryAge, int maxCarryFrames, int px, int py);

// Sliced refinement: which slice of `slices` the frame numbered `frame` (counting every sliced
// frame) advances. A power of two goes through its slices in bit-reversed order (0, 4, 2, 6, 1,
// ... of 8), so that the tiles refined so far spread over the whole view rather than filling it
// from the top; any other count in plain order. Every slice comes once in `slices` frames.
int sliceOfFrame(int frame, int slices);

// The tiles a view is sliced by: the 32x8 workgroups of the passes that run per pixel
// (shaders/viewport_common.glsl, slicePixel; viewport_march.comp says why 32x8).
inline constexpr int kSliceTileWidth = 32, kSliceTileHeight = 8;
inline int viewTiles(int width, int height) {
    return ((width + kSliceTileWidth - 1) / kSliceTileWidth) * ((height + kSliceTileHeight - 1) / kSliceTileHeight);
}

// What the frames of a sliced view have counted, slice by slice: a sliced frame accumulates its
// slice alone (the only pixels it changed), so it counts only that slice's busy (not yet settled)
// and converged pixels, and a pixel outside it keeps its count until its slice comes again. The
// view has settled when every slice was counted since the view began (or the slicing changed)
// with no busy pixel.
struct SliceProgress {
    std::vector<int64_t> busy;  // per slice; -1: not counted yet
    std::vector<uint64_t> converged;
    // One frame's counts: `newView` started every pixel afresh (a reset or a reprojection);
    // `slices` 1: the frame counted the whole view.
    void record(bool newView, int slices, int slice, uint64_t busyPixels, uint64_t convergedPixels);
    bool settled() const;
    uint64_t convergedPixels() const;
};

// Raw counters the GPU passes add to during one frame (one uint each, see viewport_common.glsl).
struct FrameCounters {
    uint64_t deEvals = 0;       // every DE call: march, verification, cone pre-pass and shading
    uint64_t reprojected = 0;   // pixels whose ray start came from the previous frame
    uint64_t restarted = 0;     // pixels whose ray restarted from the camera (or the cone pre-pass)
    uint64_t converged = 0;     // pixels whose current sample is finished after this frame's march
    uint64_t shaded = 0;        // pixels shaded this frame (a shading cache miss)
    uint64_t shadeDeEvals = 0;  // the part of deEvals spent shading
    uint64_t marchListed = 0;   // rays the full-screen march pass left to the march list
};

// GPU time of one pass of a frame (core/viewport/pass_timer.hpp), when ViewportOptions::timePasses.
struct PassTime {
    const char* name = "";  // a string literal: "reproject", "march", "shade", ...
    double milliseconds = 0.0;
};

struct FrameStats {
    FrameAction action = FrameAction::Reset;
    int width = 0, height = 0;
    double deEvalsPerPixel = 0.0;
    double shadeDeEvalsPerPixel = 0.0;  // the part of deEvalsPerPixel spent shading
    double shareReprojected = 0.0, shareRestarted = 0.0, shareConverged = 0.0, shareShaded = 0.0;
    double shareMarchListed = 0.0;    // rays marched on from the march list (ViewportOptions::deferAfterSteps)
    int samplesAtRest = 0;            // the AA sample index the frame worked on (0 under motion)
    int slices = 1;                   // the frame advanced one slice of this many (1: the whole view)
    bool settled = false;             // every pixel is finished at the AA cap: further frames cost nothing
    double milliseconds = 0.0;        // wall time incl. glFinish; filled in by whoever times the frame
    std::vector<PassTime> passTimes;  // per pass, only with ViewportOptions::timePasses
};

FrameStats summarize(const FrameCounters& c, int width, int height, FrameAction action);

}  // namespace fraktal::viewport
