// The editor's viewport: core/viewport's progressive, reprojecting renderer (seed chapter 4)
// behind the ViewportView interface, shown through the OCIO display pass. The renderer keeps the
// image scene-linear in the preset's working space; only the display pass leaves it.
#pragma once

#include <chrono>
#include <optional>

#include "app/editor/background_compiler.hpp"
#include "app/editor/formula_edits.hpp"
#include "app/editor/ocio_display_pass.hpp"
#include "app/editor/viewport_view.hpp"
#include "core/viewport/resolution_control.hpp"
#include "core/viewport/viewport.hpp"

namespace fraktal::editor {

// The viewport's options for these view settings.
viewport::ViewportOptions viewportOptions(const ViewSettings& v);

// The shading with its colours converted from linear Rec.709 (the preset's convention) into the
// working space, as the still renderer does through resolveShading's toWorking, so that the
// viewport's image is in the same space as the still's and goes through the same display
// transform.
ShadingSettings shadingInWorkingSpace(const ShadingSettings& shading, const ColorPipeline& color,
                                      const std::string& workingSpace);

class CoreViewportView final : public ViewportView {
   public:
    // `color` is owned by the caller and outlives the view.
    explicit CoreViewportView(const ColorPipeline& color, BackgroundCompiler* compiler = nullptr);
    ~CoreViewportView() override;
    CoreViewportView(const CoreViewportView&) = delete;
    CoreViewportView& operator=(const CoreViewportView&) = delete;

    void render(const Preset& preset, const ViewSettings& settings, int width, int height) override;
    GLuint displayTexture() const override { return displayTexture_; }
    int width() const override { return displayWidth_; }
    int height() const override { return displayHeight_; }
    const ViewportStats& stats() const override { return stats_; }
    const std::string& compileError() const override { return compileError_; }
    const std::string& displayError() const override { return displayError_; }

   private:
    // Runs one viewport frame; false when nothing was rendered (compile error, skipped).
    bool renderFrame(const Preset& preset, const ViewSettings& settings, int width, int height);
    void ensureDisplayTarget(int width, int height);
    void redisplay(const Preset& preset);

    // Asks the compiler for the formula's programs; true once the viewport has them (or when
    // there is no compiler: render() compiles). False while compiling or when it failed.
    bool programsReady(const Formula& formula);
    // Dynamic resolution: the share of (width, height) to render this frame at.
    double chooseScale(const Preset& preset, const ViewSettings& settings);

    const ColorPipeline& color_;
    BackgroundCompiler* compiler_ = nullptr;
    viewport::Viewport viewport_;
    OcioDisplayPass display_;
    ProgramTracker tracker_;
    std::string failedStructure_;  // a structure whose compile failed: not retried every frame
    std::string compileError_, displayError_;
    // Cache of shadingInWorkingSpace (an OCIO processor per colour is not free every frame).
    std::optional<std::pair<ShadingSettings, std::string>> shadingKey_;
    ShadingSettings workingShading_;
    // What the display texture shows: redrawn only when the image or the transform changed.
    GLuint displayTexture_ = 0, displayFramebuffer_ = 0;
    int displayWidth_ = 0, displayHeight_ = 0;
    bool imageChanged_ = false;
    std::optional<std::pair<DisplayKey, double>> shownDisplay_;
    ViewportStats stats_;
    // Dynamic resolution: what the last frame showed (a change means motion) and when it began.
    viewport::ResolutionController resolution_;
    std::optional<viewport::FrameKey> lastView_;
    std::optional<std::chrono::steady_clock::time_point> lastFrameStart_;
};

}  // namespace fraktal::editor
