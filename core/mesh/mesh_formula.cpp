#include "core/mesh/mesh_formula.hpp"

#include <stdexcept>

namespace fraktal::mesh {

FormulaMesh meshFormula(const Formula& f, const MeshSettings& settings) {
    if (!f.cpuEvaluable())
        throw std::invalid_argument(
            "the formula has custom GLSL blocks, which the mesher (on the CPU) cannot evaluate");
    BrickPlan plan = planBricks(f, settings.layout, settings.memoryLimitBytes, settings.threads);
    SdfVolume volume = SdfVolume::build(f, plan, settings.threads);
    TriangleMesh mesh = volume.toMesh(settings.adaptivity);
    return {std::move(plan), std::move(volume), std::move(mesh)};
}

}  // namespace fraktal::mesh
