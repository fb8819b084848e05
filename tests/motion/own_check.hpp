#pragma once
// The tests' own SRP 3.7.1 check (docs/methods.md s.8), independent of motion::check_acceptance:
// spectra::psa_g at 100 points per decade over 0.1-50 Hz (or Nyquist) against the target.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>

#include "core/measures.hpp"
#include "core/units.hpp"
#include "motion/motion.hpp"
#include "spectra/response.hpp"

namespace freestand::test {

struct OwnCheck {
    double min_ratio = 1e300, max_ratio = 0.0, max_cap_band = 0.0;
    int longest_below = 0;
};

inline OwnCheck own_check(const core::Record& r, const spectra::Spectrum& target) {
    const double top = std::min(50.0, 0.5 / r.dt_s);
    const std::vector<double> f = spectra::log_frequencies(0.1, top, 100);
    const std::vector<double> psa = spectra::psa_g(r, 0.05, f);
    OwnCheck c;
    int run = 0;
    for (std::size_t i = 0; i < f.size(); ++i) {
        const double ratio = psa[i] / target.psa_at(f[i]);
        c.min_ratio = std::min(c.min_ratio, ratio);
        c.max_ratio = std::max(c.max_ratio, ratio);
        if (f[i] >= 0.2 && f[i] <= 25.0) c.max_cap_band = std::max(c.max_cap_band, ratio);
        run = ratio < 1.0 ? run + 1 : 0;
        c.longest_below = std::max(c.longest_below, run);
    }
    return c;
}

/// The realism ranges of the target (docs/methods.md s.8), from the test's own ground-motion
/// measures: PGA / ZPA, D5-75, and on horizontals V/A, AD/V^2 and D/A where set.
inline void require_realism(const core::Record& r, const motion::Target& target) {
    const core::GroundMotion gm = core::measure(r);
    const motion::RealismLimits& lim = target.realism;
    const double zpa_g = target.psa_5pct.psa_g.back();
    CHECK(gm.pga_g / zpa_g >= lim.pga_over_zpa.min);
    CHECK(gm.pga_g / zpa_g <= lim.pga_over_zpa.max);
    CHECK(gm.d5_75_s >= lim.d5_75_min_s);
    if (!target.horizontal) return;
    const double va = gm.pgv_mps / gm.pga_g;
    const double da = gm.pgd_m / gm.pga_g;
    const double adv2 = gm.pga_g * units::g_mps2 * gm.pgd_m / (gm.pgv_mps * gm.pgv_mps);
    if (lim.va_mps_per_g) {
        CHECK(va >= lim.va_mps_per_g->min);
        CHECK(va <= lim.va_mps_per_g->max);
    }
    if (lim.adv2) {
        CHECK(adv2 >= lim.adv2->min);
        CHECK(adv2 <= lim.adv2->max);
    }
    if (lim.da_max_m_per_g) CHECK(da <= *lim.da_max_m_per_g);
}

/// Every SRP 3.7.1 criterion a test can check on one record, with its own spectrum call, and the
/// realism ranges.
inline void require_srp(const core::Record& r, const motion::Target& target) {
    INFO("record " << r.name << " / " << r.source);
    const OwnCheck c = own_check(r, target.psa_5pct);
    CHECK(c.min_ratio >= 0.9);
    CHECK(c.longest_below <= 9);
    CHECK(c.max_cap_band <= 1.3);
    const core::GroundMotion gm = core::measure(r);
    CHECK(std::abs(gm.final_velocity_mps) < 1e-4);
    CHECK(std::abs(gm.final_displacement_m) < 1e-4);
    CHECK(r.dt_s <= 0.01);
    CHECK(r.duration_s() >= 20.0 - 1e-9);
    // Moderate-event durations: a strong part of several seconds, not a spike.
    CHECK(gm.d5_75_s >= 5.0);
    const motion::Acceptance a = motion::check_acceptance(r, target);
    if (target.rg160_psd_pga_g) {
        REQUIRE(a.psd_min_ratio.has_value());
        CHECK(*a.psd_min_ratio >= 0.8);
    }
    CHECK(a.passed);
    require_realism(r, target);
    // The report agrees with the test's own computation.
    CHECK(a.min_ratio == Approx(c.min_ratio).epsilon(1e-12));
    CHECK(a.max_adjacent_below == c.longest_below);
}

}  // namespace freestand::test
