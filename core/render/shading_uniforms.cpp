#include "core/render/shading_uniforms.hpp"

namespace fraktal::gl {

ShadingUniforms::ShadingUniforms(GLuint program) : program_(program) {}

void ShadingUniforms::upload(const ShadingParams& p) const {
    // Few uniforms, set once per render: looking them up by name here keeps one list of names.
    auto loc = [&](const char* name) { return glGetUniformLocation(program_, name); };
    auto f = [&](const char* name, double v) { glUniform1f(loc(name), float(v)); };
    auto i = [&](const char* name, int v) { glUniform1i(loc(name), v); };
    auto v3 = [&](const char* name, const vec3& v) { glUniform3f(loc(name), float(v.x), float(v.y), float(v.z)); };
    const ShadingSettings& s = p.s;
    f("u_detail", p.detail);
    f("u_overRelaxation", p.overRelaxation);
    v3("u_lightDirection", s.lightDirection);
    v3("u_lightColor", s.lightColor);
    v3("u_fillColor", s.fillColor);
    f("u_specular", s.specular);
    f("u_shininess", s.shininess);
    i("u_shadowSteps", s.shadowSteps);
    f("u_shadowSoftness", s.shadowSoftness);
    i("u_aoSteps", s.aoSteps);
    f("u_aoDistance", s.aoDistance);
    f("u_aoStrength", s.aoStrength);
    glUniform4f(loc("u_trapWeights"), float(s.trapWeights.x), float(s.trapWeights.y), float(s.trapWeights.z),
                float(s.trapWeights.w));
    f("u_trapScale", s.trapScale);
    f("u_trapOffset", s.trapOffset);
    v3("u_paletteA", s.paletteA);
    v3("u_paletteB", s.paletteB);
    v3("u_paletteC", s.paletteC);
    v3("u_paletteD", s.paletteD);
    v3("u_fogColor", s.fogColor);
    f("u_fogDensity", s.fogDensity);
    f("u_reflection", s.reflection);
    i("u_reflectionSteps", s.reflectionSteps);
    v3("u_backgroundTop", s.backgroundTop);
    v3("u_backgroundBottom", s.backgroundBottom);
}

}  // namespace fraktal::gl
