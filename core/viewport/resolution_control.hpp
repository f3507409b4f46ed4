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
    // Never below this share of each side. A sixteenth (one step): on a loaded 2-core machine (a
    // 2-job build beside the editor) a quarter-size Mandelbulb orbit still missed the target by
    // half (bench/viewport/README.md, "The editor under a person's hands"), and three Kleinian
    // nodes took 150-230 ms a moving frame at an eighth.
    double minScale = 1.0 / 16;
    double step = 1.0 / 16;  // scales are multiples of this (fewer distinct grids)
    int restFrames = 3;      // unchanged frames in a row before the view counts as at rest
};

// Sliced refinement at rest (ViewportOptions::slices): how many slices of the view the next frame
// at rest refines one of. A frame at rest is the editor's other work (panels, display, swap: about
// the same every frame) plus the viewport's render, whose cost is about the whole view's divided by
// the slices; the whole view's is estimated from each measured frame (render time, less the part
// that slicing does not divide, times its slices). That part (passes over the whole view, the
// counters' read-back) is taken as the cheapest render at full size seen: counted into the
// estimate, it kept 256-1024 slices on views that needed a few, and their settling 2-4x as long. The next frame gets
// the fewest slices, a power of two, that fit the render into what the target leaves after the other work, but at
// least half the target, and at least the other work itself up to the target (the render never more than the target):
// on a loaded machine the other work alone can take most of the target, and each frame's other work then slows the
// view's settling the more, the more slices. A new view (a reset: every ray starts from the camera, the costliest
// frames) is sized from the last new view's cost, or gets the most slices when none was measured; a continued view from
// its own frames: the costliest of the recent ones, fading by half over a cycle of the slices, and by at most half a
// frame (its rays finish, and the frames grow cheap). Pure logic, unit-tested (tests/resolution_control_test.cpp).
struct RestFrame {
    bool newView = false;   // the frame started a new view (a reset)
    int slices = 1;         // it refined one slice of this many
    double scale = 1.0;     // at this share of the full size (a reset under motion: slices 1)
    double renderMs = 0.0;  // the viewport's render (0: it refined nothing)
    double frameMs = 0.0;   // the editor's whole frame (0: unknown)
};

class RestSlices {
   public:
    // Takes a frame's measurement into the estimates.
    void measure(const RestFrame& frame);
    // The slices for the next frame at full size, at most maxSlices (a power of two).
    int choose(bool newView, double targetMs, int maxSlices) const;
    // A new structure: the last new view's cost says nothing about the next one.
    void forgetNewView() { newViewMs_ = -1.0; }
    double wholeViewMs() const { return viewMs_; }  // < 0: not measured yet

   private:
    double viewMs_ = -1.0;     // a whole frame of the view being refined
    double newViewMs_ = -1.0;  // a whole frame that starts a new view
    double otherMs_ = 0.0;     // the editor's frame beside the render
    double fixedMs_ = -1.0;    // the render's part slicing does not divide (< 0: none measured)
    int lastSlices_ = 0;
};

// The largest power of two up to `n` (1 for n < 1).
int floorPowerOfTwo(int n);

// The render time a frame at rest aims at when the motion target is shorter: 50 ms keeps the
// window at 20 frames a second or more while it refines (three Kleinian nodes took 900-965 ms a
// frame at rest when every frame marched the whole view).
inline constexpr double kRestFrameTargetMs = 50.0;

// The most slices a frame at rest cuts the view into (never more than the view's tiles): a
// 1280x800 window's viewport has about 1400 tiles of 32x8 pixels, so a frame then refines one or
// two of them; three Kleinian nodes took 0.9-1 s to march the whole view 30 steps a ray on two
// idle cores, and 125 ms a frame at 256 slices on loaded ones.
inline constexpr int kMaxRestSlices = 1024;

class ResolutionController {
   public:
    explicit ResolutionController(ResolutionControl control = {}) : control_(control) {}

    // The scale for the next frame. `changed`: whether the view (camera, parameters) changed since
    // the previous frame. `lastFrameMs`: the measured time of the previous frame, which was
    // rendered at scale(); 0 or less when unknown (the previous frame was not under motion).
    double next(bool changed, double lastFrameMs);

    // Until a frame under motion is measured, the estimate of a full-resolution frame is this one
    // (the frames at rest measure it: RestSlices::wholeViewMs), so that the first frame of the
    // first motion does not render the whole view at full size (kleinian.json: 3.5 s).
    void seedFullFrameMs(double ms) {
        if (fullFrameMs_ < 0.0 && ms > 0.0) seededMs_ = ms;
    }
    double scale() const { return scale_; }
    bool moving() const { return framesUnchanged_ < control_.restFrames; }
    const ResolutionControl& control() const { return control_; }
    void setControl(const ResolutionControl& control) { control_ = control; }

   private:
    ResolutionControl control_;
    double scale_ = 1.0;
    double motionScale_ = -1.0;   // the scale motion last used: the next motion starts from it (< 0: none)
    double fullFrameMs_ = -1.0;   // estimated time of a full-resolution frame (< 0: none yet)
    double seededMs_ = -1.0;      // seedFullFrameMs's, until fullFrameMs_ is measured
    int framesUnchanged_ = 1000;  // at rest until the first change
    static constexpr int kProbeWaitFrames = 30;
    bool probed_ = false;  // the last scale was a probe a step above the estimate's
    int probeWait_ = 0;    // frames until the next probe may come
};

}  // namespace fraktal::viewport
