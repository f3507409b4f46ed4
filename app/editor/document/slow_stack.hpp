// The editor's side of a slow stack's explanation (core/scene/slow_stack.hpp): measured on a
// worker thread after the step factor, shown in the Formula panel, applied in one click.
#pragma once

#include <future>
#include <optional>
#include <string>
#include <thread>

#include "app/editor/document/formula_edits.hpp"
#include "core/scene/slow_stack.hpp"

namespace fraktal::editor {

// The editor's explanation of the stack being edited. explainSlowStack takes seconds (the fit's
// estimators, the stack without each block), so it runs on a worker thread, started when the step
// factor measured after a structure change (AutoStepFactor) is under kExplainFactor, its speed is
// useless, or no factor is safe; the Formula panel shows it and offers the faster estimator.
struct SlowStackAdvice {
    std::string key;                 // the measurement explained: the structure and its factor
    std::optional<SlowStack> shown;  // the explanation for `key`, once measured
    std::string text;                // shown->text() for the formula it measured
    std::future<SlowStack> pending{};
    std::jthread worker{};  // last: stopped and joined before what it writes to

    // Each frame after AutoStepFactor::update: forgets the explanation when the measurement it
    // explains is replaced, starts one when the new measurement calls for it, and takes the
    // worker's result when it ends. Returns whether anything changed.
    bool update(const Formula& f, const Camera& camera, const AutoStepFactor& stepFactor);
    bool measuring() const { return pending.valid(); }
};

// The explanation's faster estimator, bailout and factor applied to the document; the step factor
// is measured for it again (AutoStepFactor, with its further rounds). One edit: the editor's
// commit after the click makes it one undo step. False when there is none.
bool applyFasterEstimator(Preset& p, AutoStepFactor& stepFactor, const SlowStack& advice);

}  // namespace fraktal::editor
