#pragma once
/// SRP 3.7.1 Option 1 Approach 2 numbers (docs/methods.md s.8) shared by the generator and the report.
#include <vector>

#include "core/record.hpp"
#include "core/tolerances.hpp"

namespace freestand::motion::criteria {

inline constexpr double band_low_hz = 0.1;
inline constexpr double band_high_hz = 50.0;  ///< or the Nyquist frequency if lower
inline constexpr int points_per_decade = 100;
inline constexpr double floor_ratio = 0.9;
inline constexpr int max_adjacent_below = 9;
inline constexpr double cap_low_hz = 0.2;
inline constexpr double cap_high_hz = 25.0;
inline constexpr double cap_ratio = 1.3;
inline constexpr double psd_low_hz = 0.3;
inline constexpr double psd_high_hz = 24.0;
inline constexpr double psd_floor_rg160 = 0.8;
inline constexpr double psd_band_halfwidth = 0.2;  ///< average over f (1 -+ 0.2)
inline constexpr double max_dt_s = 0.01;
inline constexpr double min_duration_s = 20.0;
inline constexpr double max_abs_correlation = 0.16;
inline constexpr double max_final_velocity_mps = 1e-4;
inline constexpr double max_final_displacement_m = 1e-4;

/// True when dt is coarser than max_dt_s by more than core::tol::dt_s.
inline bool dt_too_coarse(double dt_s) { return dt_s > max_dt_s + core::tol::dt_s; }
/// True when a record is shorter than min_duration_s by more than core::tol::duration_s.
inline bool too_short(double duration_s) {
    return duration_s < min_duration_s - core::tol::duration_s;
}
/// True when f lies in the cap band cap_low_hz..cap_high_hz, its edges within
/// core::tol::band_edge_hz.
inline bool in_cap_band(double f_hz) {
    return f_hz >= cap_low_hz - core::tol::band_edge_hz &&
           f_hz <= cap_high_hz + core::tol::band_edge_hz;
}

/// Top of the acceptance band: 50 Hz or the Nyquist frequency 1 / (2 dt), whichever is lower.
double band_high_for(double dt_s);
/// The check frequencies: >= 100 per decade, band_low_hz .. band_high_for(dt_s).
std::vector<double> check_frequencies(double dt_s);

}  // namespace freestand::motion::criteria

namespace freestand::motion {

/// Final velocity and displacement of a record as linear functionals of its samples, with the
/// trapezoidal integration of core::velocity_mps / displacement_m: v_N = sum wv_k a_k,
/// d_N = sum wd_k a_k, wv = dt (1/2, 1, ..., 1, 1/2), wd_k = dt^2 (N - k) inside,
/// dt^2 (N/2 - 1/4) at k = 0 and dt^2 / 4 at k = N.
struct EndWeights {
    std::vector<double> velocity;
    std::vector<double> displacement;
};
EndWeights end_weights(std::size_t samples, double dt_s);

/// Record PSD in the SRP 3.7.1 App. A convention, one-sided per rad/s: S(f) = |X(f)|^2 / (pi T_D),
/// X = dt FFT(a) (zero-padded to <= 0.005 Hz bins), averaged over the bins within f (1 -+ 0.2).
/// For stationary white noise of variance s^2 and T_D = its length, S = s^2 dt / pi.
std::vector<double> averaged_psd_per_radps(const core::Record& record, double td_s,
                                           const std::vector<double>& frequency_hz);

}  // namespace freestand::motion
