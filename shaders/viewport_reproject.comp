// shaders/viewport_reproject.comp — reprojection (seed 4.2) as a compute scatter: every pixel of
// the previous frame puts its point (where its centre ray got to) into the new view, and the
// nearest point per new pixel wins. This replaces rasterising a one-vertex-per-pixel grid mesh,
// which llvmpipe runs through its single-threaded vertex pipeline (~300 ms at 640x360); the
// scatter is two parallel passes, compiled apart (CLAIM 1 and 0: llvmpipe runs a pass's whole
// code for every invocation, so each holds only its own). The claim pass: imageAtomicMin of the
// new-camera distance (positive floats order like their bit patterns as uints) into u_depth,
// which is all the rays' starts need of the distances. The write pass: a colour whose point won
// a pixel writes itself there. Gaps a point scatter leaves where the view magnifies are filled
// by the starts' neighbourhood minimum (viewport_start.glsl).
// Erosion fix 1, as the seed has it (a vertex of the pixel-quad mesh reads the pixels around it):
// the points are the mesh's vertices, one per pixel corner, each at the smallest distance of the
// four pixels that share the corner, so silhouettes do not erode. With the starts' 3x3
// minimum (erosion fix 2) a start is the nearest of 4x4 pixels. Until 2026-11 each pixel centre
// took the minimum of its 3x3 neighbourhood, 5x5 in all, which started rays farther in front of
// the surface for the same image (Sierpinski tetrahedron, 30 frames from rest at 320x180: 1.57
// against 1.44 DE per pixel per frame, 27.8 dB both); holes in the no-holes test
// (ViewportGL.ReprojectedSilhouettesHaveNoHoles with coarse hits off, summed over its 6 frames,
// Sierpinski / Menger / hybrid): 0.65 / 0.42 / 0.46 % of pixels with 3x3, 0.81 / 0.37 / 0.33 %
// with corners.
//
// Colours travel in a second scatter keyed by the surface point they are the shading of (the
// colourPoint image), not by the eroded point of the distance scatter nor by the pixel's current
// hit: a carried colour then lands in the pixel its own point projects into, so it stays a true
// sample from inside that pixel however often it is carried. Keyed by anything else the colour
// drifts by up to half a pixel per carry, and the error grew with every carry (bench/README.md).
layout(local_size_x = 32, local_size_y = 8) in;  // viewport_common.glsl: why 32x8
layout(binding = 0) uniform sampler2D u_oldCentre;  // x: t, y: status, z: carry age, w: generation
layout(binding = 1) uniform sampler2D u_oldImage;
layout(binding = 2) uniform sampler2D u_oldColourPoint;  // xyz: the colour's point, w: 1 if any
// The previous frame's images are u_size (the points' grid, whose pixels this pass runs over); the
// new frame's are u_newSize, which differs when dynamic resolution changes the grid between the
// frames: the points are world points, so they scatter into any grid.
uniform ivec2 u_newSize;
// Old pixels per side that one invocation scatters (BLOCK 1: scatterBlock below).
uniform int u_block;
// Carried colours, u_newSize.x by 2 u_newSize.y: row y holds the colour whose point lies in pixel row y,
// row u_newSize.y + y the one that pixel borrows when no point lies in it (see below).
layout(rgba32f) uniform writeonly image2D u_reprojColor;     // rgb, a: carry age + 1
layout(rgba32f) uniform writeonly image2D u_reprojCarried;   // xyz: its point, w: its t
// Distance keys, u_newSize.x by 3 u_newSize.y (MarchState::reprojDepth): rows [0, h) of the start
// points; rows [h, 2h) of the carried colours whose point lies in the pixel; rows [2h, 3h) of
// those near it.
layout(r32ui) uniform uimage2D u_depth;
uniform vec3 u_newCameraPosition, u_newRight, u_newUp, u_newForward;
uniform float u_newTanHalfFovY, u_newHalfFovY;
uniform int u_newProjection;

// The new pixel a world point projects into, where in the image (pixels from the top-left), and
// its distance from the new camera; false when it is behind the camera or off-screen.
bool projectToNewView(vec3 world, out ivec2 target, out vec2 imagePos, out float t) {
    target = ivec2(0);
    if (!projectToImageOfSize(world, u_newCameraPosition, u_newRight, u_newUp, u_newForward, u_newTanHalfFovY,
                              u_newHalfFovY, u_newProjection, u_newSize, imagePos, t))
        return false;
    if (any(lessThan(imagePos, vec2(0.0))) || any(greaterThanEqual(imagePos, vec2(u_newSize)))) return false;
    target = ivec2(imagePos);
    return true;
}

// The claim pass claims the target with the nearest key; the write pass tells whether this
// point won it.
bool nearestWins(ivec2 texel, float t) {
    uint key = floatBitsToUint(t);
#if CLAIM
    imageAtomicMin(u_depth, texel, key);
    return false;
#else
    return imageLoad(u_depth, texel).x == key;  // equal keys write equal-enough data
#endif
}

