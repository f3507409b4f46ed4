#include "core/render/denoise.hpp"

#include <algorithm>
#include <cmath>

namespace fraktal {

void denoisePathImage(PathImage& image, const DenoiseSettings& s) {
    const int w = image.width, h = image.height;
    constexpr float kFloor = 0.02f;  // albedo below this is not divided out (black stays black)
    std::vector<float> illumination(size_t(w) * h * 3);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 3; ++c)
                illumination[(size_t(y) * w + x) * 3 + c] =
                    image.at(kBeauty, x, y)[c] / std::max(image.at(kAlbedo, x, y)[c], kFloor);
    std::vector<float> out = illumination;
    const double is2 = 1.0 / (2.0 * s.sigmaSpace * s.sigmaSpace), in2 = 1.0 / (2.0 * s.sigmaNormal * s.sigmaNormal),
                 ia2 = 1.0 / (2.0 * s.sigmaAlbedo * s.sigmaAlbedo), id2 = 1.0 / (2.0 * s.sigmaDepth * s.sigmaDepth);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const float* n0 = image.at(kNormal, x, y);
            const float* a0 = image.at(kAlbedo, x, y);
            const float cover0 = image.at(kBeauty, x, y)[3];
            if (cover0 <= 0.0f) continue;  // background: nothing to smooth
            double sum[3] = {0, 0, 0}, weights = 0.0;
            for (int dy = -s.radius; dy <= s.radius; ++dy)
                for (int dx = -s.radius; dx <= s.radius; ++dx) {
                    const int xx = x + dx, yy = y + dy;
                    if (xx < 0 || yy < 0 || xx >= w || yy >= h) continue;
                    if (image.at(kBeauty, xx, yy)[3] <= 0.0f) continue;
                    const float* n1 = image.at(kNormal, xx, yy);
                    const float* a1 = image.at(kAlbedo, xx, yy);
                    double dn = 0.0, da = 0.0;
                    for (int c = 0; c < 3; ++c) {
                        dn += (n1[c] - n0[c]) * (n1[c] - n0[c]);
                        da += (a1[c] - a0[c]) * (a1[c] - a0[c]);
                    }
                    const double z0 = n0[3], z1 = n1[3];
                    const double dz = z0 < 1e29 && z1 < 1e29 ? (z1 - z0) / std::max(z0, 1e-9) : 0.0;
                    const double wgt = std::exp(-(dx * dx + dy * dy) * is2 - dn * in2 - da * ia2 - dz * dz * id2);
                    for (int c = 0; c < 3; ++c) sum[c] += wgt * illumination[(size_t(yy) * w + xx) * 3 + c];
                    weights += wgt;
                }
            for (int c = 0; c < 3; ++c) out[(size_t(y) * w + x) * 3 + c] = float(sum[c] / weights);
        }
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            if (image.at(kBeauty, x, y)[3] <= 0.0f) continue;
            for (int c = 0; c < 3; ++c)
                image.at(kBeauty, x, y)[c] =
                    out[(size_t(y) * w + x) * 3 + c] * std::max(image.at(kAlbedo, x, y)[c], kFloor);
        }
}

}  // namespace fraktal
