// The generated GLSL (float, on the GL driver; llvmpipe in CI) agrees with the CPU evaluation
// (double) for every block and every shipped preset, on 10,000 points each.
#include <gtest/gtest.h>

#include <cmath>

#include "core/gl/de_probe.hpp"
#include "core/random_vec.hpp"
#include "test_support.hpp"

using namespace fraktal;

namespace {

// Enough that at least 10,000 well-conditioned points are compared per formula.
constexpr size_t kPoints = 10240;

// Relative 1e-4, or absolute 1e-5 near zero (a hundred-thousandth of the scenes' unit size).
double tolerance(double cpu) { return 1e-4 * std::max(std::abs(cpu), 0.1); }

// Whether moving any one parameter of f by `relative` (both ways) changes the result at p by more
// than `limit`.
bool sensitiveToParameters(const Formula& f, const vec3& p, double cpu, double relative, double limit) {
    for (size_t k = 0; k <= f.nodes.size(); ++k)
        for (size_t i = 0; i < (k < f.nodes.size() ? f.nodes[k] : f.estimator).values.size(); ++i)
            for (double sign : {-1.0, 1.0}) {
                Formula g = f;
                ParamValue& v = (k < g.nodes.size() ? g.nodes[k] : g.estimator).values[i];
                v *= 1.0 + sign * relative;
                if (!(std::abs(distanceEstimate(g, p) - cpu) <= limit)) return true;
            }
    return false;
}

// A point is ill-conditioned when moving it by single-precision rounding (1e-6 relative), or one
// of the formula's parameters by 1e-5 relative (the GPU's atan, cos and pow are not correctly
// rounded, and a power multiplies the error of the angle it raises: at three points of the sine
// bulb with angle offsets the GPU differed from double by 4e-4 relative where the same steps in
// float arithmetic differ by 3e-7), changes the double-precision result by more than the tolerance:
// near the boundary of an escape-time set, an orbit that passes the bailout one iteration earlier
// or later gives a different estimate, and no float evaluation can be expected to follow double
// there. Such points are counted and bounded, not compared.
bool illConditioned(const Formula& f, const vec3& p, double cpu) {
    if (sensitiveToParameters(f, p, cpu, 1e-5, 0.5 * tolerance(cpu))) return true;
    const double delta = 1e-6 * std::max(length(p), 1.0);
    for (int axis = 0; axis < 3; ++axis)
        for (double sign : {-1.0, 1.0}) {
            vec3 q = p;
            q[axis] += sign * delta;
            if (!(std::abs(distanceEstimate(f, q) - cpu) <= 0.5 * tolerance(cpu))) return true;
        }
    return false;
}

struct Agreement {
    size_t compared = 0, mismatched = 0, illConditioned = 0;
    size_t illConditionedInside = 0;  // of those, inside the set (CPU membership)
    double worstExcess = 0.0;         // max |gpu - cpu| / tolerance
    vec3 worstPoint{0.0};
};

Agreement compare(const Formula& f, const std::vector<vec3>& points) {
    test::glContext();
    gl::DEProbe probe(f);
    const std::vector<gl::GpuSample> gpu = probe.evaluate(f, points);
    Agreement a;
    for (size_t i = 0; i < points.size(); ++i) {
        const Evaluation cpu = evaluate(f, points[i]);
        const double excess = std::abs(double(gpu[i].distance) - cpu.distance) / tolerance(cpu.distance);
        if (excess > 1.0 && illConditioned(f, points[i], cpu.distance)) {
            ++a.illConditioned;
            a.illConditionedInside += cpu.inside;
            continue;
        }
        ++a.compared;
        if (!(excess <= 1.0)) ++a.mismatched;
        if (!(excess <= a.worstExcess)) {
            a.worstExcess = excess;
            a.worstPoint = points[i];
        }
    }
    return a;
}

// Inside a Julia set (add_c in Julia mode) the running derivative has no +1 and shrinks towards 0
// along the trapped orbits, so the estimate there is a large negative number that moves with
// rounding: more points are ill-conditioned than for Mandelbrot-type sets (about 1.3 % of the
// bound for juliabulb.json), all of them inside, where no ray marches. Outside the set the bound
// stays 1 %; inside and outside together, 2 %.
void expectFewIllConditioned(const Agreement& a, const std::string& what) {
    EXPECT_LE(a.illConditioned - a.illConditionedInside, kPoints / 100) << what << ": outside the set";
    EXPECT_LE(a.illConditioned, kPoints / 50) << what;
}

// A formula that exercises one block: the block repeated a few times, closed by a sphere (a dIFS
// shape: turned, scaled and closed by the dIFS estimate); or, for an estimator, a rotation and a
// scale closed by it. Its on/off parameters are all on or all
// off (`togglesOn`), so each branch of a block is compared.
Formula formulaFor(const BlockDesc& block, uint64_t seed, bool togglesOn) {
    std::mt19937_64 rng(seed);
    Node node = Node::make(block);
    // Values a quarter of the way from the default towards a random point of the range, so
    // identity defaults (angle 0, offset 0) are exercised too.
    for (size_t i = 0; i < block.params.size(); ++i) {
        const ParamDecl& d = block.params[i];
        std::uniform_real_distribution<double> u(d.min, d.max);
        const vec3 target = randomVec3(u, rng);
        vec3 v = d.defaultValue + 0.25 * (target - d.defaultValue);
        if (d.type == ParamType::Float) v = vec3(v.x, 0.0, 0.0);
        if (d.type == ParamType::Toggle) v = vec3(togglesOn ? 1.0 : 0.0, 0.0, 0.0);
        node.values[i] = v;
    }
    Formula f;
    f.iterations = 3;
    f.bailout = 100.0;
    Node rotate = Node::make(*findBlock("rotate"));
    rotate.values[1].x = 30.0;
    Node scale = Node::make(*findBlock("scale"));
    scale.values[0].x = 1.5;
    if (block.isEstimator()) {
        f.nodes = {rotate, scale};
        // The dIFS estimate reads what shape steps measured along the orbit.
        if (block.id == "difs") f.nodes.insert(f.nodes.begin(), Node::make(*findBlock("difs_box")));
        f.estimator = node;
    } else if (block.difsShape) {
        // A shape step changes nothing but the dIFS estimate: measured at each point of an orbit
        // that turns, shrinks and moves.
        f.nodes = {node, rotate, scale, Node::make(*findBlock("add_c"))};
        f.estimator = Node::make(*findBlock("difs"));
    } else {
        // add_c keeps power iterations from collapsing to 0 (float underflow, not a block error).
        f.nodes = {node, Node::make(*findBlock("add_c"))};
        f.estimator = Node::make(*findBlock("sphere"));
    }
    return f;
}

}  // namespace

