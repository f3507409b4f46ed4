// shaders/shade.glsl — needs DE()/formulaDE() from the formula and marchRay()/clipToBound() from
// shaders/march.glsl. Shading of a surface point found by the marcher, and of rays that escape.
// The CPU reference (core/cpu_render/cpu_shading.cpp) mirrors this file line for line: change both.
//
// Shading model (seed 3.3): normals by tetrahedral differences of the DE, Blinn-Phong with a key light
// and a sky/fill hemisphere term, soft shadows by marching toward the light (Quilez, "penumbra"
// estimate k * d / t), ambient occlusion by steps along the normal, orbit-trap colouring through a
// cosine palette (Quilez, "palettes": a + b * cos(2 pi (c * x + d))), depth fog, an optional mirror
// bounce with Schlick's Fresnel term. Objects beside the fractal take their own colour instead
// of the palette. All colours are scene-linear in the working space.
//
// Uniforms (set from ShadingSettings by core/render/shading_uniforms.cpp; lengths are world units):
//   vec3  u_lightDirection    unit vector toward the key light
//   vec3  u_lightColor        key light colour times intensity
//   vec3  u_fillColor         sky/fill light colour (hemisphere, brightest from +y), scaled by AO
//   float u_specular          Blinn-Phong specular weight
//   float u_shininess         Blinn-Phong exponent
//   int   u_shadowSteps       DE steps of the shadow ray (0: no shadows)
//   float u_shadowSoftness    penumbra sharpness k (bigger = harder shadows)
//   int   u_aoSteps           AO samples along the normal (0: no AO)
//   float u_aoDistance        distance of the farthest AO sample
//   float u_aoStrength        0 (no darkening) .. 1 (full)
//   vec4  u_trapWeights       weights of the orbit trap (min |x|, |y|, |z|, min |p|) in the palette index
//   float u_trapScale, u_trapOffset   palette index = offset + scale * dot(weights, trap)
//   vec3  u_paletteA, u_paletteB, u_paletteC, u_paletteD   cosine palette, display-referred (0..1)
//   vec3  u_fogColor          colour that distant surfaces fade to
//   float u_fogDensity        extinction per world unit (0: no fog)
//   float u_reflection        Fresnel reflectance at normal incidence F0 (0: no reflections)
//   int   u_reflectionSteps   march steps of the reflected ray
//   vec3  u_backgroundTop, u_backgroundBottom   background gradient by ray elevation (equal: flat)
//   vec3  u_objectColors[k]   object k's reflectance (SceneObject::color, in the working space)
uniform vec3 u_lightDirection;
uniform vec3 u_lightColor;
uniform vec3 u_fillColor;
uniform float u_specular;
uniform float u_shininess;
uniform int u_shadowSteps;
uniform float u_shadowSoftness;
uniform int u_aoSteps;
uniform float u_aoDistance;
uniform float u_aoStrength;
uniform vec4 u_trapWeights;
uniform float u_trapScale;
uniform float u_trapOffset;
uniform vec3 u_paletteA, u_paletteB, u_paletteC, u_paletteD;
uniform vec3 u_fogColor;
uniform float u_fogDensity;
uniform float u_reflection;
uniform int u_reflectionSteps;
uniform vec3 u_backgroundTop, u_backgroundBottom;
// One per object a formula may hold (kMaxObjects in core/scene_object.hpp): a uniform whatever
// the objects, so a change of colour never recompiles.
uniform vec3 u_objectColors[8];

struct SurfaceSample {
    vec3 color;   // scene-linear, with fog and reflection
    vec3 normal;  // world space, unit
    vec3 albedo;  // the surface's reflectance, linear (surfaceAlbedo)
    float ao;     // 1 = open, 0 = fully occluded
};

// Offset of the normal's differences, and of secondary rays off the surface: half the
// pixel footprint at distance t, but not below what float positions resolve.
float surfaceEpsilon(float t, float pixelAngle) { return max(0.5 * pixelAngle * t, 2e-5 * u_boundRadius); }

// The DE's gradient by tetrahedral differences (Quilez, "normals for an SDF",
// iquilezles.org/articles/normalsSDF): the four corners k of a tetrahedron, n' = sum k d(v + eps k),
// n = n'/|n'|: 4 DE evaluations where central differences take 6 (first-order accurate where those are
// second-order; at an offset of half a pixel footprint the difference is below a pixel's shading).
vec3 surfaceNormal(vec3 pos, vec3 rd, float eps, inout float deEvals) {
    const vec2 k = vec2(1.0, -1.0);
    vec3 n = k.xyy * DE(pos + k.xyy * eps) + k.yyx * DE(pos + k.yyx * eps) + k.yxy * DE(pos + k.yxy * eps) +
             k.xxx * DE(pos + k.xxx * eps);
    deEvals += 4.0;
    float len = length(n);
    return len > 1e-20 ? n / len : -rd;
}

// The reflectance of the surface at pos: an object's own colour, or the fractal's orbit trap
// through the palette.
vec3 surfaceAlbedo(vec3 pos, inout float deEvals) {
    vec4 trap;
    int surface;
    formulaSurface(pos, trap, surface);
    deEvals += 1.0;
    if (surface != FRAKTAL_FRACTAL_SURFACE) return u_objectColors[surface];
    float x = u_trapOffset + u_trapScale * dot(u_trapWeights, trap);
    vec3 display = clamp(u_paletteA + u_paletteB * cos(6.28318530718 * (u_paletteC * x + u_paletteD)), 0.0, 1.0);
    return pow(display, vec3(2.2));  // display-referred palette to linear reflectance
}

