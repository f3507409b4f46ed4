// A formula's narrow-band signed distance field as a sparse OpenVDB grid, its mesh and its .vdb
// file. The only header of core/mesh that fronts OpenVDB, with none of its types: OpenVDB's
// headers are heavy, and only sdf_volume.cpp includes them.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>

#include "core/formula.hpp"
#include "core/mesh/brick_sampler.hpp"
#include "core/mesh/triangle_mesh.hpp"

namespace fraktal::mesh {

class SdfVolume {
   public:
    // Samples the plan's bricks into a level-set grid (OpenVDB's GRID_LEVEL_SET: narrow band of
    // kBandHalfWidth voxels, background the band's width, negative inside), then makes it a
    // distance field where the estimate is not one: inside voxels of an escape-time set take
    // their distance from their outside neighbours' estimates, and fast sweeping
    // (openvdb::tools::sdfToSdf, Zhao 2005) solves |grad d| = 1 from the zero crossing outwards,
    // so that neighbours agree.
    // Progress runs from MeshStages::kPlan to kLevelSet.
    static SdfVolume build(FormulaSampler& sampler, const BrickPlan& plan, int threads,
                           const MeshControl& control = {});
    SdfVolume(SdfVolume&&) noexcept;
    SdfVolume& operator=(SdfVolume&&) noexcept;
    ~SdfVolume();

    // The zero level set as triangles (openvdb::tools::volumeToMesh; its quads split in two),
    // facing outwards. adaptivity in [0, 1]: 0 keeps one vertex per surface voxel, higher merges
    // flat regions into fewer, larger polygons.
    TriangleMesh toMesh(double adaptivity) const;
    // Keeps only the surface seen from outside: the closed cavities a fractal leaves inside
    // itself (outside space no path from the bound's edge reaches, with whatever floats in them)
    // become solid (openvdb::tools::extractEnclosedRegion). Returns the voxels filled.
    int64_t fillCavities();
    // Thickens what a printer cannot make: the parts an opening (erode, then dilate, by half of
    // `minThickness`; OpenVDB's LevelSetFilter::offset) removes are thinner than `minThickness`,
    // and those parts, dilated by half of it, are joined to the solid: a wall w thin comes out
    // w + minThickness thick, its rim reaching half of it further. Parts within a voxel and a half
    // of the opening count as thick (the grid's rounding). Returns the voxels made solid.
    int64_t thickenThinParts(double minThickness);
    // The voxels inside the surface (band and deep inside), to count what the edits changed.
    int64_t insideVoxels() const;

    // Writes the grid to a .vdb file through OpenVDB's own io, atomically (core/atomic_file.hpp).
    void writeVdb(const std::filesystem::path& path) const;

    int64_t activeVoxels() const;
    int64_t leafCount() const;
    size_t memoryBytes() const;

   private:
    struct Impl;
    explicit SdfVolume(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

// What a .vdb file holds, read back with OpenVDB (for tests and `fraktal info`-like checks).
struct VdbSummary {
    int grids = 0;
    std::string name;       // the first grid's
    std::string gridClass;  // "level set" for a level set
    double voxelSize = 0.0;
    int64_t activeVoxels = 0;
    // The first grid's value at a world point (trilinear).
    std::function<double(const vec3&)> sample;
};
VdbSummary readVdb(const std::filesystem::path& path);

// The grid's name in the files written.
inline constexpr const char* kVdbGridName = "surface";

}  // namespace fraktal::mesh
