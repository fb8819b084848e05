// Hard cases of the integrators (docs/methods.md s.3): thresholds hit exactly, Zeno impacts,
// extreme slenderness, strong shaking, a long record, and free flight.
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <string>

#include "support/paths.hpp"
#include "core/errors.hpp"
#include "helpers.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_dynamics_test_hard {

using namespace freestand;
using dynamics::Integrator;
using dynamics::Mode;

TEST_CASE("A exactly at mu g and at g tan(alpha): no motion", "[dynamics][hard]") {
    const auto blk = block::Block::uniform(0.15, 0.6, 38.0);
    const double tan_a = blk.tan_alpha(block::Edge::left);
    struct Case { double mu, a_g; };
    for (const Case c : {Case{0.15, 0.15}, Case{0.8, tan_a}}) {
        const auto model = dynamics::make_block_model(blk, c.mu);
        for (double sign : {1.0, -1.0}) {
            const auto e = test::samples(0.01, std::vector<double>(200, sign * c.a_g * 9.81));
            for (auto integ : {Integrator::event, Integrator::central_difference}) {
                const auto r = dynamics::simulate(model, e, test::opts(integ));
                CHECK(r.summary.mode_changes == 0);
                CHECK(r.summary.slide_max_m == 0.0);
                CHECK(r.summary.rock_max_rad == 0.0);
            }
        }
    }
}

TEST_CASE("restitution near 1 and small: Zeno impacts finish in bounded steps", "[dynamics][hard]") {
    const auto blk = block::Block::uniform(0.2, 0.6, 20.0);
    for (double rr : {0.999, 0.3, 0.02}) {
        for (auto integ : {Integrator::event, Integrator::central_difference}) {
            auto o = test::opts(integ);
            o.initial_rotation_rad = 0.5 * blk.alpha_rad(block::Edge::right);
            o.tail_s = 5.0;
            const auto model = dynamics::make_block_model(blk, 1.0, std::nullopt, rr);
            const auto r = dynamics::simulate(model, test::samples(0.005, {0.0, 0.0}), o);
            CHECK(r.summary.end_time_s <= 5.0 + 0.005 + 1e-9);
            CHECK(r.summary.steps < 200000);
            if (rr < 0.5) {
                CHECK(r.summary.settlements >= 1);
                CHECK(r.series.back().mode == Mode::rest);
            }
        }
    }
}

TEST_CASE("small rebounds under excitation settle instead of shrinking steps", "[dynamics][hard]") {
    // Rocking just above uplift then quiet: the impact sequence converges (Zeno) and settles.
    const auto blk = block::Block::uniform(0.15, 0.6, 38.0);
    const auto model = dynamics::make_block_model(blk, 0.8);
    const auto e = dynamics::sine_excitation({0.3, 2.0, 2.0, 0.0, 0.0});
    const auto r = dynamics::simulate(model, e, test::opts());
    CHECK(r.summary.impacts > 2);
    CHECK(r.summary.settlements >= 1);
    CHECK(r.series.back().mode == Mode::rest);
    CHECK(r.summary.end_time_s < 2.0 + 10.0);
}

TEST_CASE("alpha = 0.05 and alpha = 1.2 blocks under El Centro", "[dynamics][hard]") {
    const auto rec = test::elcentro();
    const auto e = test::scaled_to(rec, 0.4);
    // Slender: rocks (mu > tan alpha) and, at 0.4 g, overturns in both integrators.
    const auto slender = dynamics::make_block_model(block::Block::uniform(std::tan(0.05), 1.0, 10.0), 0.5);
    const auto a = dynamics::simulate(slender, e, test::opts());
    const auto ac = dynamics::simulate(slender, e, test::opts(Integrator::central_difference));
    CHECK(a.summary.time_in_mode_s[static_cast<std::size_t>(Mode::rock)] > 0.0);
    CHECK(a.summary.overturned);  // the overturn itself, not only agreement of the integrators
    CHECK(ac.summary.overturned);
    // Squat: tan(1.2) = 2.57 > mu: only slides; Housner's r would be negative: clamped to 0.
    const auto squat = dynamics::make_block_model(block::Block::uniform(std::tan(1.2), 1.0, 10.0), 0.2);
    const auto b = dynamics::simulate(squat, e, test::opts());
    const auto bc = dynamics::simulate(squat, e, test::opts(Integrator::central_difference));
    CHECK(b.summary.rock_max_rad == 0.0);
    CHECK(b.summary.slide_max_m > 0.001);
    CHECK(b.summary.slide_max_m == Approx(bc.summary.slide_max_m).epsilon(1e-3));
}

