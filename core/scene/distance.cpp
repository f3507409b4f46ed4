#include "core/scene/distance.hpp"

namespace fraktal {

DistanceAt cpuDistance(const Formula& f) {
    return [&f](const vec3& p) { return distanceEstimate(f, p); };
}

std::optional<double> traceDistance(const DistanceAt& de, const vec3& ro, const vec3& rd, double tStart, double tEnd,
                                    const cpu::MarchRule& rule, int maxSteps) {
    const auto at = [&de](const vec3& p, double) { return cpu::DistanceSample{de(p), false}; };
    double deEvals = 0.0;
    return cpu::traceFirstHit(at, ro, rd, tStart, tEnd, rule, maxSteps, deEvals);
}

}  // namespace fraktal
