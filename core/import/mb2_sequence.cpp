#include "core/import/mb2_sequence.hpp"

#include <algorithm>
#include <limits>

namespace fraktal::mb2 {

std::vector<int> slotOfEachIteration(const SlotSequencing& s, int n) {
    std::vector<int> sequence(size_t(std::max(n, 0)), s.runs[0] ? 0 : -1);
    if (!s.hybrid) return sequence;
    const int repeatFrom = std::clamp(s.repeatFrom, 1, kSlots) - 1;
    int slot = 0, counter = 0;
    for (int i = 0; i < n; ++i) {
        ++counter;
        for (int skips = 0;
             (!s.runs[size_t(slot)] || i < s.first[size_t(slot)] || i > s.last[size_t(slot)]) && skips < kSlots;
             ++skips)
            slot = slot + 1 >= kSlots ? repeatFrom : slot + 1;
        sequence[size_t(i)] = s.runs[size_t(slot)] ? slot : -1;
        if (counter >= s.count[size_t(slot)]) {
            counter = 0;
            slot = slot + 1 >= kSlots ? repeatFrom : slot + 1;
        }
    }
    return sequence;
}

std::vector<PeriodicStretch> periodicStretches(const std::vector<int>& sequence, int maxPeriod) {
    // Shortest path over the iterations: a stretch from a to b with period P costs P pattern
    // entries (each a copy of a slot's nodes) and a little for itself, so that the cover has the
    // fewest nodes, then the fewest stretches.
    const int n = int(sequence.size());
    constexpr long kPerEntry = 1000;
    std::vector<long> cost(size_t(n) + 1, std::numeric_limits<long>::max());
    struct Step {
        int start = 0, period = 1;
    };
    std::vector<Step> from(size_t(n) + 1);
    cost[0] = 0;
    for (int start = 0; start < n; ++start)
        for (int period = 1; period <= std::min(maxPeriod, n - start); ++period) {
            int stop = start + period;
            while (stop < n && sequence[size_t(stop)] == sequence[size_t(stop - period)]) ++stop;
            const long c = cost[size_t(start)] + period * kPerEntry + 1;
            for (int end = start + period; end <= stop; ++end)
                if (c < cost[size_t(end)]) cost[size_t(end)] = c, from[size_t(end)] = {start, period};
        }
    std::vector<PeriodicStretch> stretches;
    for (int end = n; end > 0; end = from[size_t(end)].start) {
        const Step s = from[size_t(end)];
        stretches.push_back(
            {s.start, end, std::vector<int>(sequence.begin() + s.start, sequence.begin() + s.start + s.period)});
    }
    std::reverse(stretches.begin(), stretches.end());
    return stretches;
}

}  // namespace fraktal::mb2