TEST_CASE("5 g sine completes in both integrators", "[dynamics][hard]") {
    const auto blk = block::Block::uniform(0.15, 0.6, 38.0);
    const auto e = dynamics::sine_excitation({5.0, 2.0, 5.0, 0.0, 0.0});
    for (double mu : {0.15, 0.8}) {
        const auto model = dynamics::make_block_model(blk, mu);
        const auto r = dynamics::simulate(model, e, test::opts());
        const auto rc = dynamics::simulate(model, e, test::opts(Integrator::central_difference));
        CHECK(std::isfinite(r.summary.slide_max_m));
        CHECK(r.summary.overturned == rc.summary.overturned);
        if (mu < 0.25) {
            // Sliding only: the block's own acceleration is capped at mu g.
            CHECK(!r.summary.overturned);
            CHECK(r.summary.top_accel_max_g <= mu + 1e-12);
            CHECK(r.summary.slide_max_m == Approx(rc.summary.slide_max_m).epsilon(1e-3));
        } else {
            CHECK(r.summary.overturned);
            CHECK(*r.summary.overturn_mode == 2);  // tips over in the first half-cycle
        }
    }
}

TEST_CASE("600 s record: one step per sliding segment, none at rest", "[dynamics][hard]") {
    const auto rec = test::elcentro();
    auto e = test::scaled_to(rec, 0.5);
    const std::vector<double> one = e.horizontal_mps2;
    while (e.duration_s() < 600.0)
        e.horizontal_mps2.insert(e.horizontal_mps2.end(), one.begin(), one.end());
    const auto model = dynamics::make_block_model(block::Block::uniform(0.15, 0.6, 38.0), 0.15);
    const auto r = dynamics::simulate(model, e, test::opts());
    CHECK(r.summary.end_time_s >= 600.0);
    CHECK(r.summary.slide_max_m > 0.01);
    // Cost without timing it (the suite asserts no wall-clock times): at most one closed-form
    // slide piece per input segment, and no segment at all while the block rests.
    const double segments = r.summary.end_time_s / e.dt_s;
    const double sliding = r.summary.time_in_mode_s[static_cast<std::size_t>(Mode::slide)] / e.dt_s;
    CHECK(static_cast<double>(r.summary.steps) <= sliding + 2.0 * static_cast<double>(r.summary.mode_changes) + 1.0);
    CHECK(static_cast<double>(r.summary.steps) < segments);
}

TEST_CASE("vertical acceleration beyond g for an instant: free flight and landing",
          "[dynamics][hard]") {
    // The base drops faster than gravity for ~0.1 s (yg'' down to -1.5 g): the block leaves it,
    // flies and lands flat (no horizontal motion, no rotation).
    std::vector<double> ay(201, 0.0);
    for (int i = 0; i <= 20; ++i) ay[static_cast<std::size_t>(10 + i)] = -1.5 * 9.81 * (1.0 - std::abs(i - 10) / 10.0);
    const auto model = dynamics::make_block_model(block::Block::uniform(0.15, 0.6, 38.0), 0.5);
    const auto e = test::samples(0.005, std::vector<double>(201, 0.0), ay);
    const auto r = dynamics::simulate(model, e, test::opts());
    const auto rc = dynamics::simulate(model, e, test::opts(Integrator::central_difference, 1e-5));
    const double fly = r.summary.time_in_mode_s[static_cast<std::size_t>(Mode::flight)];
    CHECK(fly > 0.02);
    CHECK(r.summary.impacts == 1);
    CHECK(r.series.back().mode == Mode::rest);
    CHECK(fly == Approx(rc.summary.time_in_mode_s[static_cast<std::size_t>(Mode::flight)]).epsilon(1e-3));
    // With a horizontal push while airborne it lands sliding and friction stops it.
    std::vector<double> ax(201, 0.0);
    for (int i = 15; i <= 25; ++i) ax[static_cast<std::size_t>(i)] = 2.0;
    const auto r2 = dynamics::simulate(model, test::samples(0.005, ax, ay), test::opts());
    CHECK(r2.summary.slide_max_m > 0.0);
    CHECK(std::isfinite(r2.summary.slide_residual_m));
}

TEST_CASE("bad model values name the option", "[dynamics][errors]") {
    const auto blk = block::Block::uniform(0.15, 0.6, 38.0);
    CHECK_THROWS_MATCHES(dynamics::make_block_model(blk, -0.1), InputError,
                         Catch::Matchers::Message("mu_s: value -0.1 is out of range; expected [0, 2]"));
    CHECK_THROWS_MATCHES(dynamics::make_block_model(blk, 0.3, 0.4), InputError,
                         Catch::Matchers::Message("mu_k: kinetic friction must be in [0, mu_s = 0.3]; got 0.4"));
    CHECK_THROWS_MATCHES(dynamics::make_block_model(blk, 0.3, std::nullopt, 1.2), InputError,
                         Catch::Matchers::Message("restitution: value 1.2 is out of range; expected [0, 1]"));
    CHECK_THROWS_AS(dynamics::sine_excitation({0.5, 0.0, 5.0, 0.0, 0.0}), InputError);
    CHECK_THROWS_WITH(dynamics::sine_excitation({0.5, 2.0, 5.0, -1.0, 0.0}),
                      Catch::Matchers::Contains("sine.ramp_s"));
}

