// Safe distance estimates for any stack: every block's running derivative bounds its Jacobian
// (powers excepted: the Mandelbulb's is its largest stretch, the variants' the analytic scalar
// one), and the estimator and step factor that
// the check chooses for random stacks of shipped blocks never overshoot on rays it did not see,
// without being made safe by being slow.
#include "core/safe_step.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <optional>
#include <random>
#include <string>
#include <string_view>
#include <thread>
#include <utility>

#include "app/editor/document/formula_edits.hpp"
#include "app/editor/document/slow_stack.hpp"
#include "core/cpu_render/cpu_renderer.hpp"
#include "core/preset.hpp"
#include "core/random_vec.hpp"
#include "core/scene/formula_fit.hpp"
#include "editor_test_support.hpp"

using namespace fraktal;

namespace {

// The shipped Amazing Surf at bailout 100, where it shipped before: the 12 iterations leave the
// sheet a thicker slab than at the shipped 20, and the estimate, which sees the sheet,
// overshoots the slab's face on rare rays (1.8-2.2 times the distance at factor 1).
Preset amazingSurfWithAHeavyTail() {
    Preset p = loadPreset(std::string(FRAKTAL_SOURCE_DIR) + "/presets/amazing_surf.json");
    p.formula.bailout = 100.0;
    return p;
}

// Polls the editor's step factor, as its frames do, until the further rounds have ended (a
// deadline, not a count of polls: under the sanitizers the rounds take minutes).
void finishRefining(editor::AutoStepFactor& a, Formula& f, const Camera& camera) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::minutes(10);
    while (a.refining() && std::chrono::steady_clock::now() < end) {
        if (a.update(f, camera)) break;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    ASSERT_FALSE(a.refining()) << "the further rounds did not end in ten minutes";
}

std::vector<const BlockDesc*> stepBlocks() {
    std::vector<const BlockDesc*> out;
    for (const BlockDesc& b : allBlocks())
        if (!b.isEstimator() && !b.custom) out.push_back(&b);
    return out;
}

// A node of `block` with every parameter drawn uniformly from its declared range. On/off
// parameters keep their defaults, and so do those only a toggle turns on (add_c's julia_c): a
// Julia mode with a constant drawn from the range is mostly dust (outside the connectedness
// locus), where no step factor is safe.
Node randomNode(const BlockDesc& block, std::mt19937_64& rng) {
    Node n = Node::make(block);
    for (size_t i = 0; i < block.params.size(); ++i) {
        const ParamDecl& d = block.params[i];
        std::uniform_real_distribution<double> u(d.min, d.max);
        if (d.type == ParamType::Toggle || d.name.starts_with("julia")) continue;
        n.values[i] = d.type == ParamType::Float ? vec3(u(rng), 0.0, 0.0) : randomVec3(u, rng);
    }
    return n;
}

// splitmix64's finaliser (Steele, Lea and Flood, "Fast splittable pseudorandom number
// generators", OOPSLA 2014): a well-mixed 64-bit number from any other.
uint64_t mixed(uint64_t x) {
    x += 0x9e3779b97f4a7c15ull;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
    return x ^ (x >> 31);
}

// A seed for `name` under `seed` (FNV-1a over the name's bytes, then mixed).
uint64_t keyed(uint64_t seed, std::string_view name) {
    uint64_t h = 0xcbf29ce484222325ull;
    for (const char c : name) h = (h ^ uint64_t(uint8_t(c))) * 0x100000001b3ull;
    return mixed(h ^ mixed(seed));
}

// Slot `slot` of the stack seeded `stackSeed`, drawn from `blocks`, so that the draws stay the
// same as the registry and the blocks' parameter lists grow. The block is the one whose key for
// the slot is the largest (rendezvous hashing: a block added to the registry takes the slots
// where its own key is the largest, about one in the number of blocks, and leaves the others
// as they were). Each parameter is drawn uniformly from its range by a generator of its own,
// keyed by the slot, the block and the parameter's name (a parameter added to a block leaves the
// other parameters' draws as they were). On/off parameters are drawn too, except a Julia mode
// and what only it turns on (add_c's julia and julia_c, add_c_axes's): with a constant drawn from
// the range the object is mostly dust (outside the connectedness locus), where no step factor
// is safe and `fraktal check` says NOT SOUND.
Node drawnNode(const std::vector<const BlockDesc*>& blocks, uint64_t stackSeed, int slot) {
    const uint64_t slotSeed = mixed(stackSeed ^ mixed(uint64_t(slot)));
    const BlockDesc* block = nullptr;
    uint64_t largest = 0;
    for (const BlockDesc* b : blocks)
        if (const uint64_t key = keyed(slotSeed, b->id); !block || key > largest) block = b, largest = key;
    Node n = Node::make(*block);
    for (size_t i = 0; i < block->params.size(); ++i) {
        const ParamDecl& d = block->params[i];
        if (d.name.starts_with("julia")) continue;
        std::mt19937_64 rng(keyed(largest, d.name));
        if (d.type == ParamType::Toggle) {
            n.values[i].x = double(rng() & 1u);
            continue;
        }
        std::uniform_real_distribution<double> u(d.min, d.max);
        n.values[i] = d.type == ParamType::Float ? vec3(u(rng), 0.0, 0.0) : randomVec3(u, rng);
    }
    return n;
}

// Where one step of `block` (node n's values) takes the point q, with the point c it sees.
vec3 stepImage(const BlockDesc& block, const Node& n, const vec3& c, const vec3& q) {
    P4 s{q, 1.0};
    block.apply(s, c, n.args());
    return s.xyz;
}

std::string describe(const Formula& f) {
    std::string s;
    for (const Node& n : f.nodes) {
        s += std::string(n.block->id) + "(";
        for (size_t i = 0; i < n.values.size(); ++i) {
            char buf[96];
            const vec3& v = n.values[i];
            if (isScalar(n.block->params[i].type))
                std::snprintf(buf, sizeof buf, "%s%.3g", i ? ", " : "", v.x);
            else
                std::snprintf(buf, sizeof buf, "%s(%.3g %.3g %.3g)", i ? ", " : "", v.x, v.y, v.z);
            s += buf;
        }
        s += ") ";
    }
    return s + "=> " + std::string(f.estimator.block->id);
}

double percentile(std::vector<double> v, double q) {
    if (v.empty()) return 0.0;
    const size_t k = std::min(v.size() - 1, size_t(q * double(v.size() - 1) + 0.5));
    std::nth_element(v.begin(), v.begin() + long(k), v.end());
    return v[k];
}

void printDistribution(const char* what, const std::vector<double>& v) {
    std::printf("%-34s n=%-7zu min %.3f  p1 %.3f  p10 %.3f  p25 %.3f  median %.3f  p75 %.3f  p90 %.3f  max %.3f\n",
                what, v.size(), percentile(v, 0.0), percentile(v, 0.01), percentile(v, 0.1), percentile(v, 0.25),
                percentile(v, 0.5), percentile(v, 0.75), percentile(v, 0.9), percentile(v, 1.0));
}

}  // namespace

