#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "block/block.hpp"
#include "core/errors.hpp"
#include "rocking/checks.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_rocking_test_checks {

using freestand::block::Block;
using freestand::block::Edge;
using namespace freestand::rocking;

namespace {
constexpr double g = 9.81;
}

TEST_CASE("Ishiyama bound of the 0.3 x 1.2 m steel block", "[rocking][checks]") {
    // docs/methods.md s.5: R = 0.6185 m, alpha = 0.2450 rad, cos(alpha) = 0.970143:
    // V = 0.4 sqrt(8 * 9.81 * 0.6185 * 0.029857 / (3 * 0.970143)) = 0.4 * 0.70566 = 0.2823 m/s.
    const Block blk = Block::uniform(0.15, 0.6, 38.0);
    const double v = ishiyama_velocity_mps(blk, Edge::left);
    CHECK(v == Approx(0.28).margin(0.005));
    CHECK(v == Approx(0.28227).epsilon(2e-4));
}

TEST_CASE("uplift threshold with the peak vertical taken downward", "[rocking][checks]") {
    // tan(alpha) = 0.25, A_v = 0.5 g -> 0.25 * (1 - 0.5) = 0.125 g (docs/methods.md s.5).
    const Block blk = Block::uniform(0.25, 1.0);
    CHECK(uplift_threshold_g(blk, Edge::right, 0.5) == 0.125);
    CHECK(uplift_threshold_g(blk, Edge::right, 0.0) == 0.25);
    CHECK_THROWS_WITH(uplift_threshold_g(blk, Edge::right, 1.0), Catch::Contains("av_g"));
    const Block asym = Block::general(0.2, 0.4, 1.0, 100.0, 20.0);
    CHECK(uplift_threshold_g(asym, Edge::left, 0.0) == Approx(0.2));
    CHECK(uplift_threshold_g(asym, Edge::right, 0.0) == Approx(0.4));
}

TEST_CASE("Housner energy estimate of the surviving slenderness", "[rocking][checks]") {
    // Uniform block: M R^2 / I_O = 3/4. b = 0.15, h = 0.6, R = 0.61847 m:
    // S_v = 0.5 m/s -> alpha_req = sqrt(0.75) * 0.5 / sqrt(9.81 * 0.61847) = 0.17579 rad < 0.245.
    const Block blk = Block::uniform(0.15, 0.6, 38.0);
    const HousnerEstimate h = housner_energy(blk, Edge::right, 0.5);
    CHECK(h.alpha_required_rad == Approx(0.17579).epsilon(1e-4));
    CHECK(h.survives);
    CHECK(h.e_in_jpkg == Approx(0.5 * 0.75 * 0.25).epsilon(1e-12));
    CHECK(h.e_ot_jpkg == Approx(g * 0.618466 * (1.0 - std::cos(0.2449787))).epsilon(1e-5));
    // S_v = 0.8 m/s -> alpha_req = 0.28127 > alpha: does not survive.
    const HousnerEstimate h2 = housner_energy(blk, Edge::right, 0.8);
    CHECK(h2.alpha_required_rad == Approx(0.28127).epsilon(1e-4));
    CHECK_FALSE(h2.survives);
    // The two energies balance where alpha_req = alpha, to the small-angle approximation.
    const double sv = h.alpha_rad / h.alpha_required_rad * 0.5;
    const HousnerEstimate eq = housner_energy(blk, Edge::right, sv);
    CHECK(eq.e_in_jpkg == Approx(eq.e_ot_jpkg).epsilon(0.01));
    CHECK_THROWS_WITH(housner_energy(blk, Edge::right, -1.0), Catch::Contains("sv_mps"));
}

TEST_CASE("peak pseudo-velocity of a spectrum", "[rocking][checks]") {
    freestand::spectra::Spectrum s;
    s.frequency_hz = {0.5, 2.0, 10.0};
    s.psa_g = {0.2, 1.0, 0.5};
    // PSV = PSA g / (2 pi f): 0.6245, 0.7807, 0.0781 m/s.
    CHECK(peak_pseudo_velocity_mps(s) == Approx(1.0 * g / (2.0 * std::numbers::pi * 2.0)));
}

TEST_CASE("acceleration amplification warnings by mode", "[rocking][checks]") {
    using freestand::sliding::Mode;
    CHECK(amplification_warning(Mode::rest, 0.3, 0.1).empty());
    CHECK(amplification_warning(Mode::rock, 0.5, 0.3).find("1.3 to 11") != std::string::npos);
    CHECK(amplification_warning(Mode::slide_rock, 0.3, 1.0).find("1.3 to 11") != std::string::npos);
    CHECK(amplification_warning(Mode::slide, 0.15, 0.3).find("mu / A = 0.5") != std::string::npos);
}

}  // namespace freestand_test_rocking_test_checks
