#include "core/viewport/resolution_control.hpp"

#include <algorithm>
#include <cmath>

namespace fraktal::viewport {

double ResolutionController::next(bool changed, double lastFrameMs) {
    const bool wasMoving = moving();
    framesUnchanged_ = changed ? 0 : std::min(framesUnchanged_ + 1, 1 << 20);
    if (control_.targetMs <= 0.0) return scale_ = 1.0;
    // Only frames rendered under motion measure the motion's cost (a frame at rest may idle).
    if (wasMoving && lastFrameMs > 0.0) {
        const double measured = lastFrameMs / (scale_ * scale_);
        if (fullFrameMs_ < 0.0 || lastFrameMs > control_.targetMs)
            fullFrameMs_ = fullFrameMs_ < 0.0 ? measured : std::max(measured, 0.5 * (fullFrameMs_ + measured));
        else
            fullFrameMs_ += 0.25 * (measured - fullFrameMs_);
    }
    if (!moving()) return scale_ = 1.0;
    const double fullFrameMs = fullFrameMs_ >= 0.0 ? fullFrameMs_ : seededMs_;
    // Nothing measured nor seeded (the first frames of a new editor): the smallest, not a whole
    // frame at full size.
    const double lastMotion = motionScale_ > 0.0 ? motionScale_ : control_.minScale;
    if (fullFrameMs < 0.0) return scale_ = lastMotion;
    const double ideal = std::clamp(std::sqrt(control_.targetMs / fullFrameMs), control_.minScale, 1.0);
    const double stepped = std::clamp(std::floor(ideal / control_.step) * control_.step, control_.minScale, 1.0);
    // Lower at once when over the target; raise only by a whole step beyond the current scale, and
    // by one step a frame: an estimate too low (frames at an eighth of the size are mostly the
    // editor's fixed work, and under load they vary) then costs one frame a step larger than one
    // that held the target, which lowers the scale at once. Raised to the estimate's scale in one
    // frame, light scenes orbited on a loaded machine jumped from 0.19 to full size mid-drag: 650-700 ms frames.
    const double current = wasMoving ? scale_ : lastMotion;
    double chosen = current;
    // Lowered where the estimate says so, but not below a scale whose last frame held the target.
    const bool heldTarget = wasMoving && lastFrameMs > 0.0 && lastFrameMs <= control_.targetMs;
    if (stepped < current && !heldTarget)
        chosen = stepped;
    else if (stepped >= current + control_.step)
        chosen = std::min(current + control_.step, 1.0);
    // The estimate bounds the pixels' part from above (frameMs / scale^2), so where a frame is
    // mostly the editor's fixed work (a sixteenth of the size: 8 ms of fixed work and 1 of pixels)
    // it held light scenes at the smallest scale. A frame under half the target probes a step up;
    // a probe that went over the target waits kProbeWaitFrames before the next (a heavy scene does
    // not swing between a short frame and one over the target).
    const bool probeFailed = probed_ && wasMoving && lastFrameMs > control_.targetMs;
    probeWait_ = probeFailed ? kProbeWaitFrames : std::max(probeWait_ - 1, 0);
    probed_ = false;
    if (chosen <= current && chosen < 1.0 && wasMoving && lastFrameMs > 0.0 && lastFrameMs < 0.5 * control_.targetMs &&
        probeWait_ == 0) {
        chosen = std::min(current + control_.step, 1.0);
        probed_ = true;
    }
    motionScale_ = chosen;
    return scale_ = chosen;
}

int floorPowerOfTwo(int n) {
    int p = 1;
    while (p <= n / 2) p *= 2;
    return p;
}

void RestSlices::measure(const RestFrame& f) {
    if (f.renderMs <= 0.0 || f.slices < 1 || f.scale <= 0.0) return;
    const bool fullSize = f.scale >= 1.0;
    // The render's part that slicing does not divide (passes over the whole view, the read-back):
    // at most the cheapest frame at full size seen, as the most finely sliced frames show it.
    if (fullSize && !f.newView) fixedMs_ = fixedMs_ < 0.0 ? f.renderMs : std::min(fixedMs_, f.renderMs);
    const double sliced = fullSize && fixedMs_ > 0.0 ? std::max(f.renderMs - fixedMs_, 0.0) : f.renderMs;
    const double whole = sliced * f.slices / (f.scale * f.scale);
    // Each estimate is the costliest of the recent frames, fading by half within a cycle of the
    // slices (each slice comes once a cycle) or within about 7 frames, whichever is sooner: the
    // slices of one view differ in cost (by +-40 % on kleinian.json at 64 slices), and an average
    // let one cheap slice halve the next frame's slices, whose render then took up to 1.4 times
    // the target. Fading over a whole cycle of 256 slices held a view that grew cheap at 256
    // slices, and inverted_menger.json settled in 24 s instead of 8 s.
    const double fade = std::min(0.9, std::pow(0.5, 1.0 / f.slices));
    const auto recentMost = [whole, fade](double estimate) {
        return estimate < 0.0 ? whole : std::max(whole, estimate * fade);
    };
    if (f.newView) newViewMs_ = recentMost(newViewMs_);
    if (!fullSize) return;
    viewMs_ = f.newView ? whole : recentMost(viewMs_);
    otherMs_ = f.frameMs > f.renderMs ? f.frameMs - f.renderMs : 0.0;
    lastSlices_ = f.slices;
}

int RestSlices::choose(bool newView, double targetMs, int maxSlices) const {
    const int most = floorPowerOfTwo(std::max(maxSlices, 1));
    if (targetMs <= 0.0) return 1;
    const double estimate = newView ? newViewMs_ : viewMs_;
    if (estimate < 0.0) return most;
    // The render gets what the target leaves after the other work, but never less than half the
    // target, nor less than the other work itself up to the target: a frame at rest then refines
    // at least half its time, however slow the panels and display are on this machine.
    const double budget = std::max({targetMs - otherMs_, targetMs / 2.0, std::min(otherMs_, targetMs)});
    const double sliceBudget = std::max(budget - std::max(fixedMs_, 0.0), budget / 4.0);
    int slices = 1;
    while (slices < most && estimate / slices > sliceBudget) slices *= 2;
    if (!newView) slices = std::max(slices, lastSlices_ / 2);
    return std::clamp(slices, 1, most);
}

}  // namespace fraktal::viewport
