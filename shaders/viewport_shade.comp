// shaders/viewport_shade.comp — shades only the samples whose ray finished this frame (the
// per-pixel shading cache: a finished sample is never shaded again), one invocation per entry of
// the shade list the march pass built (dispatched indirectly, viewport_common.glsl). Under camera motion a
// reprojected ray that lands where its carried colour came from keeps that colour (diffuse, AO,
// shadow and albedo of a surface point do not depend on the view; only the specular highlight
// does), so motion costs march steps, not shading. When the camera stops, reused colours are
// shaded exactly once. Needs the formula, march.glsl, shade.glsl and viewport_common.glsl.
layout(local_size_x = 64) in;
layout(rgba32f, binding = 0) uniform image2D u_rayState;
layout(rgba32i, binding = 1) uniform iimage2D u_rayInfo;
layout(rgba32f, binding = 2) uniform image2D u_sampleColor;
layout(rgba32f, binding = 5) uniform image2D u_centre;
layout(rgba32f, binding = 10) uniform writeonly image2D u_colourPoint;
uniform int u_atRest;
// A carried colour is reused for at most this many frames in a row (expiring over the last
// quarter of them, carriedColourExpires), then shaded afresh: its specular highlight and fog
// were computed for the view it was shaded in.
uniform int u_maxCarryFrames;

void main() {
    uint entry = gl_GlobalInvocationID.x;
    if (entry >= sl_count) return;
    ivec2 px = ivec2(int(sl_pixels[entry]) % u_size.x, int(sl_pixels[entry]) / u_size.x);
    ivec4 info = imageLoad(u_rayInfo, px);
    if (info.x == STATUS_MARCHING) return;
    bool finished = (info.w & FLAG_NEEDS_SHADE) != 0;
    bool makeExact = u_atRest != 0 && (info.w & FLAG_REUSED) != 0;
    if (!finished && !makeExact) return;

    float t = imageLoad(u_rayState, px).x;
    vec4 carried = imageLoad(u_sampleColor, px);
    vec3 ro = u_cameraPosition;
    vec3 rd = cameraRay(vec2(px) + 0.5 + aaJitter(info.z));
    float deEvals = 0.0;
    vec3 color;
    info.w &= ~FLAG_REUSED;
    if (info.x == STATUS_HIT) {
        vec4 centre = imageLoad(u_centre, px);
        if (keepsCarriedColour(u_atRest, info, centre.z, t, carried.a, u_maxCarryFrames, u_detail, px)) {
            color = carried.rgb;
            info.w |= FLAG_REUSED;
        } else {
            if (makeExact) {
                // The march skipped refining this hit while it kept a carried colour (march.glsl).
                MarchState s = MarchState(t, 0.0, 1.0, MARCH_HIT, info.y);
                refineHit(ro, rd, u_pixelAngle, DE(ro + rd * t), s, deEvals);
                deEvals += 1.0;
                t = s.t;
                imageStore(u_rayState, px, vec4(t, imageLoad(u_rayState, px).yzw));
                centre.x = t;
            }
            color = shadeSurface(ro + rd * t, rd, t, u_pixelAngle, deEvals).color;
            atomicAdd(c_shaded, 1u);
            if (info.z == 0) {  // a fresh colour, of this sample's own point
                imageStore(u_centre, px, vec4(centre.xy, 0.0, centre.w));  // x: the refined t
                imageStore(u_colourPoint, px, vec4(ro + rd * t, 1.0));
            }
        }
    } else {
        color = shadeBackground(rd);
        if (info.z == 0) imageStore(u_colourPoint, px, vec4(0.0));
    }
    atomicAdd(c_deEvals, uint(deEvals));
    atomicAdd(c_shadeDeEvals, uint(deEvals));
    info.w = (info.w & ~FLAG_NEEDS_SHADE) | FLAG_SHADED_NOW;
    imageStore(u_rayInfo, px, info);
    imageStore(u_sampleColor, px, vec4(color, carried.a));
}
