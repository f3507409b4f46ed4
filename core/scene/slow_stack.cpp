#include "core/scene/slow_stack.hpp"

#include <cstdio>

#include "core/scene/formula_fit.hpp"

namespace fraktal {

namespace {

std::string formatted(const char* format, auto... values) {
    char buffer[512];
    std::snprintf(buffer, sizeof buffer, format, values...);
    return buffer;
}

// A speed ratio in words: "3.2x"; "over 1000x" where the slower estimate is next to nothing.
std::string times(double ratio) { return ratio >= 1000.0 ? "over 1000x" : formatted("%.1fx", ratio); }

}  // namespace

std::optional<Formula> fittedAndMeasured(const Formula& f, const Camera& camera, const SafeStepOptions& options,
                                         EstimatorMeasurement* best) {
    if (!f.cpuEvaluable()) return std::nullopt;
    Formula fitted = f;
    fitEstimatorToBlocks(fitted);
    const std::vector<EstimatorMeasurement> measured = compareEstimators(fitted, camera, options);
    const EstimatorMeasurement& first = measured.front();
    if (first.report.samples == 0 || !first.hasFactor) return std::nullopt;
    fitted.estimator = first.estimator;
    fitted.deFactor = first.factor;
    if (best) *best = first;
    return fitted;
}

SlowStack explainSlowStack(const Formula& f, const Camera& camera, const SafeStepOptions& options,
                           std::optional<EstimatorMeasurement> current) {
    SlowStack s;
    s.current = current ? *current : measureSafeStep(f, camera, options);
    EstimatorMeasurement best;
    if (std::optional<Formula> fitted = fittedAndMeasured(f, camera, options, &best);
        fitted && best.speed() > kFasterBy * s.speed()) {
        s.faster = std::move(fitted);
        s.fasterSpeed = best.speed();
    }
    // The block: each enabled step taken out in turn from the faster stack (the cause that is
    // left once the estimator suits the blocks), its estimator fitted again.
    const Formula& base = s.faster ? *s.faster : f;
    const double baseSpeed = s.faster ? s.fasterSpeed : s.speed();
    s.blockBaseSpeed = baseSpeed;
    int enabled = 0;
    for (const Node& n : base.nodes) enabled += n.enabled;
    for (size_t k = 0; k < base.nodes.size() && enabled > 1; ++k) {
        if (!base.nodes[k].enabled) continue;
        Formula without = base;
        without.nodes[k].enabled = false;
        if (!canBoundEscape(without.nodes)) continue;
        EstimatorMeasurement m;
        if (!fittedAndMeasured(without, camera, options, &m)) continue;
        if (m.speed() > s.speedWithout) {
            s.speedWithout = m.speed();
            s.block = int(k);
        }
    }
    if (!(s.speedWithout > kFasterBy * baseSpeed)) {
        s.block = -1;
        s.speedWithout = 0.0;
        // What the declarations say, where no removal leaves a stack to measure: a jump first,
        // then a stretch that grows with |p|.
        for (size_t k = 0; k < base.nodes.size() && s.block < 0; ++k)
            if (jumps(base.nodes[k])) s.block = int(k);
        for (size_t k = 0; k < base.nodes.size() && s.block < 0; ++k)
            if (base.nodes[k].enabled && base.nodes[k].block->stretchGrowsWithRadius) s.block = int(k);
    }
    return s;
}

std::string SlowStack::text(const Formula& f) const {
    std::string out;
    if (current.report.samples == 0)
        out = "No ray reached the object from outside, so the estimate could not be measured.";
    else if (!current.hasFactor)
        out = formatted("The estimate overshoots the distance %.3gx: no step factor keeps it safe.",
                        current.report.worstRatio);
    else
        out = formatted("Step factor %.3f x median estimate / distance %.3f: a step covers %s of the gap%s.",
                        current.factor, current.report.medianRatio,
                        speed() < 1e-4 ? "next to none" : formatted("%.2g%%", 100.0 * speed()).c_str(),
                        uselessSpeed(current) ? ", so rays crawl or stop at once (the estimate is useless)" : "");
    if (faster) {
        out += formatted(" Estimator %s", std::string(faster->estimator.block->id).c_str());
        if (faster->bailout != f.bailout) out += formatted(" at bailout %g", faster->bailout);
        out += speed() > 0.0
                   ? " marches " + times(fasterSpeed / speed()) + formatted(" faster (factor %.3f).", faster->deFactor)
                   : formatted(" has a safe factor (%.3f).", faster->deFactor);
    }
    if (block >= 0) {
        const Node& n = f.nodes[size_t(block)];
        out += formatted(" %slock %d (%s) keeps the estimate loose", faster ? "With it, b" : "B", block + 1,
                         std::string(n.block->id).c_str());
        if (jumps(n))
            out += ": " + std::string(n.block->jump);
        else if (n.block->stretchGrowsWithRadius)
            out +=
                ": its stretch grows with the distance from its axis, and the running derivative takes it at "
                "every iteration";
        if (speedWithout > 0.0 && blockBaseSpeed > 0.0)
            out += " (without it the stack marches " + times(speedWithout / blockBaseSpeed) + " faster)";
        out += ".";
    }
    return out;
}

}  // namespace fraktal
