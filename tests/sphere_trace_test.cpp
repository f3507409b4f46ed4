// The one CPU marcher (core/cpu_render/sphere_trace.hpp) on distance fields whose surface is known
// exactly: where each rule stops, what it does with a lying or broken estimate.
#include "core/cpu_render/sphere_trace.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

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
    MarchState plain, relaxed;
    relaxed.omega = 1.6;
    double plainEvals = 0.0, relaxedEvals = 0.0;
    marchSteps(floor, vec3(0.0), rd, 100.0, rule, 1000, plain, plainEvals);
    marchSteps(floor, vec3(0.0), rd, 100.0, rule, 1000, relaxed, relaxedEvals);
    ASSERT_EQ(plain.status, MarchStatus::Hit);
    ASSERT_EQ(relaxed.status, MarchStatus::Hit);
    EXPECT_NEAR(relaxed.t, plain.t, 2.0 * rule.threshold(plain.t) / 0.05);
    EXPECT_LT(relaxedEvals, 0.75 * plainEvals);
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
