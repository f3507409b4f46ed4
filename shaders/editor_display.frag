#version 450 core
// The editor's display transform (app/editor/preview_viewport.cpp): the accumulated linear
// radiance is averaged, exposed, and encoded for an sRGB display. Only here does the image
// leave linear light (tev style).
// TODO(core/color): apply the same OCIO display/view transform as the still export.

layout(location = 0) out vec4 outColor;
layout(binding = 0) uniform sampler2D u_accumulated;  // rgb: summed radiance, a: sample count
uniform float u_exposureScale;                        // 2^exposure

vec3 srgbEncode(vec3 linear) {
    vec3 c = clamp(linear, 0.0, 1.0);
    return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}

void main() {
    vec4 sum = texelFetch(u_accumulated, ivec2(gl_FragCoord.xy), 0);
    vec3 radiance = sum.rgb / max(sum.a, 1.0) * u_exposureScale;
    // A touch of dither hides banding in the dark sky gradient.
    float dither = fract(sin(dot(gl_FragCoord.xy, vec2(12.9898, 78.233))) * 43758.5453) - 0.5;
    outColor = vec4(srgbEncode(radiance) + dither / 255.0, 1.0);
}