bool hasToggle(const BlockDesc& block) {
    for (const ParamDecl& d : block.params)
        if (d.type == ParamType::Toggle) return true;
    return false;
}

TEST(GpuCpuAgreement, EveryBlock) {
    int toggledBlocks = 0;
    for (const BlockDesc& block : allBlocks()) {
        for (bool on : {false, true}) {
            if (on && !hasToggle(block)) continue;
            toggledBlocks += on;
            const std::string what = std::string(block.id) + (on ? " (toggles on)" : "");
            const Formula f = formulaFor(block, 7, on);
            const Agreement a = compare(f, test::randomPoints(kPoints, 2.0, 11));
            EXPECT_EQ(a.mismatched, 0u) << "block " << what << ": worst error " << a.worstExcess
                                        << "x the tolerance at (" << a.worstPoint.x << ", " << a.worstPoint.y << ", "
                                        << a.worstPoint.z << ")";
            EXPECT_LE(a.illConditioned, kPoints / 100) << "block " << what;
            EXPECT_GE(a.compared, 10000u) << "block " << what;
        }
    }
    // add_c's Julia mode and the primitives' intersection at least.
    EXPECT_GE(toggledBlocks, 4);
}

// Objects beside the fractal: every kind, joined, intersected and carved, turned, one hollow and
// one off, after a Menger sponge and after an escape-time bulb (whose membership they change).
TEST(GpuCpuAgreement, ObjectsBesideTheFractal) {
    for (const char* preset : {"menger.json", "mandelbulb.json"}) {
        Formula f = loadPreset(test::sourceDir() / "presets" / preset).formula;
        const ObjectOperation operations[] = {ObjectOperation::Join, ObjectOperation::Carve,
                                              ObjectOperation::Intersect};
        int k = 0;
        for (const ObjectDesc& kind : allObjects()) {
            SceneObject o = SceneObject::make(kind);
            for (size_t i = 0; i < kind.params.size(); ++i)
                if (kind.params[i].type != ParamType::Toggle) o.values[i] *= 0.6;
            o.operation = operations[k % 3];
            o.center = vec3(0.3 * k - 0.6, 0.2, -0.1 * k);
            o.axis = vec3(1.0, 0.5 * k, 0.3);
            o.angle = 17.0 * k;
            o.hollow = k == 2;
            f.objects.push_back(o);
            ++k;
        }
        f.objects.push_back(f.objects.front());
        f.objects.back().enabled = false;
        const Agreement a = compare(f, test::randomPoints(kPoints, 2.0, 12));
        EXPECT_EQ(a.mismatched, 0u) << preset << ": worst error " << a.worstExcess << "x the tolerance at ("
                                    << a.worstPoint.x << ", " << a.worstPoint.y << ", " << a.worstPoint.z << ")";
        expectFewIllConditioned(a, preset);
        EXPECT_GE(a.compared, 10000u) << preset;
    }
}

