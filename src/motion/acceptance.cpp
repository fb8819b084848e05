#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/errors.hpp"
#include "core/measures.hpp"
#include "core/units.hpp"
#include "motion/criteria.hpp"
#include "core/fft.hpp"
#include "motion/motion.hpp"
#include "spectra/design.hpp"
#include "spectra/response.hpp"

namespace freestand::motion {

double criteria::band_high_for(double dt_s) { return std::min(band_high_hz, 0.5 / dt_s); }

std::vector<double> criteria::check_frequencies(double dt_s) {
    return spectra::log_frequencies(band_low_hz, band_high_for(dt_s), points_per_decade);
}

EndWeights end_weights(std::size_t samples, double dt_s) {
    EndWeights w;
    w.velocity.assign(samples, dt_s);
    w.displacement.resize(samples);
    if (samples == 0) return w;
    const std::size_t n = samples - 1;
    for (std::size_t k = 0; k < samples; ++k)
        w.displacement[k] = dt_s * dt_s * static_cast<double>(n - k);
    w.velocity.front() = w.velocity.back() = 0.5 * dt_s;
    w.displacement.front() = dt_s * dt_s * (0.5 * static_cast<double>(n) - 0.25);
    w.displacement.back() = 0.25 * dt_s * dt_s;
    if (n == 0) w.velocity.front() = w.displacement.front() = 0.0;
    return w;
}

namespace {
constexpr double kPsdResolutionHz = 0.005;
}  // namespace

std::vector<double> averaged_psd_per_radps(const core::Record& record, double td_s,
                                           const std::vector<double>& frequency_hz) {
    // Zero-padding samples X(f), the record's continuous transform, densely (<= 0.005 Hz), so the
    // +-20% band average approximates an integral even at 0.3 Hz, where it spans few 1/T bins.
    const auto dense = static_cast<std::size_t>(std::ceil(1.0 / (kPsdResolutionHz * record.dt_s)));
    const std::size_t n = core::fft_size(std::max(record.size(), dense));
    core::RealFft fft(n);
    const auto x = fft.forward(record.accel_mps2);
    const double df = 1.0 / (static_cast<double>(n) * record.dt_s);
    std::vector<double> s(x.size());
    for (std::size_t k = 0; k < x.size(); ++k)
        s[k] = std::norm(x[k] * record.dt_s) / (units::pi * td_s);
    std::vector<double> out;
    out.reserve(frequency_hz.size());
    for (double f : frequency_hz) {
        const auto k0 =
            static_cast<std::size_t>(std::ceil(f * (1.0 - criteria::psd_band_halfwidth) / df));
        const auto k1 = std::min(
            x.size() - 1,
            static_cast<std::size_t>(std::floor(f * (1.0 + criteria::psd_band_halfwidth) / df)));
        double sum = 0.0;
        for (std::size_t k = k0; k <= k1; ++k) sum += s[k];
        out.push_back(k1 >= k0 ? sum / static_cast<double>(k1 - k0 + 1) : 0.0);
    }
    return out;
}

namespace {

struct RatioStats {
    double min = 0.0, max = 0.0, mean = 0.0, max_cap_band = 0.0;
    int longest_below = 0;
};

RatioStats ratio_stats(const std::vector<double>& f, const std::vector<double>& psa,
                       const spectra::Spectrum& target) {
    RatioStats s;
    s.min = 1e300;
    s.max = -1e300;
    int run = 0;
    for (std::size_t i = 0; i < f.size(); ++i) {
        const double r = psa[i] / target.psa_at(f[i]);
        s.min = std::min(s.min, r);
        s.max = std::max(s.max, r);
        s.mean += r / static_cast<double>(f.size());
        run = r < 1.0 ? run + 1 : 0;
        s.longest_below = std::max(s.longest_below, run);
        if (criteria::in_cap_band(f[i]))
            s.max_cap_band = std::max(s.max_cap_band, r);
    }
    return s;
}

// Minimum over 0.3-24 Hz (100 per decade) of the averaged PSD over the RG 1.60 target PSD.
double psd_min_ratio(const core::Record& record, double td_s, double pga_g) {
    const double top =
        std::min(criteria::psd_high_hz, 0.5 / record.dt_s / (1.0 + criteria::psd_band_halfwidth));
    const std::vector<double> f =
        spectra::log_frequencies(criteria::psd_low_hz, top, criteria::points_per_decade);
    const std::vector<double> s = averaged_psd_per_radps(record, td_s, f);
    double worst = 1e300;
    for (std::size_t i = 0; i < f.size(); ++i)
        worst = std::min(worst, s[i] / spectra::rg160_target_psd_per_radps(f[i], pga_g));
    return worst;
}

void add_reason(std::string& reason, const std::string& text) {
    if (!reason.empty()) reason += "; ";
    reason += text;
}

// Fills the realism measures of `a` (its peaks already set) and returns the failed ranges.
std::string realism_failures(Acceptance& a, const Target& target) {
    const RealismLimits& lim = target.realism;
    a.realism = lim;
    a.horizontal = target.horizontal;
    a.zpa_g = zero_period_g(target.psa_5pct);
    a.pga_over_zpa = a.pga_g / a.zpa_g;
    if (a.pga_g > 0.0) {
        a.va_mps_per_g = a.pgv_mps / a.pga_g;
        a.da_m_per_g = a.pgd_m / a.pga_g;
    }
    if (a.pgv_mps > 0.0) a.adv2 = a.pga_g * target.g_mps2 * a.pgd_m / (a.pgv_mps * a.pgv_mps);
    std::string why;
    const auto outside = [](double v, const Range& r) { return v < r.min || v > r.max; };
    if (outside(a.pga_over_zpa, lim.pga_over_zpa))
        add_reason(why, fmt::format("PGA {:.3f} x ZPA outside {}-{}", a.pga_over_zpa,
                                    lim.pga_over_zpa.min, lim.pga_over_zpa.max));
    if (a.d5_75_s < lim.d5_75_min_s)
        add_reason(why, fmt::format("D5-75 {:.2f} s < {} s", a.d5_75_s, lim.d5_75_min_s));
    if (!target.horizontal) return why;
    if (lim.va_mps_per_g && outside(a.va_mps_per_g, *lim.va_mps_per_g))
        add_reason(why, fmt::format("V/A {:.3f} m/s/g outside {}-{}", a.va_mps_per_g,
                                    lim.va_mps_per_g->min, lim.va_mps_per_g->max));
    if (lim.adv2 && outside(a.adv2, *lim.adv2))
        add_reason(why, fmt::format("AD/V^2 {:.3f} outside {}-{}", a.adv2, lim.adv2->min,
                                    lim.adv2->max));
    if (lim.da_max_m_per_g && a.da_m_per_g > *lim.da_max_m_per_g)
        add_reason(why, fmt::format("D/A {:.3f} m/g > {}", a.da_m_per_g, *lim.da_max_m_per_g));
    return why;
}

}  // namespace

namespace {

// The SRP 3.7.1 reasons a record fails for, in the report's order.
std::string srp_failures(const Acceptance& a) {
    std::string why;
    if (criteria::dt_too_coarse(a.dt_s))
        add_reason(why, fmt::format("dt {} s > {} s", a.dt_s, criteria::max_dt_s));
    if (criteria::too_short(a.duration_s))
        add_reason(why,
                   fmt::format("duration {:.3f} s < {} s", a.duration_s, criteria::min_duration_s));
    if (a.min_ratio < criteria::floor_ratio)
        add_reason(why, fmt::format("min ratio {:.4f} < {}", a.min_ratio, criteria::floor_ratio));
    if (a.max_adjacent_below > criteria::max_adjacent_below)
        add_reason(why, fmt::format("{} adjacent points below target > {}", a.max_adjacent_below,
                                    criteria::max_adjacent_below));
    if (a.max_ratio_cap_band > criteria::cap_ratio)
        add_reason(why,
                   fmt::format("ratio {:.4f} > {} in {}-{} Hz", a.max_ratio_cap_band,
                               criteria::cap_ratio, criteria::cap_low_hz, criteria::cap_high_hz));
    if (a.psd_min_ratio && *a.psd_min_ratio < criteria::psd_floor_rg160)
        add_reason(why, fmt::format("PSD ratio {:.4f} < {} in {}-{} Hz", *a.psd_min_ratio,
                                    criteria::psd_floor_rg160, criteria::psd_low_hz,
                                    criteria::psd_high_hz));
    if (std::abs(a.final_velocity_mps) >= criteria::max_final_velocity_mps)
        add_reason(why, fmt::format("final velocity {:.3g} m/s", a.final_velocity_mps));
    if (std::abs(a.final_displacement_m) >= criteria::max_final_displacement_m)
        add_reason(why, fmt::format("final displacement {:.3g} m", a.final_displacement_m));
    return why;
}

// The criteria of srp_failures by what they need: the record's measures, its 5% spectrum, its PSD.
bool measures_fail(const Acceptance& a) {
    return criteria::dt_too_coarse(a.dt_s) ||
           criteria::too_short(a.duration_s) ||
           std::abs(a.final_velocity_mps) >= criteria::max_final_velocity_mps ||
           std::abs(a.final_displacement_m) >= criteria::max_final_displacement_m;
}

bool spectrum_fails(const Acceptance& a) {
    return a.min_ratio < criteria::floor_ratio ||
           a.max_adjacent_below > criteria::max_adjacent_below ||
           a.max_ratio_cap_band > criteria::cap_ratio;
}

bool psd_fails(const Acceptance& a) {
    return a.psd_min_ratio && *a.psd_min_ratio < criteria::psd_floor_rg160;
}

// What a caller that reads only `passed` gets for a record that fails.
Acceptance rejected() {
    Acceptance a;
    a.passed = false;
    a.srp_passed = false;
    a.reason = "rejected at the first failed criterion";
    return a;
}

// The acceptance report. With stop_early, the criteria are tried in order of cost (the record's
// own measures, the 5% spectrum, the PSD) and a failed one returns rejected() at once; a record
// that passes gets the full report either way, from the same computations.
Acceptance evaluate(const core::Record& record, const Target& target, bool stop_early) {
    core::validate(record);
    Acceptance a;
    a.dt_s = record.dt_s;
    a.duration_s = record.duration_s();
    const core::GroundMotion gm = core::measure(record, target.g_mps2);
    a.pga_g = gm.pga_g;
    a.pgv_mps = gm.pgv_mps;
    a.pgd_m = gm.pgd_m;
    a.d5_75_s = gm.d5_75_s;
    a.d5_95_s = gm.d5_95_s;
    a.final_velocity_mps = gm.final_velocity_mps;
    a.final_displacement_m = gm.final_displacement_m;
    a.arias_mps = gm.arias_mps;
    if (stop_early && (measures_fail(a) || !realism_failures(a, target).empty())) return rejected();

    const std::vector<double> f = criteria::check_frequencies(record.dt_s);
    a.check_points = f.size();
    const RatioStats r5 = ratio_stats(f, spectra::psa_g(record, 0.05, f, target.g_mps2), target.psa_5pct);
    a.min_ratio = r5.min;
    a.max_ratio = r5.max;
    a.mean_ratio = r5.mean;
    a.max_adjacent_below = r5.longest_below;
    a.max_ratio_cap_band = r5.max_cap_band;
    if (stop_early && spectrum_fails(a)) return rejected();
    if (target.rg160_psd_pga_g && gm.d5_75_s > 0.0)
        a.psd_min_ratio = psd_min_ratio(record, gm.d5_75_s, *target.rg160_psd_pga_g);
    if (stop_early && psd_fails(a)) return rejected();
    // Reported, not a criterion.
    if (target.psa_10pct) {
        const RatioStats r10 = ratio_stats(f, spectra::psa_g(record, 0.10, f, target.g_mps2),
                                            *target.psa_10pct);
        a.ratio_10pct_min = r10.min;
        a.ratio_10pct_max = r10.max;
    }

    a.reason = srp_failures(a);
    a.srp_passed = a.reason.empty();
    const std::string realism = realism_failures(a, target);
    a.realism_passed = realism.empty();
    if (!a.realism_passed) add_reason(a.reason, realism);
    a.passed = a.srp_passed && a.realism_passed;
    return a;
}

}  // namespace

Acceptance check_acceptance(const core::Record& record, const Target& target) {
    return evaluate(record, target, false);
}

Acceptance check_acceptance_or_reject(const core::Record& record, const Target& target) {
    return evaluate(record, target, true);
}

}  // namespace freestand::motion