// Scatters the colour of old pixel px (of the old view), keyed by its own point, into the pixel
// that point lies in and the neighbours it is near.
void scatterColour(ivec2 px) {
    ivec2 target;
    vec2 imagePos;
    float t;
    vec4 colourPoint = texelFetch(u_oldColourPoint, px, 0);
    if (colourPoint.w > 0.0 && projectToNewView(colourPoint.xyz, target, imagePos, t)) {
        vec4 color = vec4(texelFetch(u_oldImage, px, 0).rgb, texelFetch(u_oldCentre, px, 0).z + 1.0);
        vec4 carried = vec4(colourPoint.xyz, t);
        if (nearestWins(ivec2(target.x, u_newSize.y + target.y), t)) {
            imageStore(u_reprojColor, target, color);
            imageStore(u_reprojCarried, target, carried);
        }
        // The point is also a sample of the neighbours whose centre lies within half a pixel
        // diagonal of it: a point scatter leaves pixels that no point lands in (points crowd into
        // one pixel and spread apart next to it), and such a pixel takes the nearest of these.
        // Those include points that lost their own pixel to a nearer one, which would otherwise
        // be dropped, and it is a sample from inside the pixel's circumscribed circle, so it
        // stays a sample of what the pixel sees.
        vec2 offset = imagePos - (vec2(target) + 0.5);  // in [-0.5, 0.5)
        ivec2 toward = ivec2(offset.x < 0.0 ? -1 : 1, offset.y < 0.0 ? -1 : 1);
        for (int k = 1; k < 4; ++k) {
            ivec2 step = ivec2(k & 1, k >> 1) * toward;
            ivec2 q = target + step;
            if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, u_newSize))) continue;
            if (length(imagePos - (vec2(q) + 0.5)) >= HALF_DIAGONAL) continue;
            if (nearestWins(ivec2(q.x, 2 * u_newSize.y + q.y), t)) {
                imageStore(u_reprojColor, ivec2(q.x, u_newSize.y + q.y), color);
                imageStore(u_reprojCarried, ivec2(q.x, u_newSize.y + q.y), carried);
            }
        }
    }
}

// One point per old pixel: the vertex at its lower right corner, at the nearest distance of the
// four pixels that share the corner (of those whose ray is of the old view: a sliced reset leaves
// the pixels whose slice did not come yet with an older view's, u_generation), and its colour.
void scatterPixel(ivec2 px) {
#if CLAIM
    float tMin = 1e30;
    for (int k = 0; k < 4; ++k) {
        vec4 centre = texelFetch(u_oldCentre, clamp(px + ivec2(k & 1, k >> 1), ivec2(0), u_size - 1), 0);
        if (centre.w == float(u_generation)) tMin = min(tMin, centre.x);
    }
    ivec2 target;
    vec2 imagePos;
    float t;
    vec3 rd = cameraRay(vec2(px) + 1.0);
    if (tMin < 1e30 && projectToNewView(u_cameraPosition + rd * tMin, target, imagePos, t)) nearestWins(target, t);
#endif
    if (texelFetch(u_oldCentre, px, 0).w == float(u_generation)) scatterColour(px);
}

// Blocks of old pixels, u_block per side (reproject_pass.cpp: reprojectBlock). Where motion moves
// onto a grid several times smaller than the one at rest (the editor's dynamic resolution: 690x520
// to 86x65), a point per old pixel cost 35-55 ms of CPU on llvmpipe for that frame, nearly all of
// it each point's ray and projection, for a grid of 5600 pixels. A block sends one point for the
// distances and one colour, its nearest pixel's; a new pixel still takes (ratio / block)^2 of each,
// 4 at the editor's ratio of 8. The point stays a lower bound of every point the block's pixels
// would have sent: it lies on the block's middle ray at their nearest distance, and their own
// vertices lie within the block's spread (half the diagonal beyond one pixel, at that distance)
// of that ray, which is taken off its key.
void scatterBlock(ivec2 origin) {
#if CLAIM
    float tMin = 1e30;
    for (int y = 0; y <= u_block; ++y)
        for (int x = 0; x <= u_block; ++x) {
            vec4 centre = texelFetch(u_oldCentre, min(origin + ivec2(x, y), u_size - 1), 0);
            if (centre.w == float(u_generation)) tMin = min(tMin, centre.x);
        }
    ivec2 target;
    vec2 imagePos;
    float t;
    vec3 rd = cameraRay(vec2(origin) + 0.5 * float(u_block + 1));
    float spread = HALF_DIAGONAL * float(u_block - 1) * u_pixelAngle * tMin;
    if (tMin < 1e30 && projectToNewView(u_cameraPosition + rd * tMin, target, imagePos, t))
        nearestWins(target, max(t - spread, 0.0));
#endif
    ivec2 px = origin;
    float nearest = 0.0;
    bool ofOldView = false;
    for (int y = 0; y < u_block; ++y)
        for (int x = 0; x < u_block; ++x) {
            ivec2 q = min(origin + ivec2(x, y), u_size - 1);
            vec4 centre = texelFetch(u_oldCentre, q, 0);
            if (centre.w == float(u_generation) && (!ofOldView || centre.x < nearest)) {
                nearest = centre.x;
                px = q;
                ofOldView = true;
            }
        }
    if (ofOldView) scatterColour(px);
}

// The two are compiled apart (BLOCK 0 and 1): under llvmpipe a branch on u_block made the point
// per pixel 1.7x slower.
void main() {
#if BLOCK
    ivec2 origin = ivec2(gl_GlobalInvocationID.xy) * u_block;
    if (any(greaterThanEqual(origin, u_size))) return;
    scatterBlock(origin);
#else
    ivec2 px = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(px, u_size))) return;
    scatterPixel(px);
#endif
}