// The running derivative is the Lipschitz bound the estimators divide by: for every fold and
// transform, at random points and random in-range parameters, the Jacobian's largest stretch
// (finite differences, along random directions) stays within the factor the block applies to
// p.w. Points on a fold's crease (where the two one-sided differences disagree) are skipped. The
// derivative tweak (Mandelbulber2's DE tweak) and the transforms with Mandelbulber2's derivative
// (an mb2_derivative toggle) lower p.w on purpose where their parameters say so (the tweak's bound
// is then None, the toggle is on): those trials are skipped, the others held to the rule, a block
// whose map jumps (its bound None for that) included: a jump is a crease, skipped as above.
TEST(SafeStep, EveryFoldAndTransformBoundsItsJacobian) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const vec3 c(0.3, -0.2, 0.1);
    for (const BlockDesc* block : stepBlocks()) {
        if (block->category == Category::Power) continue;
        int compared = 0;
        for (int trial = 0; trial < 400; ++trial) {
            const Node n = randomNode(*block, rng);
            const int mb2Derivative = block->paramIndex("mb2_derivative");
            const bool lowersOnPurpose = block->id == "derivative_tweak"
                                             ? block->derivativeAt(n.args()) == DerivativeBound::None
                                             : mb2Derivative >= 0 && n.args().f(mb2Derivative) > 0.5;
            if (lowersOnPurpose) continue;
            const vec3 x = randomVec3(u, rng) * 2.5;
            vec3 dir = randomVec3(u, rng);
            if (length(dir) < 1e-3) continue;
            dir = normalize(dir);
            P4 p{x, 1.0};
            block->apply(p, c, n.args());
            auto image = [&](const vec3& q) { return stepImage(*block, n, c, q); };
            const double h = 1e-6;
            const double forward = length(image(x + dir * h) - p.xyz) / h;
            const double backward = length(p.xyz - image(x - dir * h)) / h;
            if (std::abs(forward - backward) > 1e-3 * std::max(1.0, forward) || !std::isfinite(forward)) continue;
            ++compared;
            ASSERT_LE(forward, std::abs(p.w) * (1.0 + 1e-4) + 1e-6)
                << block->id << " stretches by " << forward << " but p.w becomes " << p.w << " at (" << x.x << ", "
                << x.y << ", " << x.z << ")";
        }
        EXPECT_GT(compared, 100) << block->id;
    }
}

// A block declared DerivativeBound::Global applies the same factor at every point, and it bounds
// the stretch between any two points, not only at each: for random pairs up to 1.7 apart (random
// in-range parameters), |F(x) - F(y)| <= |x - y| times the factor. A map whose stretch varies
// with position (a sphere fold) or that jumps (a wrap, a conditional shift) fails here, and must
// say Local or None.
TEST(SafeStep, GlobalBoundsHoldBetweenDistantPoints) {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const vec3 c(0.3, -0.2, 0.1);
    int blocks = 0;
    for (const BlockDesc* block : stepBlocks()) {
        if (block->derivative != DerivativeBound::Global) continue;
        ++blocks;
        for (int trial = 0; trial < 4000; ++trial) {
            const Node n = randomNode(*block, rng);
            const vec3 x = randomVec3(u, rng) * 3.0;
            const vec3 y = x + randomVec3(u, rng) * (trial % 2 ? 1.0 : 0.05);
            P4 px{x, 1.0}, py{y, 1.0};
            block->apply(px, c, n.args());
            block->apply(py, c, n.args());
            ASSERT_EQ(px.w, py.w) << block->id << ": a Global factor is the same at every point";
            ASSERT_LE(length(px.xyz - py.xyz), px.w * length(x - y) * (1.0 + 1e-9) + 1e-12)
                << block->id << " moves (" << x.x << ", " << x.y << ", " << x.z << ") and (" << y.x << ", " << y.y
                << ", " << y.z << ") further apart than its factor " << px.w << " allows";
        }
    }
    EXPECT_GE(blocks, 12);
}

// The power blocks whose factor is a bound (the Mandelbulb and the cosine bulb at integer powers,
// the Bristorbrot at any twist): along random directions at random points of the ball of radius
// 1.5, the stretch by central differences stays within p.w.
TEST(SafeStep, PowerBlocksBoundTheirJacobianAtIntegerPowers) {
    std::mt19937_64 rng(13);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const vec3 c(0.0);
    for (const char* id : {"mandelbulb", "mandelbulb_cosine", "bristorbrot"}) {
        const BlockDesc& block = *findBlock(id);
        int compared = 0;
        for (int trial = 0; trial < 3000; ++trial) {
            Node n = randomNode(block, rng);
            if (block.paramIndex("power") >= 0) n.values[size_t(block.paramIndex("power"))].x = double(2 + trial % 11);
            const vec3 x = randomVec3(u, rng) * 1.5;
            const vec3 dir = randomVec3(u, rng);
            if (length(x) < 0.05 || length(dir) < 1e-3) continue;
            P4 p{x, 1.0};
            block.apply(p, c, n.args());
            auto image = [&](const vec3& q) { return stepImage(block, n, c, q); };
            const double h = 1e-6;
            const vec3 d = normalize(dir);
            const double stretch = length(image(x + d * h) - image(x - d * h)) / (2.0 * h);
            ++compared;
            ASSERT_LE(stretch, p.w * (1.0 + 1e-4))
                << id << " at (" << x.x << ", " << x.y << ", " << x.z << "), parameters " << n.values[0].x;
        }
        EXPECT_GT(compared, 2500) << id;
    }
}

// Where the check's explanation names no block for a slow stack (explainSlowStack: no stack
// without one of its steps marches kFasterBy faster, and no step declares a jump or a growing
// stretch): the one step of a stack of one, or the one step that every stack without one of the
// others keeps where it measures (still slow, then: the slowness stays with that step); where
// those stacks keep more than one step, the kept step that the check names in one of them (a
// 4D turn beside a Menger step and a dIFS cylinder: without the plane fold between them the
// check names the turn, and without the turn or the Menger step there is no object); -1 when
// none stands out. `measured`: whether any stack without one of the steps could be measured.
int stepTheSlownessStaysWith(const Formula& f, const Camera& camera, const SafeStepOptions& options, bool& measured) {
    measured = false;
    if (f.nodes.size() == 1) return 0;
    std::vector<int> keptByEvery(f.nodes.size(), 1);
    std::vector<std::pair<size_t, Formula>> measuredWithout;  // the step taken out, the stack fitted
    for (size_t k = 0; k < f.nodes.size(); ++k) {
        Formula without = f;
        without.nodes.erase(without.nodes.begin() + long(k));
        if (!canBoundEscape(without.nodes)) continue;
        std::optional<Formula> fitted = fittedAndMeasured(without, camera, options);
        if (!fitted) continue;
        measured = true;
        keptByEvery[k] = 0;
        measuredWithout.emplace_back(k, std::move(*fitted));
    }
    const long kept = std::count(keptByEvery.begin(), keptByEvery.end(), 1);
    if (!measured || kept == 0) return -1;
    if (kept == 1) return int(std::find(keptByEvery.begin(), keptByEvery.end(), 1) - keptByEvery.begin());
    for (const auto& [k, without] : measuredWithout) {
        const SlowStack why = explainSlowStack(without, camera, options);
        if (why.block < 0) continue;
        const size_t step = size_t(why.block) + (size_t(why.block) >= k ? 1 : 0);
        if (keptByEvery[step]) return int(step);
    }
    return -1;
}

