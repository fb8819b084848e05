#include <catch2/catch.hpp>
#include <cmath>

#include "block/block.hpp"
#include "core/errors.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_block_test_block {

using freestand::block::Block;
using freestand::block::Edge;

TEST_CASE("uniform block derived quantities match docs/methods.md s.1", "[block]") {
    // 0.3 x 1.2 m steel block: b = 0.15, h = 0.6 -> R = 0.6185 m, alpha = atan(0.25) = 0.2450 rad.
    const Block blk = Block::uniform(0.15, 0.6, 38.0);
    CHECK(blk.R_m(Edge::left) == Approx(std::hypot(0.15, 0.6)).epsilon(1e-14));
    CHECK(blk.alpha_rad(Edge::right) == Approx(0.244978663).epsilon(1e-8));
    // Uniform block: I_O = 4/3 M R^2 and p = sqrt(3 g / (4 R)).
    const double R = blk.R_m(Edge::left);
    CHECK(blk.inertia_edge_kgm2(Edge::left) == Approx(4.0 / 3.0 * 38.0 * R * R).epsilon(1e-14));
    CHECK(blk.p_radps(Edge::left) == Approx(std::sqrt(3.0 * 9.81 / (4.0 * R))).epsilon(1e-14));
    // Housner: r = 1 - 1.5 sin^2(alpha).
    const double s = std::sin(blk.alpha_rad(Edge::left));
    CHECK(blk.housner_restitution(Edge::left) == Approx(1.0 - 1.5 * s * s).epsilon(1e-14));
}

TEST_CASE("asymmetric block has per-edge geometry and picks the slenderer edge", "[block]") {
    const Block blk = Block::general(0.2, 0.4, 1.0, 100.0, 20.0);
    CHECK(blk.tan_alpha(Edge::left) == Approx(0.2));
    CHECK(blk.tan_alpha(Edge::right) == Approx(0.4));
    CHECK(blk.critical_edge() == Edge::left);
    CHECK(blk.inertia_edge_kgm2(Edge::right) == Approx(20.0 + 100.0 * (0.16 + 1.0)));
    CHECK_FALSE(blk.symmetric());
}

TEST_CASE("a block outside the size limits is an input error naming the field and the limit",
          "[block]") {
    CHECK_THROWS_AS(Block::uniform(0.15, 1e3), freestand::InputError);
    CHECK_THROWS_WITH(Block::uniform(0.15, 1e3), Catch::Contains("h (CG height, m): length (m): "
                                                                 "1000 is above the limit 100"));
    CHECK_THROWS_WITH(Block::uniform(1e300, 0.6), Catch::Contains("b (half-width, m)"));
    CHECK_THROWS_WITH(Block::uniform(0.15, 0.6, 1e-6),
                      Catch::Contains("m (mass, kg): mass (kg): 1e-06 is below the limit 0.001"));
    CHECK_THROWS_WITH(Block::uniform(0.15, 0.6, 1e9), Catch::Contains("m (mass, kg)"));
    CHECK_THROWS_WITH(Block::general(0.1, 200.0, 1.0, 1.0, 1.0), Catch::Contains("b_right"));
    CHECK_NOTHROW(Block::uniform(100.0, 100.0, 1e-3));
    CHECK_NOTHROW(Block::uniform(1e-9, 1.0, 1e8));  // a CG over its edges: a needle
}

TEST_CASE("bad block dimensions are input errors naming the field", "[block]") {
    CHECK_THROWS_WITH(Block::uniform(0.0, 0.6), Catch::Contains("half-width"));
    CHECK_THROWS_WITH(Block::uniform(0.15, -1.0), Catch::Contains("CG height"));
    CHECK_THROWS_WITH(Block::uniform(0.15, 0.6, 0.0), Catch::Contains("mass"));
    CHECK_THROWS_AS(Block::general(0.1, 0.1, 1.0, 1.0, 0.0), freestand::InputError);
    CHECK_THROWS_WITH(Block::general(0.1, 0.1, 1.0, 1.0, 0.0),
                      Catch::Contains("I_c (inertia about CG, kg m^2): value 0 must be a finite "
                                      "number > 0"));
    CHECK_THROWS_WITH(Block::uniform(std::nan(""), 0.6), Catch::Contains("finite"));
}

TEST_CASE("restitution of an asymmetric block conserves angular momentum about the impact edge",
          "[block]") {
    // Rocking about the left edge with omega, CG velocity omega x (b_L, h) = omega (-h, b_L).
    // Angular momentum about the right edge (at (b_R, 0) from the CG foot): I_c omega +
    // M ((-b_R) (omega b_L) - h (-omega h)) = omega (I_c + M (h^2 - b_L b_R)); after the impact
    // it is I_O,R omega+. With b_L = 0.2, b_R = 0.4, h = 1, M = 100, I_c = 20:
    // r = (20 + 100 (1 - 0.08)) / (20 + 100 (0.16 + 1)) = 112 / 136.
    const Block blk = Block::general(0.2, 0.4, 1.0, 100.0, 20.0);
    CHECK(blk.housner_restitution(Edge::right) == Approx(112.0 / 136.0).epsilon(1e-14));
    CHECK(blk.housner_restitution(Edge::left) == Approx(112.0 / (20.0 + 100.0 * 1.04)).epsilon(1e-14));
}

}  // namespace freestand_test_block_test_block
