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

}  // namespace fraktal::viewport
