#include "core/viewport/march_state.hpp"

#include <algorithm>
#include <iterator>

namespace fraktal::viewport {

namespace {

GLuint makeTexture(GLenum format, int width, int height) {
    GLuint texture = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &texture);
    glTextureStorage2D(texture, 1, format, width, height);
    glTextureParameteri(texture, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(texture, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTextureParameteri(texture, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(texture, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return texture;
}

}  // namespace

MarchState::MarchState(int width, int height, int coneTile) : width_(width), height_(height), coneTile_(coneTile) {
    rayState = makeTexture(GL_RGBA32F, width, height);
    rayInfo = makeTexture(GL_RGBA32I, width, height);
    sampleColor = makeTexture(GL_RGBA32F, width, height);
    accum = makeTexture(GL_RGBA32F, width, height);
    image = makeTexture(GL_RGBA32F, width, height);
    centre = makeTexture(GL_RGBA32F, width, height);
    colourPoint = makeTexture(GL_RGBA32F, width, height);
    shown = makeTexture(GL_RGBA32F, width, height);
    samplePosition = makeTexture(GL_RGBA32F, width, height);
    // Generation 0 in every ray: of no view (`generation`). The image and shown are the viewport's
    // to fill (a resample of the previous grid, or black): with three clears here, a new 690x520
    // grid took 55-66 ms on llvmpipe.
    const GLint noRay[4] = {0, 0, 0, 0};
    glClearTexImage(rayInfo, 0, GL_RGBA_INTEGER, GL_INT, noRay);
    const float none[4] = {0, 0, 0, 0};
    glClearTexImage(centre, 0, GL_RGBA, GL_FLOAT, none);
    const int tile = std::max(coneTile, 1);
    cone = makeTexture(GL_R32F, (width + tile - 1) / tile, (height + tile - 1) / tile);

    reprojDepth = makeTexture(GL_R32UI, width, 3 * height);
    reprojColor = makeTexture(GL_RGBA32F, width, 2 * height);
    reprojCarried = makeTexture(GL_RGBA32F, width, 2 * height);
    const size_t pixels = size_t(width) * size_t(height);
    glCreateBuffers(1, &shadeList);
    glNamedBufferStorage(shadeList, GLsizeiptr((4 + pixels) * sizeof(GLuint)), nullptr, GL_DYNAMIC_STORAGE_BIT);
    glCreateBuffers(1, &marchList);
    glNamedBufferStorage(marchList, GLsizeiptr((4 + 2 * pixels) * sizeof(GLuint)), nullptr, GL_DYNAMIC_STORAGE_BIT);
}

MarchState::~MarchState() {
    glDeleteBuffers(1, &shadeList);
    glDeleteBuffers(1, &marchList);
    const GLuint textures[] = {rayState,    rayInfo, sampleColor,    accum,       image,         centre,     cone,
                               colourPoint, shown,   samplePosition, reprojColor, reprojCarried, reprojDepth};
    glDeleteTextures(GLsizei(std::size(textures)), textures);
}

void MarchState::touchAll() const {
    const float zero[4] = {0, 0, 0, 0};
    for (GLuint texture :
         {rayState, sampleColor, accum, image, colourPoint, shown, samplePosition, reprojColor, reprojCarried, cone})
        glClearTexImage(texture, 0, texture == cone ? GL_RED : GL_RGBA, GL_FLOAT, zero);
    const GLuint noKey[4] = {0, 0, 0, 0};
    glClearTexImage(reprojDepth, 0, GL_RED_INTEGER, GL_UNSIGNED_INT, noKey);
    for (GLuint list : {shadeList, marchList})
        glClearNamedBufferData(list, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, noKey);
}

void MarchState::bindLists() const {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, shadeList);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, marchList);
}

namespace {

void clearPixelList(GLuint list) {
    const GLuint empty[4] = {0, 1, 1, 0};  // groups x, y, z; count
    glNamedBufferSubData(list, 0, sizeof empty, empty);
}

}  // namespace

void MarchState::clearShadeList() const { clearPixelList(shadeList); }

void MarchState::clearMarchList() const { clearPixelList(marchList); }

uint32_t MarchState::marchListCount() const {
    GLuint count = 0;
    glGetNamedBufferSubData(marchList, 3 * sizeof(GLuint), sizeof count, &count);  // after groups x, y, z
    return count;
}

}  // namespace fraktal::viewport
