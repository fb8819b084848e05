// The overturning rule of docs/methods.md s.3 in every engine that rocks: theta reaching pi/2,
// or theta > alpha with theta' > 0 and no restoring energy left once the input has ended, also
// when the run stops there; and the peak rotation counting the rotation in flight.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "dynamics/flexible.hpp"
#include "dynamics/pair.hpp"
#include "helpers.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_dynamics_test_overturn_rule {

using namespace freestand;
using dynamics::Integrator;
using dynamics::OverturnCriterion;

namespace {

constexpr double g = 9.81;

// b 0.15 m, h 0.6 m (alpha = atan(0.25) = 0.245 rad), 38 kg.
dynamics::BlockModel slender(double mu) {
    return dynamics::make_block_model(block::Block::uniform(0.15, 0.6, 38.0), mu);
}

// 0.3 g at 1 Hz for 2.2 s: the block (mu 0.7, rocking without slip) passes alpha at 1.66 s
// and is still rising past it, at 0.35 rad = 1.44 alpha, when the input ends (its series,
// `simulate --block b=0.15,h=0.6,m=38 --mu 0.7 --sine 0.3g,1Hz,2.2s`).
dynamics::Excitation rising_past_alpha_at_the_end() {
    return dynamics::sine_excitation({0.3, 1.0, 2.2, 0.0, 0.0});
}

// The run stops where the input ends: the rule must be applied to the last state.
dynamics::Options no_tail(Integrator integrator) {
    auto o = test::opts(integrator);
    o.tail_s = 0.0;
    return o;
}

// The critical angle of slender(), atan(b / h).
const double kAlpha_rad = std::atan(0.25);
// Central difference's rotation in one step of 1e-4 s at about 1 rad/s.
constexpr double kHalfPiStep_rad = 1e-4;

// 0.5 g to the left for 0.2 s tips the block onto its right edge; -1.5 g vertical from 0.15 s
// for 2 s throws it into the air still turning: the rigid block overturns in flight (1.57 rad
// in its series) after rocking to 0.03 rad on the base.
dynamics::Excitation tipped_then_thrown() {
    std::vector<double> ax(1000, 0.0), ay(1000, 0.0);
    for (std::size_t i = 1; i <= 40; ++i) ax[i] = -0.5 * g;
    for (std::size_t i = 30; i <= 430; ++i) ay[i] = -1.5 * g;
    return test::samples(0.005, ax, ay);
}

double series_peak_rad(const std::vector<dynamics::Sample>& series) {
    double peak = 0.0;
    for (const auto& s : series) peak = std::max(peak, std::abs(s.rotation_rad));
    return peak;
}

}  // namespace

TEST_CASE("a rigid block past alpha and rising when its run ends has overturned, both integrators",
          "[dynamics][overturn]") {
    for (Integrator integrator : {Integrator::event, Integrator::central_difference}) {
        INFO(dynamics::integrator_name(integrator));
        const auto r = dynamics::simulate(slender(0.7), rising_past_alpha_at_the_end(),
                                          no_tail(integrator));
        REQUIRE(r.series.back().rotation_rad < -1.3 * 0.245);
        CHECK(r.summary.overturned);
        CHECK(r.summary.overturn_criterion == OverturnCriterion::past_alpha_after_excitation);
        // Decided on the state the run ends with, when the input has ended (its last
        // segment, 2.2 s to 2.2025 s, returns the acceleration to 0).
        CHECK(r.summary.overturn_time_s.value_or(0.0) == r.summary.end_time_s);
        CHECK(r.summary.end_time_s == Approx(2.2025).margin(1e-9));
        // With the tail the same block is followed to the criterion, as before.
        const auto tail = dynamics::simulate(slender(0.7), rising_past_alpha_at_the_end(),
                                             test::opts(integrator));
        CHECK(tail.summary.overturned);
        CHECK(tail.summary.overturn_criterion == OverturnCriterion::past_alpha_after_excitation);
    }
}

