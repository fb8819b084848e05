#pragma once
/// Lognormal fragility by maximum likelihood (Baker 2015, Earthquake Spectra 31(1) 579-599):
/// maximise sum_j [k_j ln Phi(z_j) + (n_j - k_j) ln Phi(-z_j)], z_j = (ln a_j - ln theta_m) /
/// beta, over the levels a_j with k_j failures of n_j.
#include <vector>

#include "fragility/fragility.hpp"

namespace freestand::fragility {

/// The fit, or a note saying why there is none: no level with a failure, every sample failing,
/// failures falling with the PGA, or the levels perfectly separated (failures only above some
/// level and none below it: the likelihood grows without bound as beta -> 0, so no finite
/// beta is the estimate). Levels with n = 0 are skipped. Sizes must match.
EventFit fit_lognormal(const std::vector<double>& pga_g, const std::vector<int>& k,
                       const std::vector<int>& n);

}  // namespace freestand::fragility
