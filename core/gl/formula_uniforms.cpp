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
    boundRadius_ = glGetUniformLocation(program, "u_boundRadius");
    for (size_t index = 0; index <= f.fractals.size(); ++index) {
        const Formula& fractal = f.fractalAt(index);
        const std::string suffix = fractalSuffix(index);
        auto location = [&](std::string_view what) {
            return glGetUniformLocation(program, fractalUniformName(what, suffix).c_str());
        };
        FractalLocations at{
            location("iterations"),  location("bailout"),      location("deFactor"),      location("fractalCenter"),
            location("fractalTurn"), location("fractalScale"), location("fractalRepeat"), {}};
        for (size_t k = 0; k <= fractal.nodes.size(); ++k) {
            const bool estimator = k == fractal.nodes.size();
            const Node& n = estimator ? fractal.estimator : fractal.nodes[k];
            std::vector<GLint> locations;
            for (const ParamDecl& p : n.block->params) {
                const std::string name =
                    estimator ? estimatorUniformName(p.name, suffix) : nodeUniformName(int(k), p.name, suffix);
                locations.push_back(glGetUniformLocation(program, name.c_str()));
            }
            at.nodes.push_back(std::move(locations));
        }
        fractals_.push_back(std::move(at));
    }
    for (size_t j = 0; j < f.objects.size(); ++j) {
        ObjectLocations o;
        o.center = glGetUniformLocation(program, objectPlacementUniformName(int(j), "center").c_str());
        o.turn = glGetUniformLocation(program, objectPlacementUniformName(int(j), "turn").c_str());
        o.repeat = glGetUniformLocation(program, objectPlacementUniformName(int(j), "repeat").c_str());
        for (const ParamDecl& p : f.objects[j].block->params)
            o.params.push_back(glGetUniformLocation(program, objectUniformName(int(j), p.name).c_str()));
        objects_.push_back(std::move(o));
    }
}

void FormulaUniforms::upload(const Formula& f) const {
    glUniform1f(boundRadius_, float(f.boundRadius));
    for (size_t index = 0; index < fractals_.size() && index <= f.fractals.size(); ++index) {
        const Formula& fractal = f.fractalAt(index);
        const FractalLocations& at = fractals_[index];
        glUniform1i(at.iterations, fractal.iterations);
        glUniform1f(at.bailout, float(fractal.bailout));
        glUniform1f(at.deFactor, float(fractal.deFactor));
        const FractalPlacement& place = fractal.placement;
        glUniform3f(at.center, float(place.center.x), float(place.center.y), float(place.center.z));
        const glm::mat3 turn(place.Placement::localFromWorld());
        glUniformMatrix3fv(at.turn, 1, GL_FALSE, &turn[0][0]);
        glUniform1f(at.scale, float(place.scale));
        glUniform3f(at.repeat, float(place.repeat.x), float(place.repeat.y), float(place.repeat.z));
        for (size_t k = 0; k < at.nodes.size(); ++k) {
            const Node& n = k == fractal.nodes.size() ? fractal.estimator : fractal.nodes[k];
            for (size_t i = 0; i < at.nodes[k].size(); ++i)
                uploadParam(at.nodes[k][i], n.block->params[i], n.values[i]);
        }
    }
    for (size_t j = 0; j < objects_.size() && j < f.objects.size(); ++j) {
        const SceneObject& o = f.objects[j];
        const ObjectLocations& at = objects_[j];
        glUniform3f(at.center, float(o.center.x), float(o.center.y), float(o.center.z));
        const glm::mat3 turn(o.localFromWorld());
        glUniformMatrix3fv(at.turn, 1, GL_FALSE, &turn[0][0]);
        glUniform3f(at.repeat, float(o.repeat.x), float(o.repeat.y), float(o.repeat.z));
        for (size_t i = 0; i < at.params.size(); ++i) uploadParam(at.params[i], o.block->params[i], o.values[i]);
    }
}

}  // namespace fraktal::gl
