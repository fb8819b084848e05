#pragma once
/// Lognormal fragility by maximum likelihood (Baker 2015, Earthquake Spectra 31(1) 579-599):
/// maximise sum_j [k_j ln Phi(z_j) + (n_j - k_j) ln Phi(-z_j)], z_j = (ln a_j - ln theta_m) /
/// beta, over the levels a_j with k_j failures of n_j.
#include <array>
#include <vector>

#include "fragility/fragility.hpp"

namespace freestand::fragility {

/// The fit, or a note saying why there is none: no level with a failure, every sample failing,
/// failures falling with the PGA, or the levels perfectly separated (failures only above some
/// level and none below it: the likelihood grows without bound as beta -> 0, so no finite
/// beta is the estimate). Levels with n = 0 are skipped. Sizes must match.
EventFit fit_lognormal(const std::vector<double>& pga_g, const std::vector<int>& k,
                       const std::vector<int>& n);

/// P(a_g) = Phi(ln(a_g / theta_m) / beta) of the fitted curve; a_g > 0.
double fitted_p(const Fit& fit, double a_g);

/// One point of a fitted curve: the PGA and P there.
struct CurvePoint {
    double pga_g = 0.0;
    double p = 0.0;
};

/// The fitted curve at intervals + 1 PGAs spaced evenly in ln a over [lo_g, hi_g] (both > 0,
/// intervals >= 1), the first lo_g and the last hi_g: what a figure draws as the curve.
std::vector<CurvePoint> fitted_curve(const Fit& fit, double lo_g, double hi_g, int intervals);

/// The probability of failure at one PGA, with its 95% interval.
struct Probability {
    double p = 0.0;
    std::array<double, 2> ci95{};  ///< [lower, upper], lower <= p <= upper
};

/// P(a_g) of the lognormal fitted to the levels by maximum likelihood (as fit_lognormal), with
/// its 95% profile-likelihood interval: every P whose best curve through (a_g, P) has a log
/// likelihood within chi2_1(0.95) / 2 = 1.92 of the best curve's (the likelihood-ratio
/// interval, Venzon & Moolgavkar 1988, Applied Statistics 37(1) 87-94, by Wilks' theorem).
/// Curves are non-decreasing with beta >= 1e-3 (fit_lognormal's step limit), so the answer
/// exists where the fit has none: with no failure the likelihood is largest as P -> 0 and p is
/// 0 (its upper bound still finite); with separated levels p is the step's value. Values
/// below 1e-15 are written 0 and above 1 - 1e-15 are written 1. Levels with n = 0 are
/// skipped; sizes must match and a_g must be > 0 (std::invalid_argument otherwise).
Probability probability_at(const std::vector<double>& pga_g, const std::vector<int>& k,
                           const std::vector<int>& n, double a_g);

}  // namespace freestand::fragility
