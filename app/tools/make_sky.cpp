// Writes a procedural sky with a sun as a small equirectangular half-float OpenEXR (linear
// Rec.709): the environment map presets/env/sky.exr is made by this, no downloaded asset.
// Usage: fraktal_make_sky OUT.exr [WIDTH HEIGHT]
// The sky is a zenith-to-horizon gradient with a Rayleigh-like blue overhead, a brighter hazy
// horizon, a dim ground, and a sun disc of 2 degrees radius at elevation 35 degrees (larger than
// the real 0.27 so that a 256-wide map resolves it) whose radiance gives about 6x the sky's
// irradiance on a surface facing it.
#include <ImfRgbaFile.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

int main(int argc, char** argv) {
    if (argc != 2 && argc != 4) {
        std::fprintf(stderr, "usage: %s OUT.exr [WIDTH HEIGHT]\n", argv[0]);
        return 2;
    }
    const int w = argc == 4 ? std::atoi(argv[2]) : 256, h = argc == 4 ? std::atoi(argv[3]) : 128;
    if (w < 8 || h < 4 || w > 16384 || h > 8192) {
        std::fprintf(stderr, "%s: WIDTH must be 8..16384 and HEIGHT 4..8192\n", argv[0]);
        return 2;
    }
    const double pi = 3.14159265358979323846;
    const double sunElevation = 35.0 * pi / 180.0, sunAzimuth = 0.6, sunRadius = 2.0 * pi / 180.0;
    // The same equirectangular convention as core/image/environment.cpp (u = 0.5 looks down -z).
    auto direction = [&](double u, double v, double d[3]) {
        const double phi = (u - 0.5) * 2.0 * pi, theta = v * pi;
        d[0] = std::sin(theta) * std::sin(phi);
        d[1] = std::cos(theta);
        d[2] = -std::sin(theta) * std::cos(phi);
    };
    const double sun[3] = {std::cos(sunElevation) * std::sin(sunAzimuth), std::sin(sunElevation),
                           -std::cos(sunElevation) * std::cos(sunAzimuth)};
    const double sunSolidAngle = 2.0 * pi * (1.0 - std::cos(sunRadius));
    const double sunRadiance = 6.0 / sunSolidAngle;  // irradiance 6 at normal incidence
    std::vector<Imf::Rgba> pixels(size_t(w) * h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            double d[3];
            direction((x + 0.5) / w, (y + 0.5) / h, d);
            double r, g, b;
            if (d[1] >= 0.0) {
                const double k = std::pow(1.0 - d[1], 4.0);  // haze toward the horizon
                r = 0.25 + 0.75 * k;
                g = 0.45 + 0.55 * k;
                b = 1.0;
            } else {
                const double k = std::exp(8.0 * d[1]);
                r = 0.12 + 0.5 * k;
                g = 0.10 + 0.55 * k;
                b = 0.08 + 0.6 * k;
            }
            const double cosToSun = d[0] * sun[0] + d[1] * sun[1] + d[2] * sun[2];
            if (cosToSun > std::cos(sunRadius)) {
                r += sunRadiance * 1.0;
                g += sunRadiance * 0.95;
                b += sunRadiance * 0.85;
            }
            pixels[size_t(y) * w + x] = Imf::Rgba(half(float(r)), half(float(g)), half(float(b)), half(1.0f));
        }
    const std::string out = argv[1], tmp = out + ".tmp";
    try {
        Imf::RgbaOutputFile file(tmp.c_str(), w, h, Imf::WRITE_RGBA);
        file.setFrameBuffer(pixels.data(), 1, w);
        file.writePixels(h);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s: cannot write '%s': %s\n", argv[0], out.c_str(), e.what());
        std::remove(tmp.c_str());
        return 1;
    }
    if (std::rename(tmp.c_str(), out.c_str()) != 0) {
        std::fprintf(stderr, "%s: cannot rename '%s' to '%s'\n", argv[0], tmp.c_str(), out.c_str());
        return 1;
    }
    return 0;
}
