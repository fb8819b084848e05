#include "core/limits.hpp"

#include <fmt/format.h>

#include <cmath>

namespace freestand::core::limits {

void require_within(double needed, double limit, const SourceLocation& where,
                    std::string_view what) {
    if (needed <= limit) return;
    throw InputError(where, fmt::format("{}: {:.4g} is above the limit {:.4g} (README, Limits)",
                                        what, needed, limit));
}

void require_at_least(double given, double limit, const SourceLocation& where,
                      std::string_view what) {
    if (given >= limit) return;
    throw InputError(where, fmt::format("{}: {:.4g} is below the limit {:.4g} (README, Limits)",
                                        what, given, limit));
}

void require_accelerations(const std::vector<double>& series_mps2, const SourceLocation& where) {
    for (double a : series_mps2) {
        if (!std::isfinite(a)) throw InputError(where, "an acceleration is not a finite number");
        require_within(std::abs(a), max_abs_accel_mps2, where,
                       "an excitation acceleration (m/s^2, 100 g)");
    }
}

}  // namespace freestand::core::limits
