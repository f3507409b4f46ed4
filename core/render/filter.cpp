#include "core/render/filter.hpp"

#include <cmath>
#include <numbers>

namespace fraktal {

namespace {
constexpr double a0 = 0.35875, a1 = 0.48829, a2 = 0.14128, a3 = 0.01168;
constexpr double pi = std::numbers::pi;
}  // namespace

// Centred form of w(t) = a0 - a1 cos(2 pi t) + a2 cos(4 pi t) - a3 cos(6 pi t), t = (x + 1) / 2.
double blackmanHarris(double x) {
    if (x <= -1.0 || x >= 1.0) return 0.0;
    return a0 + a1 * std::cos(pi * x) + a2 * std::cos(2 * pi * x) + a3 * std::cos(3 * pi * x);
}

double blackmanHarrisCdf(double x) {
    if (x <= -1.0) return 0.0;
    if (x >= 1.0) return 1.0;
    const double integral = a0 * (x + 1.0) + a1 * std::sin(pi * x) / pi + a2 * std::sin(2 * pi * x) / (2 * pi) +
                            a3 * std::sin(3 * pi * x) / (3 * pi);
    return integral / (2.0 * a0);
}

std::vector<float> blackmanHarrisInverseCdfTable(int size) {
    std::vector<float> table(size_t(std::max(size, 2)));
    for (size_t i = 0; i < table.size(); ++i) {
        const double u = double(i) / double(table.size() - 1);
        double lo = -1.0, hi = 1.0;  // the CDF is monotonic: bisection
        for (int k = 0; k < 60; ++k) {
            const double mid = 0.5 * (lo + hi);
            (blackmanHarrisCdf(mid) < u ? lo : hi) = mid;
        }
        table[i] = float(0.5 * (lo + hi));
    }
    return table;
}

}  // namespace fraktal
