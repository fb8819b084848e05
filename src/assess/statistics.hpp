#pragma once
/// The statistics of a simulated level (docs/methods.md s.6 step 3): per limit state the 84th
/// percentile of the peak demands over the history sets governs; the mean, the maximum and the
/// exceedance count k/N with its Clopper-Pearson 95% interval are reported beside it.
#include <array>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace freestand::assess {

/// The percentile that governs a simulated level's demand.
inline constexpr double governing_percentile = 0.84;

/// Mean, 84th percentile and maximum of a peak response over the history sets, with the
/// per-set values they came from (NaN where a set has no value: the rotation of a set that
/// overturned), so a resample of the sets can redo them (assess/settle.hpp).
struct Stats {
    Stats() = default;
    Stats(double mean_, double p84_, double max_, std::vector<double> values_ = {})
        : mean(mean_), p84(p84_), max(max_), values(std::move(values_)) {}

    double mean = 0.0;
    double p84 = 0.0;  ///< the ceil(0.84 n)-th smallest of the n values: an observed peak
    double max = 0.0;
    std::vector<double> values;  ///< per set, in set order
};

/// The ceil(q n)-th smallest value (an order statistic, no interpolation: ASCE 4-16 s.C2.5
/// practice reads percentiles of the sets' own peaks). values must not be empty.
double order_statistic(std::vector<double> values, double q);

/// Mean, 84th percentile and maximum of the finite values (all 0 when none is), keeping every
/// value, NaN included, in `values`.
Stats stats_of(const std::vector<double>& values);

/// The statistics of the sets at the given indices (a bootstrap resample; repeats allowed).
Stats resample(const Stats& s, const std::vector<std::size_t>& sets);

/// How many of n sets exceed a limit (k/N), with the exact (Clopper-Pearson 1934) 95% interval.
struct Exceedance {
    int k = 0;
    int n = 0;
    std::array<double, 2> ci95{0.0, 0.0};
};

/// Sets whose value exceeds limit, plus `always` sets counted as exceeding whatever their value
/// (overturned sets for a rotation limit), out of values.size().
Exceedance exceedance(const std::vector<double>& values, double limit, int always = 0);

/// "k/n (95% lo-hi%)", as the trail and the report print a count.
std::string exceedance_text(const Exceedance& e);

}  // namespace freestand::assess
