#include "core/render/shading_uniforms.hpp"

#include <array>
#include <string>

namespace fraktal::gl {

namespace {

void setUniform(GLint location, double v) { glUniform1f(location, float(v)); }
void setUniform(GLint location, int v) { glUniform1i(location, v); }
void setUniform(GLint location, const vec3& v) { glUniform3f(location, float(v.x), float(v.y), float(v.z)); }
void setUniform(GLint location, const glm::vec4& v) { glUniform4f(location, v.x, v.y, v.z, v.w); }

// Every uniform with its value, in one list: set(name, value) for each, in the same order on
// every call, so that the locations found on one pass over it serve every later upload.
template <class Set>
void eachUniform(const ShadingParams& p, Set&& set) {
    set("u_detail", p.detail);
    set("u_overRelaxation", p.overRelaxation);
    set("u_maxStepGrowth", p.maxStepGrowth);
    set("u_viewDistance", p.viewDistance);
    const ShadingSettings& s = p.s;
    set("u_lightDirection", s.lightDirection);
    set("u_lightColor", s.lightColor);
    set("u_fillColor", s.fillColor);
    set("u_specular", s.specular);
    set("u_shininess", s.shininess);
    set("u_shadowSteps", s.shadowSteps);
    set("u_shadowSoftness", s.shadowSoftness);
    set("u_aoSteps", s.aoSteps);
    set("u_aoDistance", s.aoDistance);
    set("u_aoStrength", s.aoStrength);
    set("u_trapWeights", glm::vec4(s.trapWeights));
    set("u_trapScale", s.trapScale);
    set("u_trapOffset", s.trapOffset);
    set("u_paletteA", s.paletteA);
    set("u_paletteB", s.paletteB);
    set("u_paletteC", s.paletteC);
    set("u_paletteD", s.paletteD);
    set("u_fogColor", s.fogColor);
    set("u_fogDensity", s.fogDensity);
    set("u_reflection", s.reflection);
    set("u_reflectionSteps", s.reflectionSteps);
    set("u_backgroundTop", s.backgroundTop);
    set("u_backgroundBottom", s.backgroundBottom);
    static const std::array<std::string, kMaxObjects> objectColorNames = [] {
        std::array<std::string, kMaxObjects> names;
        for (int k = 0; k < kMaxObjects; ++k) names[size_t(k)] = "u_objectColors[" + std::to_string(k) + "]";
        return names;
    }();
    for (size_t k = 0; k < p.objectColors.size(); ++k) set(objectColorNames[k].c_str(), p.objectColors[k]);
}

}  // namespace

ShadingUniforms::ShadingUniforms(GLuint program) {
    eachUniform(ShadingParams{},
                [&](const char* name, const auto&) { locations_.push_back(glGetUniformLocation(program, name)); });
}

void ShadingUniforms::upload(const ShadingParams& p) const {
    size_t k = 0;
    eachUniform(p, [&](const char*, const auto& value) { setUniform(locations_[k++], value); });
}

}  // namespace fraktal::gl
