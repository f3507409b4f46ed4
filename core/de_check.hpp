// Checks a formula's distance estimate against the seed's baseline marcher (3.1): fixed-step
// ray marching with a membership test, refined by bisection. A DE must never exceed the
// distance to the surface along any ray ("never overshoots", seed 3.2).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "core/camera.hpp"
#include "core/formula.hpp"

namespace fraktal {

// Evaluates a formula at many points at once. The CPU one is exact (double); the GL one
// (gl::GpuSampler, core/gl/de_probe.hpp) serves formulas with custom GLSL blocks.
class FormulaSampler {
   public:
    virtual ~FormulaSampler() = default;
    virtual const Formula& formula() const = 0;
    virtual void evaluate(std::span<const vec3> points, std::span<Evaluation> out) = 0;
    // Whether evaluate may be called from several threads at once (the CPU's pure functions; a GL
    // probe has one context).
    virtual bool concurrent() const { return false; }
};

class CpuSampler final : public FormulaSampler {
   public:
    explicit CpuSampler(const Formula& f) : formula_(f) {}
    const Formula& formula() const override { return formula_; }
    void evaluate(std::span<const vec3> points, std::span<Evaluation> out) override {
        for (size_t i = 0; i < points.size(); ++i) out[i] = fraktal::evaluate(formula_, points[i]);
    }
    bool concurrent() const override { return true; }

   private:
    const Formula& formula_;
};

struct BaselineHit {
    bool hit = false;
    double t = 0.0;  // distance along the ray to the first point inside the fractal
};

// Marches [tStart, tEnd] in steps of `step`, testing membership; bisects the first crossing.
BaselineHit baselineMarch(FormulaSampler& sampler, const vec3& origin, const vec3& dir, double tStart, double tEnd,
                          double step);
BaselineHit baselineMarch(const Formula& f, const vec3& origin, const vec3& dir, double tStart, double tEnd,
                          double step);

// Ray / bound sphere intersection: the part of the ray inside the formula's bound.
bool clipToBound(const Formula& f, const vec3& origin, const vec3& dir, double& tStart, double& tEnd);

struct ConservativenessOptions {
    int rays = 200;
    int stepsAcrossBound = 4000;  // baseline step = 2 * boundRadius / stepsAcrossBound
    uint64_t seed = 1;
    // Threads that march the rays when the sampler is concurrent (0: one a core). The samples
    // are the same whatever the count: each ray is drawn first and marched alone.
    int threads = 0;
};

struct ConservativenessReport {
    int rays = 0;
    int raysHit = 0;
    long samples = 0;          // (point, true distance along the ray) pairs compared
    double worstRatio = 0.0;   // max over samples of DE / distance-to-hit
    double medianRatio = 0.0;  // how fast marching is: near 1, each step covers the whole gap
    vec3 worstPoint{0.0};
    // The worst ratio of each hit ray with samples, largest first: the rays are independent
    // draws where the samples along one ray are not, so the tail of the ratios is estimated on these.
    std::vector<double> rayWorst;
    // Largest multiplier of the DE that keeps every sample at or under the true distance.
    double safeStepMultiplier() const { return worstRatio > 1.0 ? 1.0 / worstRatio : 1.0; }
    bool conservative(double tolerance = 0.01) const { return worstRatio <= 1.0 + tolerance; }
};

// Points on rays in front of the fractal, each with the true distance along its ray to the first
// hit (the baseline marcher's). They depend only on the formula's membership, so estimators that
// share it (every escape-time one) can be compared on the same samples.
struct RaySamples {
    int rays = 0;
    int raysHit = 0;
    std::vector<vec3> points;
    std::vector<double> distances;
    // One past each hit ray's last sample, in order: the samples of hit ray i are
    // [rayEnds[i - 1], rayEnds[i]) (from 0 for the first).
    std::vector<size_t> rayEnds;
};

// Half the rays start at the camera through random pixels, half at random points on the bound
// sphere aimed at random points inside it.
RaySamples sampleRays(FormulaSampler& sampler, const Camera& camera, const ConservativenessOptions& options = {});
// The DE of `sampler`'s formula against the samples' true distances.
ConservativenessReport compareWithSamples(FormulaSampler& sampler, const RaySamples& samples);
// Its two halves: DE / true distance at each sample (not a number counts as infinite), and the
// report of those ratios (one per sample, in order).
std::vector<double> ratiosAt(FormulaSampler& sampler, const RaySamples& samples);
ConservativenessReport reportOf(const RaySamples& samples, std::vector<double> ratios);

ConservativenessReport checkConservativeness(FormulaSampler& sampler, const Camera& camera,
                                             const ConservativenessOptions& options = {});
ConservativenessReport checkConservativeness(const Formula& f, const Camera& camera,
                                             const ConservativenessOptions& options = {});

struct GridReport {
    long points = 0;
    long nonFinite = 0;
    long inside = 0;
    double minDistance = 0.0, maxDistance = 0.0;
    double secondsPerEvaluation = 0.0;
};

// The DE on an n^3 grid over the bound's cube.
GridReport evaluateGrid(FormulaSampler& sampler, int n);
GridReport evaluateGrid(const Formula& f, int n);

}  // namespace fraktal
