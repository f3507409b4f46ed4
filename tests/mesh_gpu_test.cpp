// core/mesh with the GL probe's estimates (gl::GpuSampler): what `fraktal mesh --device gpu` and
// formulas with custom GLSL blocks mesh with.
#include <gtest/gtest.h>

#include "core/gl/de_probe.hpp"
#include "core/mesh/mesh_formula.hpp"
#include "test_support.hpp"

namespace fraktal {
namespace {

// The GL probe (the renderer's GLSL, single precision) meshes the same solid as the CPU.
TEST(Mesh, GpuSamplerMeshesTheSameSolidAsTheCpu) {
    test::glContext();
    for (const char* name : {"mandelbulb.json", "menger.json"}) {
        const Formula f = test::shippedPreset(name).formula;
        mesh::MeshSettings s;
        s.layout = mesh::layoutByResolution(f, 64);
        s.threads = 2;
        const mesh::FormulaMesh cpu = mesh::meshFormula(f, s);
        gl::GpuSampler gpu(f);
        const mesh::FormulaMesh onGpu = mesh::meshFormula(gpu, s);
        EXPECT_NEAR(onGpu.mesh.enclosedVolume() / cpu.mesh.enclosedVolume(), 1.0, 0.005) << name;
        EXPECT_NEAR(double(onGpu.plan.bricks.size()) / double(cpu.plan.bricks.size()), 1.0, 0.01) << name;
        EXPECT_TRUE(mesh::checkManifold(onGpu.mesh).manifold()) << name;
    }
}

}  // namespace
}  // namespace fraktal
