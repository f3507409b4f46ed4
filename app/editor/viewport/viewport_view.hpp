// What the editor needs from its viewport renderer, kept small so panels and the main loop do not
// depend on the renderer's internals. The one implementation (viewport_adapter.cpp) is
// core/viewport's progressive, reprojecting fraktal::viewport::Viewport with the OCIO display
// pass (ocio_display_pass.hpp) behind it.
#pragma once

#include <epoxy/gl.h>

#include <memory>
#include <string>

#include "app/editor/document/view_settings.hpp"
#include "core/color/color_pipeline.hpp"
#include "core/preset.hpp"
#include "core/scene/scene_revision.hpp"

namespace fraktal::editor {

// The viewport's own per-frame statistics (viewport::FrameStats) as the overlay shows them.
struct ViewportStats {
    double renderMs = 0.0;  // wall time of the last frame's viewport work (0 when settled and idle)
    double deEvaluationsPerPixel = 0.0;
    double reprojectedShare = 0.0;  // pixels whose ray start came from the previous frame
    double convergedShare = 0.0;    // pixels whose current sample is finished
    const char* action = "reset";   // what the last frame did: reset, reproject, hold or continue
    int aaLevel = 0;                // samples per pixel being worked on (the cap once settled)
    int aaCap = 1;
    bool settled = false;        // every pixel of this document's image has all its samples (never while compiling)
    int width = 0, height = 0;   // render resolution
    double internalScale = 1.0;  // dynamic resolution: the share of the full size rendered (1 at rest)
    int compiles = 0;            // formula programs built so far (a value edit must not add one)
    int stepsPerFrame = 0;       // march steps per ray the last frame took
    int slices = 1;              // the last frame refined one slice of the view of this many (1: all of it)
    bool compiling = false;      // a new structure compiles in the background; the old image stays
    // "Path traced at rest" (ViewSettings::pathTraceAtRest): whether the image shown is the path
    // tracer's, and its samples per pixel so far (0 while the fast mode shows) out of the cap.
    bool pathTracing = false;
    int pathSamples = 0;
    int pathSppCap = 0;
};

class ViewportView {
   public:
    virtual ~ViewportView() = default;
    // Advances the image of this preset by one frame's work on the current GL context, and
    // refreshes displayTexture() through the preset's OCIO display/view and exposure. What the
    // frame does is decided on `revision` (scene::sceneRevision of `preset`, built once a frame by
    // the caller): a structure change recompiles, a value change restarts with new uniforms, a
    // camera change reprojects, a display change only redisplays. When the compile fails,
    // compileError() says why and the last good image stays.
    virtual void render(const Preset& preset, const scene::SceneRevision& revision, const ViewSettings& settings,
                        int width, int height) = 0;
    // The same for a caller without a revision of its own (thumbnails, tests).
    void render(const Preset& preset, const ViewSettings& settings, int width, int height) {
        render(preset, scene::sceneRevision(preset), settings, width, height);
    }
    // What a frame of this structure needs and can get ready before it renders (its programs, on
    // the background compiler), without rendering: the editor holds the last image while a new
    // structure's step factor is measured. The image shown is then not this document's: never settled.
    virtual void prepare(const Formula& /*formula*/, const std::string& /*structure*/) {}
    // The display-referred RGBA8 image, top row first (draw with ImGui uv (0,0)-(1,1)). 0 before
    // the first frame.
    virtual GLuint displayTexture() const = 0;
    virtual int width() const = 0;
    virtual int height() const = 0;
    virtual const ViewportStats& stats() const = 0;
    // Empty when the current structure compiled; else the log, naming the node (explainLog).
    virtual const std::string& compileError() const = 0;
    // Empty when the display transform is set up; else why not (bad OCIO view, ...).
    virtual const std::string& displayError() const = 0;
    // The document's file, where the path tracer's relative environment map paths start (as for
    // `fraktal render`); empty for an unsaved document.
    virtual void setPresetFile(const std::string& /*file*/) {}
    // Whether a frame at rest (and a reset at rest) refines the slice of the view that fits the
    // frame-time target (the default) or always the whole view (a scripted run: the picture after
    // N frames is then the same on every machine, and a screenshot shows whole frames).
    virtual void setSlicedAtRest(bool /*sliced*/) {}
};

class BackgroundCompiler;

// With a compiler, structure changes compile on its thread and the old image stays meanwhile;
// without one (tests on a headless context) they compile in render(). `compiler` outlives the view.
std::unique_ptr<ViewportView> makeViewportView(const ColorPipeline& color, BackgroundCompiler* compiler = nullptr);

}  // namespace fraktal::editor
