// The formula's distance estimate as a function of the point: what the scene services (the
// formula fit, the framing, the editor's fly speed and light placement) march and probe with.
#pragma once

#include <functional>

#include "core/formula.hpp"

namespace fraktal {

// The formula's distance estimate at a point (trusted inside formula.boundRadius).
using DistanceAt = std::function<double(const vec3&)>;

// The CPU DE (fraktal::distanceEstimate, double precision). Needs f.cpuEvaluable(); `f` must
// outlive the function.
DistanceAt cpuDistance(const Formula& f);

}  // namespace fraktal
