#include "validate/rows.hpp"

#include <fmt/format.h>

#include <cmath>

namespace freestand::validate {

std::string sig(double v, int digits) {
    if (v == 0.0) return "0";
    const int magnitude = static_cast<int>(std::floor(std::log10(std::fabs(v))));
    const int decimals = std::max(0, digits - 1 - magnitude);
    return fmt::format("{:.{}f}", v, decimals);
}

void compare_numbers(Row& row, double thesis_value, double predicted_value,
                     const std::string& unit, double abs_tol, double rel_tol) {
    row.unit = unit;
    row.thesis_value = thesis_value;
    row.predicted_value = predicted_value;
    const double diff = predicted_value - thesis_value;
    row.difference_value = diff;
    const std::string sign = diff >= 0.0 ? "+" : "-";
    row.difference = fmt::format("{}{} {}", sign, sig(std::fabs(diff), 2), unit);
    if (thesis_value != 0.0)
        row.difference += fmt::format(" ({}{:.1f}%)", sign, 100.0 * std::fabs(diff / thesis_value));
    const bool within =
        std::fabs(diff) <= abs_tol || std::fabs(diff) <= rel_tol * std::fabs(thesis_value);
    row.agreement = within ? Agreement::agrees : Agreement::differs;
}

}  // namespace freestand::validate
