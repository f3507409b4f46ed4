#include "core/mesh/mesh_formula.hpp"

#include <algorithm>
#include <stdexcept>

namespace fraktal::mesh {

FormulaVolume buildVolume(FormulaSampler& formulaSampler, const MeshSettings& settings) {
    std::optional<BoxClippedSampler> clipped;
    if (settings.clip) clipped.emplace(formulaSampler, *settings.clip);
    FormulaSampler& sampler = clipped ? *clipped : formulaSampler;
    BrickPlan plan =
        planBricks(sampler, settings.layout, settings.memoryLimitBytes, settings.threads, settings.control);
    SdfVolume volume = SdfVolume::build(sampler, plan, settings.threads, settings.control);
    int64_t filled = 0, thickened = 0;
    if (settings.fillCavities) {
        settings.control.throwIfCancelled();
        filled = volume.fillCavities();
    }
    if (settings.minThickness > 0.0) {
        settings.control.throwIfCancelled();
        thickened = volume.thickenThinParts(settings.minThickness);
    }
    settings.control.report("level set", MeshStages::kLevelSet);
    return {std::move(plan), std::move(volume), filled, thickened};
}

TriangleMesh meshVolume(FormulaSampler& sampler, const SdfVolume& volume, const MeshSettings& settings) {
    settings.control.throwIfCancelled();
    TriangleMesh mesh = volume.toMesh(settings.adaptivity);
    if (settings.colors) {
        settings.control.throwIfCancelled();
        colorVertices(sampler, *settings.colors, mesh, settings.threads);
    }
    settings.control.report("meshing", MeshStages::kMesh);
    return mesh;
}

FormulaMesh meshFormula(FormulaSampler& sampler, const MeshSettings& settings) {
    FormulaVolume v = buildVolume(sampler, settings);
    TriangleMesh mesh = meshVolume(sampler, v.volume, settings);
    return {std::move(v), std::move(mesh)};
}

FormulaMesh meshFormula(const Formula& f, const MeshSettings& settings) {
    if (!f.cpuEvaluable())
        throw std::invalid_argument(
            "the formula has custom GLSL blocks, which the CPU cannot evaluate (mesh it with the GL sampler)");
    CpuSampler sampler(f);
    return meshFormula(sampler, settings);
}

void colorVertices(FormulaSampler& sampler, const ShadingParams& shading, TriangleMesh& mesh, int threads) {
    mesh.colors.resize(mesh.points.size());
    // In slices: a mesh of millions of points would otherwise hold all their estimates at once.
    constexpr size_t kSlice = 1 << 18;
    std::vector<vec3> points;
    std::vector<Evaluation> estimates;
    for (size_t first = 0; first < mesh.points.size(); first += kSlice) {
        const size_t count = std::min(kSlice, mesh.points.size() - first);
        points.resize(count);
        estimates.resize(count);
        for (size_t i = 0; i < count; ++i) points[i] = mesh.point(uint32_t(first + i));
        evaluatePoints(sampler, points, estimates, threads);
        for (size_t i = 0; i < count; ++i) {
            const vec3 c = albedoOf(shading, estimates[i]);
            mesh.colors[first + i] = {float(c.x), float(c.y), float(c.z)};
        }
    }
}

}  // namespace fraktal::mesh
