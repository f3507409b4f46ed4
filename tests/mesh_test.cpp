// core/mesh: the sparse level set and its mesh against shapes whose surface and volume are known.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>
#include <map>
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
    EXPECT_EQ(mesh::countCrossingTriangles(out.mesh), 0);
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
    EXPECT_EQ(mesh::countCrossingTriangles(out.mesh), 0) << "level " << level;
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
    EXPECT_EQ(mesh::countCrossingTriangles(out.mesh), 0);
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

// The crossing count sees a triangle through another, and not neighbours that touch.
TEST(Mesh, CrossingTrianglesAreCounted) {
    mesh::TriangleMesh m;
    m.points = {{0, 0, 0},      {2, 0, 0},     {0, 2, 0},    // in the plane z = 0
                {0.5, 0.5, -1}, {0.5, 0.5, 1}, {1, 0.2, 1},  // through its inside
                {2, 0, 0},      {3, 0, 0},     {2, 1, 0}};   // touching it at a corner only
    m.triangles = {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}};
    EXPECT_EQ(mesh::countCrossingTriangles(m), 1);
    m.points[3] = {0.5, 0.5, 0.1};  // lifted wholly above the plane
    EXPECT_EQ(mesh::countCrossingTriangles(m), 0);
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
        CpuSampler sampler(f);
        mesh::planBricks(sampler, mesh::layoutByResolution(f, 1 << 20), 8.0 * 1024 * 1024 * 1024, 2);
        FAIL() << "no error";
    } catch (const mesh::TooBigError& e) {
        EXPECT_NE(std::string(e.what()).find("needs about"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("GiB"), std::string::npos) << e.what();
    }
}

// The Mandelbulb's enclosed volume against a Monte Carlo estimate of its membership: the share
// of uniform points of the bound that the estimator counts inside. The mesh's volume must lie
// within the estimate's error bars (3 sigma) plus the meshing's own error at this voxel size,
// which the sphere above bounds (1 %).
TEST(Mesh, MandelbulbVolumeAgreesWithMonteCarloMembership) {
    const Formula f = test::shippedPreset("mandelbulb.json").formula;
    const FormulaMesh out = mesh::meshFormula(f, byResolution(f, 128));
    constexpr int kPoints = 200000;
    std::vector<vec3> points(kPoints);
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(-f.boundRadius, f.boundRadius);
    for (vec3& p : points) p = randomVec3(u, rng);
    std::vector<Evaluation> estimates(kPoints);
    CpuSampler sampler(f);
    mesh::evaluatePoints(sampler, points, estimates, 2);
    int inside = 0;
    for (const Evaluation& e : estimates) inside += e.inside;
    const double box = std::pow(2.0 * f.boundRadius, 3.0);
    const double share = double(inside) / kPoints;
    const double monteCarlo = share * box;
    const double sigma = box * std::sqrt(share * (1.0 - share) / kPoints);
    const double meshVolume = out.mesh.enclosedVolume();
    EXPECT_NEAR(meshVolume, monteCarlo, 3.0 * sigma + 0.01 * monteCarlo)
        << "Monte Carlo " << monteCarlo << " +- " << sigma << " (" << inside << " of " << kPoints << " inside)";
}

// A sampler of an exact signed distance (for shapes no block draws), with the formula it stands
// for giving the bound and the membership rule (the sign).
class ExactSampler final : public FormulaSampler {
   public:
    ExactSampler(double bound, std::function<double(const vec3&)> distance)
        : formula_(primitive("sphere", vec3(1.0, 0.0, 0.0), bound)), distance_(std::move(distance)) {}
    const Formula& formula() const override { return formula_; }
    void evaluate(std::span<const vec3> points, std::span<Evaluation> out) override {
        for (size_t i = 0; i < points.size(); ++i) {
            out[i] = Evaluation{};
            out[i].distance = distance_(points[i]);
            out[i].inside = out[i].distance < 0.0;
        }
    }
    bool concurrent() const override { return true; }

   private:
    Formula formula_;
    std::function<double(const vec3&)> distance_;
};

double sphereVolume(double r) { return 4.0 / 3.0 * M_PI * r * r * r; }

