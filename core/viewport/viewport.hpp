// The real-time viewport (seed chapter 4): progressive marching, progressive anti-aliasing and
// reprojection of march distances. Owns its GL resources; call render() once per displayed frame
// with the current formula, camera and settings, then show imageTexture() (scene-linear RGBA32F)
// through drawDisplay() or read it back. Needs a current GL 4.5 context (the editor's window or
// gl::HeadlessContext).
//
// Frame: decideFrame() picks reset / reproject / continue; on a new view march_pass starts the
// rays (from reproject_pass's scatter, or from the camera on a reset); march_pass advances
// unfinished rays by options.stepsPerFrame steps; shade_pass shades only samples that finished;
// accumulate_pass adds them to the AA mean and starts the next jittered sample while the camera rests. A structure
// change recompiles before anything else happens, and every reset keeps the old image on screen
// per pixel until that pixel's new sample is shaded.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "core/camera.hpp"
#include "core/formula.hpp"
#include "core/gl/color_target.hpp"
#include "core/render_settings.hpp"
#include "core/scene/scene_revision.hpp"
#include "core/viewport/frame_logic.hpp"
#include "core/viewport/gpu_counters.hpp"
#include "core/viewport/march_state.hpp"
#include "core/viewport/pass_timer.hpp"
#include "core/viewport/passes.hpp"
#include "core/viewport/viewport_options.hpp"
#include "core/viewport/viewport_programs.hpp"

namespace fraktal::viewport {

class Viewport {
   public:
    explicit Viewport(ViewportOptions options = {});
    ~Viewport();
    Viewport(const Viewport&) = delete;
    Viewport& operator=(const Viewport&) = delete;

    // Renders one frame. Uses render.maxSteps, detail, overRelaxation (and exposure only in the
    // display pass); width/height are the viewport's, not render.width/height. Throws
    // std::runtime_error naming the node if a new structure does not compile (the previous
    // programs and image stay). With a thin lens the anti-aliasing samples at rest (from the second
    // on, which replaces the pinhole first one) leave their own points of the aperture, so the
    // settled image has the lens's depth of field; under motion the image is the pinhole's.
    // `revision`, when the caller has one (the editor: core/scene/scene_revision.hpp), says what
    // changed for the whole scene; without it the formula's own values are compared
    // (formulaValuesKey).
    FrameStats render(const Formula& formula, const Camera& camera, const RenderSettings& render,
                      const ShadingSettings& shading, int width, int height, const ThinLens& lens = {},
                      const scene::SceneRevision* revision = nullptr);

    // What render() with these arguments decides its frame on (decideFrame's key), so that a caller
    // that stops rendering for a while (the editor's path tracing at rest) asks the same question
    // about whether the view changed.
    FrameKey frameKey(const Formula& formula, const Camera& camera, const RenderSettings& render,
                      const ShadingSettings& shading, int width, int height, const ThinLens& lens = {},
                      const scene::SceneRevision* revision = nullptr) const;

    // Whether render() of a formula of this structure (Formula::structureKey, as the frame's
    // scene::SceneRevision holds it) would compile first: the current programs were built for
    // another structure (or none yet).
    bool needsPrograms(const std::string& structure) const { return !programs_ || programs_->structure != structure; }
    // Whether a grid of this size is here (the present one, or the spare one kept for it).
    bool hasGrid(int width, int height) const;
    // A grid made ahead (on a context sharing this one's objects, its commands complete), kept as
    // the spare one until a frame at its size takes it. Dropped when its cone tile is not this
    // viewport's.
    void adoptSpareGrid(std::unique_ptr<MarchState> grid);
    // Programs compiled elsewhere, e.g. on a shared context in a background thread (the editor's
    // BackgroundCompiler), so that render() of their structure does not compile.
    void adoptPrograms(std::unique_ptr<ViewportPrograms> programs) { programs_ = std::move(programs); }
    // Gives the programs up (warm_up.hpp renders with them, then hands them on).
    std::unique_ptr<ViewportPrograms> releasePrograms() { return std::move(programs_); }

    // Changing options takes effect on the next frame (a cone tile change resets).
    void setOptions(const ViewportOptions& options);
    const ViewportOptions& options() const { return options_; }

    // Every pixel has all its samples: further frames of this view cost nothing.
    bool settled() const { return settled_; }
    GLuint imageTexture() const { return state_ ? state_->shown : 0; }
    int width() const { return state_ ? state_->width() : 0; }
    int height() const { return state_ ? state_->height() : 0; }

    // Exposure + sRGB into the bound framebuffer at the current glViewport (rows bottom-up).
    void drawDisplay(float exposure);
    // The scene-linear image shown (MarchState::shown), RGBA floats, rows from the top.
    std::vector<float> readImage() const;
    // The pixel-centre (sample 0) ray of every pixel, RGBA per pixel as the centre image holds it:
    // its distance t, its status (0 marching, 1 hit, 2 escaped), carry age, 0. Rows from the top.
    std::vector<float> readCentreRays() const;
    // The world point each pixel's sample-0 colour is the shading of (xyz; w: 1 for a surface
    // colour, 0 for background or none), MarchState::colourPoint. Rows from the top.
    std::vector<float> readColourPoints() const;
    // The display-referred image, RGBA8, rows from the top.
    std::vector<uint8_t> readDisplay(float exposure);

   private:
    std::vector<float> readState(GLuint MarchState::*texture) const;  // an RGBA32F state image
    // One state image of `from` into `to`'s, bilinearly resampled to its size.
    void resampleInto(const MarchState& from, GLuint MarchState::*texture, const MarchState& to);

    ViewportOptions options_;
    std::unique_ptr<ViewportPrograms> programs_;
    std::unique_ptr<MarchState> state_;
    // The larger grid motion left (a smaller grid renders under motion), kept for the return to its
    // size; at most one, dropped once the grid is as large again.
    std::unique_ptr<MarchState> spareGrid_;
    std::unique_ptr<GpuCounters> counters_;
    std::unique_ptr<PassTimer> timer_;
    std::optional<FrameKey> previous_;
    FrameAction previousAction_ = FrameAction::Reset;
    bool settled_ = false;
    bool forceReset_ = false;
    int slicedFrames_ = 0;  // sliced frames so far: the next one's slice (sliceOfFrame)
    // The last new view's number (MarchState::generation), 1 to kMaxGeneration and round again:
    // rayInfo.w holds it above its flags, 15 bits of a positive int.
    static constexpr int kMaxGeneration = (1 << 15) - 1;
    int generation_ = 0;
    SliceProgress sliceProgress_;
    GLuint resampleFramebuffers_[2] = {0, 0};
    GLuint displayVertexArray_ = 0;
    gl::ColorTarget display_{GL_RGBA8};  // readDisplay's image
};

}  // namespace fraktal::viewport
