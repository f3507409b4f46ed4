// Progressive anti-aliasing: accumulation and the next sample (shaders/viewport_accumulate.comp).
#include "core/cpu_render/sphere_trace.hpp"
#include "core/viewport/passes.hpp"

namespace fraktal::viewport {

void runAccumulatePass(const ViewportPrograms& p, const MarchState& s, const FrameContext& c) {
    // A sliced frame (at rest, or a reset at rest) changed its slice's pixels alone: it accumulates
    // those, as at rest (a pixel's next sample starts in the frame its last one finished either
    // way), and shows the image itself (runResolvePass).
    const bool sliced = c.sliceCount > 1;
    const Pass& pass = c.atRest || sliced ? p.accumulateAtRest : p.accumulateMoving;
    const GLuint program = pass.id();
    pass.use(s);
    setViewUniforms(pass.uniforms, c.camera, s.width(), s.height(), c.lens);
    glUniform1i(pass.uniforms.maxSamples, c.options.maxSamples);
    glUniform1f(pass.uniforms.initialOmega, float(cpu::quantizedOmega(std::max(c.shading.overRelaxation, 1.0))));
    dispatchOverSlice(program, pass.uniforms, s, c);
    imageBarrier();
}

// The image shown (shaders/viewport_resolve.comp).
void runResolvePass(const ViewportPrograms& p, const MarchState& s, const FrameContext& c) {
    if (c.atRest || c.sliceCount > 1 || !c.options.motionFilter) {
        // The image itself: a copy costs a fraction of a pass, which llvmpipe would run whole.
        glCopyImageSubData(s.image, GL_TEXTURE_2D, 0, 0, 0, 0, s.shown, GL_TEXTURE_2D, 0, 0, 0, 0, s.width(),
                           s.height(), 1);
        return;
    }
    const GLuint program = p.resolve.id();
    p.resolve.use(s);
    setViewUniforms(p.resolve.uniforms, c.camera, s.width(), s.height());
    glUniform1f(p.resolve.uniforms.radius, float(c.options.motionFilterRadius));
    gl::dispatchOver(program, s.width(), s.height());
    imageBarrier();
}

}  // namespace fraktal::viewport
