#include "core/errors.hpp"

#include <cmath>
#include <fmt/format.h>

namespace freestand {

std::string format_location(const SourceLocation& where, const std::string& message) {
    std::string out;
    if (!where.file.empty()) {
        out += where.file;
        if (where.line > 0) out += fmt::format(":{}", where.line);
        out += ": ";
    }
    if (!where.field.empty()) out += where.field + ": ";
    return out + message;
}

void require_in_range(double value, double lo, double hi, const SourceLocation& where,
                      bool lo_inclusive, bool hi_inclusive) {
    const bool above_lo = lo_inclusive ? value >= lo : value > lo;
    const bool below_hi = hi_inclusive ? value <= hi : value < hi;
    if (std::isfinite(value) && above_lo && below_hi) return;
    throw InputError(where, fmt::format("value {} is out of range; expected {}{}, {}{}", value,
                                        lo_inclusive ? '[' : '(', lo, hi,
                                        hi_inclusive ? ']' : ')'));
}

void require_positive(double value, const SourceLocation& where) {
    if (std::isfinite(value) && value > 0.0) return;
    throw InputError(where, fmt::format("value {} must be a finite number > 0", value));
}

void require_non_negative(double value, const SourceLocation& where) {
    if (std::isfinite(value) && value >= 0.0) return;
    throw InputError(where, fmt::format("value {} must be a finite number >= 0", value));
}

}  // namespace freestand
