#version 450 core
// The editor viewport's display pass (app/editor/viewport/ocio_display_pass.cpp): the only place its image
// leaves scene-linear data. Exposure (a gain of 2^stops in the working space), then the OCIO
// display/view transform whose GLSL OpenColorIO generates (GpuShaderDesc, GLSL 4.0; it defines
// `vec4 OCIODisplay(vec4)` and its LUT samplers and replaces the marker line below), then the
// clamp to [0, 1] that the 8-bit target and the still's PNG (DisplayTransform::toDisplay8) apply.
// Draw with editor_fullscreen.vert into a target of the image's size.

// OCIO_SHADER_TEXT

layout(binding = 0) uniform sampler2D u_image;
uniform float u_gain;
// The editor's 2D view: the image holds sample sums in rgb and the sample count in alpha
// (u_divideByCount = 1), in linear Rec.709 that u_toWorking takes to the working space (the
// identity for the 3D viewport, whose image is in the working space already).
uniform int u_divideByCount;
uniform mat3 u_toWorking;
layout(location = 0) out vec4 o_color;

void main() {
    vec4 texel = texelFetch(u_image, ivec2(gl_FragCoord.xy), 0);
    if (u_divideByCount != 0) texel.rgb /= max(texel.a, 1.0);
    vec3 linear = u_toWorking * texel.rgb * u_gain;
    vec3 display = OCIODisplay(vec4(linear, 1.0)).rgb;
    // Non-finite values show black, as in the PNG export.
    for (int i = 0; i < 3; ++i)
        if (isnan(display[i]) || isinf(display[i])) display[i] = 0.0;
    o_color = vec4(clamp(display, 0.0, 1.0), 1.0);
}
