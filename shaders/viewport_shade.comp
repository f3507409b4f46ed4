// shaders/viewport_shade.comp — shades the surface samples whose ray finished this frame (the
// per-pixel shading cache: a finished sample is never shaded again), one invocation per entry of
// the shade list the march pass built (dispatched indirectly, viewport_common.glsl). The march
// pass already gave the background its colour, and under camera motion let a reprojected ray
// that lands where its carried colour came from keep that colour (diffuse, AO, shadow and albedo
// of a surface point do not depend on the view; only the specular highlight does), so motion
// costs march steps, not shading. When the camera stops, reused colours are listed and shaded
// exactly once. Needs the formula, march.glsl, shade.glsl and viewport_common.glsl.
layout(local_size_x = 64) in;
layout(rgba32f) uniform image2D u_rayState;
layout(rgba32i) uniform iimage2D u_rayInfo;
layout(rgba32f) uniform image2D u_sampleColor;
layout(rgba32f) uniform image2D u_centre;
layout(rgba32f) uniform writeonly image2D u_colourPoint;
uniform int u_atRest;
uniform int u_maxCarryFrames;  // keepsCarriedColour

void main() {
    uint entry = gl_GlobalInvocationID.x;
    if (entry >= sl_count) return;
    ivec2 px = listedPixel(sl_pixels[entry]);
    ivec4 info = imageLoad(u_rayInfo, px);
    if (info.x != STATUS_HIT) return;
    bool finished = (info.w & FLAG_NEEDS_SHADE) != 0;
    bool makeExact = u_atRest != 0 && (info.w & FLAG_REUSED) != 0;
    if (!finished && !makeExact) return;

    vec4 state = imageLoad(u_rayState, px);
    float t = state.x;
    float tCarried = imageLoad(u_sampleColor, px).a;
    vec3 ro = u_cameraPosition;
    vec3 rd = cameraRay(vec2(px) + 0.5 + aaJitter(info.z));
    lensSampleRay(px, info.z, ro, rd);
    float deEvals = 0.0;
    vec4 centre = imageLoad(u_centre, px);
    bool refines = makeExact || (info.w & FLAG_NEEDS_REFINE) != 0;
    if (refines) {
        // A hit the march pass left unrefined: a fresh one (with the DE at the hit in
        // rayState.y), or one that kept a carried colour until now.
        float d = state.y;
        if (makeExact) {
            d = DE(ro + rd * t);
            deEvals += 1.0;
        }
        MarchState s = MarchState(t, d, 1.0, MARCH_HIT, info.y, 1e30, STEEPEST_FLOOR);
        refineHit(ro, rd, u_pixelAngle, d, s, deEvals);
        t = s.t;
        imageStore(u_rayState, px, vec4(t, state.yzw));
        centre.x = t;
    }
    info.w &= ~(FLAG_NEEDS_SHADE | FLAG_NEEDS_REFINE | FLAG_REUSED);
    // From its refined depth a hit may still keep the colour reprojection carried to it.
    if (keepsCarriedColour(u_atRest, info, centre.z, t, tCarried, u_maxCarryFrames, u_detail, px)) {
        if (info.z == 0) imageStore(u_centre, px, centre);  // x: the refined t
        imageStore(u_rayInfo, px, ivec4(info.xyz, info.w | FLAG_REUSED | FLAG_SHADED_NOW));
        atomicAdd(c_deEvals, uint(deEvals));
        return;
    }
    vec3 color = shadeSurface(ro + rd * t, rd, t, u_pixelAngle, deEvals).color;
    if (info.z == 0) {  // a fresh colour, of this sample's own point
        imageStore(u_centre, px, vec4(centre.xy, 0.0, centre.w));  // x: the refined t
        imageStore(u_colourPoint, px, vec4(ro + rd * t, 1.0));
    }
    atomicAdd(c_shaded, 1u);
    atomicAdd(c_deEvals, uint(deEvals));
    atomicAdd(c_shadeDeEvals, uint(deEvals));
    imageStore(u_rayInfo, px, ivec4(info.xyz, info.w | FLAG_SHADED_NOW));
    imageStore(u_sampleColor, px, vec4(color, tCarried));
}
