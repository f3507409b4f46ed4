// What a still (and the viewport) is rendered with: the preset's `render` and `shading` sections
// (parsed in core/preset.cpp; saved only where they differ from these defaults). Plain data.
#pragma once

#include <string>

#include "core/vec.hpp"

namespace fraktal {

// Limits that keep a render bounded (bad input gets an error, not an out-of-memory).
inline constexpr int kMaxImageSide = 65536;
inline constexpr int kMaxSpp = 4096;
inline constexpr int kMaxMarchSteps = 10000;
inline constexpr double kMaxStepGrowth = 64.0;

struct RenderSettings {
    int width = 1280;
    int height = 720;
    int spp = 4;                  // samples per pixel
    int maxSteps = 256;           // march steps per camera ray
    double detail = 0.5;          // hit threshold, in pixel footprints (smaller = finer)
    double overRelaxation = 1.3;  // initial omega of the over-relaxed marcher (1 = plain)
    // The largest multiple of the estimate a ray's adaptive step may reach (shaders/march.glsl): up
    // to 2 every step is verified by the spheres of its ends; above 2, steps are trusted where the
    // estimate falls slowly, faster on cautious estimates and at a risk of stepping across thin
    // parts. 1: no longer than over-relaxation's first steps.
    double maxStepGrowth = 1.9;
    double filterRadius = 2.0;  // Blackman-Harris reconstruction filter radius, pixels
    // Camera rays end this far from the camera (Mandelbulber2's view_distance_max); 0: at the bound
    // sphere alone. Shadow, reflection and light rays keep the bound sphere.
    double viewDistance = 0.0;
    bool transparentBackground = false;
    // Colour: the working (scene-linear) space is an OCIO colour space name or the role
    // "scene_linear"; the PNG preview goes through display/view with exposure (stops).
    std::string workingSpace = "scene_linear";
    std::string display = "sRGB";
    std::string view = "Standard";
    double exposure = 0.0;

    bool operator==(const RenderSettings&) const = default;
};

// Colours are linear Rec.709 as written in the preset; the renderer converts them to the working
// space. Lengths marked "x bound" are fractions of formula.boundRadius so that one shading setup
// suits fractals of any size.
struct ShadingSettings {
    vec3 lightDirection{0.55, 0.75, 0.35};  // toward the key light (normalised on use)
    vec3 lightColor{1.7, 1.6, 1.45};
    vec3 fillColor{0.22, 0.27, 0.36};  // sky/fill hemisphere
    double specular = 0.25;
    double shininess = 40.0;
    int shadowSteps = 96;  // 0: no shadows
    double shadowSoftness = 12.0;
    int aoSteps = 5;          // 0: no ambient occlusion
    double aoDistance = 0.1;  // x bound
    double aoStrength = 1.0;
    // Orbit-trap palette: index = offset + scale * dot(weights, trap), trap = (min|x|, min|y|,
    // min|z|, min|p|) over the orbit (seed 3.3); colour = a + b cos(2 pi (c index + d)).
    vec4 trapWeights{0.6, 0.2, 0.4, 0.8};
    double trapScale = 1.0;
    double trapOffset = 0.0;
    vec3 paletteA{0.6, 0.5, 0.44};
    vec3 paletteB{0.32, 0.26, 0.24};
    vec3 paletteC{0.8, 0.8, 0.8};
    vec3 paletteD{0.0, 0.15, 0.3};
    vec3 fogColor{0.55, 0.6, 0.7};
    double fogDensity = 0.0;  // per bound radius travelled
    double reflection = 0.0;  // Fresnel F0 (0: no reflections)
    int reflectionSteps = 96;
    vec3 backgroundTop{0.18, 0.24, 0.36};
    vec3 backgroundBottom{0.02, 0.02, 0.03};

    bool operator==(const ShadingSettings&) const = default;
};

}  // namespace fraktal
