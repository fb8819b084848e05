#include "core/record.hpp"

#include <cmath>
#include <fmt/format.h>

#include "core/errors.hpp"

namespace freestand::core {

void validate(const Record& record) {
    const SourceLocation where{record.source, 0, ""};
    if (record.accel_mps2.empty()) throw InputError(where, "record has no samples");
    if (!(std::isfinite(record.dt_s) && record.dt_s > 0.0))
        throw InputError(where, fmt::format("time step {} s must be finite and > 0", record.dt_s));
    for (std::size_t i = 0; i < record.accel_mps2.size(); ++i) {
        if (!std::isfinite(record.accel_mps2[i]))
            throw InputError(where, fmt::format("sample {} is not a finite number", i));
    }
}

}  // namespace freestand::core
