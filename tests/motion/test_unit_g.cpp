// Targets carry their unit g (a case's site.g_mps2): the acceptance of a record reads its PGA
// and spectrum in it.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "motion/motion.hpp"
#include "spectra/design.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_motion_test_unit_g {

using namespace freestand;

TEST_CASE("RG 1.60 targets in the caller's unit g, and the acceptance reads a record in it",
          "[motion][gravity]") {
    constexpr double standard_g_mps2 = 9.80665;
    const motion::TargetSet t = motion::rg160_targets(0.3, 1.0, standard_g_mps2);
    CHECK(t.horizontal.g_mps2 == standard_g_mps2);
    CHECK(t.vertical.g_mps2 == standard_g_mps2);
    const std::vector<double> f = t.horizontal.psa_5pct.frequency_hz;
    CHECK(t.horizontal.psa_5pct.psa_g == spectra::rg160(0.3, 0.05, false, f, standard_g_mps2).psa_g);
    // A 20 s, 2 Hz sine of 1 m/s^2: its PGA in the target's unit g.
    core::Record r;
    r.dt_s = 0.01;
    for (int i = 0; i < 2000; ++i)
        r.accel_mps2.push_back(
            std::sin(2.0 * 3.141592653589793 * 2.0 * 0.01 * static_cast<double>(i)));
    double peak = 0.0;
    for (double v : r.accel_mps2) peak = std::max(peak, std::abs(v));
    const motion::Acceptance a = motion::check_acceptance(r, t.horizontal);
    CHECK(a.pga_g == peak / standard_g_mps2);
    motion::Target thesis = t.horizontal;
    thesis.g_mps2 = 9.81;
    CHECK(motion::check_acceptance(r, thesis).pga_g == peak / 9.81);
}

}  // namespace freestand_test_motion_test_unit_g
