// Two units joined by a tunnel (docs/methods.md s.10): the relative displacement at tunnel height.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "core/errors.hpp"
#include "dynamics/helpers.hpp"
#include "dynamics/pair.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_dynamics_test_pair {

using namespace freestand;

namespace {

// A unit that only slides (wide: tan(alpha) = 2 > mu) and a slender one that rocks.
dynamics::BlockModel sliding_unit(double mu) {
    return dynamics::make_block_model(block::Block::uniform(1.0, 0.5, 400.0), mu);
}
dynamics::BlockModel rocking_unit(double mu) {
    return dynamics::make_block_model(block::Block::uniform(0.4, 1.6, 400.0), mu);
}

dynamics::PairOptions at_height(double h_m, std::size_t refine = 1) {
    dynamics::PairOptions p;
    p.tunnel_height_m = h_m;
    p.refine = refine;
    return p;
}

// max_i |d_1(t_i) - d_2(t_i)| from two single-unit runs.
double relative_from_singles(const dynamics::BlockModel& a, const dynamics::BlockModel& b,
                             const dynamics::Excitation& ex, double h_m) {
    const auto ra = dynamics::simulate(a, ex), rb = dynamics::simulate(b, ex);
    double peak = 0.0;
    const std::size_t n = std::max(ra.series.size(), rb.series.size());
    for (std::size_t i = 0; i < n; ++i) {
        const auto& sa = ra.series[std::min(i, ra.series.size() - 1)];
        const auto& sb = rb.series[std::min(i, rb.series.size() - 1)];
        peak = std::max(peak, std::abs(dynamics::displacement_at_height_m(sa, a.block.h_m, h_m) -
                                       dynamics::displacement_at_height_m(sb, b.block.h_m, h_m)));
    }
    return peak;
}

}  // namespace

TEST_CASE("pair: identical units have no relative displacement", "[pair]") {
    const auto ex = test::scaled_to(test::elcentro(), 0.5);
    for (const auto& unit : {sliding_unit(0.15), rocking_unit(0.6)}) {
        const auto r = dynamics::simulate_pair({unit, unit}, ex, at_height(1.0));
        CHECK(r.units[0].slide_max_m + r.units[0].rock_max_rad > 1e-3);
        CHECK(r.relative_max_m == 0.0);
        CHECK(r.relative_residual_m == 0.0);
    }
}

TEST_CASE("pair: units differing only in friction give the difference of their single runs",
          "[pair]") {
    const auto ex = test::scaled_to(test::elcentro(), 0.5);
    const auto a = sliding_unit(0.12), b = sliding_unit(0.18);
    const auto r = dynamics::simulate_pair({a, b}, ex, at_height(1.0));
    const double expected = relative_from_singles(a, b, ex, 1.0);
    CHECK(expected > 0.01);
    CHECK(r.relative_max_m == Approx(expected).epsilon(1e-12));
    CHECK(r.units[0].slide_max_m == dynamics::simulate(a, ex).summary.slide_max_m);
    CHECK(r.units[1].slide_max_m == dynamics::simulate(b, ex).summary.slide_max_m);
    // Sliding only: theta = 0, so the tunnel's height does not matter.
    CHECK(dynamics::simulate_pair({a, b}, ex, at_height(0.0)).relative_max_m ==
          Approx(r.relative_max_m).epsilon(1e-12));
}

TEST_CASE("pair: a rocking unit's tilt adds h_t theta, + on the right edge", "[pair]") {
    // Unit 2 stays at rest (mu = 0.6 > PGA 0.5 g, wide), unit 1 rocks (0.1 rad) without sliding.
    const auto ex = test::scaled_to(test::elcentro(), 0.5);
    const auto rock = rocking_unit(0.6), still = sliding_unit(0.6);
    const auto single = dynamics::simulate(rock, ex);
    REQUIRE(single.summary.rock_max_rad > 1e-3);
    REQUIRE(single.summary.slide_max_m < 1e-9);
    double peak = 0.0;
    for (const auto& s : single.series) peak = std::max(peak, std::abs(1.5 * s.rotation_rad));
    const auto r = dynamics::simulate_pair({rock, still}, ex, at_height(1.5));
    CHECK(r.units[1].slide_max_m == 0.0);
    CHECK(r.relative_max_m == Approx(peak).epsilon(1e-12));
    dynamics::Sample s;
    s.rotation_rad = 0.01;  // rocking on the right edge: the top moves right
    s.slide_m = 0.002;
    CHECK(dynamics::displacement_at_height_m(s, 0.8, 1.5) == Approx(0.002 + 0.015));
    s.mode = dynamics::Mode::flight;  // slide_m is then the CG's displacement
    CHECK(dynamics::displacement_at_height_m(s, 0.8, 1.5) == Approx(0.002 + 0.007));
}

TEST_CASE("pair: refining the samples changes neither run, and the input samples miss little",
          "[pair]") {
    const auto ex = test::scaled_to(test::elcentro(), 0.5);
    const auto a = rocking_unit(0.6), b = sliding_unit(0.15);
    const auto coarse = dynamics::simulate_pair({a, b}, ex, at_height(1.0, 1));
    const auto fine = dynamics::simulate_pair({a, b}, ex, at_height(1.0, 16));
    for (std::size_t k = 0; k < 2; ++k) {
        CHECK(fine.units[k].slide_max_m == Approx(coarse.units[k].slide_max_m).epsilon(1e-8));
        CHECK(fine.units[k].rock_max_rad ==
              Approx(coarse.units[k].rock_max_rad).epsilon(1e-8).margin(1e-12));
    }
    CHECK(fine.samples > 15 * coarse.samples);
    REQUIRE_FALSE(fine.overturned);
    CHECK(fine.relative_max_m >= coarse.relative_max_m * (1.0 - 1e-9));
    // The miss between input samples (El Centro, 0.01 s) is below 0.1% of the peak.
    CHECK(fine.relative_max_m - coarse.relative_max_m < 1e-3 * fine.relative_max_m);
}

TEST_CASE("pair: bad tunnel height or refinement is refused naming it", "[pair][errors]") {
    const auto ex = test::samples(0.01, {0.0, 1.0, 0.0});
    const auto u = sliding_unit(0.2);
    CHECK_THROWS_MATCHES(dynamics::simulate_pair({u, u}, ex, at_height(-0.1)), InputError,
                         Catch::Matchers::Message(
                             "tunnel_height_m: must be >= 0 m; got -0.1"));
    CHECK_THROWS_MATCHES(dynamics::simulate_pair({u, u}, ex, at_height(1.0, 0)), InputError,
                         Catch::Matchers::Message("refine: must be a whole number >= 1; got 0"));
}

}  // namespace freestand_test_dynamics_test_pair
