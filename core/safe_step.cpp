#include "core/safe_step.hpp"

#include <algorithm>
#include <cmath>

namespace fraktal {

double safeStepFactor(double worstRatio, double margin) {
    if (!(worstRatio > 0.0) || !std::isfinite(worstRatio)) return worstRatio > 0.0 ? kMinStepFactor : 1.0;
    return std::clamp(std::floor(1000.0 * margin / worstRatio) / 1000.0, kMinStepFactor, kMaxStepFactor);
}

SafeStepRays sampleSafeStepRays(FormulaSampler& sampler, const Camera& camera, const SafeStepOptions& options) {
    RaySamples all;
    std::vector<double> ratios;
    double worst = 0.0;
    int quiet = 0;  // rounds in a row that did not raise the worst
    for (int round = 0; round < std::max(1, options.maxRounds); ++round) {
        ConservativenessOptions o = options.rays;
        o.seed = options.rays.seed + uint64_t(round);
        const RaySamples more = sampleRays(sampler, camera, o);
        const std::vector<double> moreRatios = ratiosAt(sampler, more);
        double roundWorst = 0.0;
        for (double r : moreRatios) roundWorst = std::max(roundWorst, r);
        all.rays += more.rays;
        all.raysHit += more.raysHit;
        all.points.insert(all.points.end(), more.points.begin(), more.points.end());
        all.distances.insert(all.distances.end(), more.distances.begin(), more.distances.end());
        ratios.insert(ratios.end(), moreRatios.begin(), moreRatios.end());
        const bool raised = !(roundWorst <= worst * (1.0 + options.settled));
        worst = std::max(worst, roundWorst);
        quiet = raised ? 0 : quiet + 1;
        // Nothing measured yet (no hit): more rounds of the same camera will not find the object.
        if (all.points.empty() || quiet >= options.settledRounds || !std::isfinite(worst)) break;
    }
    ConservativenessReport report = reportOf(all, std::move(ratios));
    return {std::move(all), report};
}

double SafeStepOptions::factorFor(double worstRatio, const BlockDesc& estimator, const std::vector<Node>& steps) const {
    const double measured = safeStepFactor(worstRatio, marginFor(steps));
    if (!proven(estimator, steps)) return measured;
    return std::max(measured, std::min(safeStepFactor(worstRatio, boundMargin), 1.0));
}

bool hasSafeStepFactor(double worstRatio, double margin) {
    return std::isfinite(worstRatio) && worstRatio * kMinStepFactor <= margin;
}

namespace {

// The report as if the formula's deFactor were 1 (the sampler applies its own).
ConservativenessReport atUnitFactor(ConservativenessReport r, double deFactor) {
    r.worstRatio /= deFactor;
    r.medianRatio /= deFactor;
    return r;
}

// `estimator` closing the steps of `f`, measured at factor 1.
EstimatorMeasurement measured(const Formula& f, const Node& estimator, const ConservativenessReport& atUnit,
                              const SafeStepOptions& options) {
    EstimatorMeasurement m{estimator, atUnit, 1.0, options.marginFor(f.nodes)};
    m.factor = atUnit.samples > 0 ? options.factorFor(atUnit.worstRatio, *estimator.block, f.nodes) : 1.0;
    return m;
}

}  // namespace

EstimatorMeasurement measureSafeStep(FormulaSampler& sampler, const Camera& camera, const SafeStepOptions& options) {
    const Formula& f = sampler.formula();
    const ConservativenessReport r = sampleSafeStepRays(sampler, camera, options).report;
    return measured(f, f.estimator, atUnitFactor(r, f.deFactor), options);
}

EstimatorMeasurement measureSafeStep(const Formula& f, const Camera& camera, const SafeStepOptions& options) {
    CpuSampler s(f);
    return measureSafeStep(s, camera, options);
}

Node linearEstimator() { return Node::make(*findBlock("escape_linear")); }

std::vector<EstimatorMeasurement> compareEstimators(const Formula& f, const Camera& camera,
                                                    const SafeStepOptions& options) {
    CpuSampler s(f);
    return compareEstimators(f, sampleSafeStepRays(s, camera, options), options);
}

std::vector<EstimatorMeasurement> compareEstimators(const Formula& f, const SafeStepRays& rays,
                                                    const SafeStepOptions& options) {
    const RaySamples& samples = rays.samples;
    Formula unit = f;
    unit.deFactor = 1.0;
    // The rounds evaluated f's own estimate on these samples already.
    std::vector<EstimatorMeasurement> out{measured(f, f.estimator, atUnitFactor(rays.report, f.deFactor), options)};
    auto add = [&](const Node& estimator) {
        for (const EstimatorMeasurement& m : out)
            if (m.estimator.block == estimator.block && m.estimator.values == estimator.values) return;
        Formula g = unit;
        g.estimator = estimator;
        CpuSampler s(g);
        out.push_back(measured(f, estimator, compareWithSamples(s, samples), options));
    };
    if (f.estimator.block->membership == Membership::EscapeTime) {
        add(linearEstimator());
        add(Node::make(*findBlock("escape_log")));
        add(Node::make(*findBlock("escape_potential")));
    }
    // The gradient twins of the estimators measured so far, with their parameters.
    for (size_t i = 0, measuredSoFar = out.size(); i < measuredSoFar; ++i)
        for (const BlockDesc& twin : allBlocks())
            if (twin.gradientOf == out[i].estimator.block->id) {
                Node g = Node::make(twin);
                g.values = out[i].estimator.values;
                add(g);
                if (out.back().estimator.block == &twin && out.back().report.worstRatio > options.gradientWorst)
                    out.pop_back();
            }
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
