#include "core/mesh/brick_sampler.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <mutex>
#include <string>
#include <thread>

namespace fraktal::mesh {

namespace {

GridLayout checkedLayout(GridLayout l) {
    if (l.voxel < kSmallestVoxel) {
        char text[160];
        std::snprintf(text, sizeof text,
                      "a voxel of %.3g is under the smallest OpenVDB takes (%g in the preset's units): mesh a "
                      "larger box or at a lower resolution",
                      l.voxel, kSmallestVoxel);
        throw std::invalid_argument(text);
    }
    return l;
}

double largestSide(const Box& box) {
    const vec3 side = box.hi - box.lo;
    if (!(side.x > 0.0 && side.y > 0.0 && side.z > 0.0))
        throw std::invalid_argument("the box is empty: each side of its high corner must exceed its low corner's");
    return std::max(side.x, std::max(side.y, side.z));
}

}  // namespace

double Box::signedDistance(const vec3& p) const {
    const vec3 centre = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
    const vec3 q = glm::abs(p - centre) - half;
    return glm::length(glm::max(q, 0.0)) + std::min(std::max(q.x, std::max(q.y, q.z)), 0.0);
}

GridLayout layoutOfBox(const Box& box, int resolution) {
    if (resolution < 2) throw std::invalid_argument("resolution " + std::to_string(resolution) + " is under 2 voxels");
    GridLayout l;
    l.minCorner = box.lo;
    l.voxel = largestSide(box) / resolution;
    l.voxelsAcross = resolution;
    return checkedLayout(l);
}

GridLayout layoutOfBoxByVoxel(const Box& box, double voxel) {
    if (!(voxel > 0.0)) throw std::invalid_argument("voxel size " + std::to_string(voxel) + " is not positive");
    const double across = std::ceil(largestSide(box) / voxel);
    if (across > 1e7)
        throw std::invalid_argument("voxel size " + std::to_string(voxel) + " makes over 1e7 voxels across");
    GridLayout l;
    l.minCorner = box.lo;
    l.voxel = voxel;
    l.voxelsAcross = std::max(2, int(across));
    return checkedLayout(l);
}

// The bound's cube is a box like any other.
GridLayout layoutByResolution(const Formula& f, int resolution) {
    return layoutOfBox({vec3(-f.boundRadius), vec3(f.boundRadius)}, resolution);
}

GridLayout layoutByVoxel(const Formula& f, double voxel) {
    return layoutOfBoxByVoxel({vec3(-f.boundRadius), vec3(f.boundRadius)}, voxel);
}

void BoxClippedSampler::evaluate(std::span<const vec3> points, std::span<Evaluation> out) {
    inner_.evaluate(points, out);
    for (size_t i = 0; i < points.size(); ++i) {
        const double d = box_.signedDistance(points[i]);
        Evaluation& e = out[i];
        if (d > 0.0) {
            e.distance = e.inside ? d : std::max(e.distance, d);
            e.inside = false;
        } else if (!inner_.formula().membershipIsFlag() || !e.inside) {
            e.distance = std::max(e.distance, d);
        } else {
            // Inside an escape-time set the estimate is no distance: the cut's is the one known.
            e.distance = d;
        }
    }
}

void parallelFor(int64_t count, int threads, const std::function<void(int64_t)>& body) {
    if (threads <= 0) threads = int(std::max(1u, std::thread::hardware_concurrency()));
    threads = int(std::min<int64_t>(threads, std::max<int64_t>(count, 1)));
    std::atomic<int64_t> next{0};
    std::exception_ptr failure;
    std::mutex failureLock;
    auto work = [&] {
        try {
            for (int64_t i; (i = next.fetch_add(1)) < count;) body(i);
        } catch (...) {
            std::lock_guard lock(failureLock);
            if (!failure) failure = std::current_exception();
            next = count;
        }
    };
    std::vector<std::thread> pool;
    for (int t = 1; t < threads; ++t) pool.emplace_back(work);
    work();
    for (std::thread& t : pool) t.join();
    if (failure) std::rethrow_exception(failure);
}

double availableMemoryBytes() {
    std::ifstream meminfo("/proc/meminfo");
    std::string key;
    double kib = 0.0;
    std::string unit;
    while (meminfo >> key >> kib >> unit)
        if (key == "MemAvailable:") return kib * 1024.0;
    return 1e18;  // unknown: refuse nothing
}

namespace {

std::string gib(double bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f GiB", bytes / (1024.0 * 1024.0 * 1024.0));
    return text;
}

enum class CellKind : uint8_t { Empty, Surface, UnknownInside };

}  // namespace

void evaluatePoints(FormulaSampler& sampler, std::span<const vec3> points, std::span<Evaluation> out, int threads) {
    if (!sampler.concurrent()) {
        sampler.evaluate(points, out);
        return;
    }
    constexpr size_t kChunk = 256;
    parallelFor(int64_t((points.size() + kChunk - 1) / kChunk), threads, [&](int64_t chunk) {
        const size_t first = size_t(chunk) * kChunk, count = std::min(kChunk, points.size() - first);
        sampler.evaluate(points.subspan(first, count), out.subspan(first, count));
    });
}

BrickPlan planBricks(FormulaSampler& sampler, const GridLayout& layout, double memoryLimitBytes, int threads,
                     const MeshControl& control) {
    const Formula& f = sampler.formula();
    BrickPlan plan;
    plan.layout = layout;
    const int bricks = layout.bricksAcross();
    int top = 1, levels = 0;
    while (top < bricks) top *= 2, ++levels;
    const double margin = layout.background();
    const bool flagMembership = f.membershipIsFlag();

    // Cells of `size` bricks a side, by their cell coordinate; each level halves the size.
    std::vector<std::array<int, 3>> cells{{0, 0, 0}};
    std::vector<CellKind> kinds;
    // Estimated a slice at a time: the last level's cells are millions at 2048^3.
    constexpr size_t kSlice = 1 << 16;
    std::vector<vec3> centres;
    std::vector<Evaluation> estimates;
    for (int size = top, level = 0;; size /= 2, ++level) {
        control.report("planning", MeshStages::kPlan * level / std::max(1, levels + 1));
        // A surface's bricks grow 4x per halving, a fractal surface's faster, but cells many
        // bricks wide are all near a surface that does not fill them: the Mandelbulb at 2048^3
        // projects 23.7 GiB from its 97,000 cells of 4 bricks, where its 1.10 million bricks
        // need 16.8. Planning is cheap (3 million cells estimated for 2048^3, 6 s on the CPU), so
        // the plan's own brick count decides (below); a projection refuses here only at 16x the
        // memory (a lattice absurdly fine: 8192^3 of the Mandelbulb projects 400 GiB), or when
        // the planning's own cells would take a quarter of it.
        const double projected = double(cells.size()) * std::pow(4.0, levels - level) * kBytesPerBrick;
        constexpr double kPlanningBytesPerCell = 64.0;  // its coordinates, kind, centre and estimate
        if (projected > 16.0 * memoryLimitBytes ||
            double(cells.size()) * kPlanningBytesPerCell > 0.25 * memoryLimitBytes)
            throw TooBigError("a " + std::to_string(layout.voxelsAcross) + "^3 lattice (voxel " +
                              std::to_string(layout.voxel) + ") needs about " + gib(projected) + ", over the " +
                              gib(memoryLimitBytes) + " available: lower --resolution or raise --voxel");
        kinds.assign(cells.size(), CellKind::Empty);
        const double cellSize = double(size * kBrickSize) * layout.voxel;
        const double halfDiagonal = 0.5 * std::sqrt(3.0) * cellSize;
        for (size_t first = 0; first < cells.size(); first += kSlice) {
            control.throwIfCancelled();
            const size_t count = std::min(kSlice, cells.size() - first);
            centres.resize(count);
            estimates.resize(count);
            for (size_t i = 0; i < count; ++i) {
                const auto& c = cells[first + i];
                centres[i] = layout.minCorner + (vec3(c[0], c[1], c[2]) + 0.5) * cellSize;
            }
            evaluatePoints(sampler, centres, estimates, threads);
            for (size_t i = 0; i < count; ++i) {
                const Evaluation& e = estimates[i];
                CellKind& kind = kinds[first + i];
                if (!e.inside) {
                    if (!(e.distance > halfDiagonal + margin)) kind = CellKind::Surface;
                } else if (flagMembership) {
                    kind = CellKind::UnknownInside;
                } else if (!(-e.distance > halfDiagonal + margin)) {
                    kind = CellKind::Surface;
                }
            }
        }
        plan.cellsEvaluated += int64_t(cells.size());
        if (size == 1) break;
        std::vector<std::array<int, 3>> children;
        for (size_t i = 0; i < cells.size(); ++i) {
            if (kinds[i] == CellKind::Empty) continue;
            for (int dz = 0; dz < 2; ++dz)
                for (int dy = 0; dy < 2; ++dy)
                    for (int dx = 0; dx < 2; ++dx) {
                        const std::array<int, 3> child{2 * cells[i][0] + dx, 2 * cells[i][1] + dy,
                                                       2 * cells[i][2] + dz};
                        // Children wholly past the lattice's last brick hold no voxel.
                        if ((child[0] * size / 2) < bricks && (child[1] * size / 2) < bricks &&
                            (child[2] * size / 2) < bricks)
                            children.push_back(child);
                    }
        }
        cells = std::move(children);
    }

    // Bricks whose centre is inside an escape-time set: sampled beside any brick that is not.
    auto key = [](const std::array<int, 3>& b) {
        return (uint64_t(uint32_t(b[2])) << 42) | (uint64_t(uint32_t(b[1])) << 21) | uint64_t(uint32_t(b[0]));
    };
    std::vector<uint64_t> unknown;
    for (size_t i = 0; i < cells.size(); ++i)
        if (kinds[i] == CellKind::UnknownInside) unknown.push_back(key(cells[i]));
    std::sort(unknown.begin(), unknown.end());
    auto isUnknown = [&](const std::array<int, 3>& b) {
        for (int a = 0; a < 3; ++a)
            if (b[a] < 0 || b[a] >= bricks) return false;
        return std::binary_search(unknown.begin(), unknown.end(), key(b));
    };
    for (size_t i = 0; i < cells.size(); ++i) {
        bool sample = kinds[i] == CellKind::Surface;
        if (kinds[i] == CellKind::UnknownInside) {
            for (int dz = -1; dz <= 1 && !sample; ++dz)
                for (int dy = -1; dy <= 1 && !sample; ++dy)
                    for (int dx = -1; dx <= 1 && !sample; ++dx)
                        sample = !isUnknown({cells[i][0] + dx, cells[i][1] + dy, cells[i][2] + dz});
        }
        if (sample) plan.bricks.push_back(cells[i]);
    }
    std::sort(plan.bricks.begin(), plan.bricks.end(),
              [](const auto& a, const auto& b) { return std::tie(a[2], a[1], a[0]) < std::tie(b[2], b[1], b[0]); });
    const double needed = double(plan.bricks.size()) * kBytesPerBrick;
    if (needed > memoryLimitBytes)
        throw TooBigError("a " + std::to_string(layout.voxelsAcross) + "^3 lattice (voxel " +
                          std::to_string(layout.voxel) + ") needs about " + gib(needed) + " for its " +
                          std::to_string(plan.bricks.size()) + " surface bricks, over the " + gib(memoryLimitBytes) +
                          " available: lower --resolution or raise --voxel");
    return plan;
}

void sampleBricks(FormulaSampler& sampler, const BrickPlan& plan, int threads,
                  const std::function<void(std::vector<SampledBrick>&)>& sink, const MeshControl& control) {
    const GridLayout& layout = plan.layout;
    const float background = float(layout.background());
    const bool flagMembership = sampler.formula().membershipIsFlag();
    // 512 bricks (256K points) a batch: one GL dispatch stays well under a second on a software
    // rasteriser, and the batch's points and estimates take about 25 MB.
    constexpr size_t kBatch = 512;
    std::vector<SampledBrick> batch;
    std::vector<vec3> points;
    std::vector<Evaluation> estimates;
    for (size_t first = 0; first < plan.bricks.size(); first += kBatch) {
        control.throwIfCancelled();
        control.report("sampling", MeshStages::kPlan + (MeshStages::kSample - MeshStages::kPlan) * double(first) /
                                                           double(plan.bricks.size()));
        batch.resize(std::min(kBatch, plan.bricks.size() - first));
        points.resize(batch.size() * kBrickVoxels);
        estimates.resize(points.size());
        for (size_t b = 0; b < batch.size(); ++b) {
            batch[b].brick = plan.bricks[first + b];
            const auto& brick = batch[b].brick;
            for (int z = 0; z < kBrickSize; ++z)
                for (int y = 0; y < kBrickSize; ++y)
                    for (int x = 0; x < kBrickSize; ++x)
                        points[b * kBrickVoxels + size_t(SampledBrick::index(x, y, z))] = layout.voxelCentre(
                            brick[0] * kBrickSize + x, brick[1] * kBrickSize + y, brick[2] * kBrickSize + z);
        }
        evaluatePoints(sampler, points, estimates, threads);
        for (size_t b = 0; b < batch.size(); ++b)
            for (int v = 0; v < kBrickVoxels; ++v) {
                const Evaluation& e = estimates[b * kBrickVoxels + size_t(v)];
                float& out = batch[b].values[size_t(v)];
                if (!e.inside) {
                    // A NaN estimate (an orbit's 0 / 0) counts as far outside.
                    out = std::isnan(e.distance) ? background : float(std::clamp(e.distance, 0.0, double(background)));
                } else if (flagMembership) {
                    out = -background;
                } else {
                    out = -float(std::clamp(-e.distance, 0.0, double(background)));
                }
            }
        sink(batch);
    }
}

}  // namespace fraktal::mesh
