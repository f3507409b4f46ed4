#include "core/viewport/pass_images.hpp"

#include <algorithm>
#include <iterator>
#include <stdexcept>

#include "core/gl/portable_limits.hpp"

namespace fraktal::viewport {

namespace {

// Every image a viewport shader may declare (shaders/viewport_common.glsl lists what each holds).
constexpr StateImage kStateImages[] = {
    {"u_rayState", &MarchState::rayState, GL_RGBA32F},
    {"u_rayInfo", &MarchState::rayInfo, GL_RGBA32I},
    {"u_sampleColor", &MarchState::sampleColor, GL_RGBA32F},
    {"u_accum", &MarchState::accum, GL_RGBA32F},
    {"u_image", &MarchState::image, GL_RGBA32F},
    {"u_centre", &MarchState::centre, GL_RGBA32F},
    {"u_cone", &MarchState::cone, GL_R32F},
    {"u_colourPoint", &MarchState::colourPoint, GL_RGBA32F},
    {"u_shown", &MarchState::shown, GL_RGBA32F},
    {"u_samplePosition", &MarchState::samplePosition, GL_RGBA32F},
    {"u_depth", &MarchState::reprojDepth, GL_R32UI},
    {"u_reprojColor", &MarchState::reprojColor, GL_RGBA32F},
    {"u_reprojCarried", &MarchState::reprojCarried, GL_RGBA32F},
};

}  // namespace

PassImages::PassImages(const gl::Program& program) {
    for (const gl::ImageUniform& uniform : gl::activeImageUniforms(program.id())) {
        const std::string& name = uniform.name;
        const auto found = std::find_if(std::begin(kStateImages), std::end(kStateImages),
                                        [&](const StateImage& s) { return name == s.uniform; });
        if (found == std::end(kStateImages))
            throw std::runtime_error("viewport pass " + program.name() + ": image uniform " + name +
                                     " is no march-state image (core/viewport/pass_images.cpp)");
        const GLint unit = GLint(units_.size());
        if (unit >= gl::PortableLimits::imageUnits)
            throw std::runtime_error("viewport pass " + program.name() + ": image uniform " + name +
                                     " would take unit " + std::to_string(unit) +
                                     ", and OpenGL 4.5 guarantees units 0-" +
                                     std::to_string(gl::PortableLimits::imageUnits - 1));
        glProgramUniform1i(program.id(), uniform.location, unit);
        units_.push_back(&*found);
    }
}

void PassImages::bind(const MarchState& state) const {
    for (size_t unit = 0; unit < units_.size(); ++unit) {
        const StateImage& image = *units_[unit];
        glBindImageTexture(GLuint(unit), state.*image.texture, 0, GL_FALSE, 0, GL_READ_WRITE, image.format);
    }
}

}  // namespace fraktal::viewport
