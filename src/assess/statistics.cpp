#include "assess/statistics.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/contract.hpp"
#include "core/statistics.hpp"
#include "core/steps.hpp"

namespace freestand::assess {

double order_statistic(std::vector<double> values, double q) {
    FREESTAND_EXPECT(!values.empty(), "an order statistic needs values");
    const auto n = static_cast<double>(values.size());
    // ceil(q n), guarded: 0.84 * 25 = 21.000000000000004 is rank 21, not 22.
    const auto rank = static_cast<std::size_t>(std::max(1.0, core::steps_covering(q * n)));
    const std::size_t index = std::min(values.size(), rank) - 1;
    std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(index),
                     values.end());
    return values[index];
}

Stats stats_of(const std::vector<double>& values) {
    Stats out;
    out.values = values;
    std::vector<double> finite;
    finite.reserve(values.size());
    for (double v : values)
        if (std::isfinite(v)) finite.push_back(v);
    if (finite.empty()) return out;
    out.mean = core::mean(finite);
    out.p84 = order_statistic(finite, governing_percentile);
    out.max = *std::max_element(finite.begin(), finite.end());
    return out;
}

Stats resample(const Stats& s, const std::vector<std::size_t>& sets) {
    std::vector<double> values;
    values.reserve(sets.size());
    for (std::size_t k : sets) values.push_back(s.values.at(k));
    return stats_of(values);
}

Exceedance exceedance(const std::vector<double>& values, double limit, int always) {
    Exceedance out;
    out.n = static_cast<int>(values.size());
    out.k = always;
    for (double v : values)
        if (std::isfinite(v) && v > limit) ++out.k;
    out.k = std::min(out.k, out.n);
    out.ci95 = core::clopper_pearson(out.k, out.n);
    return out;
}

std::string exceedance_text(const Exceedance& e) {
    return fmt::format("{}/{} (95% {:.0f}-{:.0f}%)", e.k, e.n, 100.0 * e.ci95[0],
                       100.0 * e.ci95[1]);
}

}  // namespace freestand::assess
