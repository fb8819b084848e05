#include "sliding/asce.hpp"

#include <cmath>
#include <fmt/format.h>

#include "core/tolerances.hpp"
#include "core/errors.hpp"
#include "core/units.hpp"

namespace freestand::sliding {

namespace {

SourceLocation field(const char* name) { return SourceLocation{"", 0, name}; }

void require_damping(const spectra::Spectrum& s, double damping) {
    if (std::abs(s.damping - damping) > core::tol::damping_equal)
        throw InputError(field("damping"),
                         fmt::format("spectrum \"{}\" has damping {}; expected {} (ASCE 4 sliding "
                                     "reads 10%-damped spectra)",
                                     s.label, s.damping, damping));
}

// Shared tail of both overloads: C_s, f_es known (or not), the two displacements.
SlidingEstimate finish(SlidingEstimate est, const SlidingInput& in) {
    if (!est.f_es_hz) {
        est.slide_asce_reason = est.f_es_reason;
        est.slide_energy_reason = "not applied below the sliding threshold: " + est.f_es_reason;
        return est;
    }
    est.slides = true;
    est.slide_asce_m = asce_displacement_m(est.c_s_mps2, *est.f_es_hz);
    if (!in.pgd_m) {
        est.slide_energy_reason = "needs the peak ground displacement (pgd_m)";
    } else if (in.pga_h_g && *in.pga_h_g <= est.mu_e) {
        est.slide_energy_reason = fmt::format(
            "not applied below the sliding threshold: PGA {} g <= mu_e = {}", *in.pga_h_g, est.mu_e);
    } else {
        est.slide_energy_m = energy_displacement_m(est.mu_e, *est.f_es_hz, *in.pgd_m, in.g_mps2);
    }
    return est;
}

SlidingEstimate start(const SlidingInput& in) {
    if (in.pgd_m) require_in_range(*in.pgd_m, 0.0, HUGE_VAL, field("pgd_m"), true, false);
    if (in.pga_h_g) require_in_range(*in.pga_h_g, 0.0, HUGE_VAL, field("pga_h_g"), true, false);
    SlidingEstimate est;
    est.mu_e = effective_friction(in.mu_s, in.av_g);
    est.c_s_mps2 = 2.0 * est.mu_e * in.g_mps2;
    return est;
}

// mu_e = 0: C_s = 0 is reached at every frequency, and delta_s -> SD at f -> 0; the method
// degenerates. A frictionless block stays put while the ground moves under it.
bool frictionless(SlidingEstimate& est, const SlidingInput& in) {
    if (est.mu_e > 0.0) return false;
    const std::string why =
        "frictionless base (mu_e = 0): C_s = 0 and the method degenerates; the block stays "
        "still while the ground moves, so its slip equals the ground displacement" +
        (in.pgd_m ? fmt::format(" ({} m)", *in.pgd_m) : std::string());
    est.slides = true;
    est.f_es_reason = why;
    est.slide_asce_reason = why;
    est.slide_energy_reason = why;
    return true;
}

}  // namespace

double effective_friction(double mu_s, double av_g) {
    require_in_range(mu_s, 0.0, HUGE_VAL, field("mu_s"), true, false);
    require_in_range(av_g, 0.0, 2.5, field("av_g"), true, false);
    return mu_s * (1.0 - 0.4 * av_g);
}

Crossing lowest_crossing(const spectra::Spectrum& s, double level_g) {
    require_positive(level_g, field("level_g"));
    const auto& f = s.frequency_hz;
    const auto& a = s.psa_g;
    if (f.empty() || f.size() != a.size())
        throw InputError(field("spectrum"),
                         fmt::format("spectrum \"{}\" has {} frequencies and {} PSA values", s.label,
                                     f.size(), a.size()));
    Crossing c;
    std::size_t peak = 0;
    for (std::size_t i = 0; i < f.size(); ++i) {
        if (a[i] > a[peak]) peak = i;
        if (a[i] < level_g) continue;
        if (a[i] == level_g) {
            c.f_hz = f[i];
            c.note = "at a spectrum point";
        } else if (i == 0) {
            // psa_at below the first point: PSA = psa0 (f / f0)^2 (constant displacement).
            c.f_hz = f[0] * std::sqrt(level_g / a[0]);
            c.note = fmt::format("below the spectrum's first point ({} Hz), extrapolated at "
                                 "constant spectral displacement",
                                 f[0]);
        } else {
            const double t = std::log(level_g / a[i - 1]) / std::log(a[i] / a[i - 1]);
            c.f_hz = f[i - 1] * std::pow(f[i] / f[i - 1], t);
            c.note = "interpolated on log-log axes";
        }
        return c;
    }
    c.reason = fmt::format("peak {} g at {} Hz < {} g", a[peak], f[peak], level_g);
    return c;
}

double asce_displacement_m(double c_s_mps2, double f_es_hz) {
    require_in_range(c_s_mps2, 0.0, HUGE_VAL, field("c_s_mps2"), true, false);
    require_positive(f_es_hz, field("f_es_hz"));
    const double w = units::hz_to_radps(f_es_hz);
    return c_s_mps2 / (w * w);
}

double energy_displacement_m(double mu_e, double f_es_hz, double pgd_m, double g_mps2) {
    require_in_range(mu_e, 0.0, HUGE_VAL, field("mu_e"), true, false);
    require_positive(f_es_hz, field("f_es_hz"));
    require_in_range(pgd_m, 0.0, HUGE_VAL, field("pgd_m"), true, false);
    const double w = units::hz_to_radps(f_es_hz);
    const double qa = 0.5 * w * w;
    const double qb = 4.0 * mu_e * g_mps2;
    const double qc = g_mps2 * pgd_m;
    // Positive root of qa d^2 + qb d - qc = 0 in the cancellation-free form 2c / (b + sqrt(.)).
    const double disc = std::sqrt(qb * qb + 4.0 * qa * qc);
    return disc + qb > 0.0 ? 2.0 * qc / (qb + disc) : 0.0;
}

SlidingEstimate estimate_sliding(const SlidingInput& in, double f_es_hz) {
    require_positive(f_es_hz, field("f_es_hz"));
    SlidingEstimate est = start(in);
    if (frictionless(est, in)) return est;
    est.f_es_hz = f_es_hz;
    est.f_es_source = "given";
    return finish(est, in);
}

SlidingEstimate estimate_sliding(const SlidingInput& in, const spectra::Spectrum& sa_vh10,
                                 double expected_damping) {
    require_damping(sa_vh10, expected_damping);
    SlidingEstimate est = start(in);
    if (frictionless(est, in)) return est;
    const Crossing c = lowest_crossing(sa_vh10, est.c_s_mps2 / in.g_mps2);
    est.f_es_hz = c.f_hz;
    if (!c.f_hz)
        est.f_es_reason = fmt::format("{:g}% SA_VH never reaches C_s ({}): does not slide (ASCE 4)",
                                      100.0 * sa_vh10.damping, c.reason);
    est.f_es_source = c.f_hz ? fmt::format("{:g}% SA_VH, {}", 100.0 * sa_vh10.damping, c.note) : "";
    return finish(est, in);
}

}  // namespace freestand::sliding
