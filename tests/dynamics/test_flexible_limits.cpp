// Where the flexible body stops being a flexible body (docs/methods.md s.10): above the
// frequency at which its mode moves with the base the rigid block runs, and says so; below it
// the flexible answer approaches the rigid one as the mode stiffens; the cost of a run is
// bounded; central difference refuses a step its elastic mode makes unstable.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "core/errors.hpp"
#include "dynamics/flexible.hpp"
#include "dynamics/flexible_detail.hpp"
#include "helpers.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_dynamics_test_flexible_limits {

using namespace freestand;
using Catch::Matchers::Contains;

namespace {

// A slender body rocking under a sine: `simulate --block b=0.15,h=0.6,m=38 --mu 0.3 --sine 0.5g,2Hz,5s`.
dynamics::BlockModel slender() {
    return dynamics::make_block_model(block::Block::uniform(0.15, 0.6, 38.0), 0.3);
}
dynamics::Excitation sine() { return dynamics::sine_excitation({0.5, 2.0, 5.0, 0.0, 0.0}); }

dynamics::FlexibleModel at(double f_hz) {
    dynamics::FlexibleMode mode;
    mode.frequency_hz = f_hz;
    return dynamics::make_flexible_model(slender(), mode);
}

dynamics::Options no_series(dynamics::Integrator integrator = dynamics::Integrator::event,
                            double cd_dt_s = 1e-4) {
    auto o = test::opts(integrator, cd_dt_s);
    o.record_series = false;
    return o;
}

// Largest relative difference of the peak slip and rotation from the rigid block's.
double from_rigid(const dynamics::Summary& s, const dynamics::Summary& rigid) {
    return std::max(std::abs(s.slide_max_m - rigid.slide_max_m) / rigid.slide_max_m,
                    std::abs(s.rock_max_rad - rigid.rock_max_rad) / rigid.rock_max_rad);
}

}  // namespace

TEST_CASE("above the rigid limit the flexible body is the rigid block, and says so",
          "[dynamics][flexible][stiff]") {
    const auto e = sine();
    const dynamics::Summary rigid = dynamics::simulate(slender(), e, no_series()).summary;
    // The mode moves with the base when it keeps below 1% of an impact's velocity change
    // (1 / ((2 f T)^2 - 1)) and amplifies the input by less than 1% (up to its Nyquist
    // frequency, 400 Hz here): 50 kHz at T = 0.1 ms.
    const double limit_hz = dynamics::rigid_limit_hz(at(1000.0), e);
    CHECK(limit_hz == Approx(std::sqrt(101.0) / (2.0 * dynamics::default_impact_duration_s)));
    for (double f_hz : {1e6, 1e8, limit_hz}) {
        INFO("f = " << f_hz << " Hz");
        for (auto integrator : {dynamics::Integrator::event, dynamics::Integrator::central_difference}) {
            const auto flex = dynamics::simulate_flexible(at(f_hz), e, no_series(integrator));
            const auto ref = dynamics::simulate(slender(), e, no_series(integrator)).summary;
            CHECK(flex.summary.rigid_handover);
            CHECK(flex.summary.base.integrator == ref.integrator);
            CHECK(flex.summary.base.rock_max_over_alpha == ref.rock_max_over_alpha);
            CHECK(flex.summary.base.slide_max_m == ref.slide_max_m);
            CHECK(flex.summary.base.overturned == ref.overturned);
            // The rigid block's work, not a stiff mode's (integrated as such, a 1e6 Hz mode
            // needs some 45 M Dormand-Prince steps here).
            CHECK(flex.summary.base.steps == ref.steps);
            CHECK(flex.summary.rejected_steps == 0);
            CHECK(flex.summary.modal_max_m == 0.0);
        }
    }
    CHECK(rigid.rock_max_over_alpha == Approx(0.5832).margin(1e-4));
    // Below the limit the flexible model runs.
    CHECK_FALSE(dynamics::simulate_flexible(at(1000.0), e, no_series()).summary.rigid_handover);
}

