#include "dynamics/modal_checks.hpp"

#include <cmath>
#include <fmt/format.h>

#include "core/errors.hpp"

namespace freestand::dynamics::detail {

void require_modal_frequency(double frequency_hz, const char* field) {
    if (!std::isfinite(frequency_hz) || frequency_hz <= 0.0)
        throw InputError({"", 0, field}, fmt::format("fixed-base frequency must be > 0 Hz; got {}",
                                                     frequency_hz));
}

void require_modal_damping(double damping) {
    if (!std::isfinite(damping) || damping < 0.0 || damping >= 1.0)
        throw InputError({"", 0, "flexible.zeta"},
                         fmt::format("modal damping ratio must be in [0, 1); got {}", damping));
}

void require_modal_mass_fraction(double fraction) {
    if (!std::isfinite(fraction) || fraction <= 0.0 || fraction >= 1.0)
        throw InputError({"", 0, "flexible.mass"},
                         fmt::format("modal mass fraction must be in (0, 1); got {}", fraction));
}

void require_modal_height(double height_m) {
    if (!std::isfinite(height_m) || height_m <= 0.0)
        throw InputError({"", 0, "flexible.height"},
                         fmt::format("modal height must be > 0 m; got {}", height_m));
}

}  // namespace freestand::dynamics::detail
