// Mandelbulber2's hybrid sequence (nine_fractals.cpp, CreateSequence): which formula slot runs on
// each iteration, and its cover by periodic stretches, which fraktal's node schedules express
// (period and phase within an iteration window).
#pragma once

#include <array>
#include <vector>

namespace fraktal::mb2 {

inline constexpr int kSlots = 9;

struct SlotSequencing {
    bool hybrid = false;
    int repeatFrom = 1;               // 1-based: after slot 9 the sequence goes on from here
    std::array<bool, kSlots> runs{};  // a formula is chosen and the slot is enabled
    std::array<int, kSlots> count{};  // formula_iterations_N: consecutive iterations per turn
    std::array<int, kSlots> first{};  // formula_start_iteration_N
    std::array<int, kSlots> last{};   // formula_stop_iteration_N (inclusive, as MB2 tests it)
};

// The slot (0-based) of each iteration 0 .. n - 1, or -1 where no formula runs, exactly as
// Mandelbulber2 builds it: slots without a formula or outside their window are skipped (at most
// one round of skips), and the count of consecutive runs is not reset by a skip.
std::vector<int> slotOfEachIteration(const SlotSequencing& s, int n);

// A stretch [start, stop) of the sequence that repeats `pattern` (its period is pattern.size()):
// the slot of iteration i is pattern[(i - start) % period].
struct PeriodicStretch {
    int start = 0, stop = 0;
    std::vector<int> pattern;
};

// Covers the sequence with stretches of period at most maxPeriod, with the fewest pattern entries
// (each a copy of a slot's nodes), then the fewest stretches: a plain cycle is one stretch,
// "slot 1 once, then slot 2" two.
std::vector<PeriodicStretch> periodicStretches(const std::vector<int>& sequence, int maxPeriod);

}  // namespace fraktal::mb2
