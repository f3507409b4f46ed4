// The fly-speed rule: how far the fly camera may move per frame. The speed is proportional to
// a lower bound of the distance from the eye to the fractal (the CPU DE, fraktal::evaluate), so
// one slows down automatically when diving into a Menger tunnel; and one frame's step never
// exceeds half that distance, so even a long frame (llvmpipe) cannot carry the eye through a
// surface. Same idea as Mandelbulber's "distance-dependent" navigation speed.
#pragma once

#include "core/formula.hpp"

namespace fraktal::editor {

struct FlyRule {
    double speedPerDistance = 1.0;   // units per second per unit of distance to the surface
    double maxStepFraction = 0.5;    // a step covers at most this share of the distance
    double escapeSpeed = 1e-3;       // units per second when the eye is inside the fractal
    // Closest approach, as a share of formula.boundRadius: below it double precision can no
    // longer tell the eye from the surface, so only steps that move away are taken.
    double standoff = 1e-9;
};

// A lower bound of the distance from `eye` to the fractal. Inside formula.boundRadius it is
// the DE. Outside, where escape-time estimates are not trusted, it uses the point `s` where the
// ray from the origin leaves the bound sphere: every point q of the ball satisfies
// |eye - q|^2 >= |s - q|^2 + |eye - s|^2, so sqrt(DE(s)^2 + |eye - s|^2) is still a bound.
double safeDistance(const Formula& f, const vec3& eye);

// Speed in units per second at `eye` (before the per-frame step cap).
double flySpeed(const Formula& f, const vec3& eye, const FlyRule& rule = {});

// The displacement for one frame: `direction` (any length; normalised here, zero for none)
// times speed * dt * boost, capped at maxStepFraction of the safe distance.
vec3 flyStep(const Formula& f, const vec3& eye, const vec3& direction, double dt, double boost = 1.0,
             const FlyRule& rule = {});

}  // namespace fraktal::editor
