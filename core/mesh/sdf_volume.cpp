// The one translation unit that includes OpenVDB (its headers take long to compile).
#include "core/mesh/sdf_volume.hpp"

#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>
#include <openvdb/tools/ChangeBackground.h>
#include <openvdb/tools/Count.h>
#include <openvdb/tools/FastSweeping.h>
#include <openvdb/tools/Interpolation.h>
#include <openvdb/tools/Prune.h>
#include <openvdb/tools/SignedFloodFill.h>
#include <openvdb/tools/VolumeToMesh.h>
#include <openvdb/tree/LeafManager.h>
#include <tbb/global_control.h>

#include <algorithm>
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

// Inside an escape-time set the estimate is no distance: an inside voxel next to an outside one
// whose estimate is d (a lower bound of its distance to the surface) is given d - voxel, which
// puts the zero crossing on the edge between them where the estimate says (volumeToMesh
// interpolates linearly along the edge). Between several outside neighbours the crossing nearest
// the inside voxel wins, so no estimate is overstepped; voxels with no outside neighbour keep
// -background until fast sweeping fills them in.
void correctUnknownInside(openvdb::FloatGrid& grid, float voxel) {
    const float background = grid.background();
    openvdb::tree::LeafManager<Tree> leaves(grid.tree());
    leaves.foreach ([&](Leaf& leaf, size_t) {
        openvdb::tree::ValueAccessor<const Tree> neighbours(grid.constTree());
        for (auto v = leaf.beginValueOn(); v; ++v) {
            if (*v > -background) continue;
            const openvdb::Coord c = v.getCoord();
            float nearest = -background;
            for (int axis = 0; axis < 3; ++axis)
                for (int step = -1; step <= 1; step += 2) {
                    openvdb::Coord n = c;
                    n[axis] += step;
                    float outside;
                    if (!neighbours.probeValue(n, outside) || outside < 0.0f) continue;
                    nearest = std::max(nearest, std::min(outside - voxel, -1e-3f * voxel));
                }
            v.setValue(nearest);
        }
    });
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

}  // namespace

struct SdfVolume::Impl {
    openvdb::FloatGrid::Ptr grid;
};

SdfVolume::SdfVolume(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
SdfVolume::SdfVolume(SdfVolume&&) noexcept = default;
SdfVolume& SdfVolume::operator=(SdfVolume&&) noexcept = default;
SdfVolume::~SdfVolume() = default;

SdfVolume SdfVolume::build(const Formula& f, const BrickPlan& plan, int threads) {
    initializeOpenVdb();
    const auto cap = capThreads(threads);
    const GridLayout& layout = plan.layout;
    auto grid = openvdb::FloatGrid::create(float(layout.background()));
    // Index (i, j, k) is the lattice's voxel (i, j, k), whose centre is at
    // minCorner + (i + 0.5, j + 0.5, k + 0.5) * voxel.
    auto transform = openvdb::math::Transform::createLinearTransform(layout.voxel);
    const vec3 first = layout.minCorner + 0.5 * layout.voxel;
    transform->postTranslate(openvdb::Vec3d(first.x, first.y, first.z));
    grid->setTransform(transform);
    grid->setGridClass(openvdb::GRID_LEVEL_SET);
    grid->setName(kVdbGridName);

    Tree& tree = grid->tree();
    sampleBricks(f, plan, threads, [&](std::vector<SampledBrick>& batch) {
        for (const SampledBrick& b : batch) {
            const openvdb::Coord origin(b.brick[0] * kBrickSize, b.brick[1] * kBrickSize, b.brick[2] * kBrickSize);
            Leaf* leaf = tree.touchLeaf(origin);
            for (int z = 0; z < kBrickSize; ++z)
                for (int y = 0; y < kBrickSize; ++y)
                    for (int x = 0; x < kBrickSize; ++x)
                        leaf->setValueOn(origin.offsetBy(x, y, z), b.values[size_t(SampledBrick::index(x, y, z))]);
        }
    });
    if (f.membershipIsFlag()) correctUnknownInside(*grid, float(layout.voxel));
    // Inactive space takes the sign of the band beside it (outside +background, inside
    // -background), so that sweeping and meshing see the solid.
    openvdb::tools::signedFloodFill(tree);

    auto impl = std::make_unique<Impl>();
    const auto range = openvdb::tools::minMax(tree);
    const bool anySurface = range.min() < 0.0f && range.max() > 0.0f;
    if (anySurface) {
        // Fast sweeping keeps the active topology and recomputes every active value from the zero
        // crossing (openvdb/tools/FastSweeping.h, sdfToSdf).
        impl->grid = openvdb::tools::sdfToSdf(*grid, 0.0f, 1);
        impl->grid->setTransform(transform);
        impl->grid->setGridClass(openvdb::GRID_LEVEL_SET);
        impl->grid->setName(kVdbGridName);
        grid.reset();
    } else {
        impl->grid = grid;
    }
    trimToBand(*impl->grid, float(layout.background()));
    return SdfVolume(std::move(impl));
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
