#include "core/safe_step.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>

namespace fraktal {

double safeStepFactor(double worstRatio, double margin) {
    if (!(worstRatio > 0.0) || !std::isfinite(worstRatio)) return worstRatio > 0.0 ? kMinStepFactor : 1.0;
    return std::clamp(std::floor(1000.0 * margin / worstRatio) / 1000.0, kMinStepFactor, kMaxStepFactor);
}

SafeStepRays sampleSafeStepRays(FormulaSampler& sampler, const Camera& camera, const SafeStepOptions& options) {
    RaySamples all;
    std::vector<double> ratios;
    ConservativenessReport tail;  // the worst ratio and each ray's worst, for the tail's projection
    const Formula& f = sampler.formula();
    int quiet = 0;  // rounds in a row that did not raise the worst
    for (int round = 0; round < std::max({1, options.maxRounds, options.tailRounds}); ++round) {
        if (round > 0 && options.stop.stop_requested()) break;
        ConservativenessOptions o = options.rays;
        o.seed = options.rays.seed + uint64_t(round);
        const RaySamples more = sampleRays(sampler, camera, o);
        const std::vector<double> moreRatios = ratiosAt(sampler, more);
        const ConservativenessReport moreReport = reportOf(more, moreRatios);
        all.rays += more.rays;
        all.raysHit += more.raysHit;
        for (size_t end : more.rayEnds) all.rayEnds.push_back(all.points.size() + end);
        all.points.insert(all.points.end(), more.points.begin(), more.points.end());
        all.distances.insert(all.distances.end(), more.distances.begin(), more.distances.end());
        ratios.insert(ratios.end(), moreRatios.begin(), moreRatios.end());
        const bool raised = !(moreReport.worstRatio <= tail.worstRatio * (1.0 + options.settled));
        tail.worstRatio = std::max(tail.worstRatio, moreReport.worstRatio);
        tail.rayWorst.insert(tail.rayWorst.end(), moreReport.rayWorst.begin(), moreReport.rayWorst.end());
        std::sort(tail.rayWorst.begin(), tail.rayWorst.end(), std::greater<>());
        quiet = raised ? 0 : quiet + 1;
        // Nothing measured yet (no hit): more rounds of the same camera will not find the object.
        if (all.points.empty() || !std::isfinite(tail.worstRatio)) break;
        const bool settled = quiet >= options.settledRounds || round + 1 >= options.maxRounds;
        if (settled && (round + 1 >= options.tailRounds || options.tailCovered(tail, *f.estimator.block, f.nodes)))
            break;
    }
    ConservativenessReport report = reportOf(all, std::move(ratios));
    return {std::move(all), report};
}

double projectedWorst(const ConservativenessReport& report, double rays) {
    const std::vector<double>& y = report.rayWorst;  // largest first
    const size_t kMax = std::clamp<size_t>(y.size() / 5, 5, 100);
    if (y.size() < kMax + 2 || !(y[kMax] > 0.0)) return 2.0 * report.worstRatio;
    const double n = double(y.size());
    double projected = report.worstRatio, sumOfLogs = 0.0;
    for (size_t k = 1; k <= kMax; ++k) {
        sumOfLogs += std::log(y[k - 1]);
        if (k < 2) continue;
        const double hill = sumOfLogs / double(k) - std::log(y[k]);
        projected = std::max(projected, y[k] * std::pow(double(k) * rays / n, hill));
    }
    return projected;
}

ConservativenessReport atUnitFactor(ConservativenessReport r, double deFactor) {
    r.worstRatio /= deFactor;
    r.medianRatio /= deFactor;
    for (double& ratio : r.rayWorst) ratio /= deFactor;
    return r;
}

double SafeStepOptions::factorFor(const ConservativenessReport& atUnit, const BlockDesc& estimator,
                                  const std::vector<Node>& steps) const {
    const double measured = std::max(safeStepFactor(atUnit.worstRatio, marginFor(steps)),
                                     safeStepFactor(projectedWorst(atUnit, raysAhead), tailMargin));
    if (!proven(estimator, steps)) return measured;
    return std::max(measured, std::min(safeStepFactor(atUnit.worstRatio, boundMargin), 1.0));
}

bool SafeStepOptions::tailCovered(const ConservativenessReport& atUnit, const BlockDesc& estimator,
                                  const std::vector<Node>& steps) const {
    return proven(estimator, steps) || projectedWorst(atUnit, raysAhead) * marginFor(steps) <= atUnit.worstRatio;
}

bool SafeStepOptions::hasFactor(const ConservativenessReport& atUnit, const std::vector<Node>& steps) const {
    return hasSafeStepFactor(atUnit.worstRatio, marginFor(steps)) ||
           hasSafeStepFactor(projectedWorst(atUnit, raysAhead), tailMargin);
}

bool hasSafeStepFactor(double worstRatio, double margin) {
    return std::isfinite(worstRatio) && worstRatio * kMinStepFactor <= margin;
}

namespace {

// `estimator` closing the steps of `f`, measured at factor 1.
EstimatorMeasurement measured(const Formula& f, const Node& estimator, const ConservativenessReport& atUnit,
                              const SafeStepOptions& options) {
    EstimatorMeasurement m{estimator, atUnit, projectedWorst(atUnit, options.raysAhead)};
    m.factor = atUnit.samples > 0 ? options.factorFor(atUnit, *estimator.block, f.nodes) : 1.0;
    m.hasFactor = options.hasFactor(atUnit, f.nodes);
    return m;
}

}  // namespace

EstimatorMeasurement measureSafeStep(FormulaSampler& sampler, const Camera& camera, const SafeStepOptions& options) {
    return measureSafeStep(sampler.formula(), sampleSafeStepRays(sampler, camera, options), options);
}

EstimatorMeasurement measureSafeStep(const Formula& f, const SafeStepRays& rays, const SafeStepOptions& options) {
    return measured(f, f.estimator, atUnitFactor(rays.report, f.deFactor), options);
}

EstimatorMeasurement measureSafeStep(const Formula& f, const Camera& camera, const SafeStepOptions& options) {
    CpuSampler s(f);
    return measureSafeStep(s, camera, options);
}

std::string stepFactorTag(const Formula& f) {
    uint64_t hash = 0xcbf29ce484222325ull;  // FNV-1a, 64 bits
    for (const unsigned char c : f.structureKey()) {
        hash ^= c;
        hash *= 0x100000001b3ull;
    }
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
    return text;
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
    std::vector<EstimatorMeasurement> out{measureSafeStep(f, rays, options)};
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
    // The gradient twins of the estimators measured so far, with their parameters; none after a
    // step that declares a jump: differences across the jump are no derivative, and the rays that
    // straddle it are too rare for the rounds to see. Of 18 twins chosen after a jump on 1500
    // random stacks, 4 overshot 2000 fresh rays, by 1.86x to 104x (bench/stills/README.md).
    const bool jumpsBefore = derivativeBound(f.nodes) == DerivativeBound::None;
    for (size_t i = 0, measuredSoFar = jumpsBefore ? 0 : out.size(); i < measuredSoFar; ++i)
        for (const BlockDesc& twin : allBlocks())
            if (twin.offeredAsTwin && twin.gradientOf == out[i].estimator.block->id) {
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
