// The path-traced still's denoiser (core/render/denoise.hpp), measured against the image it was
// given: on flat regions the noise drops by a clear factor with the level kept, and the edges that
// its guides see (a turn of the normal, a step in depth, a step in albedo) keep their 10-90 %
// width. The input is a synthetic path image whose noise is known, built as the path tracer's
// passes are: beauty = albedo x illumination, the normal pass with the depth in its fourth float.
#include "core/render/denoise.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <vector>

namespace fraktal {
namespace {

// 160 x 128 pixels, all covered. Left of x = 80 a face turned to the camera, right of it one
// turned by 45 degrees at the same depth (a corner: the normal turns, nothing else does), lit at
// 0.9 and 0.35. Above y = 56 the albedo is 0.8, below it 0.3 (a texture step under the same
// light). The right face's rows from y = 96 lie behind, at depth 6 instead of 4, in shadow (0.05):
// a step in depth alone, the normal the same.
constexpr int kW = 160, kH = 128, kCorner = 80, kTexture = 56, kStep = 96;
constexpr double kNoise = 0.35;  // relative standard deviation of the beauty, as at a few samples per pixel

struct Scene {
    PathImage noisy, clean;
};

Scene syntheticScene() {
    Scene s;
    s.noisy.resize(kW, kH);
    s.clean.resize(kW, kH);
    std::mt19937 rng(51);
    std::normal_distribution<double> gauss(0.0, 1.0);
    const double turned = std::sqrt(0.5);
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            const bool right = x >= kCorner, behind = right && y >= kStep;
            const double albedo = y < kTexture ? 0.8 : 0.3;
            const double light = behind ? 0.05 : right ? 0.35 : 0.9;
            const float normal[4] = {right ? float(turned) : 0.0f, 0.0f, right ? float(turned) : 1.0f,
                                     behind ? 6.0f : 4.0f};
            for (PathImage* image : {&s.noisy, &s.clean}) {
                for (int c = 0; c < 4; ++c) image->at(kNormal, x, y)[c] = normal[c];
                for (int c = 0; c < 3; ++c) image->at(kAlbedo, x, y)[c] = float(albedo);
                image->at(kBeauty, x, y)[3] = 1.0f;
            }
            for (int c = 0; c < 3; ++c) {
                s.clean.at(kBeauty, x, y)[c] = float(albedo * light);
                s.noisy.at(kBeauty, x, y)[c] = float(albedo * light * (1.0 + kNoise * gauss(rng)));
            }
        }
    return s;
}

double green(const PathImage& image, int x, int y) { return image.at(kBeauty, x, y)[1]; }

struct Window {
    int x0, y0, x1, y1;  // [x0, x1) x [y0, y1)
};

// Mean and variance of the green beauty over a window.
std::pair<double, double> meanAndVariance(const PathImage& image, const Window& w) {
    double sum = 0.0, sq = 0.0;
    const double n = double(w.x1 - w.x0) * double(w.y1 - w.y0);
    for (int y = w.y0; y < w.y1; ++y)
        for (int x = w.x0; x < w.x1; ++x) {
            sum += green(image, x, y);
            sq += green(image, x, y) * green(image, x, y);
        }
    const double mean = sum / n;
    return {mean, sq / n - mean * mean};
}

// The 10-90 % width in pixels of the step in `profile` between samples kEdge - 1 and kEdge, from
// the level `first` to the level `last` (the noise-free image's). Each crossing is the one nearest
// the edge (noise far from it crosses too), interpolated between the two samples it falls between:
// a one-pixel step reads 0.8 px.
constexpr int kEdge = 24;
double stepWidth(const std::vector<double>& profile, double first, double last) {
    auto crossing = [&](double level) {
        double best = -1e9;
        for (size_t i = 1; i < profile.size(); ++i) {
            const double a = (profile[i - 1] - first) / (last - first), b = (profile[i] - first) / (last - first);
            if ((a < level) == (b < level)) continue;
            const double at = double(i - 1) + (level - a) / (b - a);
            if (std::abs(at - (kEdge - 0.5)) < std::abs(best - (kEdge - 0.5))) best = at;
        }
        return best;
    };
    return crossing(0.9) - crossing(0.1);
}

// The profile across a step: `along` samples of the mean over `across` lines, from `at(i, j)`
// (i along the profile, j across it).
std::vector<double> profile(int along, int across, const std::function<double(int, int)>& at) {
    std::vector<double> out(size_t(along), 0.0);
    for (int i = 0; i < along; ++i)
        for (int j = 0; j < across; ++j) out[size_t(i)] += at(i, j) / across;
    return out;
}

TEST(Denoise, FlatRegionsLoseTheirNoiseAndKeepTheirLevel) {
    const Scene s = syntheticScene();
    PathImage denoised = s.noisy;
    denoisePathImage(denoised);
    // Each window lies more than the filter's radius (6 px) from every edge.
    const struct {
        const char* name;
        Window w;
    } flats[] = {{"front face, light texture", {8, 8, 72, 48}},
                 {"turned face, light texture", {88, 8, 152, 48}},
                 {"front face, dark texture", {8, 64, 72, 120}},
                 {"face behind, dark texture", {88, 104, 152, 124}}};
    for (const auto& flat : flats) {
        const auto [rawMean, rawVariance] = meanAndVariance(s.noisy, flat.w);
        const auto [mean, variance] = meanAndVariance(denoised, flat.w);
        const double level = meanAndVariance(s.clean, flat.w).first;
        std::printf("%s: variance %.3g raw, %.3g denoised (%.1fx less); mean %.4f raw, %.4f denoised, %.4f true\n",
                    flat.name, rawVariance, variance, rawVariance / variance, rawMean, mean, level);
        // A Gaussian of sigma 3 px averages about 4 pi 3^2 = 113 pixels: the variance drops about
        // a hundredfold where nothing stops the filter. Less than tenfold is no denoiser.
        EXPECT_GT(rawVariance / variance, 10.0) << flat.name;
        EXPECT_NEAR(mean, level, 0.02 * level) << flat.name << ": the denoiser moved the level";
    }
}

TEST(Denoise, EdgesItsGuidesSeeStaySharp) {
    const Scene s = syntheticScene();
    PathImage denoised = s.noisy;
    denoisePathImage(denoised);
    const struct {
        const char* name;
        std::function<std::vector<double>(const PathImage&)> profileOf;
    } edges[] = {
        // Each profile is 48 samples long with the edge in the middle, each sample the mean of
        // 40 to 64 lines more than the radius from any other edge.
        // The corner at x = 80, across x 56..103, over rows 8..47 (light texture).
        {"the normal's turn",
         [](const PathImage& im) { return profile(48, 40, [&](int i, int j) { return green(im, 56 + i, 8 + j); }); }},
        // The texture step at y = 56 on the front face, across y 32..79, over columns 8..71.
        {"the albedo's step",
         [](const PathImage& im) { return profile(48, 64, [&](int i, int j) { return green(im, 8 + j, 32 + i); }); }},
        // The step in depth at y = 96 on the turned face, across y 72..119, over columns 88..151.
        {"the depth's step",
         [](const PathImage& im) { return profile(48, 64, [&](int i, int j) { return green(im, 88 + j, 72 + i); }); }},
    };
    for (const auto& edge : edges) {
        const std::vector<double> clean = edge.profileOf(s.clean);
        const double first = clean.front(), last = clean.back();
        const double sharp = stepWidth(clean, first, last), raw = stepWidth(edge.profileOf(s.noisy), first, last),
                     width = stepWidth(edge.profileOf(denoised), first, last);
        std::printf("%s: 10-90 %% width %.2f px raw, %.2f px denoised (%.2f px without noise)\n", edge.name, raw, width,
                    sharp);
        ASSERT_GT(raw, 0.0) << edge.name;
        ASSERT_LT(raw, 2.0) << edge.name << ": the raw edge is not sharp, the test measures nothing";
        // A blur that ignored the guides would spread it over 2.56 sigma = 7.7 px.
        EXPECT_GT(width, 0.0) << edge.name;
        EXPECT_LT(width, raw + 1.0) << edge.name << ": the denoiser blurred the edge";
    }
}

}  // namespace
}  // namespace fraktal
