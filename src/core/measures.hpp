#pragma once
/// Ground-motion measures of an acceleration record (docs/methods.md s.8, "Response spectra":
/// PGA, PGV, PGD, Arias intensity and significant durations travel with every record).
/// Integrals use the trapezoidal rule on the record's own samples, starting from rest.
#include <vector>

#include "core/record.hpp"
#include "core/units.hpp"

namespace freestand::core {

/// Peak and integral measures of one record. Peaks are of the absolute value; finals are signed.
struct GroundMotion {
    double pga_g = 0.0;                 ///< max |a| / g
    double pgv_mps = 0.0;               ///< max |v|, v from trapezoidal integration from rest
    double pgd_m = 0.0;                 ///< max |d|, d from trapezoidal integration of v
    double arias_mps = 0.0;             ///< I_a = pi / (2 g) * integral a^2 dt, m/s
    double d5_75_s = 0.0;               ///< time between 5% and 75% of I_a (0 if I_a = 0)
    double d5_95_s = 0.0;               ///< time between 5% and 95% of I_a (0 if I_a = 0)
    double final_velocity_mps = 0.0;    ///< v at the last sample
    double final_displacement_m = 0.0;  ///< d at the last sample
};

/// All measures of a record. Throws InputError if the record is empty, has dt <= 0 or a
/// non-finite sample (core::validate). g_mps2 is gravity (Arias) and the unit g (PGA), m/s^2.
GroundMotion measure(const Record& record, double g_mps2 = units::g_mps2);

/// Ground velocity at each sample, m/s: v_0 = 0, v_i = v_{i-1} + dt (a_{i-1} + a_i) / 2.
std::vector<double> velocity_mps(const Record& record);

/// Ground displacement at each sample, m: d_0 = 0, d_i = d_{i-1} + dt (v_{i-1} + v_i) / 2.
std::vector<double> displacement_m(const Record& record);

/// The same trapezoidal integrals of bare samples (no validation: for the generator's inner
/// loops, whose samples are finite by construction).
std::vector<double> velocity_mps(const std::vector<double>& accel_mps2, double dt_s);
std::vector<double> displacement_m(const std::vector<double>& accel_mps2, double dt_s);

/// Cumulative Arias intensity at each sample, m/s: I_0 = 0,
/// I_i = I_{i-1} + pi / (2 g) * dt (a_{i-1}^2 + a_i^2) / 2. The last value is I_a.
std::vector<double> arias_intensity_mps(const Record& record, double g_mps2 = units::g_mps2);

/// Husid curve: cumulative Arias intensity divided by its final value (0..1 at each sample).
/// All zeros when the record has no energy.
std::vector<double> husid(const Record& record);

/// Significant duration, s: time between the Husid curve first reaching from_fraction and first
/// reaching to_fraction, each crossing interpolated linearly between samples. Requires
/// 0 <= from_fraction < to_fraction <= 1 (InputError otherwise). 0 when the record has no energy.
double significant_duration_s(const Record& record, double from_fraction, double to_fraction);

/// First time, s, at which a non-decreasing sampled curve (sample i at i * dt_s) reaches level,
/// interpolated linearly between the bracketing samples. Returns the last sample's time if the
/// curve never reaches level.
double crossing_time_s(const std::vector<double>& curve, double dt_s, double level);

}  // namespace freestand::core
