// The GL path tracer: progressive accumulation of shaders/pathtrace.frag over the whole image (the
// estimator of core/cpu_render/cpu_path_tracer.hpp). Needs a current GL 4.5 context.
#pragma once

#include <epoxy/gl.h>

#include <string>

#include "core/cpu_render/cpu_path_tracer.hpp"
#include "core/gl/camera_uniforms.hpp"
#include "core/gl/formula_uniforms.hpp"
#include "core/gl/program.hpp"
#include "core/render/shading_uniforms.hpp"

namespace fraktal::gl {

class PathTracer {
   public:
    // Compiles the program for the formula's structure and allocates width x height sums.
    PathTracer(const Formula& formula, int width, int height);
    ~PathTracer();
    PathTracer(const PathTracer&) = delete;
    PathTracer& operator=(const PathTracer&) = delete;

    // Sets the scene and clears the sums (the size must be the constructor's). Sample k of a pixel
    // draws the random numbers of sample index firstSampleIndex + k (an independent run of the
    // same scene starts past the samples of another).
    void setScene(const PathScene& scene, int firstSampleIndex = 0);
    // Adds `samples` more samples per pixel (draws of at most `batch` samples each). Not while a
    // pass of addSampleRows is under way (std::logic_error).
    void addSamples(int samples, int batch = 4);
    // Continues the next sample pass (sample index samplesTaken() of every pixel) over the next
    // `rows` rows; true when that completes the pass, which then counts in samplesTaken(). One
    // pass spread over several short draws (the editor's viewport keeps its frames short) gives
    // every pixel the sample addSamples would.
    bool addSampleRows(int rows);
    int rowsDone() const { return rowsDone_; }  // of the pass under way (0: none)
    int samplesTaken() const { return samples_; }
    const std::string& structure() const { return structure_; }  // the formula's structureKey()
    // The linked program (the portability checks read it).
    const Program& program() const { return program_; }
    int width() const { return width_; }
    int height() const { return height_; }
    // The beauty pass's running sum (RGBA32F, samplesTaken() samples per pixel, texture row 0 is
    // the image's bottom row), for showing the accumulation without reading it back.
    GLuint beautySumTexture() const { return targets_[kBeauty]; }
    // The sums so far divided by the samples taken (rows from the top).
    PathImage image() const;
    // DE evaluations per pixel per sample, averaged over the image.
    double deEvaluationsPerSample() const;

   private:
    // Binds the program, target and blending for draws into the sums; `end` undoes it.
    void beginDraws();
    void endDraws();
    void draw(int samples);  // one draw of `samples` samples from sample index samples_

    std::string structure_;
    int width_, height_;
    int samples_ = 0, firstSampleIndex_ = 0, rowsDone_ = 0;
    Program program_;
    FormulaUniforms formulaUniforms_;
    ShadingUniforms shadingUniforms_;
    CameraLocations cameraLocations_;
    // Looked up once when the program is built: draw() runs many times per frame.
    GLint firstSampleLocation_ = -1, writeDepthLocation_ = -1, samplesLocation_ = -1;
    GLuint framebuffer_ = 0, vertexArray_ = 0;
    GLuint targets_[kPassCount] = {};
    GLuint envBuffers_[3] = {};
};

}  // namespace fraktal::gl
