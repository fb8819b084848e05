// The lognormal fit (fragility/fit.hpp): it recovers a known curve from binomial counts drawn from
// it, and says why when there is no curve to fit.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "core/statistics.hpp"
#include "fragility/fit.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_fragility_test_fit {

using namespace freestand;
using fragility::fit_lognormal;

TEST_CASE("the fit recovers theta_m and beta from counts drawn from a known lognormal",
          "[fragility][fit]") {
    // P(a) = Phi(ln(a / 0.5) / 0.4); 2000 samples per level at 0.1-1.0 g; fixed seed.
    const double theta = 0.5, beta = 0.4;
    std::mt19937_64 rng(2015);
    std::vector<double> a;
    std::vector<int> k, n;
    for (int j = 1; j <= 10; ++j) {
        a.push_back(0.1 * j);
        const double p = core::normal_cdf(std::log(a.back() / theta) / beta);
        k.push_back(static_cast<int>(std::binomial_distribution<int>(2000, p)(rng)));
        n.push_back(2000);
    }
    const fragility::EventFit f = fit_lognormal(a, k, n);
    REQUIRE(f.fit.has_value());
    INFO("theta " << f.fit->theta_m_g << ", beta " << f.fit->beta);
    CHECK(f.fit->theta_m_g == Approx(theta).epsilon(0.02));
    CHECK(f.fit->beta == Approx(beta).epsilon(0.05));
    CHECK(f.fit->pga_50pct_g == f.fit->theta_m_g);
    CHECK(f.fit->pga_5pct_g == Approx(f.fit->theta_m_g * std::exp(-1.6448536 * f.fit->beta)).epsilon(1e-6));
    CHECK(f.fit->pga_1pct_g < f.fit->pga_5pct_g);
    // Counts drawn from the model itself: Pearson's chi2 should not reject it.
    CHECK(f.fit->dof == 8);
    REQUIRE(f.fit->p_value.has_value());
    CHECK(*f.fit->p_value > 0.01);
}

TEST_CASE("the fit is the maximum of the likelihood (exact counts at two levels)",
          "[fragility][fit]") {
    // With two levels the MLE passes through both observed proportions exactly.
    const std::vector<double> a{0.2, 0.8};
    const std::vector<int> k{10, 90}, n{100, 100};
    const auto f = fit_lognormal(a, k, n);
    REQUIRE(f.fit.has_value());
    CHECK(core::normal_cdf(std::log(0.2 / f.fit->theta_m_g) / f.fit->beta) == Approx(0.1).epsilon(1e-6));
    CHECK(core::normal_cdf(std::log(0.8 / f.fit->theta_m_g) / f.fit->beta) == Approx(0.9).epsilon(1e-6));
    CHECK(f.fit->theta_m_g == Approx(0.4).epsilon(1e-6));  // geometric mean of 0.2 and 0.8
}

TEST_CASE("no fit without a curve to fit, and the note says why", "[fragility][fit]") {
    const std::vector<double> a{0.1, 0.2, 0.3};
    CHECK(fit_lognormal(a, {0, 0, 0}, {10, 10, 10}).note == "no level has a failure");
    CHECK_FALSE(fit_lognormal(a, {0, 0, 0}, {10, 10, 10}).fit.has_value());
    CHECK_THAT(fit_lognormal(a, {10, 10, 10}, {10, 10, 10}).note,
               Catch::Contains("every sample fails"));
    const auto separated = fit_lognormal(a, {0, 10, 10}, {10, 10, 10});
    CHECK_FALSE(separated.fit.has_value());
    CHECK_THAT(separated.note,
               Catch::Contains("separate failures perfectly: every sample fails above the lowest "
                               "level, 0.1 g (0 of 10 there)"));
    CHECK_THAT(fit_lognormal(a, {0, 0, 3}, {10, 10, 10}).note,
               Catch::Contains("failures only at the highest level, 0.3 g (3 of 10 there)"));
    // One level between 0 and n with none below and all above is still separated: a step there
    // reproduces its fraction exactly, so the likelihood has no finite maximum (block-ts3 gave
    // 0/40, 0/40, 21/40, 40/40, 40/40).
    const auto quasi = fit_lognormal({0.2, 0.4, 0.6, 0.8, 1.0}, {0, 0, 21, 40, 40},
                                     {40, 40, 40, 40, 40});
    CHECK_FALSE(quasi.fit.has_value());
    CHECK_THAT(quasi.note, Catch::Contains("none below 0.6 g, only failures above it"));
    CHECK_THAT(quasi.note, Catch::Contains("a step at about 0.6 g"));
    CHECK_THAT(quasi.note, Catch::Contains("(21 of 40 there)"));
    CHECK_THAT(fit_lognormal(a, {8, 4, 1}, {10, 10, 10}).note,
               Catch::Contains("do not increase"));
    CHECK_THAT(fit_lognormal({0.3}, {4}, {10}).note, Catch::Contains("at least two levels"));
}

TEST_CASE("the fitted curve passes 0.5 at theta_m and Phi(1) one beta above it",
          "[fragility][fit]") {
    // Phi(1) = 0.8413447460685429 (Abramowitz & Stegun 26.2, Table 26.1).
    constexpr double kPhi1 = 0.8413447460685429, kTol = 1e-12;
    fragility::Fit f;
    f.theta_m_g = 0.5;
    f.beta = 0.4;
    CHECK(fragility::fitted_p(f, 0.5) == Approx(0.5).margin(kTol));
    CHECK(fragility::fitted_p(f, 0.5 * std::exp(0.4)) == Approx(kPhi1).margin(kTol));
    CHECK(fragility::fitted_p(f, 0.5 * std::exp(-0.4)) == Approx(1.0 - kPhi1).margin(kTol));
}

TEST_CASE("the fitted curve's points span the range evenly in ln a and rise with a",
          "[fragility][fit]") {
    fragility::Fit f;
    f.theta_m_g = 0.6;
    f.beta = 0.3;
    const auto curve = fragility::fitted_curve(f, 0.1, 2.0, 4);
    REQUIRE(curve.size() == 5);
    CHECK(curve.front().pga_g == Approx(0.1).epsilon(1e-14));
    CHECK(curve.back().pga_g == Approx(2.0).epsilon(1e-14));
    // The middle point is the geometric mean of the ends.
    CHECK(curve[2].pga_g == Approx(std::sqrt(0.1 * 2.0)).epsilon(1e-14));
    for (std::size_t i = 1; i < curve.size(); ++i) {
        CHECK(curve[i].p > curve[i - 1].p);
        CHECK(curve[i].p == fragility::fitted_p(f, curve[i].pga_g));
    }
}

}  // namespace freestand_test_fragility_test_fit
