#pragma once
/// Closed-form sliding estimates (docs/methods.md s.4): the ASCE 4 equivalent-linear method and
/// the energy-conservation method. Both give one equivalent peak displacement, not a history.
#include <optional>
#include <string>

#include "core/units.hpp"
#include "spectra/spectrum.hpp"

namespace freestand::sliding {

/// Damping of the spectra the ASCE 4 sliding method reads (10% of critical).
inline constexpr double asce_sliding_damping = 0.10;

/// Effective friction mu_e = mu (1 - 0.4 A_v / g) (ASCE 4; docs/methods.md s.4). mu_s >= 0,
/// 0 <= av_g < 2.5 (so mu_e >= 0 only vanishes with mu); InputError naming the field otherwise.
double effective_friction(double mu_s, double av_g);

/// The lowest frequency at which a spectrum reaches level_g, and how it was found.
struct Crossing {
    std::optional<double> f_hz;  ///< empty when the spectrum never reaches the level
    std::string reason;          ///< why f_hz is empty
    std::string note;            ///< how it was found (interpolated, at a point, extrapolated)
};

/// Lowest frequency where s.psa_at(f) = level_g: scanning the points upward, the first point
/// with PSA >= level_g; between it and the previous point the crossing is interpolated linearly
/// on log-log axes (the same interpolation as Spectrum::psa_at); exactly at a point when that
/// point's PSA equals the level. If the first point already reaches the level, the crossing is
/// below the data and follows psa_at's constant-displacement extrapolation f0 sqrt(level/psa0).
/// Empty when every point is below the level (psa_at is constant above the last point).
/// level_g > 0.
Crossing lowest_crossing(const spectra::Spectrum& s, double level_g);

/// ASCE 4 sliding displacement delta_s = C_s / (2 pi f_es)^2, m. c_s_mps2 >= 0, f_es_hz > 0.
double asce_displacement_m(double c_s_mps2, double f_es_hz);

/// Energy-conservation displacement, m: positive root of
/// g DeltaD = 4 mu_e g delta + (1/2) (2 pi f_es)^2 delta^2. mu_e >= 0, f_es_hz > 0, pgd_m >= 0;
/// g_mps2 is gravity, m/s^2.
double energy_displacement_m(double mu_e, double f_es_hz, double pgd_m,
                             double g_mps2 = units::g_mps2);

/// What the sliding estimate needs besides the spectrum or f_es.
struct SlidingInput {
    double mu_s = 0.0;              ///< static friction coefficient, >= 0
    double av_g = 0.0;              ///< peak vertical ground acceleration, g, >= 0
    std::optional<double> pgd_m;    ///< peak ground displacement, m (energy method)
    /// Peak horizontal ground acceleration, g. When given and <= mu_e, the energy method is not
    /// applied (the rigid block does not slide at all).
    std::optional<double> pga_h_g;
    /// Gravity, and the unit g of av_g, pga_h_g and the spectrum, m/s^2 (a case's site.g_mps2).
    double g_mps2 = units::g_mps2;
};

/// Both sliding estimates. Every empty optional has its "<field>_reason" set.
struct SlidingEstimate {
    double mu_e = 0.0;
    double c_s_mps2 = 0.0;                ///< C_s = 2 mu_e g
    std::optional<double> f_es_hz;
    std::string f_es_reason;
    std::string f_es_source;              ///< "given", or how it was read off the spectrum
    bool slides = false;                  ///< false: "does not slide" (or frictionless)
    std::optional<double> slide_asce_m;
    std::string slide_asce_reason;
    std::optional<double> slide_energy_m;
    std::string slide_energy_reason;
};

/// Estimates with a known f_es (e.g. read by hand off the site spectrum). f_es_hz > 0.
SlidingEstimate estimate_sliding(const SlidingInput& in, double f_es_hz);

/// Estimates with f_es found on sa_vh10, the 10%-damped vector horizontal spectrum SA_VH
/// (see vector_horizontal in sliding/spectrum_input.hpp). InputError (field "damping") when the
/// spectrum's damping is not expected_damping. ASCE 4 reads 10%; a case may deliberately choose
/// another damping, which f_es_source then states.
SlidingEstimate estimate_sliding(const SlidingInput& in, const spectra::Spectrum& sa_vh10,
                                 double expected_damping = asce_sliding_damping);

}  // namespace freestand::sliding
