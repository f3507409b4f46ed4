#include "core/safe_step.hpp"

#include <algorithm>
#include <cmath>

namespace fraktal {

double safeStepFactor(double worstRatio, double margin) {
    if (!(worstRatio > 0.0) || !std::isfinite(worstRatio)) return worstRatio > 0.0 ? kMinStepFactor : 1.0;
    return std::clamp(std::floor(1000.0 * margin / worstRatio) / 1000.0, kMinStepFactor, kMaxStepFactor);
}

namespace {

// The report as if the formula's deFactor were 1 (the sampler applies its own).
ConservativenessReport atUnitFactor(ConservativenessReport r, double deFactor) {
    r.worstRatio /= deFactor;
    r.medianRatio /= deFactor;
    return r;
}

EstimatorMeasurement measured(const Node& estimator, const ConservativenessReport& atUnit,
                              const SafeStepOptions& options) {
    EstimatorMeasurement m{estimator, atUnit, 1.0};
    m.factor = atUnit.samples > 0 ? safeStepFactor(atUnit.worstRatio, options.marginFor(estimator)) : 1.0;
    return m;
}

}  // namespace

EstimatorMeasurement measureSafeStep(FormulaSampler& sampler, const Camera& camera, const SafeStepOptions& options) {
    const Formula& f = sampler.formula();
    const ConservativenessReport r = checkConservativeness(sampler, camera, options.rays);
    return measured(f.estimator, atUnitFactor(r, f.deFactor), options);
}

EstimatorMeasurement measureSafeStep(const Formula& f, const Camera& camera, const SafeStepOptions& options) {
    CpuSampler s(f);
    return measureSafeStep(s, camera, options);
}

Node linearEstimator() { return Node::make(*findBlock("escape_linear")); }

std::vector<EstimatorMeasurement> compareEstimators(const Formula& f, const Camera& camera,
                                                    const SafeStepOptions& options) {
    CpuSampler s(f);
    return compareEstimators(f, sampleRays(s, camera, options.rays), options);
}

std::vector<EstimatorMeasurement> compareEstimators(const Formula& f, const RaySamples& samples,
                                                    const SafeStepOptions& options) {
    Formula unit = f;
    unit.deFactor = 1.0;
    CpuSampler own(unit);
    std::vector<EstimatorMeasurement> out{measured(f.estimator, compareWithSamples(own, samples), options)};
    if (f.estimator.block->membership != Membership::EscapeTime) return out;

    auto add = [&](const Node& estimator) {
        for (const EstimatorMeasurement& m : out)
            if (m.estimator.block == estimator.block && m.estimator.values == estimator.values) return;
        Formula g = unit;
        g.estimator = estimator;
        CpuSampler s(g);
        out.push_back(measured(estimator, compareWithSamples(s, samples), options));
    };
    add(linearEstimator());
    add(Node::make(*findBlock("escape_log")));
    std::stable_sort(out.begin(), out.end(), [](const EstimatorMeasurement& a, const EstimatorMeasurement& b) {
        return a.speed() > b.speed();
    });
    return out;
}

Formula withSafeEstimator(const Formula& f, const Camera& camera, const SafeStepOptions& options) {
    const EstimatorMeasurement best = compareEstimators(f, camera, options).front();
    Formula g = f;
    g.estimator = best.estimator;
    g.deFactor = best.factor;
    return g;
}

}  // namespace fraktal
