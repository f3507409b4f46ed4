// Why a stack of blocks marches slowly, and what would march it faster. A small step factor or a
// useless estimate (one far under the distance everywhere, so that every ray stops at once or
// crawls) has a cause an artist can act on: a block that keeps the estimate loose (a wrap, a jump,
// an inversion that stretches the running derivative far beyond the map's stretch), or an
// estimator and bailout that do not suit the blocks. `fraktal check` prints the explanation and
// the editor's Formula panel shows it (app/editor/document/slow_stack.hpp), with the faster
// estimator as one click.
#pragma once

#include <optional>
#include <string>

#include "core/camera.hpp"
#include "core/formula.hpp"
#include "core/preset.hpp"
#include "core/safe_step.hpp"

namespace fraktal {

// Below this step factor the editor explains the stack (the check: below it, or useless).
inline constexpr double kExplainFactor = 0.05;
// An estimate whose speed (factor x median DE / true distance, per orbit) is under this is
// useless: a step covers under 1 % of the gap, so a ray needs some 700 steps to close a gap a
// thousandfold, more than any march budget, and the image is blank or every ray stops at once.
inline constexpr double kUselessSpeed = 0.01;
// What counts as faster: another estimator or the stack without a block, by this speed ratio.
inline constexpr double kFasterBy = 2.0;

inline bool uselessSpeed(const EstimatorMeasurement& m) {
    return m.report.samples > 0 && m.hasFactor && m.speed() < kUselessSpeed;
}

struct SlowStack {
    // The formula's own estimator, measured.
    EstimatorMeasurement current;
    // The estimator and bailout the fit gives the blocks (fitEstimatorToBlocks), with the best
    // estimator the check measures for them and its factor: when it marches kFasterBy faster than
    // the current one (or the current one has no safe factor or nothing to measure).
    std::optional<Formula> faster;
    double fasterSpeed = 0.0;
    // The block that keeps the estimate loose, as an index into nodes (-1: none stands out): the
    // stack without it (its estimator fitted again) marches kFasterBy faster than the stack
    // with it, or, when no removal shows that, the first step that declares a jump, else the
    // first whose stretch grows with |p| (BlockDesc::stretchGrowsWithRadius).
    int block = -1;
    double speedWithout = 0.0;    // the best speed without that block (0: not measured)
    double blockBaseSpeed = 0.0;  // the speed it is compared with: the faster estimator's, or the current one

    double speed() const { return current.report.samples > 0 && current.hasFactor ? current.speed() : 0.0; }
    // One paragraph for the check and the editor: the speed now, the block and why (its jump, in
    // its declaration's words), and the faster estimator.
    std::string text(const Formula& f) const;
};

// Measures f as it is, then the fit's estimator and, for each enabled step of a stack of more
// than one, the stack without it. CPU-evaluable formulas only (the measurement is on the CPU).
// `current`: the formula's own measurement when the caller has it (the check, the editor).
SlowStack explainSlowStack(const Formula& f, const Camera& camera, const SafeStepOptions& options,
                           std::optional<EstimatorMeasurement> current = std::nullopt);

// f with the fit's estimator and bailout (fitEstimatorToBlocks) and the best estimator the check
// measures for them, at its safe factor; nullopt when none has a safe factor or reaches the object.
std::optional<Formula> fittedAndMeasured(const Formula& f, const Camera& camera, const SafeStepOptions& options,
                                         EstimatorMeasurement* best = nullptr);

}  // namespace fraktal
