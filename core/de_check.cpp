#include "core/de_check.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <functional>
#include <limits>
#include <mutex>
#include <random>
#include <thread>
#include <vector>

#include "core/random_vec.hpp"

namespace fraktal {

namespace {

constexpr size_t kBatch = 512;        // baseline samples evaluated together
constexpr int kBisectionPoints = 31;  // interior points per refinement round
constexpr int kBisectionRounds = 8;   // 32^8: a step refined to ~1e-12 of itself

std::vector<Evaluation> evaluateAll(FormulaSampler& s, const std::vector<vec3>& points) {
    std::vector<Evaluation> out(points.size());
    s.evaluate(points, out);
    return out;
}

}  // namespace

bool clipToBound(const Formula& f, const vec3& origin, const vec3& dir, double& tStart, double& tEnd) {
    const double b = dot(origin, dir);
    const double c = dot(origin, origin) - f.boundRadius * f.boundRadius;
    const double disc = b * b - c;
    if (disc <= 0.0) return false;
    const double s = std::sqrt(disc);
    tStart = std::max(0.0, -b - s);
    tEnd = -b + s;
    return tEnd > tStart;
}

BaselineHit baselineMarch(FormulaSampler& sampler, const vec3& origin, const vec3& dir, double tStart, double tEnd,
                          double step) {
    // Fixed steps, a batch at a time, up to the first sample inside.
    double lo = tStart, hi = -1.0;
    std::vector<vec3> points;
    for (long first = 0; hi < 0.0; first += long(kBatch)) {
        points.clear();
        for (size_t i = 0; i < kBatch; ++i) {
            const double t = tStart + double(first + long(i)) * step;
            if (t > tEnd + step) break;
            points.push_back(origin + dir * t);
        }
        if (points.empty()) return {};
        const auto e = evaluateAll(sampler, points);
        for (size_t i = 0; i < e.size(); ++i) {
            const double t = tStart + double(first + long(i)) * step;
            if (e[i].inside) {
                if (t == tStart) return {true, tStart};
                hi = t;
                break;
            }
            lo = t;
        }
    }
    // Refine the crossing in [lo, hi]: lo is outside, hi inside.
    for (int round = 0; round < kBisectionRounds; ++round) {
        points.clear();
        for (int k = 1; k <= kBisectionPoints; ++k)
            points.push_back(origin + dir * (lo + (hi - lo) * k / (kBisectionPoints + 1)));
        const auto e = evaluateAll(sampler, points);
        double newHi = hi;
        for (int k = 0; k < kBisectionPoints; ++k) {
            const double t = lo + (hi - lo) * (k + 1) / (kBisectionPoints + 1);
            if (e[size_t(k)].inside) {
                newHi = t;
                break;
            }
        }
        const double width = (hi - lo) / (kBisectionPoints + 1);
        hi = newHi;
        lo = std::max(lo, newHi - width);
    }
    return {true, hi};
}

BaselineHit baselineMarch(const Formula& f, const vec3& origin, const vec3& dir, double tStart, double tEnd,
                          double step) {
    CpuSampler s(f);
    return baselineMarch(s, origin, dir, tStart, tEnd, step);
}

namespace {

struct SampledRay {
    vec3 origin{0.0}, dir{0.0};
    bool inBound = false;  // the ray meets the bound: [t0, t1] is the part inside it
    double t0 = 0.0, t1 = 0.0;
    BaselineHit hit;
};

// Marches each ray in the bound (baselineMarch) on `threads` threads when the sampler allows it:
// the baseline march is nearly all of a check's and an import's time (4000 steps across the
// bound, each a full orbit), and the rays are independent.
void marchRays(FormulaSampler& sampler, std::vector<SampledRay>& rays, double step, int threads) {
    auto march = [&](SampledRay& r) {
        if (r.inBound) r.hit = baselineMarch(sampler, r.origin, r.dir, r.t0, r.t1, step);
    };
    const int n =
        std::min(int(rays.size()), threads > 0 ? threads : int(std::max(1u, std::thread::hardware_concurrency())));
    if (!sampler.concurrent() || n <= 1) {
        for (SampledRay& r : rays) march(r);
        return;
    }
    std::atomic<size_t> next{0};
    std::exception_ptr failure;
    std::mutex failureLock;
    auto worker = [&] {
        try {
            for (size_t i = next++; i < rays.size(); i = next++) march(rays[i]);
        } catch (...) {
            const std::lock_guard<std::mutex> lock(failureLock);
            if (!failure) failure = std::current_exception();
            next = rays.size();
        }
    };
    std::vector<std::thread> pool;
    for (int t = 1; t < n; ++t) pool.emplace_back(worker);
    worker();
    for (std::thread& t : pool) t.join();
    if (failure) std::rethrow_exception(failure);
}

}  // namespace

RaySamples sampleRays(FormulaSampler& sampler, const Camera& camera, const ConservativenessOptions& options) {
    const Formula& f = sampler.formula();
    RaySamples out;
    std::mt19937_64 rng(options.seed);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    auto randomInBall = [&](double radius) {
        vec3 v;
        do v = randomVec3(uniform, rng);
        while (dot(v, v) > 1.0);
        return v * radius;
    };
    const double step = 2.0 * f.boundRadius / options.stepsAcrossBound;
    const double minGap = step;

    // The rays in the order the generator draws them, then marched, then their samples in order.
    std::vector<SampledRay> rays(size_t(std::max(options.rays, 0)));
    for (size_t ray = 0; ray < rays.size(); ++ray) {
        SampledRay& r = rays[ray];
        if (ray % 2 == 0) {
            r.origin = camera.position;
            const vec2 film = randomVec2(uniform, rng);
            r.dir = camera.rayDirection(film.x, film.y, 1.0);
        } else {
            r.origin = normalize(randomInBall(1.0)) * f.boundRadius;
            r.dir = normalize(randomInBall(0.5 * f.boundRadius) - r.origin);
        }
        r.inBound = clipToBound(f, r.origin, r.dir, r.t0, r.t1);
    }
    marchRays(sampler, rays, step, options.threads);
    for (const SampledRay& r : rays) {
        ++out.rays;
        if (!r.hit.hit) continue;
        ++out.raysHit;
        // Points spread along the ray before the hit, each with its distance to the hit.
        const size_t first = out.points.size();
        for (double t = r.t0; t < r.hit.t - minGap; t += std::max(step, (r.hit.t - r.t0) / 400.0)) {
            out.points.push_back(r.origin + r.dir * t);
            out.distances.push_back(r.hit.t - t);
        }
        if (out.points.size() > first) out.rayEnds.push_back(out.points.size());
    }
    return out;
}

std::vector<double> ratiosAt(FormulaSampler& sampler, const RaySamples& samples) {
    const auto e = evaluateAll(sampler, samples.points);
    std::vector<double> ratios(e.size());
    for (size_t i = 0; i < e.size(); ++i) {
        const double ratio = e[i].distance / samples.distances[i];
        ratios[i] = std::isnan(ratio) ? std::numeric_limits<double>::infinity() : ratio;
    }
    return ratios;
}

ConservativenessReport reportOf(const RaySamples& samples, std::vector<double> ratios) {
    ConservativenessReport report;
    report.rays = samples.rays;
    report.raysHit = samples.raysHit;
    report.samples = long(ratios.size());
    for (size_t i = 0; i < ratios.size(); ++i)
        if (!(ratios[i] <= report.worstRatio)) {
            report.worstRatio = ratios[i];
            report.worstPoint = samples.points[i];
        }
    for (size_t ray = 0, begin = 0; ray < samples.rayEnds.size(); begin = samples.rayEnds[ray++])
        report.rayWorst.push_back(
            *std::max_element(ratios.begin() + long(begin), ratios.begin() + long(samples.rayEnds[ray])));
    std::sort(report.rayWorst.begin(), report.rayWorst.end(), std::greater<>());
    if (!ratios.empty()) {
        auto middle = ratios.begin() + long(ratios.size() / 2);
        std::nth_element(ratios.begin(), middle, ratios.end());
        report.medianRatio = *middle;
    }
    return report;
}

ConservativenessReport compareWithSamples(FormulaSampler& sampler, const RaySamples& samples) {
    return reportOf(samples, ratiosAt(sampler, samples));
}

ConservativenessReport checkConservativeness(FormulaSampler& sampler, const Camera& camera,
                                             const ConservativenessOptions& options) {
    return compareWithSamples(sampler, sampleRays(sampler, camera, options));
}

ConservativenessReport checkConservativeness(const Formula& f, const Camera& camera,
                                             const ConservativenessOptions& options) {
    CpuSampler s(f);
    return checkConservativeness(s, camera, options);
}

GridReport evaluateGrid(FormulaSampler& sampler, int n) {
    const Formula& f = sampler.formula();
    GridReport g;
    g.minDistance = std::numeric_limits<double>::infinity();
    g.maxDistance = -g.minDistance;
    const auto start = std::chrono::steady_clock::now();
    std::vector<vec3> slice;
    for (int i = 0; i < n; ++i) {
        slice.clear();
        for (int j = 0; j < n; ++j)
            for (int k = 0; k < n; ++k)
                slice.push_back(((vec3(i, j, k) + 0.5) / double(n) * 2.0 - 1.0) * f.boundRadius);
        for (const Evaluation& e : evaluateAll(sampler, slice)) {
            ++g.points;
            if (!std::isfinite(e.distance)) {
                ++g.nonFinite;
                continue;
            }
            g.inside += e.inside;
            g.minDistance = std::min(g.minDistance, e.distance);
            g.maxDistance = std::max(g.maxDistance, e.distance);
        }
    }
    g.secondsPerEvaluation = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() /
                             double(std::max(1L, g.points));
    return g;
}

GridReport evaluateGrid(const Formula& f, int n) {
    CpuSampler s(f);
    return evaluateGrid(s, n);
}

}  // namespace fraktal
