// The one CPU marcher (core/cpu_render/sphere_trace.hpp) on distance fields whose surface is known
// exactly: where each rule stops, what it does with a lying or broken estimate.
#include "core/cpu_render/sphere_trace.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "core/scene/distance.hpp"

namespace fraktal::cpu {
namespace {

// The unit sphere's exact distance, scaled by `factor` (a factor over 1 overestimates: steps land
// inside), with membership.
struct Sphere {
    double factor = 1.0;
    DistanceSample operator()(const vec3& p, double) const {
        const double d = length(p) - 1.0;
        return {factor * d, d < 0.0};
    }
};

const vec3 kOrigin(0.0, 0.0, -4.0);
const vec3 kForward(0.0, 0.0, 1.0);

TEST(SphereTrace, APlainMarchStopsOutsideWithinTheThreshold) {
    MarchRule rule;
    rule.epsilon = 1e-4;
    double evals = 0.0;
    const auto t = traceFirstHit(Sphere{}, kOrigin, kForward, 0.0, 8.0, rule, 256, evals);
    ASSERT_TRUE(t.has_value());
    // The surface is at t = 3: the hit is in front of it, no further than the threshold.
    EXPECT_LE(*t, 3.0);
    EXPECT_GT(*t, 3.0 - 1e-4);
    EXPECT_GE(evals, 1.0);
}

TEST(SphereTrace, TheConeThresholdGrowsWithDistance) {
    MarchRule rule;
    rule.coneAngle = 0.01;  // 0.03 at the surface
    double evals = 0.0;
    const auto t = traceFirstHit(Sphere{}, kOrigin, kForward, 0.0, 8.0, rule, 256, evals);
    ASSERT_TRUE(t.has_value());
    EXPECT_LE(*t, 3.0);
    EXPECT_LE(3.0 - *t, rule.threshold(*t) + 1e-12);
}

TEST(SphereTrace, AHitPastTheEndIsNone) {
    // A shadow ray toward a light in front of the sphere: the sphere behind the light casts nothing.
    MarchRule rule;
    rule.epsilon = 1e-4;
    double evals = 0.0;
    EXPECT_FALSE(traceFirstHit(Sphere{}, kOrigin, kForward, 0.0, 2.5, rule, 256, evals).has_value());
    EXPECT_FALSE(traceFirstHit(Sphere{}, kOrigin, vec3(0.0, 1.0, 0.0), 0.0, 100.0, rule, 256, evals).has_value());
}

TEST(SphereTrace, AStepCapKeepsAnOverestimateFromJumpingThrough) {
    // Estimates that claim 10x the gap: uncapped, the first step leaps far past the sphere; with the
    // cap (a probe's far-field rule) the march still meets the surface from outside.
    const Sphere liar{10.0};
    MarchRule rule;
    rule.epsilon = 1e-3;
    double evals = 0.0;
    EXPECT_FALSE(traceFirstHit(liar, kOrigin, kForward, 0.0, 8.0, rule, 256, evals).has_value());
    rule.maxStep = 0.05;
    const auto t = traceFirstHit(liar, kOrigin, kForward, 0.0, 8.0, rule, 256, evals);
    ASSERT_TRUE(t.has_value());
    EXPECT_NEAR(*t, 3.0, 0.05);
}

TEST(SphereTrace, ANonFiniteEstimateEscapesAtOnce) {
    const auto nan = [](const vec3&, double) {
        return DistanceSample{std::numeric_limits<double>::quiet_NaN(), false};
    };
    MarchState s;
    double evals = 0.0;
    marchSteps(nan, kOrigin, kForward, 8.0, MarchRule{}, 1000, s, evals);
    EXPECT_EQ(s.status, MarchStatus::Escaped);
    EXPECT_EQ(evals, 1.0);
}

TEST(SphereTrace, AStepThatLandsInsideIsBisectedBackToTheCrossing) {
    // Factor 1.2: the first step goes 1.2 gaps (3.6) and lands inside, 0.6 past the surface at 3.
    // With recovery the hit is the outside end of the crossing, within the threshold; without it
    // the ray stops where the step landed.
    MarchRule rule;
    rule.epsilon = 1e-3;
    rule.recoverOvershoot = true;
    MarchState s;
    double evals = 0.0;
    marchSteps(Sphere{1.2}, kOrigin, kForward, 8.0, rule, 256, s, evals);
    ASSERT_EQ(s.status, MarchStatus::Hit);
    EXPECT_LE(s.t, 3.0);
    EXPECT_GT(s.t, 3.0 - 2e-3);
    rule.recoverOvershoot = false;
    MarchState plain;
    marchSteps(Sphere{1.2}, kOrigin, kForward, 8.0, rule, 256, plain, evals);
    ASSERT_EQ(plain.status, MarchStatus::Hit);
    EXPECT_NEAR(plain.t, 3.6, 1e-12);
}

TEST(SphereTrace, OverRelaxationMeetsTheSameSurfaceInFewerSteps) {
    // A ray at a shallow angle to a floor (the case over-relaxation speeds up, Keinert et al. 2014:
    // consecutive spheres overlap by far): the relaxed march stops where the plain one does, to within
    // the threshold, and spends fewer evaluations.
    const auto floor = [](const vec3& p, double) { return DistanceSample{p.y + 1.0, p.y < -1.0}; };
    const vec3 rd = normalize(vec3(1.0, -0.05, 0.0));
    MarchRule rule;
    rule.coneAngle = 1e-3;
    rule.recoverOvershoot = true;
    MarchRule relaxedRule = rule;
    relaxedRule.maxStepGrowth = 1.6;  // the relaxed march's omega stays within its start
    MarchState plain, relaxed;
    relaxed.omega = 1.6;
    double plainEvals = 0.0, relaxedEvals = 0.0;
    marchSteps(floor, vec3(0.0), rd, 100.0, rule, 1000, plain, plainEvals);
    marchSteps(floor, vec3(0.0), rd, 100.0, relaxedRule, 1000, relaxed, relaxedEvals);
    ASSERT_EQ(plain.status, MarchStatus::Hit);
    ASSERT_EQ(relaxed.status, MarchStatus::Hit);
    EXPECT_NEAR(relaxed.t, plain.t, 2.0 * rule.threshold(plain.t) / 0.05);
    EXPECT_LT(relaxedEvals, 0.75 * plainEvals);
}

// The adaptive step (shaders/march.glsl) on a cautious estimate, 5 % of the sphere's distance (as
// the check finds Kleinian and random stacks at the median): it meets the surface the plain march
// meets, verified (maxStepGrowth under 2) in fewer steps and trusted in far fewer. (A verified
// step must leave a hit threshold of overlap, which a cautious estimate reaches far from the
// surface: 51 of the plain march's 78 evaluations, where omega 1.8 alone would take 44.)
TEST(SphereTrace, AdaptiveStepsMeetTheSurfaceOfACautiousEstimateInFewerSteps) {
    MarchRule rule;
    rule.coneAngle = 1e-3;
    rule.recoverOvershoot = true;
    const Sphere cautious{0.05};
    const auto march = [&](double maxStepGrowth, double omega) {
        rule.maxStepGrowth = maxStepGrowth;
        MarchState s;
        s.omega = omega;
        double evals = 0.0;
        marchSteps(cautious, kOrigin, kForward, 8.0, rule, 10000, s, evals);
        EXPECT_EQ(s.status, MarchStatus::Hit) << maxStepGrowth;
        // In front of the surface at t = 3, and within the estimate's threshold of it.
        EXPECT_LE(s.t, 3.0) << maxStepGrowth;
        EXPECT_GT(s.t, 3.0 - rule.threshold(s.t) / cautious.factor) << maxStepGrowth;
        return evals;
    };
    const double plain = march(1.0, 1.0);
    const double verified = march(1.9, quantizedOmega(1.3));
    const double trusted = march(16.0, quantizedOmega(1.3));
    std::printf("DE evaluations on a 5 %% estimate: plain %.0f, verified %.0f, trusted %.0f\n", plain, verified,
                trusted);
    EXPECT_LT(verified, 0.8 * plain);
    EXPECT_LT(trusted, 0.15 * plain);
}

// A scene of both kinds of estimate: a cautious ball (5 % of its distance) and thin exact plates
// around it, whose first crossing along any ray is known exactly. On every one of 4000 random
// rays, the verified adaptive step never passes the first surface (the spheres of a step's ends,
// empty under a 1-Lipschitz estimate, cover the step): it stops in front of it, and misses only
// rays that miss everything. The trusted step's crossings, which the spheres cannot rule out, are
// counted and printed.
struct BallAndPlates {
    struct Plate {
        vec3 centre, half;
    };
    std::vector<Plate> plates;
    static double boxDistance(const vec3& p, const Plate& b) {
        const vec3 q = glm::abs(p - b.centre) - b.half;
        return length(glm::max(q, vec3(0.0))) + std::min(std::max(q.x, std::max(q.y, q.z)), 0.0);
    }
    DistanceSample operator()(const vec3& p, double) const {
        double d = 0.05 * (length(p) - 1.0);
        bool inside = length(p) < 1.0;
        for (const Plate& b : plates) {
            const double e = boxDistance(p, b);
            d = std::min(d, e);
            inside = inside || e < 0.0;
        }
        return {d, inside};
    }
    // The first t >= 0 where the ray enters the ball or a plate (slab method), or infinity.
    double firstCrossing(const vec3& ro, const vec3& rd) const {
        double first = std::numeric_limits<double>::infinity();
        const double b = dot(ro, rd), c = dot(ro, ro) - 1.0, h = b * b - c;
        if (h >= 0.0 && -b - std::sqrt(h) >= 0.0) first = -b - std::sqrt(h);
        for (const Plate& box : plates) {
            double tNear = 0.0, tFar = std::numeric_limits<double>::infinity();
            for (int a = 0; a < 3; ++a) {
                const double lo = (box.centre[a] - box.half[a] - ro[a]) / rd[a];
                const double hi = (box.centre[a] + box.half[a] - ro[a]) / rd[a];
                tNear = std::max(tNear, std::min(lo, hi));
                tFar = std::min(tFar, std::max(lo, hi));
            }
            if (tNear <= tFar) first = std::min(first, tNear);
        }
        return first;
    }
};

TEST(SphereTrace, VerifiedAdaptiveStepsNeverPassTheFirstSurface) {
    BallAndPlates scene;
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int i = 0; i < 24; ++i) {
        const vec3 centre = 1.8 * vec3(unit(rng), unit(rng), unit(rng));
        scene.plates.push_back({centre, vec3(0.3 + 0.2 * unit(rng), 0.3 + 0.2 * unit(rng), 0.004 + 0.003 * unit(rng))});
    }
    MarchRule rule;
    rule.coneAngle = 1e-3;
    rule.recoverOvershoot = true;
    int hits = 0, trustedPast = 0;
    double plainEvals = 0.0, verifiedEvals = 0.0, trustedEvals = 0.0;
    for (int ray = 0; ray < 4000; ++ray) {
        const vec3 ro = 5.0 * normalize(vec3(unit(rng), unit(rng), unit(rng)));
        const vec3 rd = normalize(0.8 * vec3(unit(rng), unit(rng), unit(rng)) - ro);
        const double first = scene.firstCrossing(ro, rd);
        const auto march = [&](double maxStepGrowth, double omega, double& evals) {
            rule.maxStepGrowth = maxStepGrowth;
            MarchState s;
            s.omega = omega;
            marchSteps(scene, ro, rd, 10.0, rule, 20000, s, evals);
            return s;
        };
        const MarchState verified = march(1.9, quantizedOmega(1.3), verifiedEvals);
        const MarchState trusted = march(16.0, quantizedOmega(1.3), trustedEvals);
        march(1.0, 1.0, plainEvals);
        if (verified.status == MarchStatus::Hit) ++hits;
        ASSERT_TRUE(verified.status == MarchStatus::Hit ? verified.t <= first : std::isinf(first))
            << "ray " << ray << ": first surface at " << first << ", the verified march "
            << (verified.status == MarchStatus::Hit ? "stopped at " + std::to_string(verified.t) : "missed it");
        if (trusted.status == MarchStatus::Hit ? trusted.t > first : !std::isinf(first)) ++trustedPast;
    }
    std::printf(
        "%d of 4000 rays hit; DE evaluations plain %.0f, verified %.0f (%.2fx fewer), trusted %.0f (%.2fx "
        "fewer, %d rays past the first surface)\n",
        hits, plainEvals, verifiedEvals, plainEvals / verifiedEvals, trustedEvals, plainEvals / trustedEvals,
        trustedPast);
    EXPECT_GT(hits, 1000);
    EXPECT_LT(verifiedEvals, plainEvals);
}

TEST(SphereTrace, InteriorWallsStopBelowTheThresholdAndCrawlOn) {
    MarchRule rule;
    rule.coneAngle = 1e-2;
    rule.hitRule = HitRule::InteriorWalls;
    MarchState s;
    double evals = 0.0;
    // Started a unit along the ray, where the threshold is not 0: a step of the estimate less 0.8
    // thresholds lands short of the surface, not on it.
    s.t = 1.0;
    marchSteps(Sphere{}, kOrigin, kForward, 8.0, rule, 256, s, evals);
    ASSERT_EQ(s.status, MarchStatus::Hit);
    // Each step is the estimate less 0.8 thresholds: the hit lies in [0.2, 1) thresholds of the surface.
    const double gap = 3.0 - s.t;
    EXPECT_GT(gap, 0.0);
    EXPECT_LT(gap, rule.threshold(s.t));
}

TEST(SphereTrace, TraceDistanceMarchesADistanceFunction) {
    // The scene layer's entry for a DistanceAt (the editor's pick on custom GLSL, the fit's probe).
    const DistanceAt sphere = [](const vec3& p) { return length(p) - 1.0; };
    MarchRule rule;
    rule.epsilon = 1e-4;
    const auto t = traceDistance(sphere, kOrigin, kForward, 0.0, 8.0, rule, 256);
    ASSERT_TRUE(t.has_value());
    EXPECT_NEAR(*t, 3.0, 1e-4);
    EXPECT_FALSE(traceDistance(sphere, kOrigin, -kForward, 0.0, 8.0, rule, 256).has_value());
}

}  // namespace
}  // namespace fraktal::cpu
