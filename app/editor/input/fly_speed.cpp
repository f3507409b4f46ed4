#include "app/editor/input/fly_speed.hpp"

#include <algorithm>
#include <cmath>

#include "core/gl/de_probe.hpp"

namespace fraktal::editor {

namespace {

// Formulas without a CPU body when their GLSL does not compile: only the bound sphere is known.
DistanceAt boundSphereOnly(const Formula& f) {
    const double boundRadius = f.boundRadius;
    return [boundRadius](const vec3& p) { return std::max(length(p) - boundRadius, 0.0); };
}

// The DE the overloads without one use: the CPU's, or the bound sphere.
DistanceAt defaultDistance(const Formula& f) { return f.cpuEvaluable() ? cpuDistance(f) : boundSphereOnly(f); }

}  // namespace

EyeDistance::EyeDistance() = default;
EyeDistance::~EyeDistance() = default;

void EyeDistance::release() {
    probe_.reset();
    structure_.clear();
    compileFailed_ = onGpu_ = false;
}

DistanceAt EyeDistance::of(const Formula& f) {
    onGpu_ = false;
    if (f.cpuEvaluable()) return cpuDistance(f);
    const std::string structure = f.structureKey();
    if (structure != structure_) {
        structure_ = structure;
        probe_.reset();
        compileFailed_ = false;
        try {
            probe_ = std::make_unique<gl::DEProbe>(f);
        } catch (const std::exception&) {
            compileFailed_ = true;  // the viewport shows the compile error next to its node
        }
    }
    if (compileFailed_ || !probe_) return boundSphereOnly(f);
    onGpu_ = true;
    gl::DEProbe* probe = probe_.get();
    return [probe, &f](const vec3& p) {
        const vec3 points[1] = {p};
        return double(probe->evaluate(f, points).front().distance);
    };
}

double safeDistance(const Formula& f, const DistanceAt& de, const vec3& eye) {
    const double r = length(eye);
    if (r <= f.boundRadius) return de(eye);
    const vec3 s = eye * (f.boundRadius / r);
    const double onSphere = std::max(de(s), 0.0);
    const double out = r - f.boundRadius;
    return std::sqrt(onSphere * onSphere + out * out);
}

double safeDistance(const Formula& f, const vec3& eye) { return safeDistance(f, defaultDistance(f), eye); }

double flySpeed(const Formula& f, const DistanceAt& de, const vec3& eye, const FlyRule& rule) {
    const double d = safeDistance(f, de, eye);
    if (!(d > 0.0)) return rule.escapeSpeed;  // inside (or NaN): crawl, so one can get out
    return rule.speedPerDistance * d;
}

double flySpeed(const Formula& f, const vec3& eye, const FlyRule& rule) {
    return flySpeed(f, defaultDistance(f), eye, rule);
}

vec3 flyStep(const Formula& f, const DistanceAt& de, const vec3& eye, const vec3& direction, double dt, double boost,
             const FlyRule& rule) {
    const double len = length(direction);
    if (len == 0.0 || dt <= 0.0) return vec3(0.0);
    const double d = safeDistance(f, de, eye);
    double step = flySpeed(f, de, eye, rule) * dt * boost;
    if (d > 0.0) step = std::min(step, rule.maxStepFraction * d);
    const vec3 move = direction / len * step;
    const double standoff = rule.standoff * f.boundRadius;
    // Near the surface: only steps that keep the standoff or move away from the surface.
    if (d > 0.0 && safeDistance(f, de, eye + move) < std::min(standoff, d)) return vec3(0.0);
    return move;
}

vec3 flyStep(const Formula& f, const vec3& eye, const vec3& direction, double dt, double boost, const FlyRule& rule) {
    return flyStep(f, defaultDistance(f), eye, direction, dt, boost, rule);
}

}  // namespace fraktal::editor
