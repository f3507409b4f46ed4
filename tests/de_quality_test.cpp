// The distance estimators against geometry: the seed's "never overshoots" on random rays, exact
// distances where they are known in closed form, and the known bounding radii.
#include <gtest/gtest.h>

#include <cmath>

#include "core/de_check.hpp"
#include "test_support.hpp"

using namespace fraktal;

namespace {


double boxDistance(const vec3& p, const vec3& halfSize) {
    const vec3 q = abs(p) - halfSize;
    return length(max(q, 0.0)) + std::min(std::max(q.x, std::max(q.y, q.z)), 0.0);
}

ConservativenessOptions testRays() {
    ConservativenessOptions o;
    o.rays = 80;
    o.stepsAcrossBound = 8000;
    o.seed = 2024;
    return o;
}

}  // namespace

TEST(DEQuality, EveryShippedFormulaIsConservative) {
    for (const auto& path : test::shippedPresets()) {
        const Preset p = loadPreset(path);
        const ConservativenessReport r = checkConservativeness(p.formula, p.camera, testRays());
        EXPECT_GE(r.raysHit, r.rays / 10) << path.filename() << ": too few rays hit to judge";
        EXPECT_GT(r.samples, 1000) << path.filename();
        EXPECT_LE(r.worstRatio, 1.01) << path.filename() << ": DE exceeds the true distance along a ray at ("
                                      << r.worstPoint.x << ", " << r.worstPoint.y << ", " << r.worstPoint.z << ")";
        std::printf("%s: %d/%d rays hit, worst DE / distance %.4f\n", path.filename().c_str(), r.raysHit, r.rays,
                    r.worstRatio);
    }
}

// The checker must catch an overshooting DE: scale a sound one up and it has to say so, with a
// step multiplier that undoes the scaling.
TEST(DEQuality, CheckerCatchesAnOvershootingEstimate) {
    Preset p = test::shippedPreset("menger.json");
    p.formula.deFactor = 1.5;
    const ConservativenessReport r = checkConservativeness(p.formula, p.camera, testRays());
    EXPECT_FALSE(r.conservative());
    EXPECT_GT(r.worstRatio, 1.3);
    EXPECT_LT(r.safeStepMultiplier(), 1.0 / 1.3);
}

TEST(DEQuality, MengerWithNoIterationsIsTheExactBox) {
    Formula f = test::shippedPreset("menger.json").formula;
    f.iterations = 0;
    for (const vec3& p : test::randomPoints(5000, 2.0, 3))
        ASSERT_NEAR(distanceEstimate(f, p), boxDistance(p, vec3(1.0)), 1e-12);
}

// The sponge keeps its eight corners at every level, so from a point whose nearest point on the
// cube is a corner, the distance to the sponge is exactly the distance to the cube.
TEST(DEQuality, MengerEqualsTheBoxDistanceWhereThatIsExact) {
    const Formula f = test::shippedPreset("menger.json").formula;
    int checked = 0;
    for (const vec3& p : test::randomPoints(20000, f.boundRadius, 5)) {
        if (std::min({std::abs(p.x), std::abs(p.y), std::abs(p.z)}) <= 1.0) continue;
        ASSERT_NEAR(distanceEstimate(f, p), boxDistance(p, vec3(1.0)), 1e-9) << p.x << " " << p.y << " " << p.z;
        ++checked;
    }
    EXPECT_GT(checked, 500);
    // In front of a face-centre tunnel the sponge is farther than the cube: the DE lies between
    // the box distance and the distance to the tunnel's rim.
    const vec3 front(0.0, 0.0, 1.5);
    EXPECT_GE(distanceEstimate(f, front), 0.5 - 1e-12);
    EXPECT_LE(distanceEstimate(f, front), std::sqrt(0.25 + 1.0 / 9.0) + 1e-12);
}

// |z^8 + c| >= |z|^8 - |c| > |z| once |z| = |c| > 2^(1/7): every orbit from there escapes.
TEST(DEQuality, MandelbulbInsideItsBoundingRadius) {
    const Formula f = test::shippedPreset("mandelbulb.json").formula;
    const double radius = std::pow(2.0, 1.0 / 7.0);
    long outside = 0;
    double farthestInside = 0.0;
    for (const vec3& p : test::randomPoints(40000, f.boundRadius, 7)) {
        const Evaluation e = evaluate(f, p);
        if (e.inside)
            farthestInside = std::max(farthestInside, length(p));
        else if (length(p) > radius)
            ++outside;
    }
    EXPECT_LE(farthestInside, radius);
    EXPECT_GT(farthestInside, 0.9);  // and the bulb really reaches out there
    EXPECT_GT(outside, 1000);
}

