// Stacks of blocks as a new user writes them into a preset, with values drawn at random from the
// blocks' ranges (seeded): for the tests that run `fraktal check --fit --apply` on them.
#pragma once

#include <iterator>
#include <optional>
#include <random>
#include <string_view>
#include <vector>

#include "core/de_check.hpp"
#include "core/preset.hpp"
#include "core/random_vec.hpp"

namespace fraktal::test {

// The blocks of a trial of random stacks (folds, inversions, twists, KIFS, the Mandelbulb).
inline constexpr std::string_view kTrialBlocks[] = {
    "sphere_invert",   "smooth_box_fold",  "sphere_fold",   "amazing_surf", "twist_y",
    "kifs_octahedral", "kifs_icosahedral", "menger_rotate", "box_fold",     "mandelbulb",
};

// A node of `block` with every parameter drawn uniformly from its range; switches keep their
// defaults.
inline Node drawnNode(const BlockDesc& block, std::mt19937_64& rng) {
    Node n = Node::make(block);
    for (size_t i = 0; i < block.params.size(); ++i) {
        const ParamDecl& d = block.params[i];
        if (d.type == ParamType::Toggle) continue;
        std::uniform_real_distribution<double> u(d.min, d.max);
        n.values[i] = d.type == ParamType::Float ? vec3(u(rng), 0.0, 0.0) : randomVec3(u, rng);
    }
    return n;
}

// The preset a user writes for `nodes`: 12 iterations, bound radius 4, step factor 1, the log
// estimate at bailout 4 after a power step, else a box at bailout 1000; the camera at (0, 1, 6)
// looking at the origin. Nullopt unless at least 6 of `fraktal check`'s 120 rays meet the object,
// with 100 samples in front of it (a stack the user sees and keeps).
inline std::optional<Preset> userPreset(std::vector<Node> nodes) {
    if (!canBoundEscape(nodes)) return std::nullopt;
    Preset p;
    p.camera.position = vec3(0.0, 1.0, 6.0);
    p.camera.fovY = 45.0;
    Formula& f = p.formula;
    f.iterations = 12;
    f.boundRadius = 4.0;
    bool power = false;
    for (const Node& n : nodes) power |= n.block->category == Category::Power;
    f.nodes = std::move(nodes);
    f.estimator = Node::make(*findBlock(power ? "escape_log" : "box"));
    f.bailout = power ? 4.0 : 1000.0;
    CpuSampler sampler(f);
    const RaySamples rays = sampleRays(sampler, p.camera, {120, 4000, 1});
    if (rays.raysHit < 6 || rays.points.size() < 100) return std::nullopt;
    return p;
}

// `ids` in order, drawn until the user keeps the stack (userPreset).
inline Preset drawnStack(const std::vector<std::string_view>& ids, std::mt19937_64& rng) {
    for (;;) {
        std::vector<Node> nodes;
        for (std::string_view id : ids) nodes.push_back(drawnNode(*findBlock(id), rng));
        if (std::optional<Preset> p = userPreset(std::move(nodes))) return *p;
    }
}

// 2 to 4 of kTrialBlocks, drawn until the user keeps the stack.
inline Preset trialStack(std::mt19937_64& rng) {
    for (;;) {
        std::vector<Node> nodes;
        for (int k = std::uniform_int_distribution<int>(2, 4)(rng); k > 0; --k) {
            const int pick = std::uniform_int_distribution<int>(0, int(std::size(kTrialBlocks)) - 1)(rng);
            nodes.push_back(drawnNode(*findBlock(kTrialBlocks[size_t(pick)]), rng));
        }
        if (std::optional<Preset> p = userPreset(std::move(nodes))) return *p;
    }
}

}  // namespace fraktal::test
