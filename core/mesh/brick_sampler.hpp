// Sparse sampling of a formula's signed distance on a voxel lattice, brick by brick: the distance
// estimate proves most of space empty (a ball of the estimate's radius about any outside point
// holds no surface), so only the bricks near the surface are sampled, never the dense grid.
// No OpenVDB types here: core/mesh/sdf_volume.cpp takes the bricks into an OpenVDB grid.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <span>
#include <stdexcept>
#include <vector>

#include "core/de_check.hpp"
#include "core/formula.hpp"
#include "core/vec.hpp"

namespace fraktal::mesh {

// A brick is 8 voxels a side: the size of an OpenVDB leaf node (openvdb::FloatTree's LeafNode
// Log2Dim 3), so that a sampled brick fills exactly one leaf.
inline constexpr int kBrickSize = 8;
inline constexpr int kBrickVoxels = kBrickSize * kBrickSize * kBrickSize;
// The narrow band's half width in voxels: OpenVDB's level-set default (LEVEL_SET_HALF_WIDTH).
inline constexpr int kBandHalfWidth = 3;

// The voxel lattice over the formula's bound: voxel (i, j, k) has its centre at
// minCorner + (i + 0.5, j + 0.5, k + 0.5) * voxel, for 0 <= i, j, k < voxelsAcross.
struct GridLayout {
    vec3 minCorner{0.0};
    double voxel = 0.0;
    int voxelsAcross = 0;

    int bricksAcross() const { return (voxelsAcross + kBrickSize - 1) / kBrickSize; }
    vec3 voxelCentre(int i, int j, int k) const { return minCorner + (vec3(i, j, k) + 0.5) * voxel; }
    double background() const { return kBandHalfWidth * voxel; }
};

// The cube [-boundRadius, boundRadius]^3 cut into `resolution` voxels a side.
GridLayout layoutByResolution(const Formula& f, int resolution);
// The same cube in voxels of `voxel` (the last voxel may reach past the bound).
GridLayout layoutByVoxel(const Formula& f, double voxel);

// A box of the user's, [lo, hi] (a detail to print, a cut-away), in the formula's units.
struct Box {
    vec3 lo{0.0}, hi{0.0};
    // The exact signed distance to the box (negative inside).
    double signedDistance(const vec3& p) const;
};
// The cube on the box's low corner as wide as its largest side, in `resolution` voxels a side or
// in voxels of `voxel`.
GridLayout layoutOfBox(const Box& box, int resolution);
GridLayout layoutOfBoxByVoxel(const Box& box, double voxel);

// The formula's solid cut by a box: inside where both are, the distance the larger of the two
// (a lower bound of the distance to their intersection, as each is to its own solid), so that
// the mesh is closed along the cut.
class BoxClippedSampler final : public FormulaSampler {
   public:
    BoxClippedSampler(FormulaSampler& inner, const Box& box) : inner_(inner), box_(box) {}
    const Formula& formula() const override { return inner_.formula(); }
    void evaluate(std::span<const vec3> points, std::span<Evaluation> out) override;
    bool concurrent() const override { return inner_.concurrent(); }

   private:
    FormulaSampler& inner_;
    Box box_;
};

// A sampled brick: its brick coordinate and the signed distance of its voxels (x fastest),
// clamped to the band (+-GridLayout::background()). Negative inside, by the estimator's
// membership (Evaluation::inside). Where membership is a flag (Formula::membershipIsFlag:
// escape-time estimators), the estimate says nothing of the distance inside: every inside voxel
// then holds -background, for the grid to correct from its outside neighbours.
struct SampledBrick {
    std::array<int, 3> brick{};
    std::array<float, kBrickVoxels> values{};

    static int index(int x, int y, int z) { return x + kBrickSize * (y + kBrickSize * z); }
};

// What pruning left to sample.
struct BrickPlan {
    GridLayout layout;
    std::vector<std::array<int, 3>> bricks;  // the bricks to sample, in z, y, x order
    int64_t cellsEvaluated = 0;              // one estimate per octree cell visited
};

// Memory the mesh pipeline is expected to use per sampled brick: the grid's leaf, the
// re-normalised copy, the mesh and its colours (measured with a coloured PLY: 14 KB a brick at
// 1024^3 on the Mandelbulb, bench/mesh/README.md).
inline constexpr double kBytesPerBrick = 16.0 * 1024.0;

// Raised when a lattice would need more memory than `memoryLimitBytes`, with the estimate.
struct TooBigError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Raised at the next batch after the job's cancel flag is set.
struct MeshCancelled : std::runtime_error {
    MeshCancelled() : std::runtime_error("meshing cancelled") {}
};

// What a long meshing job reports and how it is stopped: `progress` gets the stage's name and the
// share of the whole job done (0..1, rising), on the calling thread; `cancel`, when set, is polled
// between batches.
struct MeshControl {
    std::function<void(const char* stage, double done)> progress;
    const std::atomic<bool>* cancel = nullptr;

    void report(const char* stage, double done) const {
        if (progress) progress(stage, done);
    }
    void throwIfCancelled() const {
        if (cancel && cancel->load()) throw MeshCancelled();
    }
};

// The shares of the whole job each stage takes (measured on the Mandelbulb at 512^3: sampling is
// most of the time), for one progress figure across them.
struct MeshStages {
    static constexpr double kPlan = 0.10, kSample = 0.75, kLevelSet = 0.85, kMesh = 0.95;
};

// Evaluates `points` with the sampler: spread over `threads` threads (0: all cores) when it may be
// called concurrently (the CPU's), in one call otherwise (the GL probe's one context).
void evaluatePoints(FormulaSampler& sampler, std::span<const vec3> points, std::span<Evaluation> out, int threads);

// Finds the bricks that may hold surface: an octree over the bricks, each cell's centre
// estimated once. A cell is empty outside when the estimate exceeds its half-diagonal plus the
// band (the estimate, deFactor included, is a lower bound of the distance), and full inside when
// membership is the estimate's sign and its magnitude does the same. An escape-time brick whose
// centre is inside is sampled when a neighbour (of 26) is not (the surface reaches it from
// there); an outside pocket wholly inside 3x3x3 inside bricks is missed.
// Before each level, the bricks the surface will need are projected (4x per halving: a
// surface's area) and a plan over `memoryLimitBytes` is refused with TooBigError.
BrickPlan planBricks(FormulaSampler& sampler, const GridLayout& layout, double memoryLimitBytes, int threads,
                     const MeshControl& control = {});

// Samples the plan's bricks on `threads` threads (0: all cores), handing them to `sink` in
// batches on the calling thread (so that the caller stores them as they come, and the samples
// never all sit in memory twice).
// Progress runs from MeshStages::kPlan to kSample.
void sampleBricks(FormulaSampler& sampler, const BrickPlan& plan, int threads,
                  const std::function<void(std::vector<SampledBrick>&)>& sink, const MeshControl& control = {});

// Runs body(i) for i in [0, count) on `threads` threads (0: all cores).
void parallelFor(int64_t count, int threads, const std::function<void(int64_t)>& body);

// The memory this process may still take: MemAvailable from /proc/meminfo.
double availableMemoryBytes();

}  // namespace fraktal::mesh
