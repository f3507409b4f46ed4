// A formula to a printable mesh: prune the bound by the distance estimate (brick_sampler.hpp),
// sample the bricks near the surface into a sparse level set (sdf_volume.hpp), edit it for
// printing (cavities filled, thin parts thickened), mesh its zero level set and colour the
// vertices by the preset's palette. The estimates come from a FormulaSampler: the CPU's
// (double precision, every core) or the GL probe's (the renderer's own GLSL, which also serves
// custom GLSL blocks and Fragmentarium estimators).
#pragma once

#include <optional>

#include "core/formula.hpp"
#include "core/mesh/brick_sampler.hpp"
#include "core/mesh/sdf_volume.hpp"
#include "core/mesh/triangle_mesh.hpp"
#include "core/shading_params.hpp"

namespace fraktal::mesh {

struct MeshSettings {
    GridLayout layout;
    double adaptivity = 0.0;  // volumeToMesh's, in [0, 1]
    int threads = 0;          // 0: all cores
    // Plans needing more are refused up front (TooBigError, with the estimate).
    double memoryLimitBytes = availableMemoryBytes();
    // Only what lies in this box, closed along its faces (BoxClippedSampler); the layout should
    // cover it (layoutOfBox).
    std::optional<Box> clip;
    bool fillCavities = false;  // SdfVolume::fillCavities
    double minThickness = 0.0;  // SdfVolume::thickenThinParts, when > 0
    // Vertex colours from this shading's palette and object colours, when set.
    std::optional<ShadingParams> colors;
    MeshControl control;
};

struct FormulaVolume {
    BrickPlan plan;
    SdfVolume volume;
    int64_t cavityVoxelsFilled = 0;
    int64_t thickenedVoxels = 0;
};

struct FormulaMesh : FormulaVolume {
    TriangleMesh mesh;
};

// The level set with the settings' edits (progress to MeshStages::kLevelSet). Throws
// TooBigError before sampling when the plan would not fit in memory, MeshCancelled when the
// control's flag is set.
FormulaVolume buildVolume(FormulaSampler& sampler, const MeshSettings& settings);
// Its mesh, coloured when the settings ask (progress to MeshStages::kMesh).
TriangleMesh meshVolume(FormulaSampler& sampler, const SdfVolume& volume, const MeshSettings& settings);
// Both, on the CPU. Throws std::invalid_argument for a formula the CPU cannot evaluate (custom
// GLSL blocks: use a gl::GpuSampler with the sampler overloads).
FormulaMesh meshFormula(const Formula& f, const MeshSettings& settings);
FormulaMesh meshFormula(FormulaSampler& sampler, const MeshSettings& settings);

// Colours each vertex with the albedo the palette gives the estimate there (albedoOf).
void colorVertices(FormulaSampler& sampler, const ShadingParams& shading, TriangleMesh& mesh, int threads);

}  // namespace fraktal::mesh
