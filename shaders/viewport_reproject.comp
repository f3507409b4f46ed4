// shaders/viewport_reproject.comp — reprojection (seed 4.2) as a compute scatter: every pixel of
// the previous frame puts its point (where its centre ray got to) into the new view, and the
// nearest point per new pixel wins. This replaces rasterising a one-vertex-per-pixel grid mesh,
// which llvmpipe runs through its single-threaded vertex pipeline (~300 ms at 640x360); the
// scatter is two parallel passes. Pass u_resolve = 0: atomicMin of the new-camera distance
// (positive floats order like their bit patterns as uints) into u_depth. Pass u_resolve = 1: the
// winner writes its distances and colour. Gaps a point scatter leaves where the view magnifies
// are filled by the start pass's neighbourhood minimum (viewport_neighbour_min.comp).
// Erosion fix 1: the point takes the smallest distance of its 3x3 neighbourhood, so silhouettes
// do not erode. The camera uniforms of viewport_common.glsl hold the PREVIOUS camera here.
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) uniform sampler2D u_oldCentre;  // x: t, y: status, z: carry age
layout(binding = 1) uniform sampler2D u_oldImage;
layout(rgba32f, binding = 7) uniform writeonly image2D u_reprojDistance;  // t, hit weight, t of the carried hit
layout(rgba32f, binding = 8) uniform writeonly image2D u_reprojColor;
layout(std430, binding = 1) buffer ReprojectDepth { uint u_depth[]; };
uniform vec3 u_newCameraPosition, u_newRight, u_newUp, u_newForward;
uniform float u_newTanHalfFovY;
uniform int u_resolve;

void main() {
    ivec2 px = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(px, u_size))) return;
    vec4 own = texelFetch(u_oldCentre, px, 0);
    float tMin = own.x;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
            tMin = min(tMin, texelFetch(u_oldCentre, clamp(px + ivec2(dx, dy), ivec2(0), u_size - 1), 0).x);
    vec3 rd = cameraRay(vec2(px) + 0.5);
    vec3 start = u_cameraPosition + rd * tMin - u_newCameraPosition;
    // Into the new camera's image (the inverse of cameraRay with the new camera).
    float z = dot(start, u_newForward);
    if (z <= 0.0) return;
    float aspect = float(u_size.x) / float(u_size.y);
    float ndcX = dot(start, u_newRight) / (z * u_newTanHalfFovY * aspect);
    float ndcY = dot(start, u_newUp) / (z * u_newTanHalfFovY);
    vec2 imagePos = vec2(0.5 * (ndcX + 1.0) * float(u_size.x), 0.5 * (1.0 - ndcY) * float(u_size.y));
    if (any(lessThan(imagePos, vec2(0.0))) || any(greaterThanEqual(imagePos, vec2(u_size)))) return;
    ivec2 target = ivec2(imagePos);
    uint index = uint(target.y * u_size.x + target.x);
    float t = length(start);
    uint key = floatBitsToUint(t);
    if (u_resolve == 0) {
        atomicMin(u_depth[index], key);
        return;
    }
    if (u_depth[index] != key) return;  // a nearer point won (equal keys write equal-enough data)
    vec3 ownHit = u_cameraPosition + rd * own.x - u_newCameraPosition;
    float hit = own.y == float(STATUS_HIT) ? 1.0 : 0.0;
    imageStore(u_reprojDistance, target, vec4(t, hit, length(ownHit), 1.0));
    imageStore(u_reprojColor, target, vec4(texelFetch(u_oldImage, px, 0).rgb, own.z + 1.0));  // a: carry age
}