TEST_CASE("the handover keeps the series and the impacts of the rigid run",
          "[dynamics][flexible][stiff]") {
    auto o = test::opts();
    o.record_series = true;
    const auto rigid = dynamics::simulate(slender(), sine(), o);
    const auto flex = dynamics::simulate_flexible(at(1e8), sine(), o);
    REQUIRE(flex.series.size() == rigid.series.size());
    for (std::size_t i = 0; i < rigid.series.size(); i += 97) {
        CHECK(flex.series[i].time_s == rigid.series[i].time_s);
        CHECK(flex.series[i].rotation_rad == rigid.series[i].rotation_rad);
        CHECK(flex.series[i].slide_m == rigid.series[i].slide_m);
        CHECK(flex.series[i].modal_m == 0.0);
    }
    CHECK(flex.impact_log.size() == rigid.impact_log.size());
}

TEST_CASE("the flexible answer approaches the rigid block's as the mode stiffens",
          "[dynamics][flexible][stiff]") {
    // Measured (docs/methods.md s.10): peak slip and rotation from the rigid block's, 10 Hz
    // 8.7 / 0.19, 1 kHz 17 / 0.05, 3 kHz 2.0 / 0.12, 10 kHz 0.02 / 1e-3, 30 kHz 4e-3 / 5e-6.
    const auto e = sine();
    const dynamics::Summary rigid = dynamics::simulate(slender(), e, no_series()).summary;
    double previous = std::numeric_limits<double>::infinity();
    for (double f_hz : {3e3, 1e4, 3e4}) {
        INFO("f = " << f_hz << " Hz");
        const auto flex = dynamics::simulate_flexible(at(f_hz), e, no_series()).summary;
        REQUIRE_FALSE(flex.rigid_handover);
        const double d = from_rigid(flex.base, rigid);
        CHECK(d < previous);
        previous = d;
    }
    CHECK(previous < 5e-3);
}

TEST_CASE("the flexible integrator's work is bounded", "[dynamics][flexible][errors]") {
    using dynamics::detail::require_step_budget;
    CHECK_NOTHROW(require_step_budget(1000, 1.0, 7.5, 50250.0));
    CHECK_THROWS_MATCHES(
        require_step_budget(static_cast<std::size_t>(2e7) + 1, 3.25, 40000.0, 50250.0), NumericalError,
        Catch::Matchers::Message(
            "flexible-body integrator: 20000001 Dormand-Prince steps by t = 3.25 s, above the "
            "limit 20000000 (README, Limits): the mode at 40000 Hz is too stiff for the record "
            "(the rigid block runs from 50250 Hz)"));
}

TEST_CASE("central difference refuses a step beyond the elastic mode's stability limit",
          "[dynamics][flexible][cd][errors]") {
    const auto e = sine();
    // 1e-4 s is taken as 0.00125 s / 13 = 9.6e-5 s on this input's samples.
    for (double f_hz : {500.0, 1000.0}) {
        INFO("f = " << f_hz << " Hz");
        const double limit_s = dynamics::cd_stable_step_s(at(f_hz));
        CHECK(limit_s < 9.6e-5);
        const auto cd = no_series(dynamics::Integrator::central_difference);
        CHECK_THROWS_AS(dynamics::simulate_flexible(at(f_hz), e, cd), NumericalError);
        CHECK_THROWS_WITH(dynamics::simulate_flexible(at(f_hz), e, cd),
                          Contains("central difference: step 9.62e-05 s exceeds the stability "
                                   "limit") &&
                              Contains("of the elastic mode at f = " + std::to_string(int(f_hz)) +
                                       " Hz"));
    }
    // The limit is the scheme's own (rates at half steps, x'_n extrapolated: the root -1 of
    // its characteristic polynomial at omega dt = 2 (sqrt(1 + 4 zeta^2) - 2 zeta)) for the
    // mode against the free base, the highest of its contact states: 5.5 omega for this body.
    CHECK(dynamics::cd_stable_step_s(at(500.0)) == Approx(9.3e-5).epsilon(0.03));
    CHECK(dynamics::cd_stable_step_s(at(7.5)) > 5e-3);
    // A step within the limit runs and agrees with the event integrator (0.3% at 1e-5 s).
    const auto ev = dynamics::simulate_flexible(at(500.0), e, no_series()).summary;
    const auto cd = dynamics::simulate_flexible(
        at(500.0), e, no_series(dynamics::Integrator::central_difference, 1e-5)).summary;
    CHECK(cd.base.overturned == ev.base.overturned);
    CHECK(cd.base.rock_max_over_alpha == Approx(ev.base.rock_max_over_alpha).epsilon(0.01));
    CHECK(cd.modal_max_m == Approx(ev.modal_max_m).epsilon(0.01));
}

}  // namespace freestand_test_dynamics_test_flexible_limits
