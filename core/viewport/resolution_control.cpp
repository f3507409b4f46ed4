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
    if (fullFrameMs_ < 0.0) return scale_ = motionScale_;  // nothing measured yet
    const double ideal = std::clamp(std::sqrt(control_.targetMs / fullFrameMs_), control_.minScale, 1.0);
    const double stepped = std::clamp(std::floor(ideal / control_.step) * control_.step, control_.minScale, 1.0);
    // Lower at once when over the target; raise only by a whole step beyond the current scale.
    const double current = wasMoving ? scale_ : motionScale_;
    double chosen = current;
    if (stepped < current || stepped >= current + control_.step) chosen = stepped;
    motionScale_ = chosen;
    return scale_ = chosen;
}

int RestSteps::next(int steps, double frameMs, double targetMs, int cap) {
    if (targetMs <= 0.0) return cap;
    if (lastSteps_ > 0 && steps != lastSteps_) {
        const double slope = (frameMs - lastMs_) / double(steps - lastSteps_);
        if (slope > 0.0) msPerStep_ = msPerStep_ < 0.0 ? slope : 0.5 * (msPerStep_ + slope);
    }
    lastSteps_ = steps;
    lastMs_ = frameMs;
    // Before two frames tell the parts apart, the whole frame counts as march.
    const double fixedMs = msPerStep_ < 0.0 ? 0.0 : std::clamp(frameMs - msPerStep_ * steps, 0.0, frameMs);
    const double marchMs = frameMs - fixedMs;
    const double marchBudgetMs = std::max(targetMs - fixedMs, 2.0 * fixedMs);
    const double fitting = steps * marchBudgetMs / std::max(marchMs, 1e-3);
    return int(std::clamp(fitting, 1.0, double(std::max(std::min(2 * steps, cap), 1))));
}

}  // namespace fraktal::viewport
