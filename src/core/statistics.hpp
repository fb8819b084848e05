#pragma once
/// Small statistics of a sample of peak responses and of failure counts (docs/methods.md s.6
/// step 5, s.9). Shared by the assessment's histories and the fragility samples.
#include <array>
#include <optional>
#include <string>
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

/// Standard normal CDF Phi(z) and its inverse (Boost.Math).
double normal_cdf(double z);
double normal_quantile(double p);

/// An uncertain property (docs/methods.md s.9): uniform on [a, b], or lognormal with median a
/// and logarithmic standard deviation b, optionally truncated above at `upper` (a restitution
/// cannot exceed 1: the distribution is conditioned on x <= upper, never clipped).
struct Distribution {
    enum class Kind { uniform, lognormal };
    Kind kind = Kind::uniform;
    double a = 0.0;  ///< uniform: lower bound; lognormal: median (> 0)
    double b = 0.0;  ///< uniform: upper bound (>= a); lognormal: beta (> 0)
    std::optional<double> upper;  ///< lognormal only: truncation point (> 0)

    /// The value at probability u in [0, 1) (inverse CDF of the possibly truncated law).
    double at(double u) const;
    /// "uniform [0.12, 0.18]" / "lognormal median 0.15, beta 0.2 (truncated at 1)".
    std::string describe() const;
};

}  // namespace freestand::core
