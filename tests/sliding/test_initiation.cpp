#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "block/block.hpp"
#include "core/errors.hpp"
#include "sliding/initiation.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_sliding_test_initiation {

using freestand::block::Block;
using freestand::block::Edge;
using namespace freestand::sliding;

namespace {
// Uniform block with tan(alpha) = 0.25 exactly (b / h = 0.25 / 1.0), so every boundary below is
// an exactly representable number.
const Block quarter = Block::uniform(0.25, 1.0, 10.0);

double up(double x) { return std::nextafter(x, HUGE_VAL); }
double down(double x) { return std::nextafter(x, -HUGE_VAL); }

// Shenton (1996) uniform-block formula as printed in docs/methods.md s.2.
double shenton(double A, double gamma) {
    return (A * (1.0 + 4.0 * gamma * gamma) + 3.0 * gamma) / (4.0 + gamma * gamma + 3.0 * A * gamma);
}
}  // namespace

TEST_CASE("mu_crit of a uniform block is Shenton's formula and equals tan(alpha) at uplift",
          "[sliding][initiation]") {
    // Hand calculation, the b=0.15, h=0.6, mu 0.32, 0.8 g example: gamma = 0.25, A = 0.8:
    // (0.8 * 1.25 + 0.75) / (4.0625 + 0.6) = 1.75 / 4.6625 = 0.375335...
    const Block blk = Block::uniform(0.15, 0.6);
    CHECK(mu_crit(blk, Edge::right, 0.8) == Approx(1.75 / 4.6625).epsilon(1e-12));
    for (double A : {0.0, 0.1, 0.25, 0.5, 1.0, 3.0})
        CHECK(mu_crit(quarter, Edge::left, A) == Approx(shenton(A, 0.25)).epsilon(1e-13));
    CHECK(mu_crit(quarter, Edge::left, 0.25) == Approx(0.25).epsilon(1e-15));
    CHECK(mu_crit(blk, Edge::left, blk.tan_alpha(Edge::left)) ==
          Approx(blk.tan_alpha(Edge::left)).epsilon(1e-15));
}

TEST_CASE("general-block mu_crit matches the base reactions computed by hand",
          "[sliding][initiation]") {
    // b = 0.2, h = 1, M = 100, I_c = 20 -> I_O = 20 + 100 * 1.04 = 124. At A = 0.5 (G = 1):
    // theta'' = M G (A h - b) / I_O = 100 * 0.3 / 124 = 0.2419355 G;
    // F / (M G) = -A + h theta'' / G = -0.2580645;  N / (M G) = 1 + b theta'' / G = 1.0483871;
    // |F| / N = 0.2461538 (= 32 / 130).
    const Block blk = Block::general(0.2, 0.4, 1.0, 100.0, 20.0);
    CHECK(mu_crit(blk, Edge::left, 0.5) == Approx(32.0 / 130.0).epsilon(1e-13));
    CHECK(mu_crit(blk, Edge::left, 0.2) == Approx(0.2).epsilon(1e-14));
    CHECK(mu_crit(blk, Edge::right, 0.4) == Approx(0.4).epsilon(1e-14));
    // A general block with the uniform-box I_c reduces to Shenton's formula.
    const double b = 0.3, h = 0.9, m = 7.0;
    const Block g = Block::general(b, b, h, m, m * (b * b + h * h) / 3.0);
    for (double A : {0.2, 0.5, 2.0})
        CHECK(mu_crit(g, Edge::right, A) == Approx(shenton(A, b / h)).epsilon(1e-13));
}

