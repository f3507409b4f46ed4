// What the path tracer produces per pixel (CPU reference and GL alike): the beauty image and the
// passes a compositor expects, as sample means. beauty = background + emission + diffuse_direct +
// diffuse_indirect + specular (the background, seen by camera rays that miss, is in no pass).
#pragma once

#include <array>
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

}  // namespace fraktal
