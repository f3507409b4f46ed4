// Dynamic resolution: the share of the viewport's full resolution to render at while the camera
// or a parameter moves, chosen from measured frame times to hold a frame-time target. At rest it
// is 1: the view refines at full resolution (progressive marching and AA). Pure logic, unit-tested
// without GL (tests/viewport_logic_test.cpp).
//
// Model: a frame costs a fixed part plus a part proportional to the pixels, i.e. to scale^2. The
// controller keeps an estimate of the milliseconds a full-resolution frame would take,
// frameMs / scale^2 (an upper bound of the pixel part, so it errs toward smaller scales), and
// picks the scale whose predicted time is the target. A frame over the target lowers the
// estimate's trust at once (the new measurement replaces it); faster frames raise the scale only
// through a slow average, and scale changes smaller than a step are ignored, so the scale settles
// instead of hunting (each change also costs the viewport a re-scatter into a new grid).
#pragma once

namespace fraktal::viewport {

struct ResolutionControl {
    double targetMs = 33.0;  // frame time to hold under motion; <= 0: always full resolution
    // Never below this share of each side. An eighth: on a loaded 2-core machine (a 2-job build
    // beside the editor) a quarter-size Mandelbulb orbit still missed the target by half
    // (bench/viewport/README.md, "The editor under a person's hands").
    double minScale = 0.125;
    double step = 1.0 / 16;  // scales are multiples of this (fewer distinct grids)
    int restFrames = 3;      // unchanged frames in a row before the view counts as at rest
};

// At rest the viewport refines at full size, and a frame marches every unfinished ray by its
// steps per frame. RestSteps picks the steps of the next frame at rest from the last ones. A
// frame's time (the editor's whole frame) is a fixed part (the viewport's shading and
// accumulation over the whole view, the UI, the display, whatever the steps) plus a part per
// step; the part per step is estimated from two frames in a row with different steps (their busy
// rays change little from one frame to the next), the fixed part is the rest. The march gets what
// the target leaves after the fixed part, but never less than twice the fixed part: where that
// alone is over the target (a loaded machine, a large view, llvmpipe), fewer steps would make the
// frames hardly shorter and the view much slower to settle. With twice the fixed part, settling
// takes at most 1.5 times the pure march time by this model; against the fixed 30 steps it took
// 1.2-1.7 times as long on five heavy presets (bench/viewport/README.md). GPU timestamps cannot
// tell the parts apart on llvmpipe, which runs a dispatch when a later pass needs its result. The
// steps grow at most twice a frame (a frame that found little left to march says little about
// the next one) and stay within 1..cap (<= 0 target: `cap`, always).
class RestSteps {
   public:
    // The steps for the next frame at rest; the last one took `frameMs` with `steps`.
    int next(int steps, double frameMs, double targetMs, int cap);
    double msPerStep() const { return msPerStep_; }  // < 0: not measured yet

   private:
    int lastSteps_ = 0;
    double lastMs_ = 0.0;
    double msPerStep_ = -1.0;
};

// The render time a frame at rest aims at when the motion target is shorter: a frame at rest
// also shades, accumulates and draws the whole view, so steps fitted to 33 ms leave much of the
// frame to that fixed work and the view takes longer to settle; 50 ms keeps the window at 20
// frames a second or more while it refines (three Kleinian nodes took 900-965 ms a frame at rest
// with 30 steps a frame).
inline constexpr double kRestFrameTargetMs = 50.0;

class ResolutionController {
   public:
    explicit ResolutionController(ResolutionControl control = {}) : control_(control) {}

    // The scale for the next frame. `changed`: whether the view (camera, parameters) changed since
    // the previous frame. `lastFrameMs`: the measured time of the previous frame, which was
    // rendered at scale(); 0 or less when unknown (the previous frame was not under motion).
    double next(bool changed, double lastFrameMs);

    double scale() const { return scale_; }
    bool moving() const { return framesUnchanged_ < control_.restFrames; }
    const ResolutionControl& control() const { return control_; }
    void setControl(const ResolutionControl& control) { control_ = control; }

   private:
    ResolutionControl control_;
    double scale_ = 1.0;
    double motionScale_ = 1.0;    // the scale motion last used: the next motion starts from it
    double fullFrameMs_ = -1.0;   // estimated time of a full-resolution frame (< 0: none yet)
    int framesUnchanged_ = 1000;  // at rest until the first change
};

}  // namespace fraktal::viewport
