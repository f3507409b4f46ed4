// What every OpenGL 4.5 driver provides, and a linked program's needs measured against it.
//
// The limits are the minimum maxima of the OpenGL 4.5 core profile specification (section 23,
// "State Tables", the implementation-dependent limits tables 23.53-23.67). Mesa's llvmpipe, which
// the tests run on, gives far more (32 image units); NVIDIA's driver gives exactly 8 image units,
// and the viewport once failed to compile there on image unit 10. A program within these limits
// links on every 4.5 driver.
#pragma once

#include <epoxy/gl.h>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fraktal::gl {

class Program;

struct PortableLimits {
    // Image units (MAX_IMAGE_UNITS) and image uniforms per stage (MAX_{COMPUTE,FRAGMENT}_IMAGE_UNIFORMS,
    // MAX_COMBINED_IMAGE_UNIFORMS); a vertex shader gets none (MAX_VERTEX_IMAGE_UNIFORMS).
    static constexpr int imageUnits = 8;
    static constexpr int vertexImageUniforms = 0;
    // Texture image units per stage (MAX_{VERTEX_,COMPUTE_,}TEXTURE_IMAGE_UNITS); a sampler's unit
    // is kept below this too, so that one stage's samplers fit whichever units it is given.
    static constexpr int textureUnitsPerStage = 16;
    // Shader storage blocks per stage and their bindings (MAX_{COMPUTE,FRAGMENT}_SHADER_STORAGE_BLOCKS,
    // MAX_COMBINED_SHADER_STORAGE_BLOCKS, MAX_SHADER_STORAGE_BUFFER_BINDINGS); none in a vertex shader.
    static constexpr int storageBlocks = 8;
    static constexpr int vertexStorageBlocks = 0;
    // Uniform blocks per stage (MAX_{VERTEX,FRAGMENT,COMPUTE}_UNIFORM_BLOCKS), their bindings
    // (MAX_UNIFORM_BUFFER_BINDINGS) and a block's size (MAX_UNIFORM_BLOCK_SIZE, bytes).
    static constexpr int uniformBlocksPerStage = 14;
    static constexpr int uniformBufferBindings = 84;
    static constexpr int uniformBlockBytes = 16384;
    // Components of the default uniform block (MAX_{VERTEX,FRAGMENT,COMPUTE}_UNIFORM_COMPONENTS).
    static constexpr int vertexUniformComponents = 1024;
    static constexpr int fragmentUniformComponents = 1024;
    static constexpr int computeUniformComponents = 512;
    // Compute work groups (MAX_COMPUTE_WORK_GROUP_INVOCATIONS, MAX_COMPUTE_WORK_GROUP_SIZE) and
    // their shared memory (MAX_COMPUTE_SHARED_MEMORY_SIZE, bytes).
    static constexpr int workGroupInvocations = 1024;
    static constexpr int workGroupSize[3] = {1024, 1024, 64};
    static constexpr int sharedMemoryBytes = 32768;
    // Fragment outputs (MAX_DRAW_BUFFERS).
    static constexpr int drawBuffers = 8;
};

// Every way `program` exceeds PortableLimits, one line each naming the resource and its stage:
// "compute stage: image uniform u_colourPoint at unit 10 (OpenGL 4.5 guarantees units 0-7)".
// Reads the active image and sampler uniforms' units (their values now: a program whose units are
// assigned after linking is checked again after that), the storage and uniform blocks' bindings
// and sizes, the default block's components, the fragment outputs, the work group size and the
// shared memory its compute source declares. Empty when the program runs on every 4.5 driver.
//
// What linking refuses leaves out the default block's components: the formula's parameters are
// uniforms, so they grow with the node stack (up to kMaxNodes), and real drivers give 1024 (Mesa)
// to 2048 and more (NVIDIA) where the minimum is 512 for a compute shader; a driver that has less
// than a stack needs refuses it itself, and the compile error names the program and its words.
// The tests check the shipped presets against the minimum.
enum class LimitScope { Everything, LinkTime };
std::vector<std::string> portableLimitViolations(const Program& program, LimitScope scope = LimitScope::Everything);

// Whether a uniform of this GL_TYPE is an image (takes an image unit) or a sampler (a texture unit).
bool isImageType(GLenum type);
bool isSamplerType(GLenum type);

// A linked program's active image uniforms, in the order GL lists them.
struct ImageUniform {
    std::string name;
    GLint location;
};
std::vector<ImageUniform> activeImageUniforms(GLuint program);

// The bytes of `shared` variables a compute shader's source declares (std430 sizes of scalars,
// vectors, matrices and their arrays of literal length); nullopt when a declaration is not one
// of those, so that the caller can refuse what it cannot measure.
std::optional<int> sharedMemoryBytes(std::string_view computeSource);

}  // namespace fraktal::gl
