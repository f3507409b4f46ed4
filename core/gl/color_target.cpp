#include "core/gl/color_target.hpp"

namespace fraktal::gl {

ColorTarget::~ColorTarget() {
    glDeleteFramebuffers(1, &framebuffer_);
    glDeleteTextures(1, &texture_);
}

bool ColorTarget::resize(int width, int height) {
    if (width == width_ && height == height_ && texture_) return false;
    glDeleteFramebuffers(1, &framebuffer_);
    glDeleteTextures(1, &texture_);
    glCreateTextures(GL_TEXTURE_2D, 1, &texture_);
    glTextureStorage2D(texture_, 1, format_, width, height);
    glCreateFramebuffers(1, &framebuffer_);
    glNamedFramebufferTexture(framebuffer_, GL_COLOR_ATTACHMENT0, texture_, 0);
    width_ = width;
    height_ = height;
    return true;
}

}  // namespace fraktal::gl
