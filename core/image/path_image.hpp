// What the path tracer produces per pixel (CPU reference and GL alike): the beauty image and the
// passes a compositor expects, as sample means. beauty = background + emission + diffuse_direct +
// diffuse_indirect + specular (the background, seen by camera rays that miss, is in no pass).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace fraktal {

enum PathPass { kBeauty, kDiffuseDirect, kDiffuseIndirect, kSpecular, kEmission, kAlbedo, kNormal, kPassCount };

// EXR layer names of the passes after the beauty (R G B A): <name>.R/G/B, and N.x/y/z.
inline constexpr std::array<const char*, kPassCount> kPathPassNames = {
    "", "diffuse_direct", "diffuse_indirect", "specular", "emission", "albedo", "N"};

struct PathImage {
    int width = 0, height = 0, spp = 0;
    // Four floats per pixel per pass, rows from the top. Beauty's fourth is coverage (alpha);
    // Normal's fourth is the in-focus depth (the distance along the lens-centre ray through the
    // pixel centre; 1e30 where it misses); the others' is unused.
    std::array<std::vector<float>, kPassCount> passes;

    void resize(int w, int h) {
        width = w;
        height = h;
        for (auto& p : passes) p.assign(size_t(w) * size_t(h) * 4, 0.0f);
    }
    float* at(int pass, int x, int y) { return &passes[pass][(size_t(y) * size_t(width) + size_t(x)) * 4]; }
    const float* at(int pass, int x, int y) const { return &passes[pass][(size_t(y) * size_t(width) + size_t(x)) * 4]; }
};

// PSNR in dB of a's beauty RGB against the reference's (peak: the reference's brightest value),
// the convergence measure of the tests and bench/stills/pathtrace.sh.
inline double meanImagePsnr(const PathImage& a, const PathImage& reference) {
    double sq = 0.0, peak = 0.0;
    size_t n = 0;
    for (size_t i = 0; i < reference.passes[kBeauty].size(); ++i) {
        if (i % 4 == 3) continue;
        const double d = a.passes[kBeauty][i] - reference.passes[kBeauty][i];
        sq += d * d;
        peak = std::max(peak, double(reference.passes[kBeauty][i]));
        ++n;
    }
    return 10.0 * std::log10(peak * peak / std::max(sq / double(std::max<size_t>(n, 1)), 1e-30));
}

}  // namespace fraktal
