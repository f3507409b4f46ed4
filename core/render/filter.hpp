// The reconstruction filter of stills: a separable Blackman-Harris window (Harris 1978, the
// 4-term window; pbrt-v4 and Cycles use it for its low ringing). Samples are drawn from the filter
// itself (importance sampling, pbrt-v4 FilterSampler), so every sample weighs the same.
#pragma once

#include <vector>

namespace fraktal {

// The 1D window over x in [-1, 1] (in units of the filter radius); 1 at the centre, 0 at the ends.
double blackmanHarris(double x);
// Its cumulative distribution over [-1, x], normalised to 1 at x = 1.
double blackmanHarrisCdf(double x);
// Inverse CDF sampled at u = i / (size - 1): offsets in [-1, 1] for a table the shader interpolates.
std::vector<float> blackmanHarrisInverseCdfTable(int size);

}  // namespace fraktal
