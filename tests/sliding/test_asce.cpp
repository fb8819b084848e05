#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "core/errors.hpp"
#include "core/units.hpp"
#include "sliding/asce.hpp"
#include "sliding/spectrum_input.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_sliding_test_asce {

using namespace freestand::sliding;
using freestand::spectra::Spectrum;

namespace {
constexpr double g = 9.81;
constexpr double pi = std::numbers::pi;

// PSA = 0.1 f (g, f in Hz): a power law, so log-log interpolation is exact between points and
// the crossing of level L is f = 10 L exactly.
Spectrum power_law(double damping = 0.10) {
    Spectrum s;
    s.damping = damping;
    s.frequency_hz = {0.25, 1.0, 4.0, 16.0};
    s.psa_g = {0.025, 0.1, 0.4, 1.6};
    s.label = "PSA = 0.1 f";
    return s;
}

Spectrum flat(double psa_g, double damping = 0.10) {
    Spectrum s;
    s.damping = damping;
    s.frequency_hz = {0.5, 5.0, 50.0};
    s.psa_g = {psa_g, psa_g, psa_g};
    s.label = "flat";
    return s;
}
}  // namespace

TEST_CASE("glove box example of docs/methods.md s.4", "[sliding][asce]") {
    // docs/methods.md s.4: mu = 0.15, A_v = 2.2 m/s^2 -> mu_e = 0.15 (1 - 0.4 * 2.2 / 9.81) = 0.1365,
    // C_s = 2 mu_e g = 2.679 m/s^2; f_es = 1.2 Hz; delta_s = 2.679 / (2 pi 1.2)^2 = 0.0471 m;
    // energy: 28.42 d^2 + 5.358 d - 0.3924 = 0 -> d = 0.056 m (DeltaD = 0.040 m).
    SlidingInput in;
    in.mu_s = 0.15;
    in.av_g = 2.2 / g;
    in.pgd_m = 0.040;
    const SlidingEstimate e = estimate_sliding(in, 1.2);
    CHECK(e.mu_e == Approx(0.1365).margin(5e-5));
    CHECK(e.c_s_mps2 == Approx(2.679).margin(5e-4));
    REQUIRE(e.slide_asce_m);
    CHECK(*e.slide_asce_m == Approx(0.047).margin(5e-4));
    CHECK(*e.slide_asce_m == Approx(e.c_s_mps2 / std::pow(2.0 * pi * 1.2, 2)).epsilon(1e-14));
    REQUIRE(e.slide_energy_m);
    CHECK(*e.slide_energy_m == Approx(0.056).margin(5e-4));
    // The quadratic with docs/methods.md s.4's rounded coefficients: root 0.05636.
    const double d = (-5.358 + std::sqrt(5.358 * 5.358 + 4.0 * 28.42 * 0.3924)) / (2.0 * 28.42);
    CHECK(*e.slide_energy_m == Approx(d).epsilon(1e-3));
    CHECK(e.f_es_source == "given");
    CHECK(e.slides);
}

TEST_CASE("energy root satisfies its quadratic", "[sliding][asce]") {
    const double mu_e = 0.2, f = 0.7, pgd = 0.15;
    const double d = energy_displacement_m(mu_e, f, pgd);
    const double w = 2.0 * pi * f;
    CHECK(4.0 * mu_e * g * d + 0.5 * w * w * d * d == Approx(g * pgd).epsilon(1e-14));
    CHECK(energy_displacement_m(mu_e, f, 0.0) == 0.0);
}

TEST_CASE("f_es on a power-law spectrum is exact", "[sliding][asce]") {
    // C_s = 2 * 0.15 g = 0.3 g -> crossing of PSA = 0.1 f at f = 3 Hz (between 1 and 4 Hz).
    SlidingInput in;
    in.mu_s = 0.15;
    const SlidingEstimate e = estimate_sliding(in, power_law());
    REQUIRE(e.f_es_hz);
    CHECK(*e.f_es_hz == Approx(3.0).epsilon(1e-13));
    CHECK(*e.slide_asce_m == Approx(0.3 * g / std::pow(6.0 * pi, 2)).epsilon(1e-12));
    CHECK(e.f_es_source.find("log-log") != std::string::npos);
    CHECK_FALSE(e.slide_energy_m);
    CHECK(e.slide_energy_reason.find("pgd_m") != std::string::npos);
}

TEST_CASE("f_es exactly at a spectrum point", "[sliding][asce]") {
    const Crossing c = lowest_crossing(power_law(), 0.4);
    REQUIRE(c.f_hz);
    CHECK(*c.f_hz == 4.0);
    CHECK(c.note == "at a spectrum point");
}

TEST_CASE("f_es is the lowest crossing of a non-monotone spectrum", "[sliding][asce]") {
    Spectrum s = power_law();
    s.frequency_hz = {0.5, 2.0, 8.0, 32.0};
    s.psa_g = {0.1, 0.8, 0.2, 0.9};  // crosses 0.4 g going up, down, and up again
    const Crossing c = lowest_crossing(s, 0.4);
    REQUIRE(c.f_hz);
    // log-log between (0.5, 0.1) and (2, 0.8): f = 0.5 * 4^(ln 4 / ln 8) = 0.5 * 4^(2/3).
    CHECK(*c.f_hz == Approx(0.5 * std::pow(4.0, 2.0 / 3.0)).epsilon(1e-13));
    CHECK(s.psa_at(*c.f_hz) == Approx(0.4).epsilon(1e-13));
}

