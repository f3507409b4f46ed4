#include "core/gl/formula_uniforms.hpp"

#include "core/glsl_gen.hpp"

namespace fraktal::gl {

FormulaUniforms::FormulaUniforms(GLuint program, const Formula& f) {
    iterations_ = glGetUniformLocation(program, "u_iterations");
    bailout_ = glGetUniformLocation(program, "u_bailout");
    deFactor_ = glGetUniformLocation(program, "u_deFactor");
    boundRadius_ = glGetUniformLocation(program, "u_boundRadius");
    for (size_t k = 0; k <= f.nodes.size(); ++k) {
        const bool estimator = k == f.nodes.size();
        const Node& n = estimator ? f.estimator : f.nodes[k];
        std::vector<GLint> locations;
        for (const ParamDecl& p : n.block->params) {
            const std::string name = estimator ? estimatorUniformName(p.name) : nodeUniformName(int(k), p.name);
            locations.push_back(glGetUniformLocation(program, name.c_str()));
        }
        nodes_.push_back(std::move(locations));
    }
}

void FormulaUniforms::upload(const Formula& f) const {
    glUniform1i(iterations_, f.iterations);
    glUniform1f(bailout_, float(f.bailout));
    glUniform1f(deFactor_, float(f.deFactor));
    glUniform1f(boundRadius_, float(f.boundRadius));
    for (size_t k = 0; k < nodes_.size(); ++k) {
        const Node& n = k == f.nodes.size() ? f.estimator : f.nodes[k];
        for (size_t i = 0; i < nodes_[k].size(); ++i) {
            const ParamValue& v = n.values[i];
            if (isScalar(n.block->params[i].type)) glUniform1f(nodes_[k][i], float(v.x));
            else glUniform3f(nodes_[k][i], float(v.x), float(v.y), float(v.z));
        }
    }
}

}  // namespace fraktal::gl