// Steps the random stacks below leave out, each for its reason. Every other step of the registry
// (allBlocks, estimators and custom blocks aside) is drawn. None at present: a dIFS shape stands
// in a stack closed by the dIFS estimate (and is an identity under any other), start_w and the
// 4D steps stand anywhere (w starts at 0 without start_w), and a Julia mode is left off by the
// draw (drawnNode), not the block.
const std::map<std::string_view, std::string_view>& stepsNotDrawn() {
    static const std::map<std::string_view, std::string_view> notDrawn{};
    return notDrawn;
}

// The random stacks the next test measures: `wanted` stacks of draws from `seed` (drawnNode), each
// with the check's estimator and factor applied; the draws that were drawn again are counted.
struct CheckedStack {
    uint64_t draw = 0;
    Formula formula;  // with the check's estimator and step factor
    double speed = 0.0, checkedWorst = 0.0;
};
struct StackDraws {
    std::vector<CheckedStack> stacks;
    int refused = 0, redrawn = 0, unsound = 0;
};
StackDraws drawCheckedStacks(const std::vector<const BlockDesc*>& blocks, uint64_t seed, int wanted,
                             const Camera& camera, const SafeStepOptions& check) {
    StackDraws out;
    for (uint64_t draw = 0; int(out.stacks.size()) < wanted && draw < 4000u; ++draw) {
        const uint64_t stackSeed = mixed(seed ^ mixed(draw));
        Formula f;
        f.iterations = 6;
        f.bailout = 4.0;
        f.boundRadius = 3.0;
        f.estimator = Node::make(*findBlock("escape_log"));
        for (int slot = 0, count = 1 + int(stackSeed % 4); slot < count; ++slot)
            f.nodes.push_back(drawnNode(blocks, stackSeed, slot));
        if (!canBoundEscape(f.nodes)) {
            ++out.refused;  // a preset with this stack is refused
            continue;
        }
        if (std::any_of(f.nodes.begin(), f.nodes.end(), [](const Node& n) { return n.block->difsShape; }))
            f.estimator = Node::make(*findBlock("difs"));
        fitEstimatorToBlocks(f);
        const std::vector<EstimatorMeasurement> options = compareEstimators(f, camera, check);
        if (!hasSafeStepFactor(options.front())) {
            ++out.unsound;  // the estimate overflows, or overshoots more than any factor makes up for
            continue;
        }
        if (options.front().report.samples == 0) {
            ++out.redrawn;
            continue;
        }
        Formula g = f;
        g.estimator = options.front().estimator;
        g.deFactor = options.front().factor;
        out.stacks.push_back({draw, g, options.front().speed(), options.front().report.worstRatio});
    }
    return out;
}

