#include "core/statistics.hpp"

#include <algorithm>
#include <boost/math/distributions/beta.hpp>
#include <boost/math/distributions/normal.hpp>
#include <fmt/format.h>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace freestand::core {

double mean(const std::vector<double>& values) {
    if (values.empty()) return 0.0;
    return std::accumulate(values.begin(), values.end(), 0.0) / static_cast<double>(values.size());
}

double quantile(std::vector<double> values, double q) {
    if (values.empty()) throw std::invalid_argument("quantile of an empty sample");
    if (!(q >= 0.0 && q <= 1.0)) throw std::invalid_argument("quantile: q outside [0, 1]");
    std::sort(values.begin(), values.end());
    const double pos = q * static_cast<double>(values.size() - 1);
    const auto lo = static_cast<std::size_t>(std::floor(pos));
    const std::size_t hi = std::min(lo + 1, values.size() - 1);
    const double frac = pos - static_cast<double>(lo);
    return values[lo] + frac * (values[hi] - values[lo]);
}

std::array<double, 2> clopper_pearson(int k, int n, double confidence) {
    if (n < 1 || k < 0 || k > n) throw std::invalid_argument("clopper_pearson: need 0 <= k <= n, n >= 1");
    if (!(confidence > 0.0 && confidence < 1.0))
        throw std::invalid_argument("clopper_pearson: confidence outside (0, 1)");
    const double tail = (1.0 - confidence) / 2.0;
    const double kd = k;
    const double nd = n;
    const double lower =
        k == 0 ? 0.0 : boost::math::quantile(boost::math::beta_distribution<>(kd, nd - kd + 1.0), tail);
    const double upper =
        k == n ? 1.0
               : boost::math::quantile(boost::math::beta_distribution<>(kd + 1.0, nd - kd), 1.0 - tail);
    return {lower, upper};
}

double normal_cdf(double z) { return boost::math::cdf(boost::math::normal_distribution<>(), z); }

double normal_quantile(double p) {
    return boost::math::quantile(boost::math::normal_distribution<>(), p);
}

double Distribution::at(double u) const {
    if (kind == Kind::uniform) return a + u * (b - a);
    // Inverse CDF of ln X ~ N(ln a, b^2), on [0, F(upper)) when truncated.
    const double top = upper ? normal_cdf(std::log(*upper / a) / b) : 1.0;
    const double p = std::clamp(u * top, 1e-300, 1.0 - 1e-16);
    return a * std::exp(b * normal_quantile(p));
}

std::string Distribution::describe() const {
    if (kind == Kind::uniform) return fmt::format("uniform [{:.4g}, {:.4g}]", a, b);
    return fmt::format("lognormal median {:.4g}, beta {:.4g}{}", a, b,
                       upper ? fmt::format(" (truncated at {:.4g})", *upper) : "");
}

}  // namespace freestand::core
