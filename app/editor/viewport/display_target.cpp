#include "app/editor/viewport/display_target.hpp"

#include <initializer_list>

namespace fraktal::editor {

bool DisplayTarget::resize(int width, int height) {
    if (!target_.resize(width, height)) return false;
    // Upscaled to the window by ImGui: linear filtering.
    for (GLenum filter : {GL_TEXTURE_MIN_FILTER, GL_TEXTURE_MAG_FILTER})
        glTextureParameteri(target_.texture(), filter, GL_LINEAR);
    for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T})
        glTextureParameteri(target_.texture(), wrap, GL_CLAMP_TO_EDGE);
    return true;
}

DisplayTarget::Binding DisplayTarget::bind() const {
    Binding b;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &b.previous);
    glBindFramebuffer(GL_FRAMEBUFFER, target_.framebuffer());
    glViewport(0, 0, target_.width(), target_.height());
    return b;
}

}  // namespace fraktal::editor
