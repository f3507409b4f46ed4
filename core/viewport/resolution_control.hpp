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
