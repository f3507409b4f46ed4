// The display-referred image a viewport shows: an RGBA8 texture (top row first, linear
// filtering for ImGui's upscale) with the framebuffer the OCIO display pass draws it through.
// Needs the editor's current GL context.
#pragma once

#include "core/gl/color_target.hpp"

namespace fraktal::editor {

class DisplayTarget {
   public:
    // Recreates the texture at a new size; returns true when it did (the image is gone).
    bool resize(int width, int height);
    GLuint texture() const { return target_.texture(); }
    int width() const { return target_.width(); }
    int height() const { return target_.height(); }

    // Binds the framebuffer with a viewport of the target's size; the destructor of the returned
    // guard restores the framebuffer that was bound before.
    struct Binding {
        GLint previous = 0;
        ~Binding() { glBindFramebuffer(GL_FRAMEBUFFER, GLuint(previous)); }
    };
    [[nodiscard]] Binding bind() const;

   private:
    gl::ColorTarget target_{GL_RGBA8};
};

}  // namespace fraktal::editor