// Random stacks of 1-4 steps drawn from every step block in the registry (stepsNotDrawn aside),
// with random in-range parameters (drawnNode: seeded per stack, slot and parameter), built as the
// editor and the import build them: a stack with a dIFS shape closed by the dIFS estimate (as the
// import closes a dIFS formula), any other by the log estimate, then its estimator and bailout
// fitted as the editor fits them after a structure change (fitEstimatorToBlocks: power stacks
// keep the log estimate, stacks that add c get the linear one, pure IFS stacks a distance
// estimate, a box unless they have one). The bound stays 3 and the camera at (0, 0, 6): the
// editor's bound fit (fitFormulaAfterEdit) took some 50 s more over the stacks drawn.
// For each, the check's choice (compareEstimators on its own rays: the own, linear, log,
// potential and gradient estimates, or a primitive and its gradient twin, the twins' speed
// weighed by their five orbits) is applied at the factor the editor ends with: the settled
// rounds', or, where the rays' tail calls for them, the further rounds' (`fraktal check`'s, which
// the editor applies when they end; with the bound fitted, the settled rounds' factor of a
// box_fold_soft and a Benesi pine tree overshot other rays 8x, the further rounds' did not). On
// other rays every sampled DE * factor stays at or under the true distance along the ray
// (baseline marcher with bisection). Stacks a preset may not hold (no power, fold or scale:
// canBoundEscape), stacks the check reports NOT SOUND (no safe step factor) and stacks whose
// object the check's rays never reach from outside (nothing inside the bound, or everything)
// are drawn again.
// The distributions of the step factor and the speed (factor x median per orbit) are printed.
// Not safe by being slow: the median over the stacks of each one's worst DE * factor / true
// distance on the other rays is above 0.4 (it is 0.54). Many of the blocks added after the first
// 28 have estimates far looser than theirs, so the median of every sample (0.53 over stacks of
// those 28 alone, 0.28 here) says more of the estimates than of the margins.
// The ten slowest stacks are printed with their blocks, and every stack whose median is under
// 0.02 must have its cause named: by the check's explanation (explainSlowStack: the block that
// keeps it slow, or a faster estimator), or, where that names neither (a stack of one step, or
// one whose parts alone are refused, have no object, or are as slow), by the step the slowness
// stays with (stepTheSlownessStaysWith). Where no stack without one of the steps has an object
// to measure there is nothing to compare: those are counted and printed (2 of 150: a dIFS grid
// whose divisor of 15 w + 7 keeps its estimate far under the distance, and add_c beside a
// tetrahedral KIFS), and any other unnamed stack fails.
TEST(SafeStep, RandomStacksWithTheCheckedFactorNeverOvershoot) {
    std::vector<const BlockDesc*> blocks;
    for (const BlockDesc* b : stepBlocks())
        if (!stepsNotDrawn().contains(b->id)) blocks.push_back(b);
    for (const auto& [id, why] : stepsNotDrawn()) {
        ASSERT_TRUE(findBlock(id)) << "not drawn, yet not registered: " << id;
        std::printf("not drawn: %s: %s\n", std::string(id).c_str(), std::string(why).c_str());
    }
    const uint64_t seed = 20;
    const int wanted = 150;
    Camera camera;
    camera.position = vec3(0.0, 0.0, 6.0);
    SafeStepOptions check;
    check.rays = {64, 1200, 1};
    // The settled rounds, and the further rounds where the rays' tail calls for them (the
    // check's SafeStepOptions::tailRounds: tested below).
    const ConservativenessOptions fresh{16, 1200, 99};

    std::vector<double> ratios, stackMedians, stackWorst, factors, speeds;
    struct Stack {
        double median;
        Formula formula;
    };
    std::vector<Stack> measuredStacks;
    std::map<std::string, int> chosen, drawn;
    std::map<DerivativeBound, int> bounds;
    const StackDraws draws = drawCheckedStacks(blocks, seed, wanted, camera, check);
    ASSERT_EQ(draws.stacks.size(), size_t(wanted)) << "too few stacks with an object to measure";
    const int refused = draws.refused, redrawn = draws.redrawn, unsound = draws.unsound;
    int stacks = 0, overshooting = 0;
    for (const CheckedStack& checked : draws.stacks) {
        ++stacks;
        const uint64_t draw = checked.draw;
        const Formula& g = checked.formula;
        ++chosen[std::string(g.estimator.block->id)];
        ++bounds[derivativeBound(g.nodes)];
        for (const Node& n : g.nodes) ++drawn[std::string(n.block->id)];
        factors.push_back(g.deFactor);
        speeds.push_back(checked.speed);

        CpuSampler sampler(g);
        const RaySamples samples = sampleRays(sampler, camera, fresh);
        std::vector<double> mine;
        for (size_t i = 0; i < samples.points.size(); ++i) {
            const double ratio = distanceEstimate(g, samples.points[i]) / samples.distances[i];
            mine.push_back(std::isnan(ratio) ? INFINITY : ratio);
        }
        if (mine.empty()) continue;
        ratios.insert(ratios.end(), mine.begin(), mine.end());
        stackMedians.push_back(percentile(mine, 0.5));
        measuredStacks.push_back({stackMedians.back(), g});
        const double worst = *std::max_element(mine.begin(), mine.end());
        stackWorst.push_back(worst);
        if (worst > 1.0) ++overshooting;
        EXPECT_LE(worst, 1.0) << "stack " << stacks << " (draw " << draw << "): " << describe(g) << " with factor "
                              << g.deFactor << " (the check's worst " << checked.checkedWorst << ")";
    }
    std::printf(
        "%d stacks of %zu step blocks (drawn again: %d a preset refuses, %d with no surface the rays reach from "
        "outside, %d with no safe step factor), %d overshooting\n",
        stacks, blocks.size(), refused, redrawn, unsound, overshooting);
    for (const auto& [id, count] : chosen) std::printf("  estimator %s chosen for %d\n", id.c_str(), count);
    std::printf("  steps' derivative bound: global %d, local %d, jumps %d\n", bounds[DerivativeBound::Global],
                bounds[DerivativeBound::Local], bounds[DerivativeBound::None]);
    std::string never;
    for (const BlockDesc* b : blocks)
        if (!drawn.contains(std::string(b->id))) never += " " + std::string(b->id);
    std::printf("  steps in no measured stack:%s\n", never.empty() ? " none" : never.c_str());
    printDistribution("DE * factor / true distance", ratios);
    printDistribution("per-stack median ratio", stackMedians);
    printDistribution("per-stack worst ratio", stackWorst);
    printDistribution("step factor", factors);
    printDistribution("speed (factor x median per orbit)", speeds);
    EXPECT_GT(ratios.size(), 20000u);
    EXPECT_GT(percentile(stackWorst, 0.5), 0.4) << "safe only by being slow";

    // The slowest stacks, and why: a stack whose typical step covers under 2 % of the gap must
    // have a cause the check names (a block that keeps the estimate loose, by measurement or by
    // its declared jump, or a faster estimator), so that the artist is told what to change.
    std::sort(measuredStacks.begin(), measuredStacks.end(),
              [](const Stack& a, const Stack& b) { return a.median < b.median; });
    const SafeStepOptions editorOptions = editor::AutoStepFactor::options();
    int namedByTheTest = 0, nothingToCompare = 0;
    for (size_t i = 0; i < measuredStacks.size() && (i < 10 || measuredStacks[i].median < 0.02); ++i) {
        const Stack& slow = measuredStacks[i];
        std::printf("slow stack %zu: median DE * factor / true distance %.4f, factor %.3f, bailout %g: %s\n", i + 1,
                    slow.median, slow.formula.deFactor, slow.formula.bailout, describe(slow.formula).c_str());
        if (slow.median >= 0.02) continue;
        const SlowStack why = explainSlowStack(slow.formula, camera, editorOptions);
        std::printf("  why: %s\n", why.text(slow.formula).c_str());
        if (why.block >= 0 || why.faster) continue;
        // Named by neither: every stack without one of the steps is refused, has no object, or is
        // no kFasterBy faster. The slowness then stays with the step every measured one keeps;
        // where none of them measures there is nothing to compare with, and the stack is counted.
        bool measured = false;
        const int step = stepTheSlownessStaysWith(slow.formula, camera, editorOptions, measured);
        if (step >= 0) {
            ++namedByTheTest;
            std::printf("  the check names no block; every stack without one step that measures keeps step %d (%s)\n",
                        step + 1, std::string(slow.formula.nodes[size_t(step)].block->id).c_str());
            continue;
        }
        if (!measured) {
            ++nothingToCompare;
            std::printf("  the check names no block; no stack without one of its steps has an object to measure\n");
            continue;
        }
        ADD_FAILURE() << "a stack under 0.02 whose cause is not named: " << describe(slow.formula);
    }
    std::printf(
        "stacks under 0.02 the check names no block or estimator for: %d where every stack without one step that "
        "measures keeps the same step, %d where none of those has an object to measure\n",
        namedByTheTest, nothingToCompare);
}

