// 2D blocks: the plane counterpart of core/block.hpp. A 2D block is one step of a membership
// test in the plane (seed 2.1): a fold, a transform, a triangle test or the complex power
// iteration, or the closing estimator. Each is declared once (formulas/plane/*.hpp) with its id,
// help, one ParamDecl list (the same declarations the editor's widgets and the preset reader use)
// and its GLSL and CPU bodies side by side; formulas/plane/registry.cpp holds one line per block.
#pragma once

#include <algorithm>
#include <cmath>
#include <span>
#include <string_view>

#include "core/block.hpp"

namespace fraktal {

// The shader's number type: double where the driver has fp64 (deep zooms), else float. The CPU
// bodies use the same names so that they read line for line like the GLSL.
using real = double;
using real2 = glm::dvec2;

// The iteration state. GLSL declares the same struct (shaders/plane_formula.glsl).
struct PlaneState {
    real2 z{0.0};           // the point
    real dz = 1.0;          // running scale (folds, scales) or derivative bound |dz/dc| (power iteration)
    double power = 1.0;     // degree of the last power step: smooth iteration count uses log(power)
    bool escaped = false;   // decided outside (a triangle test found no corner, or the bailout)
    bool captured = false;  // decided inside (the point fell into a kept triangle)
};

// How the closing estimator's formula decides membership.
enum class PlaneMembership {
    NotEscaped,  // inside unless the orbit escaped (Mandelbrot, Julia)
    Region,      // not escaped and the closing distance <= 0 (Sierpinski: in the triangle at depth N)
    Captured,    // inside only if a test captured it (Koch snowflake: triangle plus bumps)
};

// The 2D family of core/block.hpp's BlockDescOf: the same description, concepts and
// describeAs over the plane's state.
using PlaneBlockDesc = BlockDescOf<PlaneState, real2, PlaneMembership>;
using PlaneApplyFn = PlaneBlockDesc::ApplyFn;
using PlaneEstimateFn = PlaneBlockDesc::EstimateFn;

template <class B>
concept PlaneStepBlock = StepBlockFor<B, PlaneBlockDesc>;
template <class B>
concept PlaneEstimatorBlock = EstimatorBlockFor<B, PlaneBlockDesc>;

template <class B>
consteval bool allParamsScalar() {
    for (const ParamDecl& p : B::params)
        if (!isScalar(p.type)) return false;
    return true;
}

template <class B>
requires PlaneStepBlock<B> || PlaneEstimatorBlock<B>
constexpr PlaneBlockDesc describePlane() {
    static_assert(allParamsScalar<B>(), "2D block parameters are floats or toggles (a 2D vector is two floats)");
    return describeAs<PlaneBlockDesc, B>();
}

// All registered 2D blocks (formulas/plane/registry.cpp).
std::span<const PlaneBlockDesc> allPlaneBlocks();
const PlaneBlockDesc* findPlaneBlock(std::string_view id);

// Signed distance to the equilateral triangle pointing up (+y), centroid at the origin,
// circumradius `radius` (negative inside). Inigo Quilez, "2D distance functions",
// sdEquilateralTriangle, with his half-side r = radius * sqrt(3) / 2. The GLSL twin is
// planeSdTriangle in shaders/plane_formula.glsl.
inline real planeSdTriangle(real2 p, real radius) {
    const real k = std::sqrt(3.0);
    const real r = radius * k * 0.5;
    p.x = std::abs(p.x) - r;
    p.y = p.y + r / k;
    if (p.x + k * p.y > 0.0) p = real2(p.x - k * p.y, -k * p.x - p.y) / 2.0;
    p.x -= std::clamp(p.x, -2.0 * r, 0.0);
    return -glm::length(p) * (p.y > 0.0 ? 1.0 : p.y < 0.0 ? -1.0 : 0.0);
}

}  // namespace fraktal
