// The one translation unit that includes OpenVDB (its headers take long to compile).
#include "core/mesh/sdf_volume.hpp"

#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>
#include <openvdb/tools/ChangeBackground.h>
#include <openvdb/tools/Composite.h>
#include <openvdb/tools/Count.h>
#include <openvdb/tools/FastSweeping.h>
#include <openvdb/tools/Interpolation.h>
#include <openvdb/tools/LevelSetFilter.h>
#include <openvdb/tools/LevelSetUtil.h>
#include <openvdb/tools/Prune.h>
#include <openvdb/tools/SignedFloodFill.h>
#include <openvdb/tools/VolumeToMesh.h>
#include <openvdb/tree/LeafManager.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <array>
#include <mutex>

#include "core/atomic_file.hpp"

namespace fraktal::mesh {

namespace {

void initializeOpenVdb() {
    static std::once_flag once;
    std::call_once(once, [] { openvdb::initialize(); });
}

// OpenVDB runs its tools on TBB's pool: `threads` caps it (0: TBB's default, all cores).
std::unique_ptr<tbb::global_control> capThreads(int threads) {
    if (threads <= 0) return nullptr;
    return std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, size_t(threads));
}

using Tree = openvdb::FloatTree;
using Leaf = Tree::LeafNodeType;
static_assert(Leaf::DIM == kBrickSize, "a sampled brick fills one leaf node");

// A voxel's six face neighbours: the lattice edges from it.
std::array<openvdb::Coord, 6> faceNeighbours(const openvdb::Coord& c) {
    std::array<openvdb::Coord, 6> n;
    n.fill(c);
    for (int axis = 0; axis < 3; ++axis) {
        n[size_t(2 * axis)][axis] -= 1;
        n[size_t(2 * axis + 1)][axis] += 1;
    }
    return n;
}

// Puts the zero crossing where the estimator's membership changes. The sampled values beside the
// surface are estimates: outside, a lower bound of the distance (so the crossing volumeToMesh
// interpolates lies too far out, and the solid comes out fat: 5 % too much volume on the
// Mandelbulb at 128^3), inside an escape-time set no distance at all. Every lattice edge from an
// outside voxel to an inside one is bisected on membership (kBisections steps from the
// estimate's bound, a 32nd of a voxel), and both ends take the distance along their edges to the
// nearest crossing: the outside end +t, the inside end -(1 - t) in voxels, so that the linear
// interpolation along that edge lands on the crossing.
constexpr int kBisections = 5;

void placeCrossingsOnMembership(openvdb::FloatGrid& grid, FormulaSampler& sampler, const GridLayout& layout,
                                int threads, const MeshControl& control) {
    const float background = grid.background();
    const float voxel = float(layout.voxel);
    Tree& tree = grid.tree();
    // The inside ends first take -background, so that the nearest crossing's value replaces the
    // estimate there (a max below); the sign, which every other leaf reads, does not change.
    {
        openvdb::tree::LeafManager<Tree> leaves(tree);
        leaves.foreach ([&](Leaf& leaf, size_t) {
            openvdb::tree::ValueAccessor<const Tree> neighbours(grid.constTree());
            for (auto v = leaf.beginValueOn(); v; ++v) {
                if (*v >= 0.0f) continue;
                for (const openvdb::Coord& n : faceNeighbours(v.getCoord())) {
                    float value;
                    if (neighbours.probeValue(n, value) && value >= 0.0f) {
                        v.setValue(-background);
                        break;
                    }
                }
            }
        });
    }
    struct Edge {
        openvdb::Coord outside, inside;
        float lo = 0.0f, hi = 1.0f;  // the crossing's share of the way from outside to inside
    };
    std::vector<Leaf*> leafList;
    tree.getNodes(leafList);
    constexpr size_t kLeavesPerSlice = 1024;
    std::vector<Edge> edges;
    std::vector<vec3> points;
    std::vector<Evaluation> estimates;
    openvdb::tree::ValueAccessor<Tree> values(tree);
    auto world = [&](const openvdb::Coord& c) { return layout.voxelCentre(c.x(), c.y(), c.z()); };
    for (size_t slice = 0; slice < leafList.size(); slice += kLeavesPerSlice) {
        control.throwIfCancelled();
        edges.clear();
        const size_t end = std::min(leafList.size(), slice + kLeavesPerSlice);
        for (size_t l = slice; l < end; ++l)
            for (auto v = leafList[l]->cbeginValueOn(); v; ++v) {
                if (*v < 0.0f) continue;
                for (const openvdb::Coord& n : faceNeighbours(v.getCoord())) {
                    float value;
                    // The outside end's estimate is a lower bound of the distance: no crossing is
                    // nearer than that.
                    if (values.probeValue(n, value) && value < 0.0f)
                        edges.push_back({v.getCoord(), n, std::min(*v / voxel, 1.0f), 1.0f});
                }
            }
        points.resize(edges.size());
        estimates.resize(edges.size());
        for (int round = 0; round < kBisections; ++round) {
            for (size_t e = 0; e < edges.size(); ++e) {
                const double t = 0.5 * (edges[e].lo + edges[e].hi);
                points[e] = glm::mix(world(edges[e].outside), world(edges[e].inside), t);
            }
            evaluatePoints(sampler, points, estimates, threads);
            for (size_t e = 0; e < edges.size(); ++e) {
                const float t = 0.5f * (edges[e].lo + edges[e].hi);
                (estimates[e].inside ? edges[e].hi : edges[e].lo) = t;
            }
        }
        // The outside ends' estimates are replaced (each is in this slice with all its edges);
        // the inside ends keep the nearest crossing of any slice.
        for (const Edge& e : edges) values.setValueOnly(e.outside, background);
        for (const Edge& e : edges) {
            const float t = 0.5f * (e.lo + e.hi);
            values.setValueOnly(e.outside, std::min(values.getValue(e.outside), t * voxel));
            values.setValueOnly(e.inside,
                                std::max(values.getValue(e.inside), std::min(-(1.0f - t) * voxel, -1e-3f * voxel)));
        }
    }
}

// Keeps the band: values clamped to +-background, voxels at the band's edge made inactive, and
// the grid's background (fast sweeping's output has its own) the band's width again.
void trimToBand(openvdb::FloatGrid& grid, float background) {
    openvdb::tree::LeafManager<Tree> leaves(grid.tree());
    leaves.foreach ([&](Leaf& leaf, size_t) {
        for (auto v = leaf.beginValueOn(); v; ++v) {
            const float d = *v;
            if (std::isnan(d) || std::abs(d) >= background) {
                v.setValue(std::isnan(d) || d > 0.0f ? background : -background);
                v.setValueOff();
            }
        }
    });
    openvdb::tools::changeLevelSetBackground(grid.tree(), background);
    openvdb::tools::signedFloodFill(grid.tree());
    openvdb::tools::pruneLevelSet(grid.tree());
}

// The level set re-normalised from its zero crossing: fast sweeping keeps the active topology and
// recomputes every active value (openvdb/tools/FastSweeping.h, sdfToSdf), then the band is
// trimmed again. A grid with no crossing is kept as it is (there is nothing to sweep from).
openvdb::FloatGrid::Ptr swept(const openvdb::FloatGrid::Ptr& grid) {
    const float background = grid->background();
    const auto range = openvdb::tools::minMax(grid->tree());
    openvdb::FloatGrid::Ptr out = grid;
    if (range.min() < 0.0f && range.max() > 0.0f) {
        out = openvdb::tools::sdfToSdf(*grid, 0.0f, 1);
        out->setTransform(grid->transform().copy());
        out->setGridClass(openvdb::GRID_LEVEL_SET);
        out->setName(kVdbGridName);
    }
    trimToBand(*out, background);
    return out;
}

}  // namespace

