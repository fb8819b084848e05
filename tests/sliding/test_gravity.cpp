// The ASCE 4 estimates under the input's gravity (SlidingInput::g_mps2, a case's site.g_mps2).
#include <catch2/catch.hpp>

#include <cmath>

#include "sliding/asce.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_sliding_test_gravity {

using namespace freestand::sliding;

TEST_CASE("C_s and both displacements use the input's gravity", "[sliding][asce][gravity]") {
    constexpr double standard_g_mps2 = 9.80665;
    SlidingInput in;
    in.mu_s = 0.2;
    in.av_g = 0.1;
    in.pgd_m = 0.05;
    in.g_mps2 = standard_g_mps2;
    const SlidingEstimate est = estimate_sliding(in, 1.5);
    const double mu_e = 0.2 * (1.0 - 0.4 * 0.1);
    const double c_s = 2.0 * mu_e * standard_g_mps2;
    CHECK(est.c_s_mps2 == Approx(c_s).epsilon(1e-14));
    const double w = 2.0 * 3.141592653589793 * 1.5;
    CHECK(*est.slide_asce_m == Approx(c_s / (w * w)).epsilon(1e-14));
    // 0.5 w^2 d^2 + 4 mu_e g d - g DeltaD = 0 (docs/methods.md s.4).
    const double a = 0.5 * w * w, b = 4.0 * mu_e * standard_g_mps2, q = standard_g_mps2 * 0.05;
    CHECK(*est.slide_energy_m ==
          Approx((-b + std::sqrt(b * b + 4.0 * a * q)) / (2.0 * a)).epsilon(1e-12));
}

}  // namespace freestand_test_sliding_test_gravity
