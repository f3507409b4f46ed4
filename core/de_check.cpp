#include "core/de_check.hpp"

#include <chrono>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace fraktal {

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

BaselineHit baselineMarch(const Formula& f, const vec3& origin, const vec3& dir, double tStart, double tEnd,
                          double step) {
    double previous = tStart;
    if (evaluate(f, origin + dir * tStart).inside) return {true, tStart};
    for (double t = tStart + step; t <= tEnd + step; t += step) {
        if (!evaluate(f, origin + dir * t).inside) {
            previous = t;
            continue;
        }
        double lo = previous, hi = t;
        for (int i = 0; i < 48; ++i) {
            const double mid = 0.5 * (lo + hi);
            (evaluate(f, origin + dir * mid).inside ? hi : lo) = mid;
        }
        return {true, hi};
    }
    return {};
}

ConservativenessReport checkConservativeness(const Formula& f, const Camera& camera,
                                             const ConservativenessOptions& options) {
    ConservativenessReport report;
    std::mt19937_64 rng(options.seed);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    auto randomInBall = [&](double radius) {
        vec3 v;
        do v = vec3(uniform(rng), uniform(rng), uniform(rng));
        while (dot(v, v) > 1.0);
        return v * radius;
    };
    const double step = 2.0 * f.boundRadius / options.stepsAcrossBound;
    const double minGap = step;

    for (int ray = 0; ray < options.rays; ++ray) {
        vec3 origin, dir;
        if (ray % 2 == 0) {
            origin = camera.position;
            dir = camera.rayDirection(uniform(rng), uniform(rng), 1.0);
        } else {
            origin = normalize(randomInBall(1.0)) * f.boundRadius;
            dir = normalize(randomInBall(0.5 * f.boundRadius) - origin);
        }
        double t0, t1;
        ++report.rays;
        if (!clipToBound(f, origin, dir, t0, t1)) continue;
        const BaselineHit hit = baselineMarch(f, origin, dir, t0, t1, step);
        if (!hit.hit) continue;
        ++report.raysHit;
        // Compare the DE with the distance to the hit at points spread along the ray before it.
        for (double t = t0; t < hit.t - minGap; t += std::max(step, (hit.t - t0) / 400.0)) {
            const vec3 p = origin + dir * t;
            const double ratio = distanceEstimate(f, p) / (hit.t - t);
            ++report.samples;
            if (!(ratio <= report.worstRatio)) {
                report.worstRatio = std::isfinite(ratio) ? ratio : std::numeric_limits<double>::infinity();
                report.worstPoint = p;
            }
        }
    }
    return report;
}

GridReport evaluateGrid(const Formula& f, int n) {
    GridReport g;
    g.minDistance = std::numeric_limits<double>::infinity();
    g.maxDistance = -g.minDistance;
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            for (int k = 0; k < n; ++k) {
                const vec3 p = (vec3(i, j, k) + 0.5) / double(n) * 2.0 - 1.0;
                const Evaluation e = evaluate(f, p * f.boundRadius);
                ++g.points;
                if (!std::isfinite(e.distance)) {
                    ++g.nonFinite;
                    continue;
                }
                g.inside += e.inside;
                g.minDistance = std::min(g.minDistance, e.distance);
                g.maxDistance = std::max(g.maxDistance, e.distance);
            }
    g.secondsPerEvaluation =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / double(std::max(1L, g.points));
    return g;
}

}  // namespace fraktal
