#include "app/editor/viewport/plane_viewport.hpp"

#include <chrono>

#include "core/plane/plane_still.hpp"

namespace fraktal::editor {

void PlaneViewport::render(const PlanePreset& preset, int width, int height) {
    using Clock = std::chrono::steady_clock;
    const Clock::time_point now = Clock::now();
    const int samplesBefore = view_.samples();
    view_.setPreset(preset);
    if (!sameRect(view_.rect(), preset.view)) view_.setRect(preset.view);
    if (samplesBefore > 0 && view_.samples() == 0) lastChange_ = now;  // an edit or a move restarted it
    const bool moving =
        reducedWhileMoving_ && lastChange_ && std::chrono::duration<double>(now - *lastChange_).count() < kRestSeconds;
    const double scale = moving ? planeInteractiveScale(msPerPixelSample_, width, height, kPassBudgetMs) : 1.0;
    width = std::max(int(width * scale), 2);
    height = std::max(int(height * scale), 2);

    stats_.passMs = 0.0;
    const std::string structure = preset.formula.structureKey();
    if (failedStructure_.empty() || structure != failedStructure_) {
        // As many samples per pass as a whole image fits in the budget (at least one), and as
        // many rows of the pass per frame as fit (the same rule, per row).
        const int perPass =
            planeSamplesForBudget(msPerPixelSample_ * width * height, kPassBudgetMs, kMaxSamplesPerPass);
        view_.refinement().maxPerPass = perPass;
        const int maxRows = planeSamplesForBudget(msPerPixelSample_ * width * perPass, kPassBudgetMs, height);
        const auto start = Clock::now();
        try {
            if (view_.update(width, height, maxRows)) {
                imageChanged_ = true;
                // update() waits for nothing: finish here so that the time is the band's own.
                glFinish();
                stats_.passMs = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
                // Rows differ a lot in cost (inside the set every sample runs all iterations), so
                // the estimate is a slowly decaying maximum: a cheap band must not make the next
                // one large enough to stall the UI.
                msPerPixelSample_ = std::max(stats_.passMs / view_.lastPixelSamples(), msPerPixelSample_ * 0.75);
            }
            compileError_.clear();
            failedStructure_.clear();
        } catch (const std::exception& e) {
            compileError_ = e.what();
            failedStructure_ = structure;
        }
    }
    stats_.samples = view_.samples();
    stats_.target = view_.refinement().target;
    stats_.fp64 = view_.usesDouble();
    stats_.width = width;
    stats_.height = height;
    if (!view_.colourTexture() || view_.samples() == 0) return;
    if (display_.resize(width, height)) shownDisplay_.reset();
    redisplay(preset);
}

void PlaneViewport::redisplay(const PlanePreset& preset) {
    const RenderSettings& r = preset.render;
    const DisplayKey key{r.workingSpace, r.display, r.view};
    try {
        pass_.configure(color_, key);
        if (!toWorking_ || toWorking_->first != r.workingSpace)
            toWorking_.emplace(r.workingSpace, planeWorkingFromRec709(color_, r.workingSpace));
        displayError_.clear();
    } catch (const std::exception& e) {
        displayError_ = e.what();  // the last good transform stays; the Render tab says why
        if (!pass_.configured() || !toWorking_) return;
    }
    const auto shown = std::make_pair(pass_.key(), r.exposure);
    if (!imageChanged_ && shownDisplay_ == shown) return;
    const DisplayTarget::Binding bound = display_.bind();
    pass_.draw(view_.colourTexture(), r.exposure, {true, toWorking_->second});
    shownDisplay_ = shown;
    imageChanged_ = false;
}

}  // namespace fraktal::editor
