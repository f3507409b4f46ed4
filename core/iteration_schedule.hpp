// When a node runs in the iteration loop: every `period`-th iteration from `phase` (hybrids that
// alternate blocks), within the window [start, stop) (a block that runs on the first iterations
// only, or from some iteration on). Node and PlaneNode carry one; the CPU loop asks runsOn, the
// generator emits glslCondition, and both count runs with iterationsRunBefore.
#pragma once

#include <algorithm>
#include <string>

namespace fraktal {

// Limits that keep any formula bounded (no preset can hang the machine).
inline constexpr int kMaxIterations = 1000;
inline constexpr int kMaxPeriod = 16;

struct IterationSchedule {
    int period = 1;
    int phase = 0;
    int start = 0;              // the first iteration the node runs on
    int stop = kMaxIterations;  // the node runs on iterations before this one (kMaxIterations: no end)

    bool runsOn(int i) const { return i >= start && i < stop && i % period == phase; }
    bool windowed() const { return start > 0 || stop < kMaxIterations; }
    bool always() const { return period == 1 && !windowed(); }
    // How many of the iterations 0 .. count - 1 the node runs on (GLSL: iterationsRunBefore).
    int iterationsRunBefore(int count) const {
        return cycleRunsBefore(std::min(count, stop)) - cycleRunsBefore(std::min(count, start));
    }
    // Runs of the cycle alone (no window) before `count`.
    int cycleRunsBefore(int count) const { return count > phase ? (count - phase - 1) / period + 1 : 0; }

    // The GLSL test on the loop variable `i` ("" when the node runs on every iteration).
    std::string glslCondition() const {
        std::string c;
        auto add = [&c](const std::string& term) { c += (c.empty() ? "" : " && ") + term; };
        if (start > 0) add("i >= " + std::to_string(start));
        if (stop < kMaxIterations) add("i < " + std::to_string(stop));
        if (period > 1) add("i % " + std::to_string(period) + " == " + std::to_string(phase));
        return c;
    }
    // For lists and descriptions: "" for every iteration, else e.g. "iter % 3 = 1, 2..8".
    std::string describe() const {
        std::string d;
        if (period > 1) d += "iter % " + std::to_string(period) + " = " + std::to_string(phase);
        if (windowed())
            d += (d.empty() ? "iter " : ", ") + std::to_string(start) + ".." +
                 (stop < kMaxIterations ? std::to_string(stop - 1) : std::string("end"));
        return d;
    }
    // What a change of needs a recompile: all of it.
    std::string key() const {
        return std::to_string(period) + "/" + std::to_string(phase) + "/" + std::to_string(start) + "/" +
               std::to_string(stop);
    }
    bool operator==(const IterationSchedule&) const = default;
    // The schedule alone, of a node that carries one (copying it between nodes).
    IterationSchedule& schedule() { return *this; }
    const IterationSchedule& schedule() const { return *this; }
};

}  // namespace fraktal