// add_c in Julia mode (juliabulb.json) and the same formula with the toggle off: the GPU follows
// the CPU in both, and the two differ, so the toggle reaches the shader as the CPU reads it.
TEST(GpuCpuAgreement, AddCJuliaModeAndItsToggle) {
    Preset p = loadPreset(test::sourceDir() / "presets/juliabulb.json");
    p.formula.deFactor = 1.0;
    Node& addC = p.formula.nodes[1];
    ASSERT_EQ(addC.block->id, "add_c");
    const size_t julia = size_t(addC.block->paramIndex("julia"));
    ASSERT_EQ(addC.values[julia].x, 1.0);
    const auto points = test::randomPoints(kPoints, p.formula.boundRadius, 13);
    Formula mandelbrot = p.formula;
    mandelbrot.nodes[1].values[julia].x = 0.0;
    for (const Formula* f : {&p.formula, &mandelbrot}) {
        const std::string what = f == &mandelbrot ? "julia off" : "julia on";
        const Agreement a = compare(*f, points);
        EXPECT_EQ(a.mismatched, 0u) << what << ": worst error " << a.worstExcess << "x the tolerance";
        expectFewIllConditioned(a, what);
        EXPECT_GE(a.compared, 10000u) << what;
        std::printf("%s: %zu points agree, %zu ill-conditioned skipped (%zu inside)\n", what.c_str(), a.compared,
                    a.illConditioned, a.illConditionedInside);
    }
    size_t differ = 0;
    for (size_t i = 0; i < 1000; ++i)
        differ += std::abs(distanceEstimate(p.formula, points[i]) - distanceEstimate(mandelbrot, points[i])) > 1e-3;
    EXPECT_GT(differ, 500u) << "Julia mode hardly changes the estimate";
}

