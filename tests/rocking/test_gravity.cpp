// The closed-form rocking checks under the caller's gravity (a case's site.g_mps2).
#include <catch2/catch.hpp>

#include <cmath>

#include "block/block.hpp"
#include "rocking/checks.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_rocking_test_gravity {

using freestand::block::Block;
using freestand::block::Edge;
using namespace freestand::rocking;

TEST_CASE("p, the Ishiyama bound, the overturning energy and Housner's estimate take g",
          "[rocking][checks][gravity]") {
    constexpr double standard_g_mps2 = 9.80665;
    // The 0.3 x 1.2 m steel block: b = 0.15 m, h = 0.6 m, uniform, M = 38 kg.
    const Block blk = Block::uniform(0.15, 0.6, 38.0);
    const double R = std::sqrt(0.15 * 0.15 + 0.6 * 0.6);
    const double c = 0.6 / R;  // cos(alpha)
    const double i_o = 38.0 * (0.3 * 0.3 + 1.2 * 1.2) / 12.0 + 38.0 * R * R;
    CHECK(blk.p_radps(Edge::left, standard_g_mps2) ==
          Approx(std::sqrt(38.0 * standard_g_mps2 * R / i_o)).epsilon(1e-13));
    CHECK(ishiyama_velocity_mps(blk, Edge::left, standard_g_mps2) ==
          Approx(0.4 * std::sqrt(8.0 * standard_g_mps2 * R * (1.0 - c) / (3.0 * c)))
              .epsilon(1e-13));
    CHECK(overturning_energy_jpkg(blk, Edge::left, standard_g_mps2) ==
          Approx(standard_g_mps2 * R * (1.0 - c)).epsilon(1e-13));
    const HousnerEstimate h = housner_energy(blk, Edge::left, 0.3, standard_g_mps2);
    CHECK(h.e_ot_jpkg == Approx(standard_g_mps2 * R * (1.0 - c)).epsilon(1e-13));
    CHECK(h.alpha_required_rad ==
          Approx(std::sqrt(38.0 * R * R / i_o) * 0.3 / std::sqrt(standard_g_mps2 * R))
              .epsilon(1e-13));
    // PSV = PSA g / (2 pi f): 0.5 g at 1 Hz.
    freestand::spectra::Spectrum s;
    s.damping = 0.05;
    s.frequency_hz = {1.0, 2.0};
    s.psa_g = {0.5, 0.5};
    CHECK(peak_pseudo_velocity_mps(s, standard_g_mps2) ==
          Approx(0.5 * standard_g_mps2 / (2.0 * 3.141592653589793)).epsilon(1e-14));
}

}  // namespace freestand_test_rocking_test_gravity