// A hollow ball (radius 1 with a closed cavity of 0.6) holding a loose ball (0.25) in its
// cavity, and a ball (0.2) outside beside it. Filling the cavities leaves the outer ball and the
// one outside: the cavity's wall and the loose ball are gone, the volume is theirs.
TEST(Mesh, FillingCavitiesKeepsOnlyWhatIsSeenFromOutside) {
    const vec3 outside(1.35, 0.0, 0.0);
    ExactSampler sampler(1.6, [&](const vec3& p) {
        const double r = glm::length(p);
        const double hollow = std::max(r - 1.0, 0.6 - r);
        const double loose = r - 0.25;
        const double beside = glm::length(p - outside) - 0.2;
        return std::min(std::min(hollow, loose), beside);
    });
    MeshSettings s;
    s.layout = mesh::layoutByResolution(sampler.formula(), 96);
    s.threads = 2;
    const FormulaMesh as = mesh::meshFormula(sampler, s);
    const double solid = sphereVolume(1.0) - sphereVolume(0.6) + sphereVolume(0.25) + sphereVolume(0.2);
    EXPECT_NEAR(as.mesh.enclosedVolume() / solid, 1.0, 0.02);
    s.fillCavities = true;
    const FormulaMesh filled = mesh::meshFormula(sampler, s);
    const double kept = sphereVolume(1.0) + sphereVolume(0.2);
    EXPECT_NEAR(filled.mesh.enclosedVolume() / kept, 1.0, 0.01);
    // Every vertex is on the outer ball or the ball outside.
    int inner = 0;
    for (size_t i = 0; i < filled.mesh.points.size(); ++i) {
        const vec3 p = filled.mesh.point(uint32_t(i));
        if (std::abs(glm::length(p) - 1.0) > s.layout.voxel &&
            std::abs(glm::length(p - outside) - 0.2) > s.layout.voxel)
            ++inner;
    }
    EXPECT_EQ(inner, 0) << "vertices left inside, of " << filled.mesh.points.size();
    // The voxels filled: the cavity less the loose ball, within the band's rounding.
    const double filledVolume = double(filled.cavityVoxelsFilled) * std::pow(s.layout.voxel, 3.0);
    EXPECT_NEAR(filledVolume / (sphereVolume(0.6) - sphereVolume(0.25)), 1.0, 0.05) << filled.cavityVoxelsFilled;
    EXPECT_TRUE(mesh::checkManifold(filled.mesh).manifold());
}

// A plate thinner than a nozzle beside a thick ball: the plate comes out at least the minimum
// thick, the ball as it was.
TEST(Mesh, ThinPartsAreThickenedAndThickOnesKept) {
    const vec3 plateHalf(0.5, 0.5, 0.02), ballCentre(0.0, 0.0, 0.9);
    auto plate = [&](const vec3& p) {
        const vec3 q = glm::abs(p) - plateHalf;
        return glm::length(glm::max(q, 0.0)) + std::min(std::max(q.x, std::max(q.y, q.z)), 0.0);
    };
    auto ball = [&](const vec3& p) { return glm::length(p - ballCentre) - 0.3; };
    MeshSettings s;
    s.threads = 2;
    s.minThickness = 0.2;

    ExactSampler ballAlone(1.4, ball);
    s.layout = mesh::layoutByResolution(ballAlone.formula(), 112);
    const FormulaMesh keptBall = mesh::meshFormula(ballAlone, s);
    MeshSettings untouched = s;
    untouched.minThickness = 0.0;
    EXPECT_NEAR(keptBall.mesh.enclosedVolume() / mesh::meshFormula(ballAlone, untouched).mesh.enclosedVolume(), 1.0,
                0.002);
    EXPECT_LT(keptBall.thickenedVoxels, 0.01 * sphereVolume(0.3) / std::pow(s.layout.voxel, 3.0));

    ExactSampler both(1.4, [&](const vec3& p) { return std::min(plate(p), ball(p)); });
    const FormulaMesh out = mesh::meshFormula(both, s);
    // The plate is 0.04 thick: a wall w thin comes out w + minThickness (0.24) thick, its rim
    // reaching 0.1 further, rounded: between the slab over its area and the box around both.
    const double plateAfter = out.mesh.enclosedVolume() - sphereVolume(0.3);
    const double slab = 0.24 * 4.0 * plateHalf.x * plateHalf.y;
    const double box = 0.24 * 4.0 * (plateHalf.x + 0.1) * (plateHalf.y + 0.1);
    EXPECT_GT(plateAfter, slab) << "plate " << plateAfter;
    EXPECT_LT(plateAfter, box) << "plate " << plateAfter;
    EXPECT_GT(out.thickenedVoxels, 0);
    EXPECT_TRUE(mesh::checkManifold(out.mesh).manifold());
}

// A box cuts the solid and closes it along its faces: half a sphere, and a corner of the
// Mandelbulb (whose inside is a flag, so the cut face comes from the box's distance alone).
TEST(Mesh, ABoxCutIsClosedAlongItsFaces) {
    ExactSampler ball(1.5, [](const vec3& p) { return glm::length(p) - 1.0; });
    MeshSettings s;
    s.threads = 2;
    s.clip = mesh::Box{vec3(-1.2, -1.2, -1.2), vec3(1.2, 1.2, 0.0)};
    s.layout = mesh::layoutOfBox(*s.clip, 96);
    const FormulaMesh half = mesh::meshFormula(ball, s);
    EXPECT_NEAR(half.mesh.enclosedVolume() / (0.5 * sphereVolume(1.0)), 1.0, 0.01);
    const auto box = half.mesh.bounds();
    EXPECT_NEAR(box[1].z, 0.0, s.layout.voxel);
    EXPECT_TRUE(mesh::checkManifold(half.mesh).manifold());
    EXPECT_EQ(mesh::countCrossingTriangles(half.mesh), 0);

    const Formula bulb = test::shippedPreset("mandelbulb.json").formula;
    s.clip = mesh::Box{vec3(0.0, 0.0, 0.0), vec3(1.5, 1.5, 1.5)};
    s.layout = mesh::layoutOfBox(*s.clip, 64);
    const FormulaMesh corner = mesh::meshFormula(bulb, s);
    const FormulaMesh whole = mesh::meshFormula(bulb, byResolution(bulb, 128));
    // The bulb's eight octants are alike (its symmetry): one holds about an eighth.
    EXPECT_NEAR(corner.mesh.enclosedVolume() / (whole.mesh.enclosedVolume() / 8.0), 1.0, 0.05);
    const mesh::ManifoldReport r = mesh::checkManifold(corner.mesh);
    EXPECT_TRUE(r.manifold()) << r.boundaryEdges << " boundary, " << r.overSharedEdges << " over-shared, "
                              << r.pinchedVertices << " pinched";
    EXPECT_GE(corner.mesh.bounds()[0].x, -1e-6);
}