// For scale 2 the Mandelbox lies in the cube |x|, |y|, |z| <= 2 (s + 1) / (s - 1) = 6.
TEST(DEQuality, MandelboxInsideItsBoundingBox) {
    const Formula f = test::shippedPreset("mandelbox.json").formula;
    double farthestInside = 0.0;
    for (const vec3& p : test::randomPoints(40000, 8.0, 9)) {
        if (evaluate(f, p).inside)
            farthestInside = std::max(farthestInside, std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}));
    }
    EXPECT_LE(farthestInside, 6.0 * 1.02);
    EXPECT_GT(farthestInside, 4.0);
    EXPECT_LE(6.0 * std::sqrt(3.0), f.boundRadius);  // the preset's bound holds the whole box
}

// Away from the bulb the estimate is close to the true distance, which is measured to a dense
// sample of the surface found by the baseline marcher.
TEST(DEQuality, MandelbulbDistanceIsCloseAwayFromTheSurface) {
    Formula f = test::shippedPreset("mandelbulb.json").formula;
    f.deFactor = 1.0;  // the estimator itself, before the preset's safety factor
    std::vector<vec3> surface;
    for (const vec3& d : test::randomPoints(6000, 1.0, 21)) {
        if (length(d) < 0.1 || length(d) > 1.0) continue;
        const vec3 origin = normalize(d) * f.boundRadius;
        const BaselineHit hit = baselineMarch(f, origin, -normalize(d), 0.0, f.boundRadius, f.boundRadius / 2000);
        if (hit.hit) surface.push_back(origin - normalize(d) * hit.t);
    }
    ASSERT_GT(surface.size(), 2000u);
    double lowest = 1e9, highest = 0.0;
    for (const vec3& d : test::randomPoints(300, 1.0, 23)) {
        if (length(d) < 0.1 || length(d) > 1.0) continue;
        const vec3 p = normalize(d) * 1.45;
        double nearest = 1e9;
        for (const vec3& s : surface) nearest = std::min(nearest, length(p - s));
        const double ratio = distanceEstimate(f, p) / nearest;
        lowest = std::min(lowest, ratio);
        highest = std::max(highest, ratio);
    }
    std::printf("Mandelbulb at |p| = 1.45: DE / true distance in [%.3f, %.3f]\n", lowest, highest);
    EXPECT_LE(highest, 1.01);
    // The derivative bounds the largest stretch, which near the poles is up to n = 8 times the
    // radial one (formulas/mandelbulb.hpp): there the estimate may be that much under.
    EXPECT_GE(lowest, 0.5 / 8.0);
}

// The drawn surface's log radius counts each power node's remaining runs from its schedule
// (formula.cpp and formula.glsl alike) instead of looping over the iterations: the count agrees
// with the iterations the node runs on, for every period, phase and window.
TEST(DEQuality, IterationsRunBeforeCountsTheIterationsANodeRunsOn) {
    const std::pair<int, int> windows[] = {{0, kMaxIterations}, {0, 1}, {1, kMaxIterations}, {3, 9}, {4, 5}, {7, 30}};
    for (const auto& [start, stop] : windows)
        for (int period = 1; period <= 5; ++period)
            for (int phase = 0; phase < period; ++phase) {
                Node n = Node::make(*findBlock("mandelbulb"));
                n.period = period;
                n.phase = phase;
                n.start = start;
                n.stop = stop;
                int runs = 0;
                for (int count = 0; count <= 23; ++count) {
                    EXPECT_EQ(n.iterationsRunBefore(count), runs)
                        << "period " << period << ", phase " << phase << ", window " << start << ".." << stop;
                    const bool inWindow = count >= start && count < stop;
                    EXPECT_EQ(n.runsOn(count), inWindow && count % period == phase);
                    runs += n.runsOn(count);
                }
            }
}