// Seed 3.3: "a few steps along the normal (far from everything = open, otherwise occluded)".
float ambientOcclusion(vec3 pos, vec3 n, inout float deEvals) {
    if (u_aoSteps <= 0) return 1.0;
    float occlusion = 0.0;
    for (int i = 1; i <= u_aoSteps; ++i) {
        float h = u_aoDistance * float(i) / float(u_aoSteps);
        // A fractal carved by an escape-time one reads its carved space as 1.5 h: open, not occluded.
        hitThreshold = h;
        float d = DE(pos + n * h);
        hitThreshold = 0.0;
        occlusion += clamp((h - d) / h, 0.0, 1.0);
    }
    deEvals += float(u_aoSteps);
    return clamp(1.0 - u_aoStrength * occlusion / float(u_aoSteps), 0.0, 1.0);
}

// Quilez's soft shadow: the smallest k * d / t along the ray toward the light.
float softShadow(vec3 ro, vec3 L, float eps, inout float deEvals) {
    if (u_shadowSteps <= 0) return 1.0;
    float tStart, tEnd;
    if (!clipToBound(ro, L, tStart, tEnd)) return 1.0;
    float result = 1.0;
    float t = max(tStart, 2.0 * eps);
    for (int i = 0; i < u_shadowSteps && t < tEnd; ++i) {
        // A carved space reads as 1.5 t / softness: lit, as in ambientOcclusion.
        hitThreshold = t / u_shadowSoftness;
        float d = DE(ro + L * t);
        hitThreshold = 0.0;
        deEvals += 1.0;
        result = min(result, u_shadowSoftness * d / t);
        if (result < 1e-3) return 0.0;
        t += clamp(d, eps, 0.1 * u_boundRadius);
    }
    result = clamp(result, 0.0, 1.0);
    return result * result * (3.0 - 2.0 * result);
}

vec3 shadeBackground(vec3 rd) { return mix(u_backgroundBottom, u_backgroundTop, 0.5 + 0.5 * rd.y); }

vec3 lightSurface(vec3 n, vec3 rd, vec3 albedo, float ao, float shadow) {
    vec3 L = u_lightDirection;
    float diffuse = max(dot(n, L), 0.0);
    vec3 h = normalize(L - rd);
    float specular = diffuse > 0.0 ? u_specular * pow(max(dot(n, h), 0.0), u_shininess) : 0.0;
    float sky = 0.5 + 0.5 * n.y;
    return albedo * (u_lightColor * (diffuse * shadow) + u_fillColor * (sky * ao)) + u_lightColor * (specular * shadow);
}

vec3 applyFog(vec3 color, float t) { return mix(u_fogColor, color, exp(-u_fogDensity * t)); }

// The mirror bounce: the reflected ray is marched and lit by the key light and the fill (no AO,
// shadow or further bounce), or sees the background.
vec3 reflectedColor(vec3 pos, vec3 n, vec3 rd, float t, float pixelAngle, float eps, inout float deEvals) {
    vec3 rr = reflect(rd, n);
    vec3 ro = pos + n * (2.0 * eps);
    float tStart, tEnd;
    if (!clipToBound(ro, rr, tStart, tEnd)) return shadeBackground(rr);
    MarchState s = marchStart(tStart);
    // The hit threshold uses the reflected ray's own length: a little finer than the true footprint.
    marchRay(ro, rr, tEnd, pixelAngle, u_reflectionSteps, s, deEvals);
    if (s.status != MARCH_HIT) return shadeBackground(rr);
    vec3 p2 = ro + rr * s.t;
    float eps2 = surfaceEpsilon(t + s.t, pixelAngle);
    vec3 n2 = surfaceNormal(p2, rr, eps2, deEvals);
    vec3 albedo2 = surfaceAlbedo(p2, deEvals);
    return applyFog(lightSurface(n2, rr, albedo2, 1.0, 1.0), s.t);
}

SurfaceSample shadeSurface(vec3 pos, vec3 rd, float t, float pixelAngle, inout float deEvals) {
    SurfaceSample result;
    float eps = surfaceEpsilon(t, pixelAngle);
    vec3 n = surfaceNormal(pos, rd, eps, deEvals);
    vec3 albedo = surfaceAlbedo(pos, deEvals);
    float ao = ambientOcclusion(pos, n, deEvals);
    // Facing away from the key light, the surface gets neither its diffuse nor its specular term,
    // which are all the shadow scales: no shadow ray (about half the shaded samples).
    float shadow = dot(n, u_lightDirection) > 0.0 ? softShadow(pos + n * (2.0 * eps), u_lightDirection, eps, deEvals) : 1.0;
    vec3 color = lightSurface(n, rd, albedo, ao, shadow);
    if (u_reflection > 0.0) {
        float cosine = clamp(-dot(rd, n), 0.0, 1.0);
        float fresnel = u_reflection + (1.0 - u_reflection) * pow(1.0 - cosine, 5.0);
        color = mix(color, reflectedColor(pos, n, rd, t, pixelAngle, eps, deEvals), fresnel);
    }
    result.color = applyFog(color, t);
    result.normal = n;
    result.albedo = albedo;
    result.ao = ao;
    return result;
}