// Measurement, not run by CI (DISABLED_): the adaptive step (shaders/march.glsl, its CPU mirror)
// on the random stacks above at the check's factor, as bench/stills/overshoot_pixels.sh measures
// the presets. Each stack is rendered by the CPU reference at 64x36 from the test's camera, without
// shadows or AO, at each maximum step growth, and against a reference at a quarter of the factor
// and of the hit threshold with plain steps; DE evaluations per pixel, and pixels that miss what
// the reference meets or land more than 10 % behind it, summed over the stacks.
//   build/tests/fraktal_tests --gtest_also_run_disabled_tests
//       --gtest_filter=SafeStep.DISABLED_AdaptiveStepOnRandomStacks
TEST(SafeStep, DISABLED_AdaptiveStepOnRandomStacks) {
    std::vector<const BlockDesc*> blocks;
    for (const BlockDesc* b : stepBlocks())
        if (!stepsNotDrawn().contains(b->id)) blocks.push_back(b);
    Camera camera;
    camera.position = vec3(0.0, 0.0, 6.0);
    SafeStepOptions check;
    check.rays = {64, 1200, 1};
    const StackDraws draws = drawCheckedStacks(blocks, 20, 200, camera, check);
    const std::vector<double> growths{1.0, 1.9, 4.0, 16.0};
    RenderSettings render;
    render.width = 64;
    render.height = 36;
    render.maxSteps = 6000;
    ShadingSettings shading;
    shading.shadowSteps = 0;
    shading.aoSteps = 0;
    struct Totals {
        double evalsAll = 0.0, evalsSlow = 0.0;
        long missed = 0, behind = 0;
        std::vector<double> ratios;
    };
    std::vector<Totals> totals(growths.size());
    long referenceHits = 0;
    int slowStacks = 0;
    for (const CheckedStack& stack : draws.stacks) {
        const auto meanEvals = [](const ImageStrip& image) {
            double sum = 0.0;
            for (size_t i = 0; i < image.stats.size(); i += 4) sum += image.stats[i];
            return sum / double(image.stats.size() / 4);
        };
        Formula reference = stack.formula;
        reference.deFactor /= 4.0;
        RenderSettings plain = render;
        plain.detail /= 4.0;
        plain.overRelaxation = 1.0;
        plain.maxStepGrowth = 1.0;
        const ImageStrip truth = renderReference(reference, camera, plain, resolveShading(shading, plain, reference));
        const bool slow = stack.formula.deFactor < 0.3;
        slowStacks += slow;
        double firstEvals = 0.0;
        for (size_t g = 0; g < growths.size(); ++g) {
            RenderSettings r = render;
            r.maxStepGrowth = growths[g];
            const ImageStrip image =
                renderReference(stack.formula, camera, r, resolveShading(shading, r, stack.formula));
            const double evals = meanEvals(image);
            if (g == 0) firstEvals = evals;
            totals[g].evalsAll += evals;
            if (slow) totals[g].evalsSlow += evals;
            totals[g].ratios.push_back(firstEvals / evals);
            for (size_t i = 3; i < truth.normalDepth.size(); i += 4) {
                const float want = truth.normalDepth[i], got = image.normalDepth[i];
                if (want >= 1e29f) continue;
                if (g == 0) ++referenceHits;
                if (got >= 1e29f)
                    ++totals[g].missed;
                else if (got > 1.1f * want)
                    ++totals[g].behind;
            }
        }
    }
    std::printf("%zu stacks (%d at a factor under 0.3), %ld reference hit pixels\n", draws.stacks.size(), slowStacks,
                referenceHits);
    for (size_t g = 0; g < growths.size(); ++g) {
        std::printf(
            "max step growth %g: DE/px %.1f (all), %.1f (factor < 0.3); fewer than growth 1: median %.2fx, p10 %.2fx, "
            "p90 %.2fx; missed %ld, behind %ld\n",
            growths[g], totals[g].evalsAll / double(draws.stacks.size()), totals[g].evalsSlow / std::max(slowStacks, 1),
            percentile(totals[g].ratios, 0.5), percentile(totals[g].ratios, 0.1), percentile(totals[g].ratios, 0.9),
            totals[g].missed, totals[g].behind);
    }
}

// The projection from the sampled rays' tail (projectedWorst), on draws whose worst over 10000
// rays is known by drawing them: where the ratio has a ceiling (the escape-time estimates near
// the surface) it stays within a few percent of the ceiling, so the factor is not made small by
// a margin the rays do not call for; a tail that thins out (uniform) gets a moderate margin; a
// heavy tail (Pareto, as after a Kleinian wrap) is projected far beyond the sampled worst,
// which alone would rarely cover the fresh rays; and one ray far above others at a ceiling (a
// rare overshoot) raises the projection well above that ray.
// The check's rays are marched on several threads (ConservativenessOptions::threads): on every
// shipped 3D preset the samples, their true distances and the rays' ends are the same, bit for
// bit, as on one thread.
TEST(SafeStep, RaysMarchedOnSeveralThreadsGiveTheSameSamples) {
    int compared = 0;
    for (const auto& file : test::shippedPresets()) {
        const Preset preset = loadPreset(file.string());
        CpuSampler sampler(preset.formula);
        ConservativenessOptions one{24, 600, 7, 1}, several{24, 600, 7, 3};
        const RaySamples a = sampleRays(sampler, preset.camera, one), b = sampleRays(sampler, preset.camera, several);
        SCOPED_TRACE(file.filename().string());
        EXPECT_EQ(a.rays, b.rays);
        EXPECT_EQ(a.raysHit, b.raysHit);
        EXPECT_EQ(a.rayEnds, b.rayEnds);
        EXPECT_EQ(a.distances, b.distances);
        ASSERT_EQ(a.points.size(), b.points.size());
        for (size_t i = 0; i < a.points.size(); ++i) ASSERT_EQ(a.points[i], b.points[i]) << "sample " << i;
        compared += a.raysHit > 0;
    }
    EXPECT_GT(compared, 10) << "too few presets whose rays meet the object";
}

TEST(SafeStep, TheSampledRaysTailProjectsTheWorstOverMoreRays) {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    // What each tail must show: trials of kTrials where the projection covers the worst of the
    // fresh draws, the median of projected / fresh worst, trials where the sampled worst covers.
    struct Tail {
        const char* name;
        std::function<double()> draw;
        int minProjectionCovers;
        double maxMedianOverFresh;
        int maxSampledCovers;
    };
    constexpr int kRays = 128, kTrials = 200, kAhead = 10000;
    const std::vector<Tail> tails{
        {"ceiling", [&] { return 0.5 * (1.0 - 0.2 * std::pow(u(rng), 3.0)); }, kTrials * 95 / 100, 1.05, kTrials},
        {"uniform", [&] { return 0.25 + 0.25 * u(rng); }, kTrials, 1.6, kTrials},
        {"pareto", [&] { return std::pow(1.0 - u(rng), -0.5); }, kTrials / 2, INFINITY, kTrials / 10 - 1},
    };
    for (const Tail& tail : tails) {
        int projectionCovers = 0, sampledCovers = 0;
        std::vector<double> overFresh;
        for (int trial = 0; trial < kTrials; ++trial) {
            ConservativenessReport r;
            for (int i = 0; i < kRays; ++i) r.rayWorst.push_back(tail.draw());
            std::sort(r.rayWorst.begin(), r.rayWorst.end(), std::greater<>());
            r.worstRatio = r.rayWorst.front();
            double fresh = 0.0;
            for (int i = 0; i < kAhead; ++i) fresh = std::max(fresh, tail.draw());
            const double projected = projectedWorst(r, kAhead);
            EXPECT_GE(projected, r.worstRatio);
            projectionCovers += projected >= fresh;
            sampledCovers += r.worstRatio >= fresh;
            overFresh.push_back(projected / fresh);
        }
        const double median = percentile(overFresh, 0.5);
        std::printf(
            "%-8s: the projection covers %d of %d trials (the sampled worst %d), projected / fresh worst median %.3f\n",
            tail.name, projectionCovers, kTrials, sampledCovers, median);
        EXPECT_GE(projectionCovers, tail.minProjectionCovers) << tail.name;
        EXPECT_LT(median, tail.maxMedianOverFresh) << tail.name;
        EXPECT_LE(sampledCovers, tail.maxSampledCovers) << tail.name;
    }

    ConservativenessReport outlier;
    for (int i = 0; i < kRays; ++i) outlier.rayWorst.push_back(0.95 + 0.05 * u(rng));
    outlier.rayWorst.push_back(1.12);
    std::sort(outlier.rayWorst.begin(), outlier.rayWorst.end(), std::greater<>());
    outlier.worstRatio = outlier.rayWorst.front();
    EXPECT_GT(projectedWorst(outlier, kAhead), 1.3);

    ConservativenessReport few;
    few.rayWorst = {0.5, 0.4, 0.3};
    few.worstRatio = 0.5;
    EXPECT_EQ(projectedWorst(few, kAhead), 1.0) << "too few rays for a tail: twice the worst";
}