namespace {

// Points from 0.02 to 2 outside the ball of radius rho, along the directions of `directions`
// (those shorter than 0.05 left out), with their distance to the ball.
std::vector<std::pair<vec3, double>> outsideTheBall(const std::vector<vec3>& directions, double rho) {
    std::vector<std::pair<vec3, double>> out;
    for (const vec3& d : directions)
        if (length(d) >= 0.05) out.push_back({normalize(d) * (rho + 0.02 + 1.98 * length(d)), 0.02 + 1.98 * length(d)});
    return out;
}

// The largest relative error of f's estimate against half the distance to the ball of radius rho.
double worstAgainstHalfTheDistance(const Formula& f, const std::vector<vec3>& directions, double rho) {
    double worst = 0.0;
    for (const auto& [p, distance] : outsideTheBall(directions, rho))
        worst = std::max(worst, std::abs(distanceEstimate(f, p) / (0.5 * distance) - 1.0));
    return worst;
}

}  // namespace

// A power alone (no add c): |F(v)| = |v|^n, and the limit set is the unit ball; the surface that
// N iterations with bailout B draw is the ball of radius rho = B^(1 / D), D = n^N, where the last
// iteration reaches the bailout. The potential estimate (formulas/estimators.hpp) is half the
// distance to that ball at every r for a map whose running derivative is its radial stretch, the
// twist-free Bristorbrot (x^2 - y^2 - z^2, 2xy, 2xz), whose Jacobian is 2r times a rotation; it
// needs the product of the degrees (2^k after k steps, P4::degree) and the drawn surface's log
// radius (P4::surfaceLogR). Measured against the unit ball instead, it is off by the whole gap
// (rho = 2 at one iteration). The log estimate there is 0.5 r log(r / rho), 0.82 of the distance
// at 2 from the unit ball and 0.69 from rho = 2. For the spherical powers the running derivative
// may be larger than the radial stretch (the phi stretch near the poles), so the estimate is at
// most half the distance.
TEST(DEQuality, PotentialEstimateIsHalfTheDistanceToTheDrawnBallOfAPower) {
    const auto points = test::randomPoints(3000, 1.0, 29);
    // The largest relative error against half the distance to the ball of radius rho, from 0.02 to
    // 2 outside it; and the log estimate's largest share of the distance from 1.9 outside.
    auto againstHalfTheDistance = [&](const Formula& f, double rho, double& logFar) {
        Formula log = f;
        log.estimator = Node::make(*findBlock("escape_log"));
        logFar = 0.0;
        for (const auto& [p, distance] : outsideTheBall(points, rho))
            if (distance > 1.9) logFar = std::max(logFar, distanceEstimate(log, p) / distance);
        return worstAgainstHalfTheDistance(f, points, rho);
    };
    for (int iterations : {1, 2, 5, 12}) {
        const Formula f = test::squaringBall(iterations);
        const double rho = std::pow(f.bailout, 1.0 / std::pow(2.0, iterations));
        double logFar = 0.0;
        // Rounding over 2^k-fold products.
        EXPECT_LT(againstHalfTheDistance(f, rho, logFar), 1e-7) << iterations << " iterations";
        EXPECT_GT(logFar, 0.65) << iterations << " iterations";
        EXPECT_EQ(distanceEstimate(f, vec3(0.0, 0.0, 0.999 * rho)), 0.0) << "inside the drawn ball";
    }
    // A node that runs on odd iterations only: 5 iterations square twice, and the drawn ball has
    // radius B^(1/4); an orbit that escapes after the first square has one run left.
    double logFar = 0.0;
    EXPECT_LT(againstHalfTheDistance(test::squaringBall(5, 2, 1), std::pow(4.0, 0.25), logFar), 1e-7)
        << "period 2, phase 1";
    for (const char* id : {"mandelbulb", "mandelbulb_sine", "mandelbulb_cosine", "mandelbulb_phase"}) {
        for (double power : {2.0, 3.0, 8.0}) {
            Formula f;
            f.iterations = 6;
            f.bailout = 4.0;
            f.estimator = Node::make(*findBlock("escape_potential"));
            Node bulb = Node::make(*findBlock(id));
            bulb.values[0].x = power;
            f.nodes = {bulb};
            const double rho = std::pow(f.bailout, 1.0 / std::pow(power, f.iterations));
            double highest = 0.0;
            for (const auto& [p, distance] : outsideTheBall(points, rho))
                highest = std::max(highest, distanceEstimate(f, p) / (0.5 * distance));
            EXPECT_LE(highest, 1.0 + 1e-9) << id << " power " << power;
            EXPECT_GT(highest, 0.99) << id << " power " << power;  // reached where the stretch is radial
        }
    }
}

