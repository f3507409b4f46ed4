// core/mesh: the sparse level set and its mesh against shapes whose surface and volume are known.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/mesh/mesh_file.hpp"
#include "core/mesh/mesh_formula.hpp"
#include "core/random_vec.hpp"
#include "test_support.hpp"

namespace fraktal {
namespace {

using mesh::FormulaMesh;
using mesh::MeshSettings;

Formula primitive(const char* estimator, const vec3& size, double bound) {
    Formula f;
    f.iterations = 1;
    f.boundRadius = bound;
    f.estimator = Node::make(*findBlock(estimator));
    f.estimator.values[0] = size;
    return f;
}

MeshSettings byResolution(const Formula& f, int resolution) {
    MeshSettings s;
    s.layout = mesh::layoutByResolution(f, resolution);
    s.threads = 2;
    return s;
}

// The largest distance from a mesh vertex to the exact surface, and from points spread over the
// exact surface to the mesh (both sides of the Hausdorff distance).
struct Hausdorff {
    double meshToSurface = 0.0, surfaceToMesh = 0.0;
    double worst() const { return std::max(meshToSurface, surfaceToMesh); }
};

double distanceToMesh(const mesh::TriangleMesh& m, const vec3& p) {
    double best = 1e300;
    for (const auto& t : m.triangles)
        best = std::min(best, mesh::pointTriangleDistance(p, m.point(t[0]), m.point(t[1]), m.point(t[2])));
    return best;
}

template <class Exact, class OnSurface>
Hausdorff hausdorff(const mesh::TriangleMesh& m, Exact exactDistance, OnSurface surfacePoint, int samples) {
    Hausdorff h;
    for (size_t i = 0; i < m.points.size(); ++i)
        h.meshToSurface = std::max(h.meshToSurface, std::abs(exactDistance(m.point(uint32_t(i)))));
    std::mt19937_64 rng(5);
    for (int i = 0; i < samples; ++i) h.surfaceToMesh = std::max(h.surfaceToMesh, distanceToMesh(m, surfacePoint(rng)));
    return h;
}

TEST(Mesh, SphereIsWithinOneVoxelAndItsVolume) {
    const Formula f = primitive("sphere", vec3(1.0, 0.0, 0.0), 1.5);
    const MeshSettings s = byResolution(f, 64);
    const FormulaMesh out = mesh::meshFormula(f, s);
    const double exactVolume = 4.0 / 3.0 * M_PI;
    EXPECT_NEAR(out.mesh.enclosedVolume() / exactVolume, 1.0, 0.01);
    std::normal_distribution<double> n;
    const Hausdorff h = hausdorff(
        out.mesh, [](const vec3& p) { return glm::length(p) - 1.0; },
        [&](std::mt19937_64& rng) { return glm::normalize(randomVec3(n, rng)); }, 300);
    EXPECT_LT(h.worst(), s.layout.voxel) << "vertex to sphere " << h.meshToSurface << ", sphere to mesh "
                                         << h.surfaceToMesh;
    // Sparse: the bricks sampled are the shell's, a small part of the (64 / 8)^3 of the bound.
    EXPECT_LT(out.plan.bricks.size(), 0.75 * std::pow(8.0, 3));
    const mesh::ManifoldReport r = mesh::checkManifold(out.mesh);
    EXPECT_TRUE(r.manifold()) << r.boundaryEdges << " boundary, " << r.overSharedEdges << " over-shared, "
                              << r.misorientedEdges << " misoriented edges, " << r.pinchedVertices << " pinched";
}

TEST(Mesh, BoxIsWithinOneVoxelAndItsVolume) {
    const vec3 half(0.9, 0.6, 0.75);
    const Formula f = primitive("box", half, 1.3);
    const MeshSettings s = byResolution(f, 64);
    const FormulaMesh out = mesh::meshFormula(f, s);
    EXPECT_NEAR(out.mesh.enclosedVolume() / (8.0 * half.x * half.y * half.z), 1.0, 0.01);
    auto exact = [&](const vec3& p) {
        const vec3 q = glm::abs(p) - half;
        return glm::length(glm::max(q, 0.0)) + std::min(std::max(q.x, std::max(q.y, q.z)), 0.0);
    };
    // A point on one of the six faces, picked by area.
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    auto onBox = [&](std::mt19937_64& rng) {
        vec3 p = randomVec3(u, rng) * half;
        const double areas[3] = {half.y * half.z, half.x * half.z, half.x * half.y};
        double pick = (u(rng) + 1.0) * 0.5 * (areas[0] + areas[1] + areas[2]);
        int axis = pick < areas[0] ? 0 : pick < areas[0] + areas[1] ? 1 : 2;
        p[axis] = u(rng) < 0.0 ? -half[axis] : half[axis];
        return p;
    };
    const Hausdorff h = hausdorff(out.mesh, exact, onBox, 300);
    EXPECT_LT(h.worst(), s.layout.voxel) << "vertex to box " << h.meshToSurface << ", box to mesh " << h.surfaceToMesh;
    EXPECT_TRUE(mesh::checkManifold(out.mesh).manifold());
}

// Level k of the sponge keeps 20 of 27 sub-cubes k times: (20/27)^k of the cube's volume.
void expectMengerVolume(int level, double voxelsAlongEdge) {
    Formula f = test::shippedPreset("menger.json").formula;
    f.iterations = level;
    MeshSettings s;
    s.layout = mesh::layoutByVoxel(f, 2.0 / voxelsAlongEdge);
    s.threads = 2;
    const FormulaMesh out = mesh::meshFormula(f, s);
    const double expected = 8.0 * std::pow(20.0 / 27.0, level);
    EXPECT_NEAR(out.mesh.enclosedVolume() / expected, 1.0, 0.02) << "level " << level;
    const mesh::ManifoldReport r = mesh::checkManifold(out.mesh);
    EXPECT_TRUE(r.manifold()) << "level " << level << ": " << r.boundaryEdges << " boundary, " << r.overSharedEdges
                              << " over-shared, " << r.misorientedEdges << " misoriented edges, " << r.pinchedVertices
                              << " pinched, " << r.degenerateTriangles << " degenerate";
}

// The smallest holes (1/3^k of the edge) 4 (level 3) to 9 (level 2) voxels wide: the mesh bevels their edges by under a
// voxel.
TEST(Mesh, MengerSpongeVolumeAtLevelTwo) { expectMengerVolume(2, 81.0); }
TEST(Mesh, MengerSpongeVolumeAtLevelThree) { expectMengerVolume(3, 108.0); }

// The Mandelbulb's interior is a flag (escape-time): the mesh is still closed, and the level set
// is a distance field (its neighbours differ by at most a voxel, so |grad| <= 1 with slack).
TEST(Mesh, MandelbulbIsClosedFromItsMembership) {
    const Formula f = test::shippedPreset("mandelbulb.json").formula;
    const MeshSettings s = byResolution(f, 96);
    const FormulaMesh out = mesh::meshFormula(f, s);
    EXPECT_GT(out.mesh.triangles.size(), 10000u);
    const mesh::ManifoldReport r = mesh::checkManifold(out.mesh);
    EXPECT_TRUE(r.manifold()) << r.boundaryEdges << " boundary, " << r.overSharedEdges << " over-shared, "
                              << r.misorientedEdges << " misoriented edges, " << r.pinchedVertices << " pinched, "
                              << r.degenerateTriangles << " degenerate";
    // Every vertex lies where the estimator's membership changes: within a voxel of it (the
    // 27 points of the cube a voxel about it) are points inside and outside.
    int wrong = 0, checked = 0;
    for (size_t i = 0; i < out.mesh.points.size(); i += 7, ++checked) {
        const vec3 p = out.mesh.point(uint32_t(i));
        bool in = false, outside = false;
        for (int dz = -1; dz <= 1; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx)
                    (evaluate(f, p + vec3(dx, dy, dz) * s.layout.voxel).inside ? in : outside) = true;
        wrong += !(in && outside);
    }
    EXPECT_LT(wrong, checked / 50) << "vertices away from the membership's change, of " << checked;
}

TEST(Mesh, VdbAndMeshFilesReopen) {
    const Formula f = primitive("sphere", vec3(1.0, 0.0, 0.0), 1.5);
    const FormulaMesh out = mesh::meshFormula(f, byResolution(f, 32));
    test::Sandbox box("fraktal_mesh_files_");
    out.volume.writeVdb(box.path("sphere.vdb"));
    const mesh::VdbSummary vdb = mesh::readVdb(box.path("sphere.vdb"));
    EXPECT_EQ(vdb.grids, 1);
    EXPECT_EQ(vdb.name, mesh::kVdbGridName);
    EXPECT_EQ(vdb.gridClass, "level set");
    EXPECT_EQ(vdb.activeVoxels, out.volume.activeVoxels());
    ASSERT_TRUE(vdb.sample);
    // A signed distance: about -0.5 halfway in, +0.2 just outside.
    EXPECT_NEAR(vdb.sample(vec3(0.2, 0.0, 0.0)), vdb.voxelSize * -3.0, 1e-6);  // deep inside: -background
    EXPECT_NEAR(vdb.sample(vec3(0.0, 0.9, 0.0)), -0.1, 0.02);
    EXPECT_NEAR(vdb.sample(vec3(0.0, 0.0, 1.1)), 0.1, 0.02);
    for (const char* name : {"sphere.ply", "sphere.obj", "sphere.stl", "sphere.glb"}) {
        mesh::writeMesh(box.path(name), out.mesh);
        const mesh::TriangleMesh back = mesh::readMesh(box.path(name));
        EXPECT_EQ(back.triangles.size(), out.mesh.triangles.size()) << name;
        EXPECT_NEAR(back.enclosedVolume(), out.mesh.enclosedVolume(), 1e-4) << name;
        const mesh::ManifoldReport r = mesh::checkManifold(back);
        EXPECT_TRUE(r.manifold()) << name << ": " << r.boundaryEdges << " boundary, " << r.overSharedEdges
                                  << " over-shared, " << r.misorientedEdges << " misoriented edges, "
                                  << r.pinchedVertices << " pinched, " << r.degenerateTriangles << " degenerate";
    }
    EXPECT_EQ(box.fileCount(), 5) << "no temporary file left";
}

TEST(Mesh, PlanThatDoesNotFitIsRefusedWithTheEstimate) {
    const Formula f = test::shippedPreset("menger.json").formula;
    try {
        mesh::planBricks(f, mesh::layoutByResolution(f, 1 << 20), 8.0 * 1024 * 1024 * 1024, 2);
        FAIL() << "no error";
    } catch (const mesh::TooBigError& e) {
        EXPECT_NE(std::string(e.what()).find("needs about"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("GiB"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace fraktal
