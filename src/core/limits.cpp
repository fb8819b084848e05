#include "core/limits.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>

#include "core/tolerances.hpp"

namespace freestand::core::limits {

namespace {

// The two numbers of a limit message at 4 significant digits, or at as many more as it takes
// to tell them apart: 3.0001 against 3 must not read "3 is above the limit 3". Shortest
// round-trip text when even 17 digits agree (a NaN against a number).
std::array<std::string, 2> distinct_texts(double value, double limit) {
    for (int digits = 4; digits <= 17; ++digits) {
        std::string a = fmt::format("{:.{}g}", value, digits);
        std::string b = fmt::format("{:.{}g}", limit, digits);
        if (a != b) return {std::move(a), std::move(b)};
    }
    return {fmt::format("{}", value), fmt::format("{}", limit)};
}

}  // namespace

bool within(double value, const Range& range) {
    const bool above_lo = range.lo_inclusive ? value >= range.lo : value > range.lo;
    const bool below_hi = range.hi_inclusive ? value <= range.hi : value < range.hi;
    return std::isfinite(value) && above_lo && below_hi;
}

std::string describe(const Range& range) {
    return fmt::format("{}{}, {}{}", range.lo_inclusive ? '[' : '(', range.lo, range.hi,
                       range.hi_inclusive ? ']' : ')');
}

void require_in(double value, const Range& range, const SourceLocation& where) {
    if (within(value, range)) return;
    throw InputError(where,
                     fmt::format("value {} is out of range; expected {}", value, describe(range)));
}

double pga_range_count(double start_g, double stop_g, double step_g) {
    return std::floor((stop_g - start_g) / step_g + tol::rounding_guard) + 1.0;
}

std::vector<double> pga_range_levels(double start_g, double step_g, double count) {
    std::vector<double> out;
    for (int i = 0; i < static_cast<int>(count); ++i)
        out.push_back(std::round((start_g + i * step_g) * 1e12) / 1e12);
    return out;
}

void require_pga_levels(const std::vector<double>& pga_g, const SourceLocation& where) {
    if (pga_g.empty()) throw InputError(where, "expected at least one PGA level");
    require_within(static_cast<double>(pga_g.size()), max_pga_levels, where, "PGA levels");
    for (std::size_t i = 0; i < pga_g.size(); ++i) {
        require_in(pga_g[i], pga_level_g, where);
        if (i > 0 && pga_g[i] <= pga_g[i - 1])
            throw InputError(where, fmt::format("levels must be strictly increasing; {} follows {}",
                                                pga_g[i], pga_g[i - 1]));
    }
}

void require_within(double needed, double limit, const SourceLocation& where,
                    std::string_view what) {
    if (needed <= limit) return;
    const auto texts = distinct_texts(needed, limit);
    throw InputError(where, fmt::format("{}: {} is above the limit {} (README, Limits)", what,
                                        texts[0], texts[1]));
}

void require_length(double length_m, const SourceLocation& where) {
    require_positive(length_m, where);
    require_within(length_m, max_length_m, where, "length (m)");
}

void require_at_least(double given, double limit, const SourceLocation& where,
                      std::string_view what) {
    if (given >= limit) return;
    const auto texts = distinct_texts(given, limit);
    throw InputError(where, fmt::format("{}: {} is below the limit {} (README, Limits)", what,
                                        texts[0], texts[1]));
}

void require_accelerations(const std::vector<double>& series_mps2, const SourceLocation& where) {
    for (double a : series_mps2) {
        if (!std::isfinite(a)) throw InputError(where, "an acceleration is not a finite number");
        require_within(std::abs(a), max_abs_accel_mps2, where,
                       "an excitation acceleration (m/s^2, 100 g)");
    }
}

}  // namespace freestand::core::limits
