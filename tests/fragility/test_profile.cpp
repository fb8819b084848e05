// P at one PGA with its profile-likelihood interval (fragility/fit.hpp probability_at): the fit's
// own P, the likelihood-ratio equation at the interval's ends, the limits where the fit has no
// curve, and the interval's coverage on counts drawn from a known lognormal.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "core/statistics.hpp"
#include "fragility/fit.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_fragility_test_profile {

using namespace freestand;
using fragility::probability_at;

namespace {

// chi2_1(0.95) / 2: the drop in ln L that bounds a 95% likelihood-ratio interval.
constexpr double kHalfChi2 = 3.841458820694124 / 2.0;

double binomial_ll(int k, int n, double p) { return k * std::log(p) + (n - k) * std::log(1.0 - p); }

}  // namespace

TEST_CASE("P at a PGA is the fitted curve's, with the estimate inside its interval",
          "[fragility][profile]") {
    // Two levels: the MLE passes through both proportions (test_fit.cpp), so P(0.2) = 0.1.
    const std::vector<double> a{0.2, 0.8};
    const std::vector<int> k{10, 90}, n{100, 100};
    const auto at = probability_at(a, k, n, 0.2);
    CHECK(at.p == Approx(0.1).epsilon(1e-6));
    CHECK(at.ci95[0] < at.p);
    CHECK(at.p < at.ci95[1]);
    // Between the levels, the curve's own value.
    const auto fit = fragility::fit_lognormal(a, k, n);
    REQUIRE(fit.fit);
    const double mid = probability_at(a, k, n, 0.5).p;
    CHECK(
        mid ==
        Approx(core::normal_cdf(std::log(0.5 / fit.fit->theta_m_g) / fit.fit->beta)).epsilon(1e-6));
}

TEST_CASE("one level: the interval is the binomial likelihood-ratio interval",
          "[fragility][profile]") {
    // With one level the slope cannot matter: ln L is the binomial's, and each end of the
    // interval lies 1.92 below its maximum at k / n.
    const auto at = probability_at({0.3}, {3}, {30}, 0.3);
    CHECK(at.p == Approx(0.1).epsilon(1e-9));
    const double top = binomial_ll(3, 30, 0.1);
    CHECK(top - binomial_ll(3, 30, at.ci95[0]) == Approx(kHalfChi2).epsilon(1e-6));
    CHECK(top - binomial_ll(3, 30, at.ci95[1]) == Approx(kHalfChi2).epsilon(1e-6));
    // No failure: p is 0 and the upper end solves n ln(1 - p) = -1.92.
    const auto none = probability_at({0.3}, {0}, {30}, 0.3);
    CHECK(none.p == 0.0);
    CHECK(none.ci95[0] == 0.0);
    CHECK(none.ci95[1] == Approx(1.0 - std::exp(-kHalfChi2 / 30.0)).epsilon(1e-6));
}

TEST_CASE("where the fit has no curve, P is the likelihood's limit", "[fragility][profile]") {
    const std::vector<double> a{0.1, 0.2, 0.3, 0.4};
    const std::vector<int> n{30, 30, 30, 30};
    // No failure anywhere: P = 0 at every PGA, and a finite upper bound below the one-level
    // bound (four levels' samples all speak for a PGA at or above them).
    const auto none = probability_at(a, {0, 0, 0, 0}, n, 0.4);
    CHECK(none.p == 0.0);
    CHECK(none.ci95[1] > 0.0);
    CHECK(none.ci95[1] < 1.0 - std::exp(-kHalfChi2 / 30.0));
    // Separated (none up to 0.2 g, every sample from 0.3 g): a step between 0.2 and 0.3 g.
    const std::vector<int> step{0, 0, 30, 30};
    CHECK(probability_at(a, step, n, 0.2).p == 0.0);
    CHECK(probability_at(a, step, n, 0.3).p == 1.0);
    // Every sample failing: P = 1.
    CHECK(probability_at(a, {30, 30, 30, 30}, n, 0.1).p == 1.0);
}

TEST_CASE("the 95% interval covers the true P about 95% of the time", "[fragility][profile]") {
    // Counts from P(a) = Phi(ln(a / 0.5) / 0.3) at 8 levels of 30 samples (the goal's design:
    // 0.5 to 3 x a DBE of 0.2 g); the interval at the DBE and at 1.5 x DBE against the truth.
    const double theta = 0.5, beta = 0.3, dbe = 0.2;
    const std::vector<double> a{0.1, 0.15, 0.2, 0.25, 0.3, 0.4, 0.5, 0.6};
    std::mt19937_64 rng(4305);
    int covered = 0, total = 0;
    for (int rep = 0; rep < 200; ++rep) {
        std::vector<int> k, n(a.size(), 30);
        for (double x : a) {
            const double p = core::normal_cdf(std::log(x / theta) / beta);
            k.push_back(std::binomial_distribution<int>(30, p)(rng));
        }
        for (double at : {dbe, 1.5 * dbe}) {
            const double truth = core::normal_cdf(std::log(at / theta) / beta);
            const auto est = probability_at(a, k, n, at);
            covered += est.ci95[0] <= truth && truth <= est.ci95[1] ? 1 : 0;
            ++total;
        }
    }
    // 400 intervals: a true 95% coverage gives 380 +- 4.4 (binomial sd); 0.90 is 4.5 sd below.
    INFO(covered << " of " << total);
    CHECK(covered >= 0.90 * total);
}

TEST_CASE("probability_at refuses bad arguments", "[fragility][profile][errors]") {
    CHECK_THROWS_AS(probability_at({0.1, 0.2}, {0}, {10, 10}, 0.1), std::invalid_argument);
    CHECK_THROWS_AS(probability_at({0.1}, {0}, {10}, 0.0), std::invalid_argument);
    CHECK_THROWS_AS(probability_at({0.1}, {0}, {0}, 0.1), std::invalid_argument);
}

}  // namespace freestand_test_fragility_test_profile
