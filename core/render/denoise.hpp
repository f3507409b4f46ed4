// Denoising of a path-traced still, guided by its albedo and normal passes: a joint (cross)
// bilateral filter (Eisemann and Durand 2004; Petschnigg et al. 2004) over the beauty's
// illumination. Debian ships no Intel Open Image Denoise, so the filter is written here. The
// albedo is divided out first and multiplied back after filtering, so texture (orbit-trap
// colour) stays sharp while the lighting noise is smoothed; neighbours weigh less the more
// their normal, albedo or depth differs, so edges and silhouettes stay sharp too.
#pragma once

#include "core/image/path_image.hpp"

namespace fraktal {

struct DenoiseSettings {
    int radius = 6;            // pixels
    double sigmaSpace = 3.0;   // pixels
    double sigmaNormal = 0.2;  // in |n1 - n2|
    double sigmaAlbedo = 0.1;  // in |a1 - a2|
    double sigmaDepth = 0.02;  // relative depth difference
};

// Filters image.passes[kBeauty] in place (alpha kept); the passes themselves are left as they are.
void denoisePathImage(PathImage& image, const DenoiseSettings& settings = {});

}  // namespace fraktal
