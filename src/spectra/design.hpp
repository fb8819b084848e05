#pragma once
/// Design spectra used as targets (docs/methods.md s.8).
#include <array>
#include <vector>

#include "core/units.hpp"
#include "spectra/spectrum.hpp"

namespace freestand::spectra {

/// The dampings RG 1.60 tabulates (docs/methods.md s.8).
inline constexpr std::array<double, 5> rg160_dampings{0.005, 0.02, 0.05, 0.07, 0.10};

/// RG 1.60's vertical zero-period acceleration over the horizontal PGA: factor A of its
/// vertical table is 1 (docs/methods.md s.8), the vertical spectrum following the maximum
/// horizontal ground acceleration above 33 Hz.
inline constexpr double rg160_vertical_zpa_ratio = 1.0;

/// US NRC RG 1.60 at damping in {0.005, 0.02, 0.05, 0.07, 0.10}; other dampings in
/// [0.005, 0.10] interpolate the factors on log damping (InputError outside). Horizontal or
/// vertical control points (A 33 Hz, B 9 Hz, C 2.5 Hz or 3.5 Hz vertical, D 0.25 Hz), straight
/// lines on log-log axes, PSA = PGA above 33 Hz, constant spectral displacement below 0.25 Hz.
/// pga_g is the horizontal design PGA for both directions (the vertical factors include the
/// vertical/horizontal ratio). PSA is in the unit g of size g_mps2, m/s^2 (the case's), which
/// converts the D point's ground displacement (m per g of PGA) to PSA.
Spectrum rg160(double pga_g, double damping, bool vertical, const std::vector<double>& frequency_hz,
               double g_mps2 = units::g_mps2);

/// ASCE 7 two-period spectrum (5%, ASCE 7-16 11.4.6); tl_s in s. T0 = 0.2 SD1/SDS,
/// TS = SD1/SDS; requires sds_g, sd1_g > 0 and tl_s > TS.
Spectrum asce7(double sds_g, double sd1_g, double tl_s, const std::vector<double>& frequency_hz);

enum class Ec8Type { type1, type2 };
/// Eurocode 8 EN 1998-1 3.2.2.2 horizontal elastic spectrum; ground 'A'..'E' (recommended S,
/// TB, TC, TD of Tables 3.2 and 3.3); damping in (0, 1) through eta = sqrt(10/(5+xi%)) >= 0.55.
/// The TD branch (constant displacement) continues beyond 4 s.
Spectrum ec8(double ag_g, Ec8Type type, char ground, double damping,
             const std::vector<double>& frequency_hz);

enum class Is1893Soil { rock, medium, soft };
/// IS 1893 (Part 1) 5% spectrum scaled by pga_g (Sa/g shape times PGA): 1 + 15 T below 0.1 s,
/// 2.5 up to 0.40/0.55/0.67 s (rock/medium/soft), then 1.0/T, 1.36/T, 1.67/T up to 4 s, then
/// constant at the 4 s value.
Spectrum is1893(double pga_g, Is1893Soil soil, const std::vector<double>& frequency_hz);

/// One-sided target PSD of RG 1.60 horizontal, SRP 3.7.1 App. A, m^2/s^3 per Hz at pga_g:
/// per-Hz one-sided convention, integral over f in Hz from 0 to infinity = mean square
/// acceleration, i.e. 2 pi times rg160_target_psd_per_radps. Compare with a record's
/// S(f) = 2 |X(f)|^2 / T_D (X = dt * FFT(a), T_D the 5-75% Arias duration).
double rg160_target_psd(double f_hz, double pga_g);

/// The same target in the convention of the SRP 3.7.1 App. A table (docs/methods.md s.8 values
/// 0.419 (f/2.5)^0.2 ... per 1 g): one-sided per rad/s, evaluated at f in Hz, so the integral
/// over omega is the mean square. Compare with a record's S(f) = |X(f)|^2 / (pi T_D).
double rg160_target_psd_per_radps(double f_hz, double pga_g);

/// RG 1.60 amplification factors (A, B, C, D) at a damping in [0.005, 0.10], interpolated on
/// log damping between the table of docs/methods.md s.8. D multiplies the ground displacement
/// 0.9144 m per 1 g; A-C multiply the PGA.
struct Rg160Factors {
    double a, b, c, d;
};
Rg160Factors rg160_factors(double damping, bool vertical);

}  // namespace freestand::spectra