TEST_CASE("rest / slide boundary when mu_s < tan(alpha)", "[sliding][initiation]") {
    const double mu = 0.125;
    CHECK(classify_edge(quarter, Edge::left, mu, down(mu), 0.0).mode == Mode::rest);
    const Initiation on = classify_edge(quarter, Edge::left, mu, mu, 0.0);
    CHECK(on.mode == Mode::rest);  // exactly on the boundary is rest
    CHECK(on.decided_by == Criterion::below_thresholds);
    const Initiation above = classify_edge(quarter, Edge::left, mu, up(mu), 0.0);
    CHECK(above.mode == Mode::slide);
    CHECK(above.decided_by == Criterion::friction_below_slenderness);
    // Well above tan(alpha) it still slides: the base cannot push harder than mu g.
    const Initiation big = classify_edge(quarter, Edge::left, mu, 2.0, 0.0);
    CHECK(big.mode == Mode::slide);
    REQUIRE(big.mu_crit.has_value());
    CHECK(on.mu_crit_reason.find("no uplift") != std::string::npos);
}

TEST_CASE("mu_s exactly tan(alpha) slides, just above it rocks", "[sliding][initiation]") {
    CHECK(classify_edge(quarter, Edge::left, 0.25, 0.25, 0.0).mode == Mode::rest);
    CHECK(classify_edge(quarter, Edge::left, 0.25, up(0.25), 0.0).mode == Mode::slide);
    // mu_s just above tan(alpha) and A just above tan(alpha): mu_crit(A) ~ tan(alpha) < mu_s.
    CHECK(classify_edge(quarter, Edge::left, 0.3, up(0.25), 0.0).mode == Mode::rock);
}

TEST_CASE("rest / rock boundary at tan(alpha) when mu_s > tan(alpha)", "[sliding][initiation]") {
    const double mu = 0.5;
    CHECK(classify_edge(quarter, Edge::right, mu, 0.25, 0.0).mode == Mode::rest);
    const Initiation r = classify_edge(quarter, Edge::right, mu, up(0.25), 0.0);
    CHECK(r.mode == Mode::rock);
    CHECK(r.decided_by == Criterion::friction_holds_at_uplift);
    CHECK(r.tan_alpha == 0.25);
}

TEST_CASE("rock / slide-rock boundary at mu_s = mu_crit(A)", "[sliding][initiation]") {
    const double A = 1.0;
    const double mc = mu_crit(quarter, Edge::left, A);  // Shenton: 2 / 4.8125 = 0.4155844
    CHECK(mc == Approx(2.0 / 4.8125).epsilon(1e-14));
    CHECK(classify_edge(quarter, Edge::left, mc, A, 0.0).mode == Mode::rock);  // on it: rock
    CHECK(classify_edge(quarter, Edge::left, up(mc), A, 0.0).mode == Mode::rock);
    const Initiation sr = classify_edge(quarter, Edge::left, down(mc), A, 0.0);
    CHECK(sr.mode == Mode::slide_rock);
    CHECK(sr.decided_by == Criterion::friction_fails_at_uplift);
    // The slide-rock band: tan(alpha) < mu_s < mu_crit(A).
    CHECK(classify_edge(quarter, Edge::left, 0.3, A, 0.0).mode == Mode::slide_rock);
}

TEST_CASE("the example b=0.15, h=0.6, mu 0.32 at 0.8 g slide-rocks", "[sliding][initiation]") {
    const PeakInitiation p = classify_peak(Block::uniform(0.15, 0.6), 0.32, 0.8, 0.0);
    CHECK(p.governing().mode == Mode::slide_rock);
    CHECK(p.governing().tan_alpha == Approx(0.25).epsilon(1e-15));
    CHECK(*p.governing().mu_crit == Approx(1.75 / 4.6625).epsilon(1e-12));
}

TEST_CASE("vertical acceleration changes the effective gravity, downward is the worst case",
          "[sliding][initiation]") {
    // a_v = -0.5 g: A = a_h / 0.5. a_h = 0.125 -> A = 0.25 = tan(alpha): rest on the boundary.
    CHECK(load_ratio(0.125, -0.5) == 0.25);
    CHECK(classify_edge(quarter, Edge::left, 0.5, 0.125, -0.5).mode == Mode::rest);
    CHECK(classify_edge(quarter, Edge::left, 0.5, up(0.125), -0.5).mode == Mode::rock);
    // Upward 1 g halves A: 0.5 g horizontal is then on the boundary.
    CHECK(classify_edge(quarter, Edge::left, 0.5, 0.5, 1.0).mode == Mode::rest);
    // Peak vertical is applied downward: peak 0.5 g makes 0.125 g the uplift boundary.
    CHECK(classify_peak(quarter, 0.5, 0.125, 0.5).governing().mode == Mode::rest);
    CHECK(classify_peak(quarter, 0.5, up(0.125), 0.5).governing().mode == Mode::rock);
}

