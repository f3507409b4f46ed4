// The fly-speed rule: how far the fly camera may move per frame. The speed is proportional to
// a lower bound of the distance from the eye to the fractal (the DE: fraktal::evaluate on the CPU,
// or the generated GLSL on the editor's GL context for formulas with custom GLSL blocks), so
// one slows down automatically when diving into a Menger tunnel; and one frame's step never
// exceeds half that distance, so even a long frame (llvmpipe) cannot carry the eye through a
// surface. Same idea as Mandelbulber's "distance-dependent" navigation speed.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "core/formula.hpp"
#include "core/scene/distance.hpp"

namespace fraktal::gl {
class DEProbe;
}

namespace fraktal::editor {

struct FlyRule {
    double speedPerDistance = 1.0;  // units per second per unit of distance to the surface
    double maxStepFraction = 0.5;   // a step covers at most this share of the distance
    double escapeSpeed = 1e-3;      // units per second when the eye is inside the fractal
    // Closest approach, as a share of formula.boundRadius: below it double precision can no
    // longer tell the eye from the surface, so only steps that move away are taken.
    double standoff = 1e-9;
};

// Where the editor gets the DE at the eye: the CPU for built-in blocks; for a formula with custom
// GLSL blocks, which has no CPU body, the generated GLSL evaluated on the current GL context
// (gl::DEProbe, single precision), recompiled only when the structure changes. If that GLSL does
// not compile, only the bound sphere is known: outside it the distance to the sphere is a lower
// bound, inside it the eye crawls (distance 0). Needs the editor's GL context current.
class EyeDistance {
   public:
    EyeDistance();
    ~EyeDistance();
    EyeDistance(const EyeDistance&) = delete;
    EyeDistance& operator=(const EyeDistance&) = delete;

    // Valid until the next call or the formula changes.
    DistanceAt of(const Formula& f);
    // Whether the last formula was evaluated on the GPU.
    bool onGpu() const { return onGpu_; }
    // Drops the GL probe (call while its context is still current, before it is destroyed).
    void release();

   private:
    std::string structure_;
    std::unique_ptr<gl::DEProbe> probe_;
    bool compileFailed_ = false, onGpu_ = false;
};

// A lower bound of the distance from `eye` to the fractal, from the DE `de`. Inside
// formula.boundRadius it is the DE. Outside, where escape-time estimates are not trusted, it uses the point `s` where
// the ray from the origin leaves the bound sphere: every point q of the ball satisfies |eye - q|^2 >= |s - q|^2 + |eye
// - s|^2, so sqrt(DE(s)^2 + |eye - s|^2) is still a bound.
double safeDistance(const Formula& f, const DistanceAt& de, const vec3& eye);
// The same with the CPU DE; for a formula without a CPU body, the bound-sphere fallback above.
double safeDistance(const Formula& f, const vec3& eye);

// Speed in units per second at `eye` (before the per-frame step cap).
double flySpeed(const Formula& f, const DistanceAt& de, const vec3& eye, const FlyRule& rule = {});
double flySpeed(const Formula& f, const vec3& eye, const FlyRule& rule = {});

// The displacement for one frame: `direction` (any length; normalised here, zero for none)
// times speed * dt * boost, capped at maxStepFraction of the safe distance.
vec3 flyStep(const Formula& f, const DistanceAt& de, const vec3& eye, const vec3& direction, double dt,
             double boost = 1.0, const FlyRule& rule = {});
vec3 flyStep(const Formula& f, const vec3& eye, const vec3& direction, double dt, double boost = 1.0,
             const FlyRule& rule = {});

}  // namespace fraktal::editor
