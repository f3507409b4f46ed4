#include "app/editor/display_target.hpp"

#include <initializer_list>

namespace fraktal::editor {

DisplayTarget::~DisplayTarget() {
    glDeleteFramebuffers(1, &framebuffer_);
    glDeleteTextures(1, &texture_);
}

bool DisplayTarget::resize(int width, int height) {
    if (width == width_ && height == height_ && texture_) return false;
    glDeleteFramebuffers(1, &framebuffer_);
    glDeleteTextures(1, &texture_);
    glCreateTextures(GL_TEXTURE_2D, 1, &texture_);
    glTextureStorage2D(texture_, 1, GL_RGBA8, width, height);
    for (GLenum filter : {GL_TEXTURE_MIN_FILTER, GL_TEXTURE_MAG_FILTER})
        glTextureParameteri(texture_, filter, GL_LINEAR);
    for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T}) glTextureParameteri(texture_, wrap, GL_CLAMP_TO_EDGE);
    glCreateFramebuffers(1, &framebuffer_);
    glNamedFramebufferTexture(framebuffer_, GL_COLOR_ATTACHMENT0, texture_, 0);
    width_ = width;
    height_ = height;
    return true;
}

DisplayTarget::Binding DisplayTarget::bind() const {
    Binding b;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &b.previous);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    glViewport(0, 0, width_, height_);
    return b;
}

}  // namespace fraktal::editor