namespace {

// log |F^count(pos)|, stepped block by block here: a reference for the orbit gradient.
double logRadiusAfter(const Formula& f, const vec3& pos, int count) {
    P4 p{pos, 1.0};
    for (int i = 0; i < count; ++i)
        for (const Node& n : f.nodes)
            if (n.enabled && n.runsOn(i)) n.block->apply(p, pos, n.args());
    return std::log(length(p.xyz));
}

// |grad log |F^count|| at pos by central differences at a step far finer than the estimators'.
double referenceGradient(const Formula& f, const vec3& pos, int count) {
    const double h = 1e-6;
    vec3 g;
    for (int axis = 0; axis < 3; ++axis) {
        vec3 step(0.0);
        step[axis] = h;
        g[axis] = (logRadiusAfter(f, pos + step, count) - logRadiusAfter(f, pos - step, count)) / (2.0 * h);
    }
    return length(g);
}

}  // namespace

// The gradient estimators divide by |grad| of the composed map's orbit value where the others
// divide by the running derivative, the product of each step's largest stretch:
// - where every step stretches alike in all directions (the twist-free squaring ball; a scale
//   before a box), the two are the same estimate, up to the differences' error;
// - after a twist the gradient is that of central differences at a fine step, never above the
//   running derivative's |w| / r, and the estimate is larger than the potential one: the twist's
//   largest stretch turns from step to step, and the product of the stretches outgrows the
//   composed map's.
TEST(DEQuality, GradientEstimatesTakeTheComposedMapsGradient) {
    const auto points = test::randomPoints(2000, 1.0, 31);
    for (int iterations : {2, 5}) {
        Formula f = test::squaringBall(iterations);
        f.estimator = Node::make(*findBlock("escape_gradient"));
        const double worst =
            worstAgainstHalfTheDistance(f, points, std::pow(f.bailout, 1.0 / std::pow(2.0, iterations)));
        std::printf("squaring ball, %d iterations: gradient estimate within %.2g of half the distance\n", iterations,
                    worst);
        EXPECT_LT(worst, 2e-2) << iterations << " iterations";
    }

    Formula scaled;
    scaled.iterations = 3;
    scaled.bailout = 1e6;
    Node scale = Node::make(*findBlock("scale"));
    scale.values[0].x = 2.0;
    scaled.nodes = {scale};
    scaled.estimator = Node::make(*findBlock("box"));
    Formula scaledGradient = scaled;
    scaledGradient.estimator = Node::make(*findBlock("box_gradient"));
    double worstBox = 0.0;
    for (const vec3& d : points) {
        const vec3 p = d * 0.5;
        const double box = distanceEstimate(scaled, p);
        if (box < 1e-3) continue;  // the box's edges and inside, where its distance bends
        worstBox = std::max(worstBox, std::abs(distanceEstimate(scaledGradient, p) / box - 1.0));
    }
    std::printf("scale 2 before a box: the gradient estimate within %.2g of the box estimate\n", worstBox);
    EXPECT_LT(worstBox, 2e-2);

    Formula twisted = test::squaringBall(4);
    Node twist = Node::make(*findBlock("twist_y"));
    twist.values[0].x = 1.5;
    twisted.nodes.insert(twisted.nodes.begin(), twist);
    Formula gradient = twisted;
    gradient.estimator = Node::make(*findBlock("escape_gradient"));
    std::vector<double> gains;
    double worstGradient = 0.0;
    for (const vec3& d : points) {
        const vec3 p = d * 1.5;
        const Evaluation e = evaluate(gradient, p);
        const double potential = distanceEstimate(twisted, p);
        if (!(potential > 1e-4)) continue;
        const double reference = referenceGradient(twisted, p, e.iterations);
        worstGradient = std::max(worstGradient, std::abs(e.orbitGradient / reference - 1.0));
        EXPECT_GE(e.distance, potential * (1.0 - 1e-9)) << "at (" << p.x << ", " << p.y << ", " << p.z << ")";
        gains.push_back(e.distance / potential);
    }
    std::sort(gains.begin(), gains.end());
    ASSERT_GT(gains.size(), 500u);
    const double medianGain = gains[gains.size() / 2];
    std::printf(
        "twist 1.5 before a square, 4 iterations: gradient within %.2g of the reference; the estimate "
        "%.3f x the potential one (median), up to %.3f x\n",
        worstGradient, medianGain, gains.back());
    EXPECT_LT(worstGradient, 2e-2);
    EXPECT_GT(medianGain, 1.2);
}
