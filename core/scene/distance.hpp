// The formula's distance estimate as a function of the point: what the scene services (the
// formula fit, the framing, the editor's fly speed and light placement) march and probe with.
#pragma once

#include <functional>
#include <optional>

#include "core/cpu_render/sphere_trace.hpp"
#include "core/formula.hpp"

namespace fraktal {

// The formula's distance estimate at a point (trusted inside formula.boundRadius).
using DistanceAt = std::function<double(const vec3&)>;

// The CPU DE (fraktal::distanceEstimate, double precision). Needs f.cpuEvaluable(); `f` must
// outlive the function.
DistanceAt cpuDistance(const Formula& f);

// The distance along the ray (ro, unit rd) over [tStart, tEnd] of the first point where `de` falls
// to the rule's threshold, marched by the one CPU marcher (core/cpu_render/sphere_trace.hpp) without
// membership; none when the ray escapes, runs out of maxSteps or meets a non-finite estimate.
std::optional<double> traceDistance(const DistanceAt& de, const vec3& ro, const vec3& rd, double tStart, double tEnd,
                                    const cpu::MarchRule& rule, int maxSteps);

}  // namespace fraktal
