// Which image unit each of a viewport pass's images takes.
//
// The viewport's state has 13 images (march_state.hpp), and OpenGL 4.5 guarantees 8 image units
// (NVIDIA's driver gives exactly 8), so no fixed unit per image fits every pass. The shaders
// declare their images without a binding; when a pass's program is built, its active image
// uniforms take units 0, 1, ... in the order GL lists them, found by name in the state, and the
// pass binds exactly those before it dispatches. A pass that declared more than 8 would be refused
// when built, naming it.
#pragma once

#include <epoxy/gl.h>

#include <string>
#include <vector>

#include "core/gl/program.hpp"
#include "core/viewport/march_state.hpp"

namespace fraktal::viewport {

// A march-state image as the shaders name it.
struct StateImage {
    const char* uniform;  // "u_rayState"
    GLuint MarchState::*texture;
    GLenum format;  // the image format the shaders declare (layout(rgba32f) ...)
};

class PassImages {
   public:
    PassImages() = default;
    // Gives each active image uniform of `program` its unit. Throws std::runtime_error naming the
    // program and the uniform when one names no state image, or when there are more than 8.
    explicit PassImages(const gl::Program& program);
    // Binds the pass's images of `state` at their units.
    void bind(const MarchState& state) const;
    // The images in unit order (unit i holds units()[i]).
    const std::vector<const StateImage*>& units() const { return units_; }

   private:
    std::vector<const StateImage*> units_;
};

}  // namespace fraktal::viewport
