// The interim viewport: a full-screen sphere-tracing pass over the generated formula GLSL
// (assembleShader + DE()), one jittered sample per pixel per frame, accumulated while nothing
// changes until settings.aaCap samples (progressive anti-aliasing). No reprojection: any
// camera or value change restarts the accumulation. Stands in until core/viewport lands.
#pragma once

#include <string>

#include "app/editor/formula_edits.hpp"
#include "app/editor/viewport_view.hpp"
#include "core/gl/formula_uniforms.hpp"
#include "core/gl/program.hpp"

namespace fraktal::editor {

// The GL images of one render size. Owned, freed on resize and destruction.
struct PreviewTargets {
    int width = 0, height = 0;
    GLuint accumulated = 0;  // RGBA32F: summed radiance, alpha = sample count
    GLuint evaluations = 0;  // RG32F with mipmaps: DE evaluations and hit per pixel
    GLuint display = 0;      // RGBA8 sRGB-encoded
    GLuint marchFbo = 0, displayFbo = 0;

    void resize(int w, int h);
    void release();
};

class PreviewViewport final : public ViewportView {
public:
    PreviewViewport();
    ~PreviewViewport() override;
    PreviewViewport(const PreviewViewport&) = delete;
    PreviewViewport& operator=(const PreviewViewport&) = delete;

    void render(const Formula& formula, const Camera& camera, const ViewSettings& settings, int width,
                int height) override;
    GLuint displayTexture() const override { return targets_.display; }
    const ViewportStats& stats() const override { return stats_; }
    const std::string& compileError() const override { return compileError_; }

private:
    bool ensureProgram(const Formula& formula);
    void marchOneSample(const Formula& formula, const Camera& camera, const ViewSettings& settings);
    void updateStats();
    void display(const ViewSettings& settings);

    gl::Program march_, display_;
    gl::FormulaUniforms uniforms_;
    ProgramTracker tracker_;
    std::string failedStructure_;  // the structure whose compile failed (not retried)
    std::string compileError_;
    std::string imageKey_;         // everything the accumulated image depends on
    GLuint emptyVao_ = 0;
    PreviewTargets targets_;
    ViewportStats stats_;
};

}  // namespace fraktal::editor