// add_c's Julia switch keyed off at frame 0 and on at frame 4, smoothly: the uniform the GPU
// receives for each frame is off or on, never a value between (a smooth curve passes 0.5 near
// frame 2), so every frame's GPU estimate is bit for bit that of the formula with the switch off
// (frames before 4) or on (from 4).
TEST(GpuCpuAgreement, AnimatedToggleReachesTheGpuOffOrOn) {
    Preset p = loadPreset(test::sourceDir() / "presets/juliabulb.json");
    const size_t julia = size_t(p.formula.nodes[1].block->paramIndex("julia"));
    p.animation.lastFrame = 6;
    p.animation.tracks.push_back(
        Track{"formula.nodes[1].params.julia", Interpolation::Smooth, {Key{0, {0.0}}, Key{4, {1.0}}}});
    Formula off = p.formula, on = p.formula;
    off.nodes[1].values[julia].x = 0.0;
    on.nodes[1].values[julia].x = 1.0;
    test::glContext();
    gl::DEProbe probe(p.formula);
    const auto points = test::randomPoints(512, p.formula.boundRadius, 17);
    const auto distances = [&](const Formula& f) {
        std::vector<float> d;
        for (const gl::GpuSample& s : probe.evaluate(f, points)) d.push_back(s.distance);
        return d;
    };
    const std::vector<float> offDistances = distances(off), onDistances = distances(on);
    ASSERT_NE(offDistances, onDistances);
    for (double frame : {0.0, 1.0, 2.0, 2.5, 3.0, 3.9, 4.0, 5.0}) {
        const std::vector<float> gpu = distances(presetAtFrame(p, frame).formula);
        EXPECT_EQ(gpu, frame < 4.0 ? offDistances : onDistances) << "frame " << frame;
    }
}

TEST(GpuCpuAgreement, EveryShippedPreset) {
    const auto presets = test::shippedPresets();
    ASSERT_GE(presets.size(), 5u);
    for (const auto& path : presets) {
        Preset p = loadPreset(path);
        // The safety factor multiplies both sides alike; comparing the raw estimate keeps the
        // tolerance's absolute floor in the estimate's own units.
        p.formula.deFactor = 1.0;
        const Agreement a = compare(p.formula, test::randomPoints(kPoints, p.formula.boundRadius, 13));
        EXPECT_EQ(a.mismatched, 0u) << path.filename() << ": worst error " << a.worstExcess << "x the tolerance at ("
                                    << a.worstPoint.x << ", " << a.worstPoint.y << ", " << a.worstPoint.z << ")";
        expectFewIllConditioned(a, path.filename().string());
        EXPECT_GE(a.compared, 10000u) << path.filename();
        std::printf("%s: %zu points agree, %zu ill-conditioned skipped\n", path.filename().c_str(), a.compared,
                    a.illConditioned);
    }
}

// Changing a value must not need a new program: the same probe, new values, still agrees.
TEST(GpuCpuAgreement, ValuesAreUniforms) {
    Preset p = loadPreset(test::sourceDir() / "presets/mandelbox.json");
    test::glContext();
    gl::DEProbe probe(p.formula);
    const auto points = test::randomPoints(2000, 4.0, 5);
    for (double scale : {2.0, -1.5, 2.5}) {
        p.formula.nodes[2].values[0].x = scale;
        const auto gpu = probe.evaluate(p.formula, points);
        size_t bad = 0;
        for (size_t i = 0; i < points.size(); ++i) {
            const double cpu = distanceEstimate(p.formula, points[i]);
            bad += !(std::abs(gpu[i].distance - cpu) <= tolerance(cpu));
        }
        EXPECT_EQ(bad, 0u) << "scale " << scale;
    }
}