TEST_CASE("a unit of a pair past alpha and rising when the run ends has overturned",
          "[dynamics][overturn][pair]") {
    const auto squat = dynamics::make_block_model(block::Block::uniform(0.4, 0.6, 100.0), 0.7);
    dynamics::PairOptions pair;
    pair.tunnel_height_m = 1.0;
    const auto r = dynamics::simulate_pair({slender(0.7), squat}, rising_past_alpha_at_the_end(),
                                           pair, no_tail(Integrator::event));
    CHECK(r.units[0].overturned);
    CHECK_FALSE(r.units[1].overturned);
    CHECK(r.overturned);
}

TEST_CASE("a flexible body toppling after the input is reported overturned, both integrators",
          "[dynamics][overturn][flexible]") {
    // `simulate --block b=0.15,h=0.6,m=38 --mu 0.3 --sine 0.5g,2Hz,5s --flexible f=0.01`: a mode
    // so soft that the modal mass drifts away; the base is past alpha when the input ends and
    // turns outward so slowly that theta is still 1.5666 rad, short of pi/2, after a 10 s tail.
    const auto sine = dynamics::sine_excitation({0.5, 2.0, 5.0, 0.0, 0.0});
    dynamics::FlexibleMode mode;
    mode.frequency_hz = 0.01;
    const auto m = dynamics::make_flexible_model(slender(0.3), mode);
    for (Integrator integrator : {Integrator::event, Integrator::central_difference}) {
        INFO(dynamics::integrator_name(integrator));
        auto o = test::opts(integrator);
        o.record_series = true;
        const auto r = dynamics::simulate_flexible(m, sine, o);
        CHECK(r.summary.base.overturned);
        CHECK(r.summary.base.overturn_criterion != OverturnCriterion::none);
        // Decided after the input ended, and the run stops there.
        CHECK(r.summary.base.overturn_time_s.value_or(0.0) >= 5.0);
        CHECK(r.summary.base.end_time_s == r.summary.base.overturn_time_s.value_or(-1.0));
    }
}

TEST_CASE("the peak rotation counts the rotation in flight, both integrators",
          "[dynamics][overturn][flight]") {
    const auto e = tipped_then_thrown();
    for (Integrator integrator : {Integrator::event, Integrator::central_difference}) {
        INFO(dynamics::integrator_name(integrator));
        const auto r = dynamics::simulate(slender(0.7), e, test::opts(integrator));
        REQUIRE(r.summary.time_in_mode_s[static_cast<std::size_t>(dynamics::Mode::flight)] > 1.0);
        CHECK(r.summary.overturned);
        CHECK(r.summary.overturn_criterion == OverturnCriterion::angle_half_pi);
        const double peak = series_peak_rad(r.series);
        REQUIRE(peak > 1.5);
        CHECK(r.summary.rock_max_rad >= peak);
        // Central difference stops a step past pi/2 (phi' ~ 1 rad/s, 1e-4 s).
        CHECK(r.summary.rock_max_rad == Approx(std::numbers::pi / 2.0).margin(kHalfPiStep_rad));
        CHECK(r.summary.rock_max_over_alpha == Approx(r.summary.rock_max_rad / kAlpha_rad));
    }
}

TEST_CASE("the flexible body's peak rotation counts its rotation in flight, both integrators",
          "[dynamics][overturn][flight][flexible]") {
    dynamics::FlexibleMode mode;
    mode.frequency_hz = 7.5;
    const auto m = dynamics::make_flexible_model(slender(0.7), mode);
    for (Integrator integrator : {Integrator::event, Integrator::central_difference}) {
        INFO(dynamics::integrator_name(integrator));
        auto o = test::opts(integrator);
        o.record_series = true;
        const auto r = dynamics::simulate_flexible(m, tipped_then_thrown(), o);
        REQUIRE(r.summary.base.time_in_mode_s[static_cast<std::size_t>(dynamics::Mode::flight)] >
                1.0);
        double peak = 0.0;
        for (const auto& s : r.series) peak = std::max(peak, std::abs(s.rotation_rad));
        REQUIRE(peak > 1.0);
        CHECK(r.summary.base.rock_max_rad >= peak);
        CHECK(r.summary.base.rock_max_over_alpha ==
              Approx(r.summary.base.rock_max_rad / kAlpha_rad));
    }
}

}  // namespace freestand_test_dynamics_test_overturn_rule