TEST_CASE("mu_s = 0 slides under any horizontal acceleration", "[sliding][initiation]") {
    CHECK(classify_edge(quarter, Edge::left, 0.0, 0.0, 0.0).mode == Mode::rest);
    CHECK(classify_edge(quarter, Edge::left, 0.0, std::numeric_limits<double>::denorm_min(), 0.0)
              .mode == Mode::slide);
}

TEST_CASE("asymmetric block classifies each edge, the slenderer edge governs",
          "[sliding][initiation]") {
    // tan(alpha_L) = 0.2, tan(alpha_R) = 0.4; mu 0.3, A 0.5.
    const Block blk = Block::general(0.2, 0.4, 1.0, 100.0, 20.0);
    const PeakInitiation p = classify_peak(blk, 0.3, 0.5, 0.0);
    CHECK(p.governing_edge == Edge::left);
    CHECK(p.left.mode == Mode::rock);  // mu_crit_L(0.5) = 0.246 < 0.3
    CHECK(*p.left.mu_crit == Approx(32.0 / 130.0).epsilon(1e-13));
    CHECK(p.right.mode == Mode::slide);  // mu 0.3 <= tan(alpha_R) 0.4
    CHECK(p.governing().edge == Edge::left);
    // At A = 0.3: about the left edge mu_crit = 27.2 / 126 = 0.2159 < 0.3 -> rock; the right
    // edge stays at rest (A <= mu and A <= 0.4).
    CHECK(classify_signed(blk, 0.3, 0.3, 0.0).mode == Mode::rock);
    CHECK(classify_signed(blk, 0.3, 0.3, 0.0).edge == Edge::left);
    CHECK(classify_signed(blk, 0.3, -0.3, 0.0).edge == Edge::right);
    CHECK(classify_signed(blk, 0.3, -0.3, 0.0).mode == Mode::rest);
    CHECK(mu_crit(blk, Edge::left, 0.3) == Approx(27.2 / 126.0).epsilon(1e-13));
}

TEST_CASE("initiation input errors name the field", "[sliding][initiation]") {
    using freestand::InputError;
    CHECK_THROWS_AS(classify_edge(quarter, Edge::left, -0.1, 0.2, 0.0), InputError);
    CHECK_THROWS_WITH(classify_edge(quarter, Edge::left, -0.1, 0.2, 0.0),
                      Catch::Contains("mu_s") && Catch::Contains("out of range"));
    CHECK_THROWS_WITH(classify_edge(quarter, Edge::left, 0.1, -0.2, 0.0), Catch::Contains("a_h_g"));
    CHECK_THROWS_WITH(classify_edge(quarter, Edge::left, 0.1, 0.2, -1.0),
                      Catch::Contains("a_v_g") && Catch::Contains("free flight"));
    CHECK_THROWS_WITH(classify_peak(quarter, 0.1, 0.2, 1.0), Catch::Contains("peak_v_g"));
    CHECK_THROWS_WITH(classify_peak(quarter, 0.1, 0.2, -0.1), Catch::Contains("peak_v_g"));
    CHECK_THROWS_WITH(mu_crit(quarter, Edge::left, -1.0), Catch::Contains("A"));
}

TEST_CASE("criterion names", "[sliding][initiation]") {
    CHECK(describe(Criterion::friction_fails_at_uplift) ==
          "A > tan(alpha) and tan(alpha) < mu_s < mu_crit(A)");
}

}  // namespace freestand_test_sliding_test_initiation
