#pragma once
/// Small statistics of a sample of peak responses and of failure counts (docs/methods.md s.6
/// step 5, s.9). Shared by the assessment's histories and the fragility samples.
#include <array>
#include <vector>

namespace freestand::core {

/// Arithmetic mean; 0 for an empty sample.
double mean(const std::vector<double>& values);

/// The q-quantile (q in [0, 1]) with linear interpolation between order statistics
/// (Hyndman & Fan 1996, type 7: position (n - 1) q). Throws std::invalid_argument for an
/// empty sample or q outside [0, 1].
double quantile(std::vector<double> values, double q);

/// Exact (Clopper-Pearson 1934) two-sided confidence interval of a binomial proportion k / n at
/// the given confidence (0.95: 2.5% in each tail), from the beta quantiles:
/// lower = B^-1(a/2; k, n - k + 1) (0 when k = 0), upper = B^-1(1 - a/2; k + 1, n - k)
/// (1 when k = n). Throws std::invalid_argument unless 0 <= k <= n, n >= 1, 0 < confidence < 1.
std::array<double, 2> clopper_pearson(int k, int n, double confidence = 0.95);

}  // namespace freestand::core
