// `fraktal check PRESET`: load a preset, print its formula, evaluate the DE on a grid and
// against the seed's baseline marcher, and say whether marching it is safe.
#include <cmath>
#include <cstdio>
#include <memory>

#include "cli/commands.hpp"
#include "core/de_check.hpp"
#include "core/gl/context.hpp"
#include "core/gl/de_probe.hpp"
#include "core/preset.hpp"

namespace fraktal::cli {

namespace {

struct CheckOptions {
    std::string preset;
    int grid = 24;
    int rays = 120;
    uint64_t seed = 1;
};

// Compiles the formula's GLSL on the GL driver and compares it with the CPU at random points.
// Returns false on a compile error; a missing GL context is reported but is not the preset's fault.
bool checkGlsl(const Formula& f, uint64_t seed) {
    std::unique_ptr<gl::HeadlessContext> context;
    try {
        context = gl::HeadlessContext::create();
    } catch (const std::exception& e) {
        std::printf("GLSL: not checked (%s)\n", e.what());
        return true;
    }
    try {
        gl::DEProbe probe(f);
        std::vector<vec3> points(2000);
        uint64_t state = seed * 6364136223846793005ull + 1442695040888963407ull;
        auto next = [&] {
            state = state * 6364136223846793005ull + 1442695040888963407ull;
            return double(state >> 11) / double(1ull << 53) * 2.0 - 1.0;
        };
        for (vec3& p : points) p = vec3(next(), next(), next()) * f.boundRadius;
        const auto gpu = probe.evaluate(f, points);
        size_t agree = 0;
        for (size_t i = 0; i < points.size(); ++i) {
            const double cpu = distanceEstimate(f, points[i]);
            agree += std::abs(gpu[i].distance - cpu) <= 1e-4 * std::max(std::abs(cpu), 0.1);
        }
        // Points that disagree sit where the orbit's escape iteration flips under rounding.
        std::printf("GLSL: compiles on %s; GPU (float) and CPU (double) agree within 1e-4 at %zu of %zu points\n",
                    context->renderer().c_str(), agree, points.size());
        return true;
    } catch (const std::exception& e) {
        std::printf("PROBLEM: %s\n", e.what());
        return false;
    }
}

int runCheck(const CheckOptions& o) {
    const Preset preset = loadPreset(o.preset);
    std::printf("%s: %s\n", o.preset.c_str(), preset.name.empty() ? "(unnamed)" : preset.name.c_str());
    std::printf("formula: %s", describeFormula(preset.formula).c_str());

    const GridReport g = evaluateGrid(preset.formula, o.grid);
    std::printf("grid %d^3 over the bound: DE in [%.6g, %.6g], %.1f%% inside, %ld non-finite, %.2f us per DE\n", o.grid,
                g.minDistance, g.maxDistance, 100.0 * double(g.inside) / double(g.points), g.nonFinite,
                g.secondsPerEvaluation * 1e6);

    ConservativenessOptions co;
    co.rays = o.rays;
    co.seed = o.seed;
    const ConservativenessReport c = checkConservativeness(preset.formula, preset.camera, co);
    std::printf("baseline marcher: %d rays, %d hit, %ld samples; worst DE / true distance = %.4f at (%.4f, %.4f, %.4f)\n",
                c.rays, c.raysHit, c.samples, c.worstRatio, c.worstPoint.x, c.worstPoint.y, c.worstPoint.z);

    int status = checkGlsl(preset.formula, o.seed) ? 0 : 1;
    if (g.nonFinite > 0) {
        std::printf("PROBLEM: the DE is not finite at %ld grid points\n", g.nonFinite);
        status = 1;
    }
    if (c.raysHit == 0) {
        std::printf("PROBLEM: no ray hit the fractal: check the camera and formula.boundRadius\n");
        status = 1;
    }
    if (c.conservative()) {
        std::printf("conservative: the DE never overshoots by more than 1%%; step multiplier 1 is safe\n");
    } else {
        std::printf("PROBLEM: the DE overshoots by up to %.1f%%: multiply formula.deFactor by %.3f (or less) "
                    "to make marching safe\n",
                    100.0 * (c.worstRatio - 1.0), 0.99 * c.safeStepMultiplier());
        status = 1;
    }
    std::printf(status == 0 ? "OK\n" : "NOT SOUND\n");
    return status;
}

}  // namespace

void addCheckCommand(CLI::App& app, Action& action) {
    auto o = std::make_shared<CheckOptions>();
    CLI::App* cmd = app.add_subcommand("check", "Validate a preset and measure its distance estimator");
    cmd->add_option("preset", o->preset, "Preset file (JSON)")->required();
    cmd->add_option("--grid", o->grid, "Grid points per axis for the DE survey")->check(CLI::Range(2, 256));
    cmd->add_option("--rays", o->rays, "Rays for the conservativeness check")->check(CLI::Range(1, 100000));
    cmd->add_option("--seed", o->seed, "Random seed");
    cmd->callback([&action, o] { action = [o] { return runCheck(*o); }; });
}

}  // namespace fraktal::cli
