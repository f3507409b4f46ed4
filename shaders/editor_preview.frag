// The editor's interim preview marcher (app/editor/preview_viewport.cpp): one jittered sample
// per pixel per frame, sphere-traced with the generated DE() and shaded from the orbit trap.
// Writes linear radiance; the display pass (editor_display.frag) applies exposure and sRGB.
// Replaced by core/viewport once that lands.

layout(location = 0) out vec4 outRadiance;  // rgb linear, a = 1 (one sample, summed by blending)
layout(location = 1) out vec4 outStats;     // x: DE evaluations this pixel, y: 1 if it hit

uniform vec2 u_resolution;       // pixels of the whole image
uniform vec2 u_jitter;           // subpixel offset of this sample, in pixels (-0.5..0.5)
uniform mat4 u_worldFromCamera;
uniform float u_tanHalfFov;
uniform int u_maxSteps;
uniform vec3 u_lightDir;         // towards the light, normalised
uniform bool u_shadows;
uniform bool u_ambientOcclusion;
uniform float u_fog;
uniform int u_palette;

int g_evaluations = 0;

float sceneDE(vec3 p) {
    ++g_evaluations;
    return DE(p);
}

// Ray / bound-sphere interval; false when the ray misses it (seed: the DE is only trusted inside).
bool clipToBound(vec3 ro, vec3 rd, out float t0, out float t1) {
    float b = dot(ro, rd);
    float c = dot(ro, ro) - u_boundRadius * u_boundRadius;
    float h = b * b - c;
    if (h < 0.0) return false;
    h = sqrt(h);
    t0 = max(-b - h, 0.0);
    t1 = -b + h;
    return t1 > 0.0;
}

// Tetrahedral central differences (Inigo Quilez, "normals for an SDF").
vec3 surfaceNormal(vec3 p, float eps) {
    const vec2 k = vec2(1.0, -1.0);
    return normalize(k.xyy * sceneDE(p + k.xyy * eps) + k.yyx * sceneDE(p + k.yyx * eps) +
                     k.yxy * sceneDE(p + k.yxy * eps) + k.xxx * sceneDE(p + k.xxx * eps));
}

// Soft shadow by sphere tracing towards the light (Quilez, "soft shadows in raymarched SDFs").
float softShadow(vec3 ro, vec3 rd, float tmin, float tmax) {
    float res = 1.0;
    float t = tmin;
    for (int i = 0; i < 48 && t < tmax; ++i) {
        float h = sceneDE(ro + rd * t);
        if (h < tmin * 0.25) return 0.0;
        res = min(res, 10.0 * h / t);
        t += clamp(h, tmin * 0.5, tmax * 0.1);
    }
    return clamp(res, 0.0, 1.0);
}

// Five-tap ambient occlusion along the normal (Quilez / Hvidtfeldt, Syntopia).
float ambientOcclusion(vec3 p, vec3 n, float scale) {
    float occ = 0.0;
    float w = 1.0;
    for (int i = 1; i <= 5; ++i) {
        float h = scale * float(i);
        occ += w * (h - sceneDE(p + n * h));
        w *= 0.6;
    }
    return clamp(1.0 - 1.5 * occ / scale, 0.0, 1.0);
}

// Cosine palettes (Quilez, "palettes"), indexed by the orbit trap (seed 3.3).
vec3 palette(vec4 trap, int iterations) {
    float t = clamp(log(1.0 + trap.w) * 0.9 + 0.04 * float(iterations), 0.0, 4.0);
    if (u_palette == 0) return vec3(0.55, 0.45, 0.36) + vec3(0.35, 0.3, 0.26) * cos(6.28318 * (t + vec3(0.0, 0.12, 0.25)));
    if (u_palette == 1) return 0.5 + 0.45 * cos(6.28318 * (vec3(1.0, 1.0, 0.5) * t + vec3(0.55, 0.45, 0.3)));
    if (u_palette == 2) return vec3(0.78, 0.74, 0.68) * (0.75 + 0.25 * cos(6.28318 * t));
    return clamp(1.0 - sqrt(trap.xyz), 0.05, 1.0);
}

vec3 sky(vec3 rd) {
    float h = rd.y * 0.5 + 0.5;
    return mix(vec3(0.035, 0.04, 0.05), vec3(0.16, 0.19, 0.24), h);
}

void main() {
    vec2 pixel = gl_FragCoord.xy + u_jitter;
    vec2 ndc = pixel / u_resolution * 2.0 - 1.0;
    float aspect = u_resolution.x / u_resolution.y;
    vec3 ro = u_worldFromCamera[3].xyz;
    vec3 dirCamera = normalize(vec3(ndc.x * u_tanHalfFov * aspect, ndc.y * u_tanHalfFov, -1.0));
    vec3 rd = normalize(mat3(u_worldFromCamera) * dirCamera);
    // Half the angle one pixel subtends: the hit threshold grows with distance (cone marching).
    float pixelCone = u_tanHalfFov / u_resolution.y;

    vec3 color = sky(rd);
    float hit = 0.0;
    float t0, t1;
    if (clipToBound(ro, rd, t0, t1)) {
        float t = t0;
        bool found = false;
        for (int i = 0; i < u_maxSteps; ++i) {
            float d = sceneDE(ro + rd * t);
            if (d < max(t, 1e-4) * pixelCone) {
                found = true;
                break;
            }
            t += d;
            if (t > t1) break;
        }
        if (found) {
            hit = 1.0;
            vec3 p = ro + rd * t;
            float eps = max(t * pixelCone, 1e-5);
            vec3 n = surfaceNormal(p, eps * 0.5);
            vec4 trap;
            int iterations;
            formulaDE(p, trap, iterations);
            ++g_evaluations;
            vec3 albedo = palette(trap, iterations);
            float diffuse = max(dot(n, u_lightDir), 0.0);
            if (u_shadows && diffuse > 0.0) diffuse *= softShadow(p + n * eps * 2.0, u_lightDir, eps * 4.0, 2.0 * u_boundRadius);
            float ao = u_ambientOcclusion ? ambientOcclusion(p, n, max(eps * 8.0, 0.002 * u_boundRadius)) : 1.0;
            vec3 h = normalize(u_lightDir - rd);
            float specular = pow(max(dot(n, h), 0.0), 40.0) * 0.25;
            vec3 lit = albedo * (vec3(1.0, 0.95, 0.88) * 1.1 * diffuse + (vec3(0.2, 0.24, 0.3) + sky(n)) * 1.1 * ao) + specular * diffuse;
            float fog = 1.0 - exp(-u_fog * max(t - t0, 0.0));
            color = mix(lit, sky(rd), fog);
        }
    }
    outRadiance = vec4(color, 1.0);
    outStats = vec4(float(g_evaluations), hit, 0.0, 1.0);
}
