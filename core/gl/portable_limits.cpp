#include "core/gl/portable_limits.hpp"

#include <algorithm>
#include <array>
#include <regex>

#include "core/gl/program.hpp"

namespace fraktal::gl {

namespace {

using L = PortableLimits;

}  // namespace

bool isImageType(GLenum type) { return type >= GL_IMAGE_1D && type <= GL_UNSIGNED_INT_IMAGE_2D_MULTISAMPLE_ARRAY; }

bool isSamplerType(GLenum type) {
    static constexpr GLenum samplers[] = {
        GL_SAMPLER_1D,
        GL_SAMPLER_2D,
        GL_SAMPLER_3D,
        GL_SAMPLER_CUBE,
        GL_SAMPLER_1D_SHADOW,
        GL_SAMPLER_2D_SHADOW,
        GL_SAMPLER_1D_ARRAY,
        GL_SAMPLER_2D_ARRAY,
        GL_SAMPLER_1D_ARRAY_SHADOW,
        GL_SAMPLER_2D_ARRAY_SHADOW,
        GL_SAMPLER_2D_MULTISAMPLE,
        GL_SAMPLER_2D_MULTISAMPLE_ARRAY,
        GL_SAMPLER_CUBE_SHADOW,
        GL_SAMPLER_BUFFER,
        GL_SAMPLER_2D_RECT,
        GL_SAMPLER_2D_RECT_SHADOW,
        GL_SAMPLER_CUBE_MAP_ARRAY,
        GL_SAMPLER_CUBE_MAP_ARRAY_SHADOW,
        GL_INT_SAMPLER_1D,
        GL_INT_SAMPLER_2D,
        GL_INT_SAMPLER_3D,
        GL_INT_SAMPLER_CUBE,
        GL_INT_SAMPLER_1D_ARRAY,
        GL_INT_SAMPLER_2D_ARRAY,
        GL_INT_SAMPLER_2D_MULTISAMPLE,
        GL_INT_SAMPLER_2D_MULTISAMPLE_ARRAY,
        GL_INT_SAMPLER_BUFFER,
        GL_INT_SAMPLER_2D_RECT,
        GL_INT_SAMPLER_CUBE_MAP_ARRAY,
        GL_UNSIGNED_INT_SAMPLER_1D,
        GL_UNSIGNED_INT_SAMPLER_2D,
        GL_UNSIGNED_INT_SAMPLER_3D,
        GL_UNSIGNED_INT_SAMPLER_CUBE,
        GL_UNSIGNED_INT_SAMPLER_1D_ARRAY,
        GL_UNSIGNED_INT_SAMPLER_2D_ARRAY,
        GL_UNSIGNED_INT_SAMPLER_2D_MULTISAMPLE,
        GL_UNSIGNED_INT_SAMPLER_2D_MULTISAMPLE_ARRAY,
        GL_UNSIGNED_INT_SAMPLER_BUFFER,
        GL_UNSIGNED_INT_SAMPLER_2D_RECT,
        GL_UNSIGNED_INT_SAMPLER_CUBE_MAP_ARRAY,
    };
    return std::find(std::begin(samplers), std::end(samplers), type) != std::end(samplers);
}

namespace {

// Components of one element of a default-block uniform, as the limits count them (one per
// scalar); a type not listed counts as a vec4.
int componentsOf(GLenum type) {
    switch (type) {
        case GL_FLOAT:
        case GL_INT:
        case GL_UNSIGNED_INT:
        case GL_BOOL: return 1;
        case GL_FLOAT_VEC2:
        case GL_INT_VEC2:
        case GL_UNSIGNED_INT_VEC2:
        case GL_BOOL_VEC2:
        case GL_DOUBLE: return 2;
        case GL_FLOAT_VEC3:
        case GL_INT_VEC3:
        case GL_UNSIGNED_INT_VEC3:
        case GL_BOOL_VEC3: return 3;
        case GL_FLOAT_MAT2:
        case GL_DOUBLE_VEC2: return 4;
        case GL_DOUBLE_VEC3:
        case GL_FLOAT_MAT2x3:
        case GL_FLOAT_MAT3x2: return 6;
        case GL_FLOAT_MAT2x4:
        case GL_FLOAT_MAT4x2:
        case GL_DOUBLE_VEC4: return 8;
        case GL_FLOAT_MAT3: return 9;
        case GL_FLOAT_MAT3x4:
        case GL_FLOAT_MAT4x3: return 12;
        case GL_FLOAT_MAT4: return 16;
        case GL_DOUBLE_MAT4: return 32;
        default: return 4;
    }
}

struct Stage {
    GLenum referencedBy;  // GL_REFERENCED_BY_*_SHADER
    const char* name;
    int imageUniforms, storageBlocks, uniformComponents;
};

constexpr std::array<Stage, 3> kStages{{
    {GL_REFERENCED_BY_VERTEX_SHADER, "vertex", L::vertexImageUniforms, L::vertexStorageBlocks,
     L::vertexUniformComponents},
    {GL_REFERENCED_BY_FRAGMENT_SHADER, "fragment", L::imageUnits, L::storageBlocks, L::fragmentUniformComponents},
    {GL_REFERENCED_BY_COMPUTE_SHADER, "compute", L::imageUnits, L::storageBlocks, L::computeUniformComponents},
}};

std::string resourceName(GLuint program, GLenum interface, GLuint index) {
    char name[256] = {};
    glGetProgramResourceName(program, interface, index, sizeof name, nullptr, name);
    return name;
}

GLint resourceProperty(GLuint program, GLenum interface, GLuint index, GLenum property) {
    GLint value = 0;
    glGetProgramResourceiv(program, interface, index, 1, &property, 1, nullptr, &value);
    return value;
}

GLint activeResources(GLuint program, GLenum interface) {
    GLint count = 0;
    glGetProgramInterfaceiv(program, interface, GL_ACTIVE_RESOURCES, &count);
    return count;
}

std::string range(int limit) { return limit == 0 ? "none" : "0-" + std::to_string(limit - 1); }

// Per stage: what its image and sampler uniforms, default-block components, storage and uniform
// blocks add up to, checked once all are read.
struct StageUse {
    int images = 0, samplers = 0, components = 0, storageBlocks = 0, uniformBlocks = 0;
};

void checkUniforms(GLuint program, std::array<StageUse, 3>& use, std::vector<std::string>& out) {
    const GLint count = activeResources(program, GL_UNIFORM);
    for (GLint i = 0; i < count; ++i) {
        const GLuint index = GLuint(i);
        const GLenum type = GLenum(resourceProperty(program, GL_UNIFORM, index, GL_TYPE));
        if (resourceProperty(program, GL_UNIFORM, index, GL_BLOCK_INDEX) != -1) continue;  // in a block
        const int elements = std::max(resourceProperty(program, GL_UNIFORM, index, GL_ARRAY_SIZE), 1);
        const GLint location = resourceProperty(program, GL_UNIFORM, index, GL_LOCATION);
        const bool image = isImageType(type), sampler = isSamplerType(type);
        for (size_t s = 0; s < kStages.size(); ++s) {
            if (!resourceProperty(program, GL_UNIFORM, index, kStages[s].referencedBy)) continue;
            if (image)
                use[s].images += elements;
            else if (sampler)
                use[s].samplers += elements;
            else
                use[s].components += elements * componentsOf(type);
        }
        if (!image && !sampler) continue;
        const int unitLimit = image ? L::imageUnits : L::textureUnitsPerStage;
        for (int e = 0; e < elements; ++e) {
            GLint unit = 0;
            glGetUniformiv(program, location + e, &unit);
            if (unit < 0 || unit >= unitLimit)
                out.push_back(std::string(image ? "image" : "sampler") + " uniform " +
                              resourceName(program, GL_UNIFORM, index) + " at unit " + std::to_string(unit) +
                              " (OpenGL 4.5 guarantees units " + range(unitLimit) + ")");
        }
    }
}

void checkBlocks(GLuint program, GLenum interface, std::array<StageUse, 3>& use, std::vector<std::string>& out) {
    const bool storage = interface == GL_SHADER_STORAGE_BLOCK;
    const int bindingLimit = storage ? L::storageBlocks : L::uniformBufferBindings;
    const GLint count = activeResources(program, interface);
    for (GLint i = 0; i < count; ++i) {
        const GLuint index = GLuint(i);
        const std::string what =
            std::string(storage ? "storage" : "uniform") + " block " + resourceName(program, interface, index);
        const GLint binding = resourceProperty(program, interface, index, GL_BUFFER_BINDING);
        if (binding < 0 || binding >= bindingLimit)
            out.push_back(what + " at binding " + std::to_string(binding) + " (OpenGL 4.5 guarantees bindings " +
                          range(bindingLimit) + ")");
        if (!storage) {
            const GLint bytes = resourceProperty(program, interface, index, GL_BUFFER_DATA_SIZE);
            if (bytes > L::uniformBlockBytes)
                out.push_back(what + " of " + std::to_string(bytes) + " bytes (OpenGL 4.5 guarantees " +
                              std::to_string(L::uniformBlockBytes) + ")");
        }
        for (size_t s = 0; s < kStages.size(); ++s)
            if (resourceProperty(program, interface, index, kStages[s].referencedBy))
                (storage ? use[s].storageBlocks : use[s].uniformBlocks) += 1;
    }
}

void checkStageTotals(const std::array<StageUse, 3>& use, LimitScope scope, std::vector<std::string>& out) {
    const auto over = [&out](const Stage& stage, const char* what, int used, int limit) {
        if (used > limit)
            out.push_back(std::string(stage.name) + " stage: " + std::to_string(used) + " " + what +
                          " (OpenGL 4.5 guarantees " + std::to_string(limit) + ")");
    };
    for (size_t s = 0; s < kStages.size(); ++s) {
        const Stage& stage = kStages[s];
        over(stage, "image uniforms", use[s].images, stage.imageUniforms);
        over(stage, "samplers", use[s].samplers, L::textureUnitsPerStage);
        if (scope == LimitScope::Everything)
            over(stage, "default-block uniform components", use[s].components, stage.uniformComponents);
        over(stage, "storage blocks", use[s].storageBlocks, stage.storageBlocks);
        over(stage, "uniform blocks", use[s].uniformBlocks, L::uniformBlocksPerStage);
    }
}

void checkFragmentOutputs(GLuint program, std::vector<std::string>& out) {
    const GLint count = activeResources(program, GL_PROGRAM_OUTPUT);
    for (GLint i = 0; i < count; ++i) {
        const GLuint index = GLuint(i);
        const GLint location = resourceProperty(program, GL_PROGRAM_OUTPUT, index, GL_LOCATION);
        const GLint elements = std::max(resourceProperty(program, GL_PROGRAM_OUTPUT, index, GL_ARRAY_SIZE), 1);
        if (location + elements > L::drawBuffers)
            out.push_back("fragment output " + resourceName(program, GL_PROGRAM_OUTPUT, index) + " at location " +
                          std::to_string(location) + " (OpenGL 4.5 guarantees " + range(L::drawBuffers) + ")");
    }
}

void checkWorkGroup(GLuint program, std::string_view source, std::vector<std::string>& out) {
    GLint size[3] = {1, 1, 1};
    glGetProgramiv(program, GL_COMPUTE_WORK_GROUP_SIZE, size);
    const long invocations = long(size[0]) * size[1] * size[2];
    const std::string declared =
        std::to_string(size[0]) + "x" + std::to_string(size[1]) + "x" + std::to_string(size[2]);
    if (invocations > L::workGroupInvocations)
        out.push_back("work group " + declared + " of " + std::to_string(invocations) +
                      " invocations (OpenGL 4.5 guarantees " + std::to_string(L::workGroupInvocations) + ")");
    for (int axis = 0; axis < 3; ++axis)
        if (size[axis] > L::workGroupSize[axis])
            out.push_back("work group " + declared + ": " + "xyz"[axis] + " size over " +
                          std::to_string(L::workGroupSize[axis]));
    const std::optional<int> shared = sharedMemoryBytes(source);
    if (!shared)
        out.push_back(
            "shared memory: a declaration whose size cannot be measured (scalars, vectors, matrices "
            "and arrays of literal length only)");
    else if (*shared > L::sharedMemoryBytes)
        out.push_back("shared memory of " + std::to_string(*shared) + " bytes (OpenGL 4.5 guarantees " +
                      std::to_string(L::sharedMemoryBytes) + ")");
}

// std430 size of one element (vec3 taken as 16, its array stride).
std::optional<int> sharedTypeBytes(const std::string& type) {
    static const std::regex vector(R"((|i|u|b|d)vec([234]))"), matrix(R"(mat([234])(?:x([234]))?)");
    if (type == "float" || type == "int" || type == "uint" || type == "bool") return 4;
    if (type == "double") return 8;
    std::smatch m;
    if (std::regex_match(type, m, vector)) {
        const int n = m[2].str()[0] - '0';
        return (m[1] == "d" ? 8 : 4) * (n == 3 ? 4 : n);
    }
    if (std::regex_match(type, m, matrix)) return (m[1].str()[0] - '0') * 16;  // columns of vec4 alignment
    return std::nullopt;
}

std::string withoutComments(std::string_view source) {
    static const std::regex comments(R"(//[^\n]*|/\*[\s\S]*?\*/)");
    return std::regex_replace(std::string(source), comments, " ");
}

}  // namespace

std::vector<ImageUniform> activeImageUniforms(GLuint program) {
    std::vector<ImageUniform> images;
    const GLint count = activeResources(program, GL_UNIFORM);
    for (GLint i = 0; i < count; ++i) {
        const GLuint index = GLuint(i);
        if (!isImageType(GLenum(resourceProperty(program, GL_UNIFORM, index, GL_TYPE)))) continue;
        images.push_back(
            {resourceName(program, GL_UNIFORM, index), resourceProperty(program, GL_UNIFORM, index, GL_LOCATION)});
    }
    return images;
}

std::optional<int> sharedMemoryBytes(std::string_view computeSource) {
    const std::string text = withoutComments(computeSource);
    static const std::regex declaration(
        R"(\bshared\s+(?:(?:highp|mediump|lowp|coherent|volatile|restrict)\s+)*(\w+)\s+([^;]*);)");
    static const std::regex declarator(R"(^\s*\w+\s*(?:\[\s*(\d+)\s*\])?\s*$)");
    int total = 0;
    for (std::sregex_iterator it(text.begin(), text.end(), declaration), end; it != end; ++it) {
        const std::optional<int> element = sharedTypeBytes((*it)[1]);
        if (!element) return std::nullopt;
        const std::string names = (*it)[2];
        size_t start = 0;
        while (start <= names.size()) {
            const size_t comma = std::min(names.find(',', start), names.size());
            std::smatch m;
            const std::string one = names.substr(start, comma - start);
            if (!std::regex_match(one, m, declarator)) return std::nullopt;
            total += *element * (m[1].matched ? std::stoi(m[1]) : 1);
            start = comma + 1;
        }
    }
    return total;
}

std::vector<std::string> portableLimitViolations(const Program& program, LimitScope scope) {
    const GLuint id = program.id();
    std::vector<std::string> out;
    std::array<StageUse, 3> use{};
    checkUniforms(id, use, out);
    checkBlocks(id, GL_SHADER_STORAGE_BLOCK, use, out);
    checkBlocks(id, GL_UNIFORM_BLOCK, use, out);
    checkStageTotals(use, scope, out);
    for (const StageSource& stage : program.stages()) {
        if (stage.stage == GL_FRAGMENT_SHADER) checkFragmentOutputs(id, out);
        if (stage.stage == GL_COMPUTE_SHADER) checkWorkGroup(id, stage.text, out);
    }
    return out;
}

}  // namespace fraktal::gl
