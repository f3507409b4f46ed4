// 2D renderer throughput, side by side in one run (bench/plane/run.sh builds and runs it): per
// 2D preset, the GL renderer (core/plane/plane_renderer.hpp) in double and in single precision
// over a whole image, and the double-precision CPU evaluation (fraktal::evaluatePlane, one
// thread, the reference the tests compare against) over a smaller one, with the iterations a
// sample runs. Prints one Markdown table row per preset.
// Usage: plane_bench WxH SPP CPU_WxH PRESET...
#include <chrono>
#include <cstdio>
#include <string>

#include "core/gl/context.hpp"
#include "core/plane/plane_preset.hpp"
#include "core/plane/plane_renderer.hpp"

using namespace fraktal;
using Clock = std::chrono::steady_clock;

namespace {

double secondsSince(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// The whole image in 512-pixel tiles, `spp` samples each, read back (so the GPU has finished).
double glSeconds(const PlanePreset& p, int width, int height, int spp, PlanePrecision precision, bool& usedDouble) {
    PlaneRenderer renderer;
    renderer.prepare(p.formula, precision);
    usedDouble = renderer.usesDouble();
    PlaneTarget target;
    // Warm-up: the first dispatch of a program pays llvmpipe's shader compilation.
    renderer.render(p.formula, p.colouring, p.view, PlaneTile{width, height, 0, 0, 16, 16}, target, 0, 1, false);
    readPlaneTarget(target);
    // The best of three runs: the machine is shared, the minimum is the least disturbed.
    const int tile = 512;
    double best = 1e30;
    for (int run = 0; run < 3; ++run) {
        const auto start = Clock::now();
        for (int y0 = 0; y0 < height; y0 += tile)
            for (int x0 = 0; x0 < width; x0 += tile) {
                const PlaneTile t{width, height, x0, y0, std::min(tile, width - x0), std::min(tile, height - y0)};
                renderer.render(p.formula, p.colouring, p.view, t, target, 0, spp, false);
                readPlaneTarget(target);
            }
        best = std::min(best, secondsSince(start));
    }
    return best;
}

struct CpuRun {
    double seconds = 0.0;
    double meanIterations = 0.0;
};

// One sample (the pixel centre) per pixel of a width x height image of the same view.
CpuRun cpuReference(const PlanePreset& p, int width, int height) {
    CpuRun r;
    double iterations = 0.0;
    const auto start = Clock::now();
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            iterations +=
                evaluatePlane(p.formula, planePixelPosition(p.view, width, height, x, y, planeSampleOffset(0)))
                    .iterations;
    r.seconds = secondsSince(start);
    r.meanIterations = iterations / (double(width) * height);
    return r;
}

bool parseSize(const char* text, int& w, int& h) { return std::sscanf(text, "%dx%d", &w, &h) == 2 && w > 0 && h > 0; }

}  // namespace

int main(int argc, char** argv) {
    int width = 0, height = 0, cpuWidth = 0, cpuHeight = 0;
    if (argc < 5 || !parseSize(argv[1], width, height) || !parseSize(argv[3], cpuWidth, cpuHeight)) {
        std::fprintf(stderr, "usage: plane_bench WxH SPP CPU_WxH PRESET...\n");
        return 2;
    }
    const int spp = std::atoi(argv[2]);
    auto context = gl::HeadlessContext::create();
    std::printf("GL: %s; GL image %dx%d at %d spp; CPU reference %dx%d at 1 spp, one thread\n\n",
                context->renderer().c_str(), width, height, spp, cpuWidth, cpuHeight);
    std::printf(
        "| preset | iterations / sample | GL fp64 ms | GL fp64 Msamples/s | GL fp32 ms | GL fp32 Msamples/s | "
        "fp32 / fp64 | CPU Msamples/s | GL fp64 / CPU |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|\n");
    for (int i = 4; i < argc; ++i) {
        const PlanePreset p = loadPlanePreset(argv[i]);
        const double samples = double(width) * height * spp;
        bool usedDouble = false, ignored = false;
        const double fp64 = glSeconds(p, width, height, spp, PlanePrecision::Double, usedDouble);
        const double fp32 = glSeconds(p, width, height, spp, PlanePrecision::Float, ignored);
        const CpuRun cpu = cpuReference(p, cpuWidth, cpuHeight);
        const double glRate = samples / fp64 / 1e6, floatRate = samples / fp32 / 1e6;
        const double cpuRate = double(cpuWidth) * cpuHeight / cpu.seconds / 1e6;
        const std::string name = std::filesystem::path(argv[i]).stem().string();
        std::printf("| %s | %.1f | %.0f%s | %.2f | %.0f | %.2f | %.2fx | %.2f | %.2fx |\n", name.c_str(),
                    cpu.meanIterations, fp64 * 1e3, usedDouble ? "" : " (no fp64)", glRate, fp32 * 1e3, floatRate,
                    floatRate / glRate, cpuRate, glRate / cpuRate);
        std::fflush(stdout);
    }
    return 0;
}
