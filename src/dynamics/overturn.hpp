#pragma once
/// Internal: the overturning rule of docs/methods.md s.3, the one place every engine that rocks
/// asks it (the planar block's two integrators, and through them the pair of units; the flexible
/// body's two), after each contact step and on the state a run ends with.
#include <limits>
#include <numbers>

#include "dynamics/simulate.hpp"

namespace freestand::dynamics::detail {

/// What the rule reads of a body on its edge (rock or slide-rock).
struct Tilt {
    double theta_rad = 0.0;    ///< uplift about the edge, >= 0
    double omega_radps = 0.0;  ///< theta', > 0 rotating away from the base
    double alpha_rad = 0.0;    ///< the edge's critical angle
    /// Horizontal distance of the whole body's CG beyond the pivot, outward > 0, m. For a rigid
    /// block it is R sin(theta - alpha); an elastic mode moves the CG against the body.
    double cg_beyond_pivot_m = 0.0;
    /// Mechanical energy relative to the base (kinetic, elastic, gravity above the base plane),
    /// J, and the least potential energy of a pose with the CG over the pivot, J: the energy
    /// the body needs to bring its CG back inside. Infinite when nothing but theta' can bring it
    /// back (a rigid block rocking on a fixed pivot: past alpha gravity's moment points outward,
    /// so theta' > 0 stays positive).
    double energy_J = 0.0;
    double ridge_energy_J = std::numeric_limits<double>::infinity();
};

/// docs/methods.md s.3: angle_half_pi when theta >= pi/2; past_alpha_after_excitation when the
/// input has ended (the base is at rest, so the energy relative to it can only fall: damping,
/// friction and impacts dissipate, nothing feeds it) while theta > alpha, theta' > 0, the CG
/// is beyond the pivot and the energy is below the ridge's (no restoring energy left: the CG
/// can never come back over the pivot); none otherwise.
OverturnCriterion overturn_criterion(const Tilt& tilt, bool input_ended);

/// Whether the rule can hold for theta, theta' on an edge of critical angle alpha (the cheap
/// test before a Tilt's energies are computed).
inline bool overturn_possible(double theta_rad, double omega_radps, double alpha_rad,
                              bool input_ended) {
    return theta_rad >= std::numbers::pi / 2.0 || (input_ended && theta_rad > alpha_rad && omega_radps > 0.0);
}

}  // namespace freestand::dynamics::detail