// `fraktal check` goes on sampling while the fixed margin does not cover the worst the rays'
// tail projects (SafeStepOptions::tailRounds). The Amazing Surf's worst rays at bailout 100 are
// rare (amazingSurfWithAHeavyTail): the settled rounds (the editor's quick measurement) see 1.48
// at factor 1 and allow a factor that 2000 other rays find overshooting; the check's further
// rounds find the heavier tail and a factor those rays do not overshoot. A proven bound (the
// Menger sponge's box) gets no more rays.
TEST(SafeStep, CheckSamplesMoreRaysWhereTheTailIsHeavy) {
    const Preset surf = amazingSurfWithAHeavyTail();
    SafeStepOptions check;
    check.rays.stepsAcrossBound = 4000;  // `fraktal check`'s default --steps
    SafeStepOptions quick = check;
    quick.tailRounds = 0;
    const EstimatorMeasurement settled = measureSafeStep(surf.formula, surf.camera, quick);
    const EstimatorMeasurement full = measureSafeStep(surf.formula, surf.camera, check);
    std::printf(
        "amazing_surf: settled rounds %d rays, worst %.3f at factor 1, factor %.3f; with the tail's rounds %d "
        "rays, worst %.3f, factor %.3f\n",
        settled.report.rays, settled.report.worstRatio, settled.factor, full.report.rays, full.report.worstRatio,
        full.factor);
    EXPECT_GT(full.report.rays, 4 * settled.report.rays);
    EXPECT_GT(full.report.worstRatio, settled.report.worstRatio);
    EXPECT_LT(full.factor, settled.factor);

    Formula f = surf.formula;
    const ConservativenessOptions other{2000, 4000, 11};
    f.deFactor = settled.factor;
    const double settledFresh = checkConservativeness(f, surf.camera, other).worstRatio;
    f.deFactor = full.factor;
    const double fullFresh = checkConservativeness(f, surf.camera, other).worstRatio;
    std::printf("on 2000 other rays: worst DE / true distance %.3f at the settled factor, %.3f at the check's\n",
                settledFresh, fullFresh);
    EXPECT_GT(settledFresh, 1.0) << "the settled rounds' factor was expected to overshoot here";
    EXPECT_LE(fullFresh, 1.0);

    const Preset menger = loadPreset(std::string(FRAKTAL_SOURCE_DIR) + "/presets/menger.json");
    ASSERT_TRUE(check.proven(*menger.formula.estimator.block, menger.formula.nodes));
    EXPECT_EQ(measureSafeStep(menger.formula, menger.camera, check).report.rays,
              measureSafeStep(menger.formula, menger.camera, quick).report.rays);
}

// The check measures every estimator next to its gradient twin (escape_gradient beside the
// escape-time ones, box_gradient beside a box), with the twin's parameters those of the
// estimator it differentiates, and weighs the twin's speed by the five orbits it runs. A gradient
// estimate is measured, never proven: after Global steps (the Menger sponge) the box is a bound
// and keeps factor 1 whatever the rays show, its gradient twin only the factor its rays allow.
TEST(SafeStep, GradientEstimatesAreMeasuredBesideTheirTwinsAtTheirCost) {
    const Camera camera = [] {
        Camera c;
        c.position = vec3(0.0, 0.0, 6.0);
        return c;
    }();
    SafeStepOptions check;
    check.rays = {64, 1200, 1};

    Formula menger = loadPreset(std::string(FRAKTAL_SOURCE_DIR) + "/presets/menger.json").formula;
    ASSERT_EQ(menger.estimator.block->id, "box");
    menger.estimator.values[0] = ParamValue(0.9, 1.0, 1.1);
    const std::vector<EstimatorMeasurement> ifs = compareEstimators(menger, camera, check);
    ASSERT_EQ(ifs.size(), 2u);
    const EstimatorMeasurement& box = ifs[0].estimator.block->id == "box" ? ifs[0] : ifs[1];
    const EstimatorMeasurement& twin = &box == &ifs[0] ? ifs[1] : ifs[0];
    ASSERT_EQ(twin.estimator.block->id, "box_gradient");
    EXPECT_EQ(twin.estimator.values, menger.estimator.values) << "the twin measures the same box";
    EXPECT_TRUE(check.proven(*box.estimator.block, menger.nodes));
    EXPECT_FALSE(check.proven(*twin.estimator.block, menger.nodes));
    EXPECT_GE(box.factor, 0.99);
    EXPECT_GT(twin.report.worstRatio, 1.0) << "the gradient across the sponge's folds is no bound";
    EXPECT_EQ(twin.factor, check.factorFor(twin.report, *twin.estimator.block, menger.nodes));
    EXPECT_GE(twin.factor, safeStepFactor(twin.report.worstRatio, check.margin));
    EXPECT_DOUBLE_EQ(twin.speed(), twin.factor * twin.report.medianRatio / 5.0);
    EXPECT_DOUBLE_EQ(box.speed(), box.factor * box.report.medianRatio);

    Formula bulb = loadPreset(std::string(FRAKTAL_SOURCE_DIR) + "/presets/mandelbulb.json").formula;
    std::vector<std::string> ids;
    for (const EstimatorMeasurement& m : compareEstimators(bulb, camera, check))
        ids.push_back(std::string(m.estimator.block->id));
    std::sort(ids.begin(), ids.end());
    EXPECT_EQ(ids, (std::vector<std::string>{"escape_gradient", "escape_linear", "escape_log", "escape_potential"}));
}

// The editor's hook: an opened document keeps its factor; a change of structure sets the one the
// check measures for the new stack, unless the user set one by hand.
TEST(SafeStep, EditorSetsTheCheckedFactorAfterAStructureChange) {
    Preset p = loadPreset(std::string(FRAKTAL_SOURCE_DIR) + "/presets/juliabulb.json");
    Formula& f = p.formula;
    editor::AutoStepFactor a = editor::AutoStepFactor::adopting(f);
    const double own = f.deFactor;
    EXPECT_FALSE(a.update(f, p.camera));
    EXPECT_EQ(f.deFactor, own);

    ASSERT_TRUE(editor::addNode(f, *findBlock("twist_y"), 0));
    Formula unit = f;
    unit.deFactor = 1.0;
    ASSERT_TRUE(test::updateUntilMeasured(a, f, p.camera));
    std::printf("measured step factor %.3f in %.3f s\n", a.measured, a.seconds);
    EXPECT_EQ(f.deFactor, a.measured);
    EXPECT_EQ(a.measured, measureSafeStep(unit, p.camera, editor::AutoStepFactor::options()).factor);
    if (a.refining()) {
        finishRefining(a, f, p.camera);
        std::printf("after the further rounds: %.3f on %d rays in %.3f s\n", a.measured, a.rays, a.seconds);
        EXPECT_EQ(f.deFactor, a.measured);
        EXPECT_NEAR(a.measured, measureSafeStep(unit, p.camera, editor::AutoStepFactor::checkOptions()).factor, 0.0015);
    }
    EXPECT_LE(checkConservativeness(f, p.camera, {40, 2000, 5}).worstRatio, 1.0);
    EXPECT_FALSE(a.update(f, p.camera));  // values and camera moves do not measure again

    a.overridden = true;
    f.deFactor = 0.3;
    ASSERT_TRUE(editor::removeNode(f, 0));
    EXPECT_TRUE(test::updateUntilMeasured(a, f, p.camera));
    EXPECT_EQ(f.deFactor, 0.3);
}

