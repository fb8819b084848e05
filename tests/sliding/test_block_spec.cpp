#include <catch2/catch.hpp>

#include "core/errors.hpp"
#include "sliding/asce.hpp"
#include "sliding/block_spec.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_sliding_test_block_spec {

using freestand::InputError;
using freestand::block::Edge;
using namespace freestand::sliding;

TEST_CASE("box spec: uniform box, CG offset and explicit inertia", "[sliding][block_spec]") {
    // Box only: uniform block, I_c = M (b^2 + h^2) / 3 (docs/methods.md s.1).
    const auto u = make_block(box_spec({{"b", 0.15}, {"h", 0.6}, {"m", 38.0}}, {}, std::nullopt));
    CHECK(u.symmetric());
    CHECK(u.inertia_cg_kgm2 == Approx(38.0 * (0.0225 + 0.36) / 3.0));
    // CG 0.05 m towards the right edge and 0.5 m high: b_L = 0.2, b_R = 0.1, h = 0.5.
    const auto g = make_block(box_spec({{"b", 0.15}, {"h", 0.6}, {"m", 38.0}}, {{"x", 0.05}, {"h", 0.5}}, 2.0));
    CHECK(g.b(Edge::left) == Approx(0.2));
    CHECK(g.b(Edge::right) == Approx(0.1));
    CHECK(g.h_m == 0.5);
    CHECK(g.inertia_cg_kgm2 == 2.0);
    CHECK(g.critical_edge() == Edge::right);
    // Inertia only: box geometry, given I_c.
    const auto i = make_block(box_spec({{"b", 0.15}, {"h", 0.6}, {"m", 38.0}}, {}, 5.0));
    CHECK(i.symmetric());
    CHECK(i.inertia_cg_kgm2 == 5.0);
}

TEST_CASE("box spec errors name the field", "[sliding][block_spec]") {
    CHECK_THROWS_WITH(box_spec({{"h", 0.6}}, {}, std::nullopt), Catch::Contains("block b: missing"));
    CHECK_THROWS_WITH(make_block(box_spec({{"b", 0.15}, {"h", 0.6}}, {}, 2.0)),
                      Catch::Contains("m: an explicit inertia needs the mass"));
    CHECK_THROWS_WITH(make_block(box_spec({{"b", 0.15}, {"h", 0.6}, {"m", 1.0}}, {{"x", 0.1}}, std::nullopt)),
                      Catch::Contains("inertia"));
    CHECK_THROWS_WITH(make_block(box_spec({{"b", 0.15}, {"h", 0.6}, {"m", 1.0}}, {{"x", 0.15}}, 1.0)),
                      Catch::Contains("cg x") && Catch::Contains("out of range"));
    CHECK_THROWS_WITH(make_block(box_spec({{"b", 0.15}, {"h", 0.6}, {"m", 1.0}}, {{"h", 0.0}}, 1.0)),
                      Catch::Contains("cg h"));
    CHECK_THROWS_AS(make_block(box_spec({{"b", 0.15}, {"h", 0.0}}, {}, std::nullopt)), InputError);
    CHECK_THROWS_WITH(make_block(box_spec({{"b", 0.15}, {"h", 0.0}}, {}, std::nullopt)),
                      Catch::Contains("h (half-height, m): value 0 must be a finite number > 0"));
}

TEST_CASE("sliding helper error paths", "[sliding][asce]") {
    freestand::spectra::Spectrum bad;
    bad.damping = 0.10;
    bad.frequency_hz = {1.0, 2.0};
    bad.psa_g = {0.5};
    CHECK_THROWS_WITH(lowest_crossing(bad, 0.3), Catch::Contains("2 frequencies and 1 PSA"));
    bad.psa_g = {0.5, 0.6};
    CHECK_THROWS_WITH(lowest_crossing(bad, 0.0), Catch::Contains("level_g"));
    CHECK_THROWS_WITH(asce_displacement_m(-1.0, 1.0), Catch::Contains("c_s_mps2"));
    CHECK_THROWS_WITH(energy_displacement_m(0.1, 1.0, -0.1), Catch::Contains("pgd_m"));
    CHECK_THROWS_WITH(energy_displacement_m(-0.1, 1.0, 0.1), Catch::Contains("mu_e"));
    SlidingInput in;
    in.mu_s = 0.2;
    in.pga_h_g = -0.1;
    CHECK_THROWS_WITH(estimate_sliding(in, 1.0), Catch::Contains("pga_h_g"));
}

}  // namespace freestand_test_sliding_test_block_spec
