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
                      Catch::Contains("box.mass_kg: an explicit inertia needs the mass"));
    CHECK_THROWS_WITH(make_block(box_spec({{"b", 0.15}, {"h", 0.6}, {"m", 1.0}}, {{"x", 0.1}}, std::nullopt)),
                      Catch::StartsWith("box.inertia_cg_kgm2: a CG position"));
    CHECK_THROWS_WITH(make_block(box_spec({{"b", 0.15}, {"h", 0.6}, {"m", 1.0}}, {{"x", 0.15}}, 1.0)),
                      Catch::StartsWith("box.cg_offset_m: value 0.15 is out of range"));
    CHECK_THROWS_WITH(make_block(box_spec({{"b", 0.15}, {"h", 0.6}, {"m", 1.0}}, {{"h", 0.0}}, 1.0)),
                      Catch::StartsWith("box.cg_height_m: value 0 must be"));
    CHECK_THROWS_AS(make_block(box_spec({{"b", 0.15}, {"h", 0.0}}, {}, std::nullopt)), InputError);
    CHECK_THROWS_WITH(make_block(box_spec({{"b", 0.15}, {"h", 0.0}}, {}, std::nullopt)),
                      Catch::Equals("box.half_height_m: value 0 must be a finite number > 0"));
}

TEST_CASE("the block's own limits are named as the box field the caller gave", "[sliding][block_spec]") {
    // block::Block names its quantities (b, h as the CG height, m, I_c); a box's caller gave a
    // half-height, or a CG offset for the distances to the edges.
    const auto spec = [](double b, double h, std::optional<double> m, std::optional<double> x,
                         std::optional<double> inertia) {
        BoxSpec s;
        s.half_width_m = b;
        s.half_height_m = h;
        s.mass_kg = m;
        s.cg_offset_m = x;
        s.inertia_cg_kgm2 = inertia;
        return s;
    };
    CHECK_THROWS_WITH(make_block(spec(200.0, 0.6, 38.0, std::nullopt, std::nullopt)),
                      Catch::StartsWith("box.half_width_m: length (m): 200 is above the limit"));
    CHECK_THROWS_WITH(make_block(spec(0.2, 200.0, 38.0, std::nullopt, std::nullopt)),
                      Catch::StartsWith("box.half_height_m: length (m): 200 is above the limit"));
    CHECK_THROWS_WITH(make_block(spec(0.2, 0.6, 1e-6, std::nullopt, std::nullopt)),
                      Catch::StartsWith("box.mass_kg: mass (kg): 1e-06 is below the limit"));
    CHECK_THROWS_WITH(make_block(spec(0.2, 0.6, 38.0, 0.0, -1.0)),
                      Catch::StartsWith("box.inertia_cg_kgm2: value -1 must be"));
    CHECK_THROWS_WITH(make_block(spec(0.2, 0.6, 0.0, 0.0, 1.0)),
                      Catch::StartsWith("box.mass_kg: value 0 must be"));
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
