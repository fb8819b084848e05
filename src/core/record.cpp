#include "core/record.hpp"

#include <cmath>
#include <fmt/format.h>

#include "core/limits.hpp"

#include "core/errors.hpp"

namespace freestand::core {

void validate(const Record& record) {
    const SourceLocation where{record.source, 0, ""};
    if (record.accel_mps2.empty()) throw InputError(where, "record has no samples");
    if (!(std::isfinite(record.dt_s) && record.dt_s > 0.0))
        throw InputError(where, fmt::format("time step {} s must be finite and > 0", record.dt_s));
    if (record.dt_s < limits::min_dt_s || record.dt_s > limits::max_dt_s) {
        throw InputError(where, fmt::format("time step {:.4g} s is outside [{:g}, {:g}] s "
                                            "(README, Limits)",
                                            record.dt_s, limits::min_dt_s, limits::max_dt_s));
    }
    for (std::size_t i = 0; i < record.accel_mps2.size(); ++i) {
        const double a = record.accel_mps2[i];
        if (!std::isfinite(a))
            throw InputError(where, fmt::format("sample {} is not a finite number", i));
        if (std::abs(a) > limits::max_abs_accel_mps2) {
            throw InputError(where, fmt::format("sample {} is {:.4g} m/s^2, beyond the limit of "
                                                "{:.4g} m/s^2 (100 g; README, Limits)",
                                                i, a, limits::max_abs_accel_mps2));
        }
    }
}

}  // namespace freestand::core
