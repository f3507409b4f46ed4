// Helpers shared by the tests: the shipped presets, a GL context, random points.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "core/gl/context.hpp"
#include "core/image/image_strip.hpp"
#include "core/preset.hpp"
#include "core/random_vec.hpp"

namespace fraktal::test {

inline std::filesystem::path sourceDir() { return FRAKTAL_SOURCE_DIR; }

// The path of a shipped preset by its name under presets/ ("mandelbulb.json", "2d/julia.json").
inline std::string shippedPresetFile(const std::string& name) { return (sourceDir() / "presets" / name).string(); }

// A shipped 3D preset by file name ("mandelbulb.json").
inline Preset shippedPreset(const std::string& name) { return loadPreset(shippedPresetFile(name)); }

// Every preset shipped in presets/, by file name.
inline std::vector<std::filesystem::path> shippedPresets() {
    std::vector<std::filesystem::path> out;
    for (const auto& e : std::filesystem::directory_iterator(sourceDir() / "presets"))
        if (e.path().extension() == ".json") out.push_back(e.path());
    std::sort(out.begin(), out.end());
    return out;
}

inline std::vector<vec3> randomPoints(size_t n, double halfSize, uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-halfSize, halfSize);
    std::vector<vec3> points(n);
    for (vec3& p : points) p = randomVec3(u, rng);
    return points;
}

// The twist-free Bristorbrot (x^2 - y^2 - z^2, 2xy, 2xz) alone, bailout 4, closed by the potential
// estimate: its Jacobian is 2r times a rotation, and the estimate is half the distance to the ball
// its iterations draw, of radius 4^(1 / 2^runs) (tests/de_quality_test.cpp).
inline Formula squaringBall(int iterations, int period = 1, int phase = 0) {
    Formula f;
    f.iterations = iterations;
    f.bailout = 4.0;
    f.estimator = Node::make(*findBlock("escape_potential"));
    Node square = Node::make(*findBlock("bristorbrot"));
    square.values[0].x = 0.0;
    square.period = period;
    square.phase = phase;
    f.nodes = {square};
    return f;
}

// The depths of an image's pixels that hit (ImageStrip::normalDepth's w below 1e30), sorted.
inline std::vector<float> hitDepths(const ImageStrip& image) {
    std::vector<float> depths;
    for (size_t i = 3; i < image.normalDepth.size(); i += 4)
        if (image.normalDepth[i] < 1e29f) depths.push_back(image.normalDepth[i]);
    std::sort(depths.begin(), depths.end());
    return depths;
}

// One headless GL context for a whole test program (made on first use).
inline gl::HeadlessContext& glContext() {
    static std::unique_ptr<gl::HeadlessContext> context = gl::HeadlessContext::create();
    return *context;
}

struct CliRun {
    int exitCode;  // -1 when the process did not exit normally (a crash)
    std::string output;
};

// A folder of the test's own under the system's temporary folder (named by `prefix` and the
// process), empty at the start and removed at the end.
struct Sandbox {
    std::filesystem::path dir;
    explicit Sandbox(const std::string& prefix)
        : dir(std::filesystem::temp_directory_path() / (prefix + std::to_string(::getpid()))) {
        std::filesystem::remove_all(dir);
        std::filesystem::create_directories(dir);
    }
    ~Sandbox() { std::filesystem::remove_all(dir); }
    std::string path(const std::string& name) const { return (dir / name).string(); }
    // Writes `text` to the file `name` in it; its path.
    std::string write(const std::string& name, const std::string& text) const {
        std::ofstream(dir / name) << text;
        return path(name);
    }
    int fileCount() const {
        return int(std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator{}));
    }
};

// Runs a shell command, capturing its stdout.
inline CliRun runShell(const std::string& command) {
    FILE* pipe = popen(command.c_str(), "r");
    std::string out;
    char buf[4096];
    while (fgets(buf, sizeof buf, pipe)) out += buf;
    const int status = pclose(pipe);
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

// Runs the fraktal command line with `args` (shell syntax; environment assignments may come
// first in `env`), capturing stdout and stderr together.
inline CliRun runCli(const std::string& args, const std::string& env = "") {
    return runShell(env + " " + std::string(FRAKTAL_CLI) + " " + args + " 2>&1");
}

}  // namespace fraktal::test
