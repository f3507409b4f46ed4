// shaders/viewport_display.frag — the only place the viewport leaves scene-linear data (tev
// style): exposure in stops, then the sRGB transfer curve (IEC 61966-2-1). Draw with
// shaders/fullscreen.vert into a framebuffer of the image's size.
layout(binding = 0) uniform sampler2D u_image;
uniform float u_exposure;
uniform int u_flipY;  // 1: window framebuffers count rows from the bottom
layout(location = 0) out vec4 o_color;

vec3 srgbEncode(vec3 c) {
    c = clamp(c, 0.0, 1.0);
    return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(0.0031308, c));
}

void main() {
    ivec2 size = textureSize(u_image, 0);
    ivec2 px = ivec2(gl_FragCoord.xy);
    if (u_flipY != 0) px.y = size.y - 1 - px.y;
    vec3 linear = texelFetch(u_image, clamp(px, ivec2(0), size - 1), 0).rgb;
    o_color = vec4(srgbEncode(linear * exp2(u_exposure)), 1.0);
}
