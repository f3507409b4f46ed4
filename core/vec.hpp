// CPU-side vector types that mirror GLSL, so a block's CPU code reads line for line like its GLSL.
#pragma once

#include <glm/glm.hpp>

namespace fraktal {

using vec2 = glm::dvec2;
using vec3 = glm::dvec3;
using vec4 = glm::dvec4;
using mat3 = glm::dmat3;

// The iteration state, as in PySpace: xyz is the point, w the running scale / derivative.
// GLSL keeps it in a vec4 p; on the CPU the members are named so that `p.xyz` and `p.w`
// read the same in both languages.
struct P4 {
    vec3 xyz{0.0};
    double w = 1.0;
    // The product of the degrees of the power steps applied so far (BlockDesc::degreeAt; GLSL:
    // `degree`, a local of formulaEval that the estimator receives): escape-time potential
    // estimates divide log r by it.
    double degree = 1.0;
    // log r on the surface the iteration count draws, in the units of this orbit's escape: the
    // surface is where the last iteration reaches the bailout B, at potential log(B) / (the
    // degrees of every iteration), so an orbit that escaped with degree D meets it at
    // log r = log(B) / (the degrees of the iterations it did not run). 0 for stacks with no power
    // step (their level sets |F_k| = B are no surface). Set after the loop, for the estimator
    // (GLSL: `surfaceLogR`).
    double surfaceLogR = 0.0;
    // |grad V|, V the estimator's orbit value at the last point as a function of the starting
    // point: log r for escape-time estimators, the estimate at w = 1 for distance ones (a
    // primitive's distance in the last point's space). By tetrahedral differences of the orbit run
    // for the same iterations (orbitValueGradient in core/formula.cpp and shaders/formula.glsl).
    // Set only for estimators that ask for it (BlockDesc::usesOrbitGradient()), else 0 (GLSL:
    // `orbitGradient`).
    double orbitGradient = 0.0;
    // The least of the distances the dIFS shape steps measured along the orbit, each over the
    // running derivative where it was taken (formulas/difs.hpp): the dIFS estimator's value. 1000
    // (Mandelbulber2's start) until a shape step runs. GLSL: the global `orbitDistance`, which
    // formulaEval resets.
    double orbitDistance = 1000.0;
    // The varying scale's running offset (formulas/scale_vary.hpp; Mandelbulber2's
    // aux.actualScaleA): 0 when the orbit starts, changed by each scale_vary step that updates it,
    // shared by all of them as Mandelbulber2 shares it between the formulas of a hybrid. GLSL: the
    // global `varyScale`, which formulaEval resets.
    double varyScale = 0.0;
    // The iteration the orbit is on, from 0: blocks whose parameters vary with it read it (the
    // sphere fold's growing inner radius, Mandelbulber2's Cpara curve). Set by the loop before
    // each iteration's nodes run. GLSL: the global `iteration`, which the loops set.
    int iteration = 0;
    // The point's fourth coordinate (Mandelbulber2's z.w), which the 4D steps read and change
    // (formulas/four_d.hpp); 0 when the orbit starts. The bailout and the linear estimate measure r
    // in 4D. GLSL: the global `pointW`, which the loops reset.
    double pointW = 0.0;
};

using glm::abs;
using glm::clamp;
using glm::cos;
using glm::dot;
using glm::length;
using glm::max;
using glm::min;
using glm::normalize;
using glm::sin;

}  // namespace fraktal