// A file whose factor was never measured for its structure (no tag, or another structure's: a file
// written by hand, or edited in a text editor since) is measured when the editor opens it, as after
// a structure change; the measurement tags the formula, so that the saved file opens as it is.
TEST(SafeStep, EditorMeasuresAnOpenedFileWhoseFactorWasNeverMeasured) {
    Preset p = loadPreset(std::string(FRAKTAL_SOURCE_DIR) + "/presets/juliabulb.json");
    Formula& f = p.formula;
    ASSERT_TRUE(stepFactorMeasured(f));
    const double own = f.deFactor;
    // An artist adds a twist in a text editor: the tag no longer names the structure.
    ASSERT_TRUE(editor::addNode(f, *findBlock("twist_y"), 0));
    EXPECT_FALSE(stepFactorMeasured(f));
    editor::AutoStepFactor a = editor::AutoStepFactor::adopting(f);
    ASSERT_TRUE(test::updateUntilMeasured(a, f, p.camera));
    if (a.refining()) finishRefining(a, f, p.camera);
    std::printf("opened untagged: factor %.3f measured (the file held %.3f)\n", f.deFactor, own);
    EXPECT_EQ(f.deFactor, a.measured);
    EXPECT_NE(f.deFactor, own);
    EXPECT_TRUE(stepFactorMeasured(f));
    EXPECT_LE(checkConservativeness(f, p.camera, {40, 2000, 5}).worstRatio, 1.0);
    // Saved and opened again: adopted as it is, nothing measured.
    Formula reopened = parsePreset(presetToJson(p).dump(), "reopened.json").formula;
    EXPECT_TRUE(stepFactorMeasured(reopened));
    editor::AutoStepFactor again = editor::AutoStepFactor::adopting(reopened);
    EXPECT_FALSE(again.update(reopened, p.camera));
    EXPECT_EQ(reopened.deFactor, f.deFactor);
}

// Every shipped preset says its factor was settled for the structure it has, so none is measured
// again when it opens (and none opens changed). A preset whose nodes were edited without measuring
// fails here: `fraktal check --apply` measures and tags it.
TEST(SafeStep, EveryShippedPresetCarriesItsStructuresTag) {
    for (const auto& path : test::shippedPresets()) {
        const Preset p = loadPreset(path);
        EXPECT_TRUE(stepFactorMeasured(p.formula))
            << path << ": formula.deFactorMeasuredFor is \"" << p.formula.deFactorMeasuredFor
            << "\", its structure's is " << stepFactorTag(p.formula) << " (fraktal check --apply " << path.filename()
            << ")";
    }
}

// The tag is the structure's alone: values, the factor and the camera leave it, a node changes it.
TEST(SafeStep, TheStepFactorTagFollowsTheStructure) {
    Preset p = loadPreset(std::string(FRAKTAL_SOURCE_DIR) + "/presets/mandelbulb.json");
    Formula f = p.formula;
    const std::string tag = stepFactorTag(f);
    EXPECT_EQ(tag.size(), 16u);
    f.deFactor *= 0.5;
    f.iterations += 1;
    f.boundRadius *= 2.0;
    EXPECT_EQ(stepFactorTag(f), tag);
    ASSERT_TRUE(editor::addNode(f, *findBlock("twist_y"), 0));
    EXPECT_NE(stepFactorTag(f), tag);
}

// Where the rays' tail is heavy, the editor applies the settled rounds' factor at once and the
// check's further rounds run on its worker: when they end, their factor (the one `fraktal check`
// reports) replaces the first. The Amazing Surf's settled factor overshoots other rays
// (CheckSamplesMoreRaysWhereTheTailIsHeavy). A structure change while they run drops them: what
// ends up applied is the new structure's measurement, never the old one's.
TEST(SafeStep, EditorAppliesTheChecksFurtherRoundsWhenTheyEnd) {
    Preset p = amazingSurfWithAHeavyTail();
    Formula& f = p.formula;
    Formula unit = f;
    unit.deFactor = 1.0;
    const EstimatorMeasurement check = measureSafeStep(unit, p.camera, editor::AutoStepFactor::checkOptions());

    editor::AutoStepFactor a;  // a structure not measured yet
    ASSERT_TRUE(test::updateUntilMeasured(a, f, p.camera));
    const double settled = a.measured;
    const int settledRays = a.rays;
    EXPECT_EQ(f.deFactor, settled);
    ASSERT_TRUE(a.refining()) << "the settled rounds' tail was expected to call for more rays";
    finishRefining(a, f, p.camera);
    std::printf("amazing_surf in the editor: %.3f on %d rays at once, %.3f on %d rays after %.2f s (the check: %.3f)\n",
                settled, settledRays, a.measured, a.rays, a.seconds, check.factor);
    EXPECT_EQ(a.rays, check.report.rays);
    EXPECT_NEAR(a.measured, check.factor, 0.0015);
    EXPECT_LT(a.measured, settled);
    EXPECT_EQ(f.deFactor, a.measured);

    // Set by hand: the further rounds' factor is measured, the user's is kept.
    editor::AutoStepFactor byHand;
    byHand.overridden = true;
    f.deFactor = 0.3;
    ASSERT_TRUE(test::updateUntilMeasured(byHand, f, p.camera));
    finishRefining(byHand, f, p.camera);
    EXPECT_NEAR(byHand.measured, check.factor, 0.0015);
    EXPECT_EQ(f.deFactor, 0.3);

    // A new structure while they run (a twist in front): whatever ends up applied is the new
    // stack's measurement, the check's where it too gets further rounds.
    editor::AutoStepFactor changed;
    ASSERT_TRUE(test::updateUntilMeasured(changed, f, p.camera));
    ASSERT_TRUE(changed.refining());
    ASSERT_TRUE(editor::addNode(f, *findBlock("twist_y"), 0));
    changed.update(f, p.camera);
    // The edit did not wait for the rounds it made obsolete: their worker is stopping on its own.
    EXPECT_EQ(changed.stoppingWorkers(), 1u);
    ASSERT_TRUE(test::updateUntilMeasured(changed, f, p.camera));
    const bool refines = changed.refining();
    finishRefining(changed, f, p.camera);
    for (int wait = 0; wait < 100 && changed.stoppingWorkers() > 0; ++wait) {
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
        changed.update(f, p.camera);
    }
    EXPECT_EQ(changed.stoppingWorkers(), 0u) << "a stopped worker was never joined";
    Formula twisted = f;
    twisted.deFactor = 1.0;
    const EstimatorMeasurement newCheck = measureSafeStep(
        twisted, p.camera, refines ? editor::AutoStepFactor::checkOptions() : editor::AutoStepFactor::options());
    std::printf("with a twist in front: %.3f on %d rays%s\n", changed.measured, changed.rays,
                refines ? ", after the further rounds" : "");
    EXPECT_EQ(changed.rays, newCheck.report.rays);
    EXPECT_NEAR(changed.measured, newCheck.factor, 0.0015);
    EXPECT_EQ(f.deFactor, changed.measured);
}

