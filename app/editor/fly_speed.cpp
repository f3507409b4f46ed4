#include "app/editor/fly_speed.hpp"

#include <algorithm>
#include <cmath>

namespace fraktal::editor {

double safeDistance(const Formula& f, const vec3& eye) {
    const double r = length(eye);
    // A formula with custom GLSL blocks has no CPU evaluation: only the bound sphere is known,
    // so outside it the distance to the sphere is the lower bound, and inside it the eye crawls.
    if (!f.cpuEvaluable()) return std::max(r - f.boundRadius, 0.0);
    if (r <= f.boundRadius) return distanceEstimate(f, eye);
    const vec3 s = eye * (f.boundRadius / r);
    const double onSphere = std::max(distanceEstimate(f, s), 0.0);
    const double out = r - f.boundRadius;
    return std::sqrt(onSphere * onSphere + out * out);
}

double flySpeed(const Formula& f, const vec3& eye, const FlyRule& rule) {
    const double d = safeDistance(f, eye);
    if (!(d > 0.0)) return rule.escapeSpeed;  // inside (or NaN): crawl, so one can get out
    return rule.speedPerDistance * d;
}

vec3 flyStep(const Formula& f, const vec3& eye, const vec3& direction, double dt, double boost, const FlyRule& rule) {
    const double len = length(direction);
    if (len == 0.0 || dt <= 0.0) return vec3(0.0);
    const double d = safeDistance(f, eye);
    double step = flySpeed(f, eye, rule) * dt * boost;
    if (d > 0.0) step = std::min(step, rule.maxStepFraction * d);
    const vec3 move = direction / len * step;
    const double standoff = rule.standoff * f.boundRadius;
    // Near the surface: only steps that keep the standoff or move away from the surface.
    if (d > 0.0 && safeDistance(f, eye + move) < std::min(standoff, d)) return vec3(0.0);
    return move;
}

}  // namespace fraktal::editor