TEST_CASE("f_es below the first point follows constant spectral displacement",
          "[sliding][asce]") {
    // psa_at below 0.25 Hz: 0.025 (f / 0.25)^2; level 0.01 -> f = 0.25 sqrt(0.4).
    const Crossing c = lowest_crossing(power_law(), 0.01);
    REQUIRE(c.f_hz);
    CHECK(*c.f_hz == Approx(0.25 * std::sqrt(0.4)).epsilon(1e-14));
    CHECK(power_law().psa_at(*c.f_hz) == Approx(0.01).epsilon(1e-13));
    CHECK(c.note.find("extrapolated") != std::string::npos);
}

TEST_CASE("a spectrum that never reaches C_s: does not slide, both estimates null with reasons",
          "[sliding][asce]") {
    SlidingInput in;
    in.mu_s = 0.2;  // C_s = 0.4 g
    in.pgd_m = 0.05;
    const SlidingEstimate e = estimate_sliding(in, flat(0.39));
    CHECK_FALSE(e.slides);
    CHECK_FALSE(e.f_es_hz);
    CHECK_FALSE(e.slide_asce_m);
    CHECK_FALSE(e.slide_energy_m);
    CHECK(e.f_es_reason.find("never reaches C_s") != std::string::npos);
    CHECK(e.slide_asce_reason.find("does not slide") != std::string::npos);
    CHECK(e.slide_energy_reason.find("not applied below the sliding threshold") !=
          std::string::npos);
    // Just reaching it: C_s = 0.4 g at a flat 0.4 g slides at the first point.
    const SlidingEstimate at = estimate_sliding(in, flat(0.4));
    REQUIRE(at.f_es_hz);
    CHECK(*at.f_es_hz == 0.5);
}

TEST_CASE("energy method is not applied when the PGA is below mu_e", "[sliding][asce]") {
    SlidingInput in;
    in.mu_s = 0.15;
    in.pgd_m = 0.04;
    in.pga_h_g = 0.15;
    const SlidingEstimate e = estimate_sliding(in, 1.2);
    CHECK(e.slide_asce_m);
    CHECK_FALSE(e.slide_energy_m);
    CHECK(e.slide_energy_reason.find("PGA 0.15 g <= mu_e") != std::string::npos);
    in.pga_h_g = std::nextafter(0.15, 1.0);
    CHECK(estimate_sliding(in, 1.2).slide_energy_m);
}

TEST_CASE("mu = 0: frictionless, the methods degenerate and say so", "[sliding][asce]") {
    SlidingInput in;
    in.mu_s = 0.0;
    in.pgd_m = 0.04;
    for (const SlidingEstimate& e : {estimate_sliding(in, 1.2), estimate_sliding(in, power_law())}) {
        CHECK(e.mu_e == 0.0);
        CHECK(e.c_s_mps2 == 0.0);
        CHECK_FALSE(e.slide_asce_m);
        CHECK_FALSE(e.slide_energy_m);
        CHECK(e.slide_asce_reason.find("frictionless") != std::string::npos);
        CHECK(e.slide_asce_reason.find("0.04 m") != std::string::npos);
    }
}

TEST_CASE("sliding input errors name the field", "[sliding][asce]") {
    using freestand::InputError;
    SlidingInput in;
    in.mu_s = -0.1;
    CHECK_THROWS_AS(estimate_sliding(in, 1.0), InputError);
    CHECK_THROWS_WITH(estimate_sliding(in, 1.0), Catch::Contains("mu_s"));
    in.mu_s = 0.2;
    CHECK_THROWS_WITH(estimate_sliding(in, 0.0), Catch::Contains("f_es_hz"));
    CHECK_THROWS_WITH(estimate_sliding(in, power_law(0.05)),
                      Catch::Contains("damping") && Catch::Contains("0.05"));
    in.av_g = 2.5;
    CHECK_THROWS_WITH(estimate_sliding(in, 1.0), Catch::Contains("av_g"));
    in.av_g = 0.0;
    in.pgd_m = -0.01;
    CHECK_THROWS_WITH(estimate_sliding(in, 1.0), Catch::Contains("pgd_m"));
}

TEST_CASE("SA_VH of two components and damping checks", "[sliding][asce]") {
    // H1 = 1 g, H2 = 0.5 g flat: SA_VH = sqrt(1 + 0.16 * 0.25) = sqrt(1.04) g (docs/methods.md s.4).
    const Spectrum v = vector_horizontal({flat(0.5), flat(1.0)}, 0.10);
    CHECK(v.psa_at(5.0) == Approx(std::sqrt(1.04)).epsilon(1e-14));
    CHECK(vector_horizontal({flat(0.7)}, 0.10).psa_at(5.0) == 0.7);
    CHECK_THROWS_WITH(vector_horizontal({flat(0.5), flat(1.0, 0.05)}, 0.10),
                      Catch::Contains("damping") && Catch::Contains("expected 0.1"));
    CHECK_THROWS_WITH(vector_horizontal({}, 0.10), Catch::Contains("expected 1 or 2"));
}

}  // namespace freestand_test_sliding_test_asce
