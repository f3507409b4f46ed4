// The display-referred image a viewport shows: an RGBA8 texture (top row first, linear
// filtering for ImGui's upscale) with the framebuffer the OCIO display pass draws it through.
// Needs the editor's current GL context.
#pragma once

#include <epoxy/gl.h>

namespace fraktal::editor {

class DisplayTarget {
   public:
    DisplayTarget() = default;
    ~DisplayTarget();
    DisplayTarget(const DisplayTarget&) = delete;
    DisplayTarget& operator=(const DisplayTarget&) = delete;

    // Recreates the texture at a new size; returns true when it did (the image is gone).
    bool resize(int width, int height);
    GLuint texture() const { return texture_; }

    // Binds the framebuffer with a viewport of the target's size; the destructor of the returned
    // guard restores the framebuffer that was bound before.
    struct Binding {
        GLint previous = 0;
        ~Binding() { glBindFramebuffer(GL_FRAMEBUFFER, GLuint(previous)); }
    };
    [[nodiscard]] Binding bind() const;

   private:
    GLuint texture_ = 0, framebuffer_ = 0;
    int width_ = 0, height_ = 0;
};

}  // namespace fraktal::editor
