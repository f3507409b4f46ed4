#include "core/gl/formula_uniforms.hpp"

#include "core/glsl_gen.hpp"

namespace fraktal::gl {

namespace {
// One parameter's value: a float for scalars and toggles, a vec3 for vectors.
void uploadParam(GLint location, const ParamDecl& decl, const ParamValue& v) {
    if (isScalar(decl.type))
        glUniform1f(location, float(v.x));
    else
        glUniform3f(location, float(v.x), float(v.y), float(v.z));
}
}  // namespace

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
    for (size_t j = 0; j < f.objects.size(); ++j) {
        ObjectLocations o;
        o.center = glGetUniformLocation(program, objectPlacementUniformName(int(j), "center").c_str());
        o.turn = glGetUniformLocation(program, objectPlacementUniformName(int(j), "turn").c_str());
        for (const ParamDecl& p : f.objects[j].block->params)
            o.params.push_back(glGetUniformLocation(program, objectUniformName(int(j), p.name).c_str()));
        objects_.push_back(std::move(o));
    }
}

void FormulaUniforms::upload(const Formula& f) const {
    glUniform1i(iterations_, f.iterations);
    glUniform1f(bailout_, float(f.bailout));
    glUniform1f(deFactor_, float(f.deFactor));
    glUniform1f(boundRadius_, float(f.boundRadius));
    for (size_t k = 0; k < nodes_.size(); ++k) {
        const Node& n = k == f.nodes.size() ? f.estimator : f.nodes[k];
        for (size_t i = 0; i < nodes_[k].size(); ++i) uploadParam(nodes_[k][i], n.block->params[i], n.values[i]);
    }
    for (size_t j = 0; j < objects_.size() && j < f.objects.size(); ++j) {
        const SceneObject& o = f.objects[j];
        const ObjectLocations& at = objects_[j];
        glUniform3f(at.center, float(o.center.x), float(o.center.y), float(o.center.z));
        const glm::mat3 turn(o.localFromWorld());
        glUniformMatrix3fv(at.turn, 1, GL_FALSE, &turn[0][0]);
        for (size_t i = 0; i < at.params.size(); ++i) uploadParam(at.params[i], o.block->params[i], o.values[i]);
    }
}

}  // namespace fraktal::gl
