// A formula to a printable mesh on the CPU: prune the bound by the distance estimate
// (brick_sampler.hpp), sample the bricks near the surface into a sparse level set
// (sdf_volume.hpp), mesh its zero level set.
#pragma once

#include "core/formula.hpp"
#include "core/mesh/brick_sampler.hpp"
#include "core/mesh/sdf_volume.hpp"
#include "core/mesh/triangle_mesh.hpp"

namespace fraktal::mesh {

struct MeshSettings {
    GridLayout layout;
    double adaptivity = 0.0;  // volumeToMesh's, in [0, 1]
    int threads = 0;          // 0: all cores
    // Plans needing more are refused up front (TooBigError, with the estimate).
    double memoryLimitBytes = availableMemoryBytes();
};

struct FormulaMesh {
    BrickPlan plan;
    SdfVolume volume;
    TriangleMesh mesh;
};

// Throws std::invalid_argument for a formula the CPU cannot evaluate (custom GLSL blocks), and
// TooBigError before sampling when the plan would not fit in memory.
FormulaMesh meshFormula(const Formula& f, const MeshSettings& settings);

}  // namespace fraktal::mesh