// The potential estimate needs the product of the power steps' degrees, which the generated
// loop multiplies after each power node (a fixed degree for the Bristorbrot, the power's uniform
// for the bulbs, inside the period test for a node that runs every other iteration), and the
// degrees of the iterations after an escape (for the drawn surface's log radius). On the ball the
// twist-free Bristorbrot draws, radius B^(1 / 2^N), it is half the distance on the GPU too, and on
// a hybrid the GPU agrees with the CPU. (The ball itself is
// not compared at the 1e-4 tolerance: the twist-free Bristorbrot's Jacobian has a double largest
// singular value, where the closed form's acos loses 1.7e-4 of it in single precision, with
// either estimate.)
TEST(GpuCpuAgreement, PotentialEstimateFollowsThePowerDegrees) {
    test::glContext();
    const Formula ball = test::squaringBall(5);
    const double rho = std::pow(ball.bailout, 1.0 / 32.0);
    std::vector<vec3> points;
    for (const vec3& d : test::randomPoints(2000, 1.0, 31))
        if (length(d) > 0.05) points.push_back(normalize(d) * (rho + 0.05 + 1.95 * length(d)));
    gl::DEProbe probe(ball);
    const auto gpu = probe.evaluate(ball, points);
    double worst = 0.0;
    for (size_t i = 0; i < points.size(); ++i)
        worst = std::max(worst, std::abs(double(gpu[i].distance) / (0.5 * (length(points[i]) - rho)) - 1.0));
    EXPECT_LT(worst, 1e-3) << "GPU potential estimate against half the distance to the drawn ball";

    Formula hybrid;
    hybrid.iterations = 8;
    hybrid.bailout = 4.0;
    hybrid.estimator = Node::make(*findBlock("escape_potential"));
    Node box = Node::make(*findBlock("box_fold"));
    box.period = 2;
    Node bulb = Node::make(*findBlock("mandelbulb"));
    bulb.values[0].x = 5.0;
    bulb.period = 2;
    bulb.phase = 1;
    // A pre-transform on the first two iterations only, and a power from the third on: windows.
    Node twist = Node::make(*findBlock("rotate"));
    twist.values[1].x = 30.0;
    twist.stop = 2;
    Node bristor = Node::make(*findBlock("bristorbrot"));
    bristor.start = 3;
    hybrid.nodes = {twist, box, bulb, bristor, Node::make(*findBlock("add_c"))};
    const Agreement a = compare(hybrid, test::randomPoints(kPoints, 2.0, 37));
    EXPECT_EQ(a.mismatched, 0u) << "worst error " << a.worstExcess << "x the tolerance at (" << a.worstPoint.x << ", "
                                << a.worstPoint.y << ", " << a.worstPoint.z << ")";
    EXPECT_GE(a.compared, 9000u);
}

// Inside a Julia bulb whose orbit settles near k = (0, 0.1, 0), the running derivative shrinks by
// about n r^(n-1) = 8e-7 per step, below float's range within the 12 iterations: 0.5 log(r) r / w
// was -inf on the GPU and -1.7e72 on the CPU, neither a distance (a hit refinement stepping by it
// jumps far back along the ray). The points are inside and the estimate is 0 on both.
TEST(GpuCpuAgreement, LogEstimateIsFiniteWhereTheDerivativeUnderflows) {
    test::glContext();
    Formula f;
    f.iterations = 12;
    f.bailout = 2.0;
    Node translate = Node::make(*findBlock("translate"));
    translate.values[0] = vec3(0.0, 0.1, 0.0);
    f.nodes = {Node::make(*findBlock("mandelbulb")), translate};
    f.estimator = Node::make(*findBlock("escape_log"));
    const std::vector<vec3> points{vec3(0.0, 0.1, 0.0), vec3(0.0, 0.3, 0.0), vec3(0.01, 0.2, -0.02)};
    gl::DEProbe probe(f);
    const auto gpu = probe.evaluate(f, points);
    for (size_t i = 0; i < points.size(); ++i) {
        const Evaluation cpu = evaluate(f, points[i]);
        EXPECT_TRUE(cpu.inside) << "point " << i;
        EXPECT_FALSE(gpu[i].escaped) << "point " << i;
        EXPECT_EQ(cpu.distance, 0.0) << "point " << i;
        EXPECT_EQ(gpu[i].distance, 0.0f) << "point " << i;
    }
}