// A structure whose object the check's rays never reach (the pseudo-Kleinian's sheets without the
// offset that gives them an inside) is not measured as safe at factor 1: the editor keeps the
// factor and says so; with the offset the same structure is measured.
TEST(SafeStep, EditorKeepsTheFactorWhenNoRayHits) {
    Preset p = loadPreset(std::string(FRAKTAL_SOURCE_DIR) + "/presets/pseudo_kleinian.json");
    Formula& f = p.formula;
    const double own = f.deFactor;
    const size_t offset = size_t(f.estimator.block->paramIndex("offset"));
    const ParamValue shipped = f.estimator.values[offset];
    f.estimator.values[offset].x = 0.0;
    editor::AutoStepFactor a;  // a structure not measured yet
    ASSERT_TRUE(test::updateUntilMeasured(a, f, p.camera));
    EXPECT_TRUE(a.noHits);
    EXPECT_EQ(a.measured, 0.0);
    EXPECT_EQ(f.deFactor, own);

    f.estimator.values[offset] = shipped;
    editor::AutoStepFactor b;
    ASSERT_TRUE(test::updateUntilMeasured(b, f, p.camera));
    EXPECT_FALSE(b.noHits);
    EXPECT_GT(b.measured, 0.0);
    EXPECT_LT(b.measured, 1.0);  // the estimate overshoots (Knighty's 0.5): the check finds it
    EXPECT_EQ(f.deFactor, b.measured);
}

// The Mandelbulb's derivative is the largest singular value of its Jacobian: along r, theta and
// phi (the map's singular directions) the stretch, by finite differences, is at most p.w, and the
// largest of the three equals it. Integer powers (|sin(n theta)| <= n |sin(theta)| holds there),
// random points of the ball of radius 1.5, points within 1e-3 of the y axis included.
TEST(SafeStep, MandelbulbDerivativeIsItsLargestStretch) {
    const BlockDesc& block = *findBlock("mandelbulb");
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const vec3 c(0.0);
    int compared = 0, nearAxis = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        Node n = Node::make(block);
        n.values[0].x = double(2 + trial % 11);
        vec3 x = randomVec3(u, rng) * 1.5;
        if (trial % 4 == 0) {  // near the pole
            const vec2 xz = randomVec2(u, rng) * 1e-3;
            x = vec3(xz.x, x.y, xz.y);
        }
        const double r = length(x);
        if (r < 0.05 || std::hypot(x.x, x.z) < 1e-6) continue;
        const double theta = std::atan2(std::hypot(x.x, x.z), x.y), phi = std::atan2(x.x, x.z);
        const vec3 radial = x / r;
        const vec3 thetaHat(std::cos(theta) * std::sin(phi), -std::sin(theta), std::cos(theta) * std::cos(phi));
        const vec3 phiHat(std::cos(phi), 0.0, -std::sin(phi));
        P4 p{x, 1.0};
        block.apply(p, c, n.args());
        auto image = [&](const vec3& q) { return stepImage(block, n, c, q); };
        const double h = 1e-7 * std::min(1.0, std::hypot(x.x, x.z) * 10.0);
        double largest = 0.0;
        for (const vec3& dir : {radial, thetaHat, phiHat}) {
            const double stretch = length(image(x + dir * h) - image(x - dir * h)) / (2.0 * h);
            ASSERT_LE(stretch, p.w * (1.0 + 1e-4))
                << "power " << n.values[0].x << " at (" << x.x << ", " << x.y << ", " << x.z << ")";
            largest = std::max(largest, stretch);
        }
        EXPECT_NEAR(largest, p.w, 1e-4 * p.w)
            << "power " << n.values[0].x << " at (" << x.x << ", " << x.y << ", " << x.z << ")";
        ++compared;
        nearAxis += std::hypot(x.x, x.z) < 2e-3;
    }
    EXPECT_GT(compared, 1500);
    EXPECT_GT(nearAxis, 300);
}

// The Mandelbulb (12 iterations), the box+bulb hybrid and the other bulbs ship with a step factor
// of at least 0.8 that the check measures as safe: `fraktal check`'s safe-step rays (rounds from
// seed 1 at 4000 steps across the bound) and margin, the same code. On 2000 other rays the
// shipped factor never overshoots: the rounds' few hundred rays had let the hybrid ship r / dr at
// 1.38, which 2000 rays find at 195x the distance.
TEST(SafeStep, BulbPresetsShipWithAMeasuredFactorOfAtLeast08) {
    for (const char* name : {"mandelbulb.json", "hybrid_box_bulb.json", "juliabulb.json", "mandelbulb_phase.json",
                             "mandelbulb_sine.json", "mandelbulb_cosine.json", "bristorbrot.json"}) {
        const Preset p = loadPreset(std::string(FRAKTAL_SOURCE_DIR) + "/presets/" + name);
        const Formula& f = p.formula;
        if (std::string(name) == "mandelbulb.json") {
            EXPECT_EQ(f.iterations, 12);
        }
        CpuSampler sampler(f);
        SafeStepOptions check;
        check.rays.stepsAcrossBound = 4000;  // `fraktal check`'s default --steps
        const ConservativenessReport c = sampleSafeStepRays(sampler, p.camera, check).report;
        ASSERT_GT(c.samples, 10000) << name;
        const double safe = check.factorFor(atUnitFactor(c, f.deFactor), f);
        std::printf("%s: worst DE / true distance %.4f at factor %.3f, median %.4f; safe step factor %.3f\n", name,
                    c.worstRatio, f.deFactor, c.medianRatio, safe);
        EXPECT_GE(safe, 0.8) << name;
        EXPECT_GE(f.deFactor, 0.8) << name;
        EXPECT_LE(f.deFactor, safe) << name;

        const ConservativenessReport fresh = checkConservativeness(f, p.camera, {2000, 4000, 77});
        std::printf("%s: on %d other rays, worst DE / true distance %.4f\n", name, fresh.rays, fresh.worstRatio);
        EXPECT_GT(fresh.samples, 100000) << name;
        EXPECT_LE(fresh.worstRatio, 1.0) << name << " overshoots at (" << fresh.worstPoint.x << ", "
                                         << fresh.worstPoint.y << ", " << fresh.worstPoint.z << ")";
    }
}