TEST_CASE("coarse records (dt 0.02 s and 0.04 s) run to the end and agree with central difference",
          "[dynamics][hard]") {
    // Sample times are k dt, so a segment can be an ulp longer than dt or than the longest
    // contact step (0.02 s); a step ending an ulp short of a sample once left a 1e-15 s step
    // behind it and threw.
    const auto rec = test::elcentro();
    const auto model = dynamics::make_block_model(block::Block::uniform(0.3, 0.6, 38.0), 0.6);
    for (std::size_t every : {4u, 8u}) {
        core::Record coarse = rec;
        coarse.dt_s = rec.dt_s * static_cast<double>(every);
        coarse.accel_mps2.clear();
        for (std::size_t i = 0; i < rec.accel_mps2.size(); i += every) coarse.accel_mps2.push_back(rec.accel_mps2[i]);
        const auto e = test::scaled_to(coarse, 0.9);
        dynamics::SimulationResult r, rc;
        REQUIRE_NOTHROW(r = dynamics::simulate(model, e, test::opts()));
        rc = dynamics::simulate(model, e, test::opts(Integrator::central_difference, 1e-4));
        INFO("dt " << coarse.dt_s << ": event " << r.summary.rock_max_rad << " cd " << rc.summary.rock_max_rad);
        CHECK(r.summary.impacts > 10);
        CHECK(r.summary.overturned == rc.summary.overturned);
        CHECK(r.summary.rock_max_rad == Approx(rc.summary.rock_max_rad).epsilon(0.02));
    }
    for (double dt : {0.02, 0.04}) {
        const auto e = dynamics::sine_excitation({0.55, 1.0, 6.0, 0.0, dt});
        dynamics::SimulationResult r;
        REQUIRE_NOTHROW(r = dynamics::simulate(model, e, test::opts()));
        const auto rc = dynamics::simulate(model, e, test::opts(Integrator::central_difference, 1e-4));
        INFO("sine dt " << dt << ": event " << r.summary.rock_max_rad << " cd " << rc.summary.rock_max_rad);
        CHECK(!r.summary.overturned);
        CHECK(r.summary.rock_max_rad > 0.001);
        CHECK(r.summary.overturned == rc.summary.overturned);
        CHECK(r.summary.rock_max_rad == Approx(rc.summary.rock_max_rad).epsilon(0.02));
    }
}

TEST_CASE("a rock onset that only grazes g tan(alpha) settles and time goes on",
          "[dynamics][hard]") {
    // A generated history of bench_fragility brings block-ts3 (y, mu 0.608738, r 0.810838) to a
    // rock onset whose excursion is below the impact search's resolution: unless the onset
    // settles, the onset, an impact at the same instant and the settling repeat at one t until
    // 100000 events throw "events accumulate". The window 9.0-9.4 s starts at rest, as in the run.
    std::ifstream in(freestand::test::data_dir() + "/grazing_rock_onset.csv");
    REQUIRE(in);
    dynamics::Excitation e;
    e.label = "grazing rock onset";
    e.dt_s = 0.005;
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == '#' || line[0] == 'h') continue;
        const auto comma = line.find(',');
        e.horizontal_mps2.push_back(std::stod(line.substr(0, comma)));
        e.vertical_mps2.push_back(std::stod(line.substr(comma + 1)));
    }
    REQUIRE(e.horizontal_mps2.size() == 81);
    const auto blk = block::Block::general(0.15, 0.15, 0.3, 35.0, 1.3124999999999998);
    const auto model = dynamics::make_block_model(blk, 0.608738, 0.608738, 0.810838, 0.6);
    dynamics::Options o = test::opts(Integrator::event);
    const auto r = dynamics::simulate(model, e, o);
    CHECK_FALSE(r.summary.overturned);
    CHECK(r.summary.settlements >= 1);
    // The onset is real but tiny: theta stays far below alpha (0.46 rad).
    CHECK(r.summary.rock_max_rad < 1e-3);
    CHECK(r.series.back().time_s >= 9.4 - 9.0 - 1e-9);
}

}  // namespace freestand_test_dynamics_test_hard
