#include "core/limits.hpp"

#include <fmt/format.h>

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

}  // namespace freestand::core::limits
