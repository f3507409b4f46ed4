// A colour texture with a framebuffer that draws into it, recreated when its size changes: the
// target of a pass whose output is read back or shown (the viewport's display image, the editor's
// path-traced image and display texture). Needs a current GL context.
#pragma once

#include <epoxy/gl.h>

namespace fraktal::gl {

class ColorTarget {
   public:
    explicit ColorTarget(GLenum internalFormat) : format_(internalFormat) {}
    ~ColorTarget();
    ColorTarget(const ColorTarget&) = delete;
    ColorTarget& operator=(const ColorTarget&) = delete;

    // Recreates the texture and framebuffer at a new size; returns true when it did (the old
    // image is gone). Does nothing when the size is the same.
    bool resize(int width, int height);

    GLuint texture() const { return texture_; }
    GLuint framebuffer() const { return framebuffer_; }
    int width() const { return width_; }
    int height() const { return height_; }

   private:
    GLenum format_;
    GLuint texture_ = 0, framebuffer_ = 0;
    int width_ = 0, height_ = 0;
};

}  // namespace fraktal::gl
