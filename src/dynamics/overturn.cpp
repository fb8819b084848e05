// The overturning rule (overturn.hpp, docs/methods.md s.3).
#include "dynamics/overturn.hpp"

#include <numbers>

namespace freestand::dynamics::detail {

OverturnCriterion overturn_criterion(const Tilt& tilt, bool input_ended) {
    if (tilt.theta_rad >= std::numbers::pi / 2.0) return OverturnCriterion::angle_half_pi;
    const bool falling_outward = tilt.theta_rad > tilt.alpha_rad && tilt.omega_radps > 0.0 &&
                                 tilt.cg_beyond_pivot_m > 0.0;
    if (input_ended && falling_outward && tilt.energy_J < tilt.ridge_energy_J)
        return OverturnCriterion::past_alpha_after_excitation;
    return OverturnCriterion::none;
}

}  // namespace freestand::dynamics::detail