// Vertex colours are the palette's albedo at each vertex, and survive the files that carry them:
// linear floats in glTF, 8-bit display values in PLY and OBJ.
TEST(Mesh, VertexColoursAreThePalettesAndReopen) {
    const Preset preset = test::shippedPreset("mandelbulb.json");
    const Formula& f = preset.formula;
    MeshSettings s = byResolution(f, 40);
    s.colors = resolveShading(preset.shading, preset.render, f);
    const FormulaMesh out = mesh::meshFormula(f, s);
    ASSERT_EQ(out.mesh.colors.size(), out.mesh.points.size());
    double spread = 0.0;
    for (size_t i = 0; i < out.mesh.points.size(); i += 13) {
        const vec3 expected = albedoOf(*s.colors, evaluate(f, out.mesh.point(uint32_t(i))));
        for (int a = 0; a < 3; ++a) EXPECT_NEAR(out.mesh.colors[i][size_t(a)], expected[a], 1e-6);
        spread = std::max(spread, std::abs(double(out.mesh.colors[i][0]) - out.mesh.colors[0][0]));
    }
    EXPECT_GT(spread, 0.05) << "the palette varies over the surface";
    test::Sandbox box("fraktal_mesh_colours_");
    // The files may order their vertices otherwise (OBJ's exporter does): matched by position.
    std::map<std::array<float, 3>, size_t> byPosition;
    for (size_t i = 0; i < out.mesh.points.size(); ++i) byPosition[out.mesh.points[i]] = i;
    for (const char* name : {"bulb.glb", "bulb.ply", "bulb.obj"}) {
        mesh::writeMesh(box.path(name), out.mesh);
        const mesh::TriangleMesh back = mesh::readMesh(box.path(name));
        ASSERT_EQ(back.colors.size(), back.points.size()) << name;
        ASSERT_EQ(back.points.size(), out.mesh.points.size()) << name;
        // 8-bit display values, which Assimp truncates: a step of 1/255 in display, up to 0.0094
        // in linear (the sRGB curve's slope is at most 2.4 there).
        const double tolerance = std::string(name) == "bulb.glb" ? 1e-6 : 0.0095;
        double worst = 0.0;
        int unmatched = 0;
        for (size_t i = 0; i < back.points.size(); ++i) {
            const auto at = byPosition.find(back.points[i]);
            if (at == byPosition.end()) {
                ++unmatched;
                continue;
            }
            for (int a = 0; a < 3; ++a)
                worst = std::max(worst,
                                 double(std::abs(back.colors[i][size_t(a)] - out.mesh.colors[at->second][size_t(a)])));
        }
        EXPECT_EQ(unmatched, 0) << name;
        EXPECT_LT(worst, tolerance) << name;
    }
    mesh::writeMesh(box.path("bulb.stl"), out.mesh);
    EXPECT_TRUE(mesh::readMesh(box.path("bulb.stl")).colors.empty()) << "STL carries no colour";
}

// Progress rises to the end of meshing, and a cancel stops the job at its next batch.
TEST(Mesh, ProgressRisesAndCancelStops) {
    const Formula f = test::shippedPreset("mandelbulb.json").formula;
    MeshSettings s = byResolution(f, 64);
    std::vector<double> seen;
    std::vector<std::string> stages;
    s.control.progress = [&](const char* stage, double done) {
        seen.push_back(done);
        if (stages.empty() || stages.back() != stage) stages.push_back(stage);
    };
    mesh::meshFormula(f, s);
    ASSERT_FALSE(seen.empty());
    EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
    EXPECT_DOUBLE_EQ(seen.back(), mesh::MeshStages::kMesh);
    EXPECT_EQ(stages, (std::vector<std::string>{"planning", "sampling", "level set", "meshing"}));

    std::atomic<bool> cancel{false};
    s.control.cancel = &cancel;
    int calls = 0;
    s.control.progress = [&](const char* stage, double) {
        if (std::string(stage) == "sampling" && ++calls == 1) cancel = true;
    };
    EXPECT_THROW(mesh::meshFormula(f, s), mesh::MeshCancelled);
    EXPECT_EQ(calls, 1) << "no batch sampled after the cancel";
}

}  // namespace
}  // namespace fraktal
