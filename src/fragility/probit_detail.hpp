#pragma once
/// The probit model's two tail-safe pieces, shared by the fit and the profile likelihood (not
/// installed).
#include <cmath>

#include "core/statistics.hpp"

namespace freestand::fragility::detail {

/// ln Phi(z) without underflow far in the lower tail (Phi(z) ~ phi(z) / -z there).
inline double log_phi_cdf(double z) {
    if (z > -30.0) return std::log(core::normal_cdf(z));
    return -0.5 * z * z - std::log(-z) - 0.5 * std::log(2.0 * M_PI);
}

/// phi(z) / Phi(z), the inverse Mills ratio, stable for z -> -infinity (~ -z).
inline double mills(double z) {
    if (z > -30.0) {
        const double phi = std::exp(-0.5 * z * z) / std::sqrt(2.0 * M_PI);
        return phi / core::normal_cdf(z);
    }
    return -z;
}

/// Below this beta a fit is taken as separated (a step, not a lognormal curve).
inline constexpr double min_beta = 1e-3;

}  // namespace freestand::fragility::detail
