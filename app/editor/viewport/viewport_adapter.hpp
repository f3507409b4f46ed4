// The editor's viewport: core/viewport's progressive, reprojecting renderer (seed chapter 4)
// behind the ViewportView interface, shown through the OCIO display pass. The renderer keeps the
// image scene-linear in the preset's working space; only the display pass leaves it.
#pragma once

#include <chrono>
#include <optional>

#include "app/editor/document/formula_edits.hpp"
#include "app/editor/viewport/background_compiler.hpp"
#include "app/editor/viewport/display_target.hpp"
#include "app/editor/viewport/ocio_display_pass.hpp"
#include "app/editor/viewport/viewport_view.hpp"
#include "core/gl/color_target.hpp"
#include "core/render/path_job.hpp"
#include "core/render/path_tracer.hpp"
#include "core/scene/scene_revision.hpp"
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

// "Path traced at rest": the accumulation the viewport shows while the view rests, and what it
// was started for. Any change of the scene but its display transform, of the size or of the file
// that environment paths are relative to drops it (back to the fast mode).
struct PathAtRest {
    scene::SceneRevision revision;
    std::string presetFile;
    RenderSettings render;  // the preset's, at the viewport's full size
};

class CoreViewportView final : public ViewportView {
   public:
    // `color` is owned by the caller and outlives the view.
    explicit CoreViewportView(const ColorPipeline& color, BackgroundCompiler* compiler = nullptr);
    ~CoreViewportView() override;
    CoreViewportView(const CoreViewportView&) = delete;
    CoreViewportView& operator=(const CoreViewportView&) = delete;

    using ViewportView::render;
    void render(const Preset& preset, const scene::SceneRevision& revision, const ViewSettings& settings, int width,
                int height) override;
    void prepare(const Formula& formula, const std::string& structure) override;
    GLuint displayTexture() const override { return displayTarget_.texture(); }
    int width() const override { return displayTarget_.width(); }
    int height() const override { return displayTarget_.height(); }
    const ViewportStats& stats() const override { return stats_; }
    const std::string& compileError() const override { return compileError_; }
    const std::string& displayError() const override { return displayError_; }
    void setPresetFile(const std::string& file) override { presetFile_ = file; }
    void setSlicedAtRest(bool sliced) override { sliceAtRest_ = sliced; }
    // The path tracer of "Path traced at rest" (null before the first rest in that mode); it holds
    // the last accumulation, shown only while stats().pathTracing.
    const gl::PathTracer* pathTracer() const { return pathTracer_.get(); }

   private:
    // Runs one viewport frame; false when nothing was rendered (compile error, skipped).
    bool renderFrame(const Preset& preset, const scene::SceneRevision& revision, const ViewSettings& settings,
                     int width, int height);
    void ensureDisplayTarget(int width, int height);
    // Draws `linearImage` (scene-linear, the size of the display target, top row first) through
    // the display transform when it or the transform changed. `gain` in stops adds to the exposure.
    void redisplay(const Preset& preset, GLuint linearImage, double gainStops = 0.0);
    const ShadingSettings& workingShading(const Preset& preset);
    // The formula as the viewport renders it: its objects' colours taken into the working space,
    // as workingShading takes the scene's other colours (the still does both in resolveShading).
    // The preset's own formula where that changes nothing.
    const Formula& workingFormula(const Preset& preset);

    // Path traced at rest: whether the accumulation still shows this view; starting one for the
    // view the fast mode rests at; one frame's samples, shown.
    bool pathStillValid(const scene::SceneRevision& revision, const ViewSettings& settings, int width, int height);
    void startPath(const Preset& preset, const scene::SceneRevision& revision, int width, int height);
    void pathFrame(const Preset& preset, const ViewSettings& settings);
    void copyPathImage();  // the tracer's whole passes into pathImage_
    void dropPath();

    // Asks the compiler for the programs of the formula (of this structure); true once the
    // viewport has them (or when there is no compiler: render() compiles). False while compiling
    // or when it failed.
    bool programsReady(const Formula& formula, const std::string& structure);
    // Dynamic resolution: the share of (width, height) to render this frame at.
    double chooseScale(const scene::SceneRevision& revision, const ViewSettings& settings);

    const ColorPipeline& color_;
    BackgroundCompiler* compiler_ = nullptr;
    viewport::Viewport viewport_;
    OcioDisplayPass display_;
    std::string failedStructure_;  // a structure whose compile failed: not retried every frame
    std::string compileError_, displayError_;
    // Cache of shadingInWorkingSpace (an OCIO processor per colour is not free every frame).
    std::optional<std::pair<ShadingSettings, std::string>> shadingKey_;
    ShadingSettings workingShading_;
    // Cache of workingFormula's colours: the preset's and the working space, then the converted.
    std::optional<std::pair<std::vector<vec3>, std::string>> objectColorsKey_;
    std::vector<vec3> workingObjectColors_;
    Formula workingFormula_;
    // What the display texture shows: redrawn only when the image or the transform changed.
    DisplayTarget displayTarget_;
    bool imageChanged_ = false;
    std::optional<std::pair<DisplayKey, double>> shownDisplay_;
    ViewportStats stats_;
    // Dynamic resolution: what the last rendered frame showed (a change but of the display transform
    // means motion) and when it began.
    viewport::ResolutionController resolution_;
    std::optional<scene::SceneRevision> lastView_;
    std::optional<std::chrono::steady_clock::time_point> lastFrameStart_;
    viewport::FrameAction lastAction_ = viewport::FrameAction::Reset;  // the last fast frame's
    // Sliced refinement at rest (viewport::ViewportOptions::slices): a heavy formula refines a
    // slice of the view a frame instead of holding the window (three Kleinian nodes took
    // 900-965 ms a frame at rest with the whole view a frame). The slices are fitted to the frame
    // time from the editor's last frames (viewport::RestSlices).
    viewport::RestSlices restSlices_;
    bool sliceAtRest_ = true;
    std::optional<viewport::RestFrame> lastRefined_;  // the last frame's, if it refined the view
    std::string slicedStructure_;                     // the structure restSlices_ measured
    double previousFrameMs_ = 0.0;                    // the editor's last frame, start to start (chooseScale)
    // Whether the last frame rendered anything: a frame that did not (its programs still compiling)
    // says nothing of what a frame costs, and is not measured.
    bool previousFrameRendered_ = false;
    // Path traced at rest. The tracer is kept while the structure and size stay (its program
    // takes a while to compile); `path_` is the running accumulation.
    std::string presetFile_;
    std::unique_ptr<gl::PathTracer> pathTracer_;
    std::optional<PathAtRest> path_;
    std::optional<PathSceneData> pathData_;  // the last scene resolved (its environment map is reused)
    std::string pathError_;                  // why the path tracer could not start (e.g. a missing environment map)
    // The lighting and the preset file + structure of a failed start: not retried for the same.
    std::optional<std::pair<Lighting, std::string>> pathFailed_;
    GLuint pathReadFramebuffer_ = 0;
    gl::ColorTarget pathImage_{GL_RGBA32F};
    double pathMsPerRow_ = 0.0;  // measured time of one row of one sample (0: none yet)
};

}  // namespace fraktal::editor