struct SdfVolume::Impl {
    openvdb::FloatGrid::Ptr grid;
    int threads = 0;
};

SdfVolume::SdfVolume(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
SdfVolume::SdfVolume(SdfVolume&&) noexcept = default;
SdfVolume& SdfVolume::operator=(SdfVolume&&) noexcept = default;
SdfVolume::~SdfVolume() = default;

SdfVolume SdfVolume::build(FormulaSampler& sampler, const BrickPlan& plan, int threads, const MeshControl& control) {
    initializeOpenVdb();
    const auto cap = capThreads(threads);
    const GridLayout& layout = plan.layout;
    auto grid = openvdb::FloatGrid::create(float(layout.background()));
    // Index (i, j, k) is the lattice's voxel (i, j, k), whose centre is at
    // minCorner + (i + 0.5, j + 0.5, k + 0.5) * voxel.
    auto transform = openvdb::math::Transform::createLinearTransform(layout.voxel);
    const vec3 first = layout.voxelCentre(0, 0, 0);
    transform->postTranslate(openvdb::Vec3d(first.x, first.y, first.z));
    grid->setTransform(transform);
    grid->setGridClass(openvdb::GRID_LEVEL_SET);
    grid->setName(kVdbGridName);

    Tree& tree = grid->tree();
    sampleBricks(
        sampler, plan, threads,
        [&](std::vector<SampledBrick>& batch) {
            for (const SampledBrick& b : batch) {
                const openvdb::Coord origin(b.brick[0] * kBrickSize, b.brick[1] * kBrickSize, b.brick[2] * kBrickSize);
                Leaf* leaf = tree.touchLeaf(origin);
                for (int z = 0; z < kBrickSize; ++z)
                    for (int y = 0; y < kBrickSize; ++y)
                        for (int x = 0; x < kBrickSize; ++x)
                            leaf->setValueOn(origin.offsetBy(x, y, z), b.values[size_t(SampledBrick::index(x, y, z))]);
            }
        },
        control);
    control.throwIfCancelled();
    control.report("level set", MeshStages::kSample);
    placeCrossingsOnMembership(*grid, sampler, layout, threads, control);
    // Inactive space takes the sign of the band beside it (outside +background, inside
    // -background), so that sweeping and meshing see the solid.
    openvdb::tools::signedFloodFill(tree);

    auto impl = std::make_unique<Impl>();
    impl->threads = threads;
    impl->grid = swept(grid);
    return SdfVolume(std::move(impl));
}

int64_t SdfVolume::insideVoxels() const {
    return int64_t(openvdb::tools::sdfInteriorMask(*impl_->grid)->activeVoxelCount());
}

int64_t SdfVolume::fillCavities() {
    const auto cap = capThreads(impl_->threads);
    openvdb::FloatGrid& grid = *impl_->grid;
    const int64_t before = insideVoxels();
    // Enclosed: the inside and the cavities; the cavities are the enclosed voxels outside.
    const auto enclosed = openvdb::tools::extractEnclosedRegion(grid);
    const float background = grid.background();
    openvdb::tree::LeafManager<Tree> leaves(grid.tree());
    leaves.foreach ([&](Leaf& leaf, size_t) {
        openvdb::tree::ValueAccessor<const openvdb::BoolTree> mask(enclosed->tree());
        for (auto v = leaf.beginValueOn(); v; ++v)
            if (*v > 0.0f && mask.isValueOn(v.getCoord())) v.setValue(-background);
    });
    // The cavities' inactive tiles take the sign of the (now solid) band around them.
    openvdb::tools::signedFloodFill(grid.tree());
    impl_->grid = swept(impl_->grid);
    return insideVoxels() - before;
}

int64_t SdfVolume::thickenThinParts(double minThickness) {
    const auto cap = capThreads(impl_->threads);
    openvdb::FloatGrid::Ptr grid = impl_->grid;
    const float background = grid->background();
    const float radius = float(0.5 * minThickness);
    const int64_t before = insideVoxels();
    // offset(+r) erodes by r (the distance grows by r everywhere), offset(-r) dilates. The
    // opening is dilated a voxel and a half further before it is taken away: the opening of a
    // thick part is that part again up to the grid's rounding, and the difference of the two
    // would be a shell of slivers that the dilation below turns into a thick coat.
    const float tolerance = 1.5f * float(grid->voxelSize()[0]);
    openvdb::FloatGrid::Ptr opened = grid->deepCopy();
    {
        openvdb::tools::LevelSetFilter<openvdb::FloatGrid> filter(*opened);
        filter.offset(radius);
        filter.offset(-radius - tolerance);
    }
    openvdb::FloatGrid::Ptr thin = grid->deepCopy();
    openvdb::tools::csgDifference(*thin, *opened);
    {
        openvdb::tools::LevelSetFilter<openvdb::FloatGrid> filter(*thin);
        filter.offset(-radius);
    }
    openvdb::tools::csgUnion(*grid, *thin);
    trimToBand(*grid, background);
    return insideVoxels() - before;
}

TriangleMesh SdfVolume::toMesh(double adaptivity) const {
    std::vector<openvdb::Vec3s> points;
    std::vector<openvdb::Vec3I> triangles;
    std::vector<openvdb::Vec4I> quads;
    openvdb::tools::volumeToMesh(*impl_->grid, points, triangles, quads, 0.0, std::clamp(adaptivity, 0.0, 1.0));
    TriangleMesh mesh;
    mesh.points.resize(points.size());
    for (size_t i = 0; i < points.size(); ++i) mesh.points[i] = {points[i].x(), points[i].y(), points[i].z()};
    points = {};
    mesh.triangles.reserve(triangles.size() + 2 * quads.size());
    for (const auto& t : triangles) mesh.triangles.push_back({t.x(), t.y(), t.z()});
    for (const auto& q : quads) {
        mesh.triangles.push_back({q.x(), q.y(), q.z()});
        mesh.triangles.push_back({q.x(), q.z(), q.w()});
    }
    // volumeToMesh winds its polygons one way for every grid: the sign of the volume says which.
    if (mesh.enclosedVolume() < 0.0) mesh.flip();
    return mesh;
}

void SdfVolume::writeVdb(const std::filesystem::path& path) const {
    AtomicFile out(path);
    {
        openvdb::io::File file(out.tempPath().string());
        file.write(openvdb::GridCPtrVec{impl_->grid});
        file.close();
    }
    out.commit();
}

int64_t SdfVolume::activeVoxels() const { return int64_t(impl_->grid->activeVoxelCount()); }
int64_t SdfVolume::leafCount() const { return int64_t(impl_->grid->tree().leafCount()); }
size_t SdfVolume::memoryBytes() const { return size_t(impl_->grid->memUsage()); }

VdbSummary readVdb(const std::filesystem::path& path) {
    initializeOpenVdb();
    openvdb::io::File file(path.string());
    file.open();
    const openvdb::GridPtrVecPtr grids = file.getGrids();
    file.close();
    VdbSummary s;
    s.grids = int(grids->size());
    if (grids->empty()) return s;
    const openvdb::GridBase::Ptr& first = grids->front();
    s.name = first->getName();
    s.gridClass = openvdb::GridBase::gridClassToString(first->getGridClass());
    s.voxelSize = first->voxelSize()[0];
    s.activeVoxels = int64_t(first->activeVoxelCount());
    if (auto floats = openvdb::gridPtrCast<openvdb::FloatGrid>(first)) {
        s.sample = [floats](const vec3& p) {
            openvdb::tools::GridSampler<openvdb::FloatGrid, openvdb::tools::BoxSampler> sampler(*floats);
            return double(sampler.wsSample(openvdb::Vec3d(p.x, p.y, p.z)));
        };
    }
    return s;
}

}  // namespace fraktal::mesh
