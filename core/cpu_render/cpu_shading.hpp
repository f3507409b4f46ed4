// Line-for-line C++ mirrors of shaders/march.glsl and shaders/shade.glsl in double precision.
// Change both together.
#pragma once

#include "core/cpu_render/sphere_trace.hpp"
#include "core/formula.hpp"
#include "core/shading_params.hpp"

namespace fraktal::cpu {

struct SurfaceSample {
    vec3 color{0.0}, normal{0.0}, albedo{0.0};
    double ao = 1.0;
};

// The scene a ray is traced in: the formula and the resolved shading.
struct Scene {
    const Formula& formula;
    const ShadingParams& params;
    // hitThreshold: the size the caller takes for a hit at p (evaluate() in core/formula.hpp).
    double de(const vec3& p, double& deEvals, double hitThreshold = 0.0) const;
    // The estimate and the estimator's membership at p (formulaInside in shaders/formula.glsl), as
    // the marcher's distance source (sphere_trace.hpp, which counts the evaluation). hitThreshold:
    // the marcher's at p (evaluate() in core/formula.hpp), 0 elsewhere.
    DistanceSample sample(const vec3& p, double hitThreshold) const;
};

// The camera ray's rule: the hit within the pixel footprint times the detail, the formula's hit
// rule, and overshoot recovery on the estimator's membership.
MarchRule cameraRule(const Scene& scene, double pixelAngle);

MarchState marchStart(const Scene& scene, double tStart);
void marchRay(const Scene& scene, const vec3& ro, const vec3& rd, double tEnd, double pixelAngle, int maxSteps,
              MarchState& s, double& deEvals);
// Mirror of march.glsl's countsAsHit (why: there).
bool countsAsHit(const Scene& scene, const MarchState& s, double pixelAngle);
bool clipToBound(const Scene& scene, const vec3& ro, const vec3& rd, double& tStart, double& tEnd);
// A camera ray's part: within the bound and within the view distance of the camera (march.glsl).
bool clipCameraRay(const Scene& scene, const vec3& ro, const vec3& rd, double& tStart, double& tEnd);
SurfaceSample shadeSurface(const Scene& scene, const vec3& pos, const vec3& rd, double t, double pixelAngle,
                           double& deEvals);
vec3 shadeBackground(const Scene& scene, const vec3& rd);
// Pieces of shadeSurface that the path tracer (cpu_path_tracer.cpp) shares.
double surfaceEpsilon(const Scene& scene, double t, double pixelAngle);
vec3 surfaceNormal(const Scene& scene, const vec3& pos, const vec3& rd, double eps, double& deEvals);
vec3 surfaceAlbedo(const Scene& scene, const vec3& pos, double& deEvals);

}  // namespace fraktal::cpu
