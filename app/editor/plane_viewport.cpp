#include "app/editor/plane_viewport.hpp"

#include <chrono>

#include "core/plane/plane_still.hpp"

namespace fraktal::editor {

void PlaneViewport::render(const PlanePreset& preset, int width, int height) {
    width = std::max(width, 2);
    height = std::max(height, 2);
    view_.setPreset(preset);
    if (!sameRect(view_.rect(), preset.view)) view_.setRect(preset.view);
    stats_.passMs = 0.0;
    const std::string structure = preset.formula.structureKey();
    if (failedStructure_.empty() || structure != failedStructure_) {
        const auto start = std::chrono::steady_clock::now();
        try {
            if (view_.update(width, height)) imageChanged_ = true;
            compileError_.clear();
            failedStructure_.clear();
        } catch (const std::exception& e) {
            compileError_ = e.what();
            failedStructure_ = structure;
        }
        if (imageChanged_)
            stats_.passMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
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
