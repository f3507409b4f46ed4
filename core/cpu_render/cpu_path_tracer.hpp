// The CPU reference path tracer, in double precision: the estimator that shaders/pathtrace.frag
// mirrors line for line (change both together). Few pixels: the definition of what the GL path
// tracer converges to, and a test oracle.
//
// Estimator (per sample; pbrt-v4 chapters 13 and 12 for the pieces):
// - camera: a uniform jitter in the pixel; with a thin lens the ray starts on the aperture (a disc,
//   Shirley-Chiu concentric map, or a regular polygon of `blades` sides) and passes through the
//   pinhole ray's point on the focus plane;
// - the camera ray marches with the still renderer's marcher (march.glsl / cpu_shading.cpp);
//   bounce and shadow rays are plain sphere-traced with the hit epsilon of the first hit;
// - at each hit: normal and orbit-trap albedo as the still shades them; emission = albedo x
//   emission; next-event estimation to every enabled light (one sample each; lights are seen only
//   this way, not by camera or bounce rays) and to the environment map (luminance-CDF sample,
//   power-heuristic MIS with the BSDF sample that escapes);
// - BSDF: Lambert (albedo x (1 - F0)) plus a GGX lobe with Schlick Fresnel (F0 = specular) and
//   separable Smith shadowing; one direction drawn from the half-half mixture of a cosine lobe
//   and GGX half-vector sampling; `bounces` directions at most;
// - rays that escape see the environment map, or without one the shading's background gradient.
// The random numbers are a PCG hash chain seeded by (pixel, sample index): the GL renderer draws
// the very same numbers, so the two differ only by float vs double arithmetic.
#pragma once

#include <cstdint>
#include <functional>

#include "core/camera.hpp"
#include "core/formula.hpp"
#include "core/image/environment.hpp"
#include "core/image/path_image.hpp"
#include "core/lighting.hpp"
#include "core/shading_params.hpp"

namespace fraktal {

struct PathScene {
    const Formula& formula;
    const Camera& camera;
    const RenderSettings& render;       // width, height, maxSteps, transparentBackground
    const ShadingParams& shading;       // detail, overRelaxation, trap palette, background gradient
    const Lighting& lighting;           // lights (colours already in the working space), lens, pathTrace
    const EnvironmentMap& environment;  // empty: none
};

// Samples [firstSample, firstSample + samples) of every pixel, averaged. `threads` 0: all cores.
PathImage pathTraceReference(const PathScene& scene, int firstSample, int samples, int threads = 0);

// Shared by both renderers: the random stream and the aperture.
uint32_t pathHash(uint32_t v);
uint32_t pathSeed(int x, int y, int sample);
// A point on the unit aperture (a disc for blades < 3, else the regular polygon inscribed in it).
vec2 sampleAperture(double u1, double u2, int blades);
// Lights with colour x intensity converted into the working space (the renderers take these).
std::vector<Light> resolveLights(const std::vector<Light>& lights,
                                 const std::function<vec3(const vec3&)>& toWorking = {});

}  // namespace fraktal
