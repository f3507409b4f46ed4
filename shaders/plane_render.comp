// Renders a tile of a 2D fractal view: `u_sampleCount` samples per pixel (starting at sample
// `u_sampleBegin` of a low-discrepancy sequence, so that later passes refine earlier ones), summed
// into two images: colour (rgb sum, sample count) and AOVs (inside count, smooth-iteration sum and
// distance sum over outside samples, outside count). Scene-linear; display transforms come later.
// 8x8 work groups: 32x8 (which made the viewport's passes ~17 % faster) rendered the Mandelbrot
// and Sierpinski presets at 1920x1080 no faster on llvmpipe (6.9 s and 1.0 s either way).
layout(local_size_x = 8, local_size_y = 8) in;

layout(rgba32f, binding = 0) uniform image2D u_colour;
layout(rgba32f, binding = 1) uniform image2D u_aov;

uniform real2 u_center;     // view centre
uniform real u_pixelSize;   // view width / image width
uniform ivec2 u_imageSize;  // the whole image
uniform ivec2 u_tileOrigin; // first pixel of this tile, from the top left
uniform ivec2 u_tileSize;
uniform ivec2 u_storeOrigin;  // where the tile's first pixel lands in the images (0: tile-sized images)
uniform int u_sampleBegin;
uniform int u_sampleCount;
uniform bool u_accumulate;  // add to what the images hold

// Colouring (linear Rec.709 converted to the working space by the caller): cosine palette
// a + b cos(2 pi (c t + d)) (Inigo Quilez, "palettes") over t = frequency * smooth iterations +
// offset; distance-estimate shading darkens outside samples closer than `edgeWidth` pixels to the
// set, which keeps boundaries crisp at any zoom.
uniform vec3 u_paletteA, u_paletteB, u_paletteC, u_paletteD;
uniform float u_paletteFrequency, u_paletteOffset;
uniform vec3 u_interior;
uniform float u_edgeWidth;

// Sample k's offset inside the pixel: the R2 sequence (Martin Roberts, 2018), sample 0 at the
// centre. Twin of fraktal::planeSampleOffset.
vec2 planeSampleOffset(int k) { return fract(vec2(0.5) + float(k) * vec2(0.7548776662466927, 0.5698402909980532)); }

void main() {
    ivec2 local = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(local, u_tileSize))) return;
    ivec2 pixel = u_tileOrigin + local;
    vec4 colour = vec4(0.0);
    vec4 aov = vec4(0.0);
    for (int k = u_sampleBegin; k < u_sampleBegin + u_sampleCount; ++k) {
        vec2 o = planeSampleOffset(k);
        real2 pos = u_center + real2(real(pixel.x) + real(o.x) - real(0.5) * real(u_imageSize.x),
                                     real(0.5) * real(u_imageSize.y) - real(pixel.y) - real(o.y)) * u_pixelSize;
        int iterations;
        float smoothIterations;
        bool inside;
        float d = planeEval(pos, iterations, smoothIterations, inside);
        vec3 rgb = u_interior;
        if (inside) {
            aov.x += 1.0;
        } else {
            float t = u_paletteFrequency * smoothIterations + u_paletteOffset;
            rgb = max(u_paletteA + u_paletteB * cos(6.283185307 * (u_paletteC * t + u_paletteD)), vec3(0.0));
            float dPixels = d / float(u_pixelSize);
            if (u_edgeWidth > 0.0) rgb *= smoothstep(0.0, 1.0, clamp(dPixels / u_edgeWidth, 0.0, 1.0));
            aov += vec4(0.0, smoothIterations, d, 1.0);
        }
        colour += vec4(rgb, 1.0);
    }
    ivec2 store = u_storeOrigin + local;
    if (u_accumulate) {
        colour += imageLoad(u_colour, store);
        aov += imageLoad(u_aov, store);
    }
    imageStore(u_colour, store, colour);
    imageStore(u_aov, store, aov);
}
