#include "app/editor/document/slow_stack.hpp"

#include <cstdio>

#include "core/scene/formula_fit.hpp"

namespace fraktal::editor {

bool SlowStackAdvice::update(const Formula& f, const Camera& camera, const AutoStepFactor& a) {
    bool changed = false;
    if (pending.valid() && pending.wait_for(std::chrono::seconds(0)) == std::future_status::ready) {
        std::future<SlowStack> ended = std::move(pending);
        worker = {};
        try {
            shown = ended.get();
            text = shown->text(f);
        } catch (const std::exception& e) {
            text = std::string("Could not measure why: ") + e.what();
        }
        changed = true;
    }
    // A new structure's settled rounds still run: its figures are the previous structure's.
    if (a.measuring()) return changed;
    char factor[32];
    std::snprintf(factor, sizeof factor, "@%.6g", a.measured);
    const std::string measurement = a.measuredKey + factor;
    if (measurement == key) return changed;
    key = measurement;
    worker = {};  // stops a measurement of the previous one
    pending = {};
    shown.reset();
    text.clear();
    const bool slow = a.noSafeFactor || (a.measured > 0.0 && (a.measured < kExplainFactor || a.speed < kUselessSpeed));
    if (!slow || a.noHits || !f.cpuEvaluable()) return true;
    std::promise<SlowStack> result;
    pending = result.get_future();
    worker = std::jthread([f, camera, result = std::move(result)](std::stop_token stop) mutable {
        yieldToRendering();
        SafeStepOptions options = AutoStepFactor::options();
        options.stop = stop;
        try {
            result.set_value(explainSlowStack(f, camera, options));
        } catch (...) {
            result.set_exception(std::current_exception());
        }
    });
    return true;
}

bool applyFasterEstimator(Preset& p, AutoStepFactor& stepFactor, const SlowStack& advice) {
    if (!advice.faster) return false;
    const Formula& faster = *advice.faster;
    if (p.formula.estimator.block != faster.estimator.block && !setEstimator(p, *faster.estimator.block)) return false;
    p.formula.estimator.values = faster.estimator.values;
    p.formula.bailout = faster.bailout;
    p.formula.deFactor = faster.deFactor;
    // Measured again on the worker from the next frame (the same settled rounds that gave the
    // advice its factor, then the check's further rounds), as after any structure change.
    stepFactor.overridden = false;
    stepFactor.measuredKey.clear();
    return true;
}

}  // namespace fraktal::editor
