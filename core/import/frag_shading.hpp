// DE-Raytracer.frag's look as fraktal's shading: the key light (SpotLight, SpotLightDir, Specular,
// SpecularExp, SpecularMax), the light from the eye (CamLight, CamLightMin), shadows (HardShadow,
// ShadowSoft), ambient occlusion (AO, DetailAO), fog (Fog), the background (BackgroundColor),
// reflections (Reflection), the orbit-trap colouring (BaseColor, OrbitStrength, X, Y, Z, R,
// CycleColors, Cycles) and the display (Exposure, ToneMapping, Gamma), each from the chosen preset's
// line, else the raytracer's own default, clamped to its slider as FragM clamps it.
//
// Colours: FragM raises a surface colour to Gamma before lighting it, and its display pass
// (BufferShader.frag) scales by Exposure, applies the tone curve and shows the result at 1 / Gamma,
// so under a white light of 1 and a linear curve the screen shows the colour as written: fraktal's
// palette is display-referred as well and takes them as they are. A light or the background is a
// value of FragM's working space; fraktal shows its scene-linear values through the sRGB curve, so
// such a value becomes the linear value fraktal shows as FragM's display pass shows it
// (FragMDisplay::linear): exactly for the flat background, and for the lights at the mean
// brightness of a white surface (the tone curve bends their sum, not each).
//
// Cosmetic settings never refuse a frag (as the Mandelbulber2 import keeps its glow, fog and
// lights as approximations): what fraktal draws differently or not at all is named in
// `approximated`. Reference: ../shared/reference/fragmentarium-frag.md, "Render settings".
#pragma once

#include <vector>

#include "core/import/fract_import.hpp"
#include "core/import/frag_file.hpp"
#include "core/render_settings.hpp"
#include "core/vec.hpp"

namespace fraktal::frag {

// Whether the frag is drawn by DE-Raytracer.frag or one of its versions (v0.9.x, Slicer, X), the
// raytracer whose settings the mapping knows. The others (Soft, Fast, DE-Kn2, the path tracers)
// light by other rules and keep fraktal's own shading.
bool drawnByDERaytracer(const FragFile& file);

// DE-Raytracer's direction toward its spot light from SpotLightDir, two angles in half turns:
// (sin(pi x) cos(pi y / 2), sin(pi y / 2) sin(pi x), cos(pi x)), unit length.
vec3 spotLightDirection(double x, double y);

// FragM's display pass: Exposure, the tone curve (ToneMapping 1 linear, 2 exponential, 3 filmic,
// 4 Reinhard; 5 to 9 are drawn as 4), then 1 / Gamma.
struct FragMDisplay {
    double exposure = 1.0;
    int toneMapping = 4;
    double gamma = 2.0;

    double shown(double v) const;  // what the screen shows for a working-space value (1: white)
    // The scene-linear value fraktal's sRGB display shows as FragM shows `v`.
    vec3 linear(const vec3& v) const;
};

struct RaytracerLook {
    ShadingSettings shading;
    // The lengths fraktal keeps per bound radius, in world units here: the caller divides by the
    // bound it settles on (0: keep the default's share of the bound).
    double aoReach = 0.0;     // the farthest AO sample from the surface
    double fogPerUnit = 0.0;  // fog extinction per world unit
    std::vector<mb2::ImportItem> approximated;
};

// DE-Raytracer's settings of `preset` (null: the raytracer's defaults) as fraktal's shading, for a
// frag drawn by DE-Raytracer.
RaytracerLook raytracerLook(const FragFile& file, const FragPreset* preset);

}  // namespace fraktal::frag
