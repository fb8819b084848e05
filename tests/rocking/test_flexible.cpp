#include <catch2/catch.hpp>
#include <cmath>

#include "core/errors.hpp"
#include "rocking/flexible.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_rocking_test_flexible {

using freestand::spectra::Spectrum;
using namespace freestand::rocking;

namespace {
// 0.1 g everywhere except a 0.3 g peak at 5 Hz (a 5%-damped spectrum with one resonance).
Spectrum peaked() {
    Spectrum s;
    s.damping = 0.05;
    s.label = "peak at 5 Hz";
    s.frequency_hz = {1.0, 4.0, 5.0, 6.0, 30.0};
    s.psa_g = {0.1, 0.1, 0.3, 0.1, 0.1};
    return s;
}

FlexibleInput fixed_base(double f_hz, double threshold_g, double pga_g) {
    FlexibleInput in;
    in.fixed_base_hz = f_hz;
    in.uplift_threshold_g = threshold_g;
    in.pga_h_g = pga_g;
    return in;
}
}  // namespace

TEST_CASE("strong content in the fixed-base band flags frequency-induced rocking",
          "[rocking][flexible]") {
    // Slender specimen of docs/methods.md s.2: static 0.25 g, PGA 0.1 g, body at 5 Hz.
    const FlexibleScreen s = flexible_screen(peaked(), fixed_base(5.0, 0.25, 0.1));
    CHECK(s.applies);
    CHECK(s.band_lo_hz == Approx(5.0 / 1.15));
    CHECK(s.band_hi_hz == Approx(5.0 * 1.15));
    CHECK(s.peak_psa_g == 0.3);
    CHECK(s.peak_f_hz == 5.0);
    CHECK(s.flagged);
    CHECK(s.reason.find("possible frequency-induced rocking") != std::string::npos);
}

TEST_CASE("the strong-content threshold on both sides", "[rocking][flexible]") {
    CHECK(flexible_screen(peaked(), fixed_base(5.0, 0.3, 0.1)).flagged);  // equal: strong
    const FlexibleScreen weak =
        flexible_screen(peaked(), fixed_base(5.0, std::nextafter(0.3, 1.0), 0.1));
    CHECK_FALSE(weak.flagged);
    CHECK(weak.reason.find("no strong content") != std::string::npos);
    // Away from the peak the band sees 0.1 g only.
    CHECK_FALSE(flexible_screen(peaked(), fixed_base(20.0, 0.25, 0.1)).flagged);
    // PGA already at the static threshold: the rigid classification does not lower the flag
    // (docs/methods.md s.6 step 1), the reason says the PGA reaches the threshold too.
    const FlexibleScreen above = flexible_screen(peaked(), fixed_base(5.0, 0.25, 0.25));
    CHECK(above.flagged);
    CHECK(above.reason.find("reaches it too") != std::string::npos);
}

TEST_CASE("the band's maximum between points uses log-log interpolation", "[rocking][flexible]") {
    // Band [4.2, 4.8] Hz lies between 4 and 5 Hz: the maximum is at its upper end.
    FlexibleInput in;
    in.rock_band_lo_hz = 4.2;
    in.rock_band_hi_hz = 4.8;
    in.uplift_threshold_g = 0.25;
    const FlexibleScreen s = flexible_screen(peaked(), in);
    CHECK(s.peak_f_hz == 4.8);
    CHECK(s.peak_psa_g == Approx(peaked().psa_at(4.8)).epsilon(1e-15));
    CHECK(s.peak_psa_g == Approx(0.1 * std::pow(3.0, std::log(1.2) / std::log(1.25))).epsilon(1e-13));
}

TEST_CASE("rigid bodies and band input errors", "[rocking][flexible]") {
    const FlexibleScreen r = flexible_screen(peaked(), fixed_base(40.0, 0.25, 0.1));
    CHECK_FALSE(r.applies);
    CHECK(r.reason.find("rigid") != std::string::npos);
    // Fixed-base band and free-rocking band together: their union.
    FlexibleInput both = fixed_base(5.0, 0.25, 0.1);
    both.rock_band_lo_hz = 1.0;
    both.rock_band_hi_hz = 2.0;
    CHECK(flexible_screen(peaked(), both).band_lo_hz == 1.0);
    CHECK(flexible_screen(peaked(), both).band_hi_hz == Approx(5.75));
    // Disjoint bands are screened as a union, not the span between them: a peak in the gap
    // (here 0.3 g at 5 Hz, between a 1-2 Hz rocking band and a 6.9-9.2 Hz fixed-base band) is
    // not seen; the 0.1 g in the bands is below the 0.25 g threshold.
    FlexibleInput gap = fixed_base(8.0, 0.25, 0.1);
    gap.rock_band_lo_hz = 1.0;
    gap.rock_band_hi_hz = 2.0;
    const FlexibleScreen g = flexible_screen(peaked(), gap);
    CHECK(g.applies);
    CHECK(g.band_lo_hz == 1.0);
    CHECK(g.band_hi_hz == Approx(9.2));
    CHECK(g.peak_psa_g == Approx(0.1).epsilon(1e-12));
    CHECK_FALSE(g.flagged);
    CHECK(g.reason.find("1-2 Hz and 6.957-9.2 Hz") != std::string::npos);
    using freestand::InputError;
    FlexibleInput none;
    none.uplift_threshold_g = 0.25;
    CHECK_THROWS_AS(flexible_screen(peaked(), none), InputError);
    CHECK_THROWS_WITH(flexible_screen(peaked(), none),
                      Catch::Contains("flexible: expected a fixed-base frequency or a free-rocking "
                                      "band"));
    FlexibleInput half = none;
    half.rock_band_lo_hz = 1.0;
    CHECK_THROWS_WITH(flexible_screen(peaked(), half), Catch::Contains("both ends"));
    half.rock_band_hi_hz = 1.0;
    CHECK_THROWS_WITH(flexible_screen(peaked(), half), Catch::Contains("lo < hi"));
    CHECK_THROWS_WITH(flexible_screen(peaked(), fixed_base(-1.0, 0.25, 0.1)),
                      Catch::Contains("fixed-base frequency"));
}

}  // namespace freestand_test_rocking_test_flexible
