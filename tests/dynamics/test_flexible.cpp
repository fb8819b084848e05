// The flexible body (docs/methods.md s.10): its two limits (an infinitely stiff mode is the
// rigid block, a held base is the linear oscillator), frequency-induced rocking, central
// difference converging to the event-driven answer, strong rocking converging with the
// tolerance, bad input.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>

#include "core/errors.hpp"
#include "dynamics/flexible.hpp"
#include "helpers.hpp"
#include "spectra/response.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_dynamics_test_flexible {

using namespace freestand;
using Catch::Matchers::Message;

namespace {
// Relative agreement of the stiff limit: the mode's static deflection under 0.5 g at 2 kHz is
// 3e-8 m; the impact's residue in the mode, (pi / omega T)^2 of the jump (flexible_detail.hpp).
constexpr double kStiffRel = 2e-3;
// A mode at 2 kHz meets a 10 ms contact pulse as a rigid body: omega T = 126 (at the default
// 0.1 ms it would keep 99.7% of its momentum through an impact, as any mode below ~1 kHz).
constexpr double kStiffHz = 2000.0;
constexpr double kLongImpact_s = 0.01;
// The spectrum's oscillator samples its peak at sub-steps of T / 20: it reads low by at most
// 1 - cos(pi / 20) = 1.2%; the model locates the peak exactly.
constexpr double kOscRel = 0.013;

dynamics::BlockModel rigid(double b, double h, double mu) {
    return dynamics::make_block_model(block::Block::uniform(b, h, 1000.0), mu);
}

dynamics::FlexibleModel flexible(const dynamics::BlockModel& r, double f_hz, double zeta = 0.02) {
    dynamics::FlexibleMode m;
    m.frequency_hz = f_hz;
    m.damping = zeta;
    return dynamics::make_flexible_model(r, m);
}

dynamics::Options quick() {
    dynamics::Options o;
    o.tail_s = 2.0;
    o.record_series = false;
    return o;
}

// A mode much stiffer than the body and faster than its impacts.
dynamics::FlexibleModel stiff(const dynamics::BlockModel& r, double zeta = 0.02) {
    auto m = flexible(r, kStiffHz, zeta);
    m.impact_duration_s = kLongImpact_s;
    return m;
}

dynamics::Options central_difference(double dt_s) {
    auto o = quick();
    o.integrator = dynamics::Integrator::central_difference;
    o.cd_dt_s = dt_s;
    return o;
}

// Largest relative difference of the peak slip, rotation and modal displacement.
double peak_error(const dynamics::FlexibleSummary& s, const dynamics::FlexibleSummary& ref) {
    const auto rel = [](double a, double b) { return b > 0.0 ? std::abs(a - b) / b : std::abs(a); };
    return std::max({rel(s.base.slide_max_m, ref.base.slide_max_m),
                     rel(s.base.rock_max_rad, ref.base.rock_max_rad),
                     rel(s.modal_max_m, ref.modal_max_m)});
}

}  // namespace

TEST_CASE("a very stiff mode reproduces the rigid block", "[dynamics][flexible]") {
    const auto sine = dynamics::sine_excitation({0.5, 2.0, 2.0, 0.0, 0.0});
    SECTION("rocking (friction holds)") {
        const auto r = rigid(0.2, 0.6, 0.7);
        const auto rig = dynamics::simulate(r, sine, quick());
        const auto flex = dynamics::simulate_flexible(stiff(r), sine, quick());
        REQUIRE(rig.summary.rock_max_rad > 0.01);
        CHECK_FALSE(rig.summary.overturned);
        CHECK(flex.summary.uplifted);
        CHECK(flex.summary.base.overturned == rig.summary.overturned);
        CHECK(flex.summary.base.rock_max_rad ==
              Approx(rig.summary.rock_max_rad).epsilon(kStiffRel));
        CHECK(flex.summary.base.impacts > 0);
        SECTION("central difference, 1e-5 s") {
            const auto o = central_difference(1e-5);
            const auto rig_cd = dynamics::simulate(r, sine, o).summary;
            const auto flex_cd = dynamics::simulate_flexible(stiff(r), sine, o).summary;
            CHECK(flex_cd.base.integrator == "cd");
            CHECK(flex_cd.base.rock_max_rad == Approx(rig_cd.rock_max_rad).epsilon(kStiffRel));
            CHECK(flex_cd.base.overturned == rig_cd.overturned);
        }
    }
    SECTION("sliding (friction below tan alpha)") {
        // The jump of friction at a slip reversal excites the mode with an acceleration that
        // does not vanish as f grows (only its displacement does): the stick-slip sequence
        // matches the rigid block's once that ringing is damped (the residual is 1.5% off at
        // 150 Hz, 0.5% at 500 Hz, 0.13% at 2000 Hz).
        const auto r = rigid(0.4, 0.6, 0.2);
        const auto rig = dynamics::simulate(r, sine, quick());
        const auto flex = dynamics::simulate_flexible(flexible(r, 2000.0, 0.5), sine, quick());
        REQUIRE(rig.summary.slide_max_m > 0.01);
        CHECK_FALSE(flex.summary.uplifted);
        CHECK(flex.summary.base.slide_max_m ==
              Approx(rig.summary.slide_max_m).epsilon(kStiffRel));
        CHECK(flex.summary.base.slide_residual_m ==
              Approx(rig.summary.slide_residual_m).epsilon(kStiffRel));
    }
}

TEST_CASE("a held base gives the linear oscillator (Nigam-Jennings)", "[dynamics][flexible]") {
    // Friction (the top of its range) and slenderness far beyond the 0.3 g demand: the base
    // never leaves rest.
    const auto r = rigid(50.0, 0.6, 2.0);
    const core::Record rec = test::elcentro();
    const auto e = test::scaled_to(rec, 0.3);
    for (double f_hz : {2.0, 7.5}) {
        auto o = quick();
        o.tail_s = 0.0;
        const auto flex = dynamics::simulate_flexible(flexible(r, f_hz, 0.05), e, o);
        core::Record scaled = rec;
        scaled.accel_mps2 = e.horizontal_mps2;
        const auto ref = spectra::peak_responses(scaled, 0.05, {f_hz});
        INFO("f = " << f_hz << " Hz");
        CHECK_FALSE(flex.summary.uplifted);
        CHECK(flex.summary.base.slide_max_m == 0.0);
        CHECK(flex.summary.modal_max_m >= std::abs(ref[0].sd_m) * (1.0 - 1e-9));
        CHECK(flex.summary.modal_max_m == Approx(std::abs(ref[0].sd_m)).epsilon(kOscRel));
    }
}

TEST_CASE("a sine at the fixed-base frequency below g tan(alpha) rocks the flexible body only",
          "[dynamics][flexible]") {
    // tan(alpha) = 1/3: a rigid block needs 0.33 g to uplift; 0.1 g at 4 Hz excites the mode at
    // resonance and its inertia lifts the base (docs/methods.md s.2, frequency-induced rocking).
    const auto r = rigid(0.25, 0.75, 0.8);
    const auto sine = dynamics::sine_excitation({0.1, 4.0, 5.0, 0.0, 0.0});
    const auto rig = dynamics::simulate(r, sine, quick());
    const auto flex = dynamics::simulate_flexible(flexible(r, 4.0), sine, quick());
    CHECK(rig.summary.rock_max_rad == 0.0);
    CHECK(rig.summary.time_in_mode_s[static_cast<std::size_t>(dynamics::Mode::rock)] == 0.0);
    CHECK(flex.summary.uplifted);
    CHECK(flex.summary.base.rock_max_rad > 1e-4);
    // Off resonance (15 Hz) the same amplitude leaves it down.
    const auto off = dynamics::sine_excitation({0.1, 15.0, 5.0, 0.0, 0.0});
    CHECK_FALSE(dynamics::simulate_flexible(flexible(r, 4.0), off, quick()).summary.uplifted);
}

TEST_CASE("the flexible model states its cantilever defaults", "[dynamics][flexible]") {
    const auto m = flexible(rigid(0.25, 0.75, 0.8), 5.0);
    CHECK(m.mass_fraction == dynamics::cantilever_modal_mass_fraction);
    CHECK(m.height_m == Approx(0.726 * 1.5));
    CHECK(m.mass_fraction_default);
    CHECK(m.height_default);
    // The body's height is the rigid model's top: 0.726 of it when the top is not at 2 h.
    const auto low_top = dynamics::make_block_model(block::Block::uniform(0.25, 0.75, 1000.0), 0.8,
                                                    std::nullopt, std::nullopt, 1.2);
    CHECK(flexible(low_top, 5.0).height_m == Approx(0.726 * 1.2).epsilon(1e-15));
}

TEST_CASE("make_flexible_model refuses bad modes", "[dynamics][flexible][errors]") {
    const auto r = rigid(0.25, 0.75, 0.8);
    auto mode = [](double f, double z, std::optional<double> mass, std::optional<double> h) {
        dynamics::FlexibleMode m;
        m.frequency_hz = f;
        m.damping = z;
        m.mass_fraction = mass;
        m.height_m = h;
        return m;
    };
    CHECK_THROWS_MATCHES(dynamics::make_flexible_model(r, mode(0.0, 0.02, {}, {})), InputError,
                         Message("flexible.f: fixed-base frequency must be > 0 Hz; got 0"));
    CHECK_THROWS_MATCHES(dynamics::make_flexible_model(r, mode(NAN, 0.02, {}, {})), InputError,
                         Message("flexible.f: fixed-base frequency must be > 0 Hz; got nan"));
    CHECK_THROWS_MATCHES(dynamics::make_flexible_model(r, mode(5.0, 1.0, {}, {})), InputError,
                         Message("flexible.zeta: modal damping ratio must be in [0, 1); got 1"));
    CHECK_THROWS_MATCHES(dynamics::make_flexible_model(r, mode(5.0, -0.1, {}, {})), InputError,
                         Message("flexible.zeta: modal damping ratio must be in [0, 1); got -0.1"));
    CHECK_THROWS_MATCHES(dynamics::make_flexible_model(r, mode(5.0, 0.02, 1.0, {})), InputError,
                         Message("flexible.mass: modal mass fraction must be in (0, 1); got 1"));
    CHECK_THROWS_MATCHES(dynamics::make_flexible_model(r, mode(5.0, 0.02, {}, 0.0)), InputError,
                         Message("flexible.height: modal height must be > 0 m; got 0"));
    CHECK_THROWS_MATCHES(
        dynamics::make_flexible_model(r, mode(5.0, 0.02, 0.9, 1.5)), InputError,
        Message("flexible.height: a modal mass of 0.9 M at 1.5 m carries more second moment "
                "than the body has (CG height 0.75 m, I_c 208.33333333333334 kg m^2): lower "
                "the mass fraction or the height"));
}

TEST_CASE("simulate_flexible refuses settings it does not support", "[dynamics][flexible][errors]") {
    const auto m = flexible(rigid(0.25, 0.75, 0.8), 5.0);
    const auto sine = dynamics::sine_excitation({0.1, 4.0, 1.0, 0.0, 0.0});
    auto o = quick();
    o.initial_rotation_rad = 0.01;
    CHECK_THROWS_MATCHES(dynamics::simulate_flexible(m, sine, o), InputError,
                         Message("initial condition: the flexible-body model starts at rest (no "
                                 "initial rotation or slip)"));
}

TEST_CASE("central difference converges to the event-driven flexible body",
          "[dynamics][flexible]") {
    // Sign checks at step ends put each switch up to one step late: the error falls about as
    // the step (to 0.04-0.1 of it from 1e-4 to 1e-5 s on these cases).
    constexpr double kRatio = 0.25;
    struct Case {
        const char* name;
        dynamics::BlockModel block;
        dynamics::SineSpec sine;
        double f_hz;
    };
    const Case cases[] = {
        {"slides (mu 0.2 < tan alpha)", rigid(0.4, 0.6, 0.2), {0.5, 2.0, 2.0, 0.0, 0.0}, 7.5},
        {"rocks with impacts and flights", rigid(0.2, 0.6, 0.7), {0.5, 2.0, 2.0, 0.0, 0.0}, 7.5},
        {"frequency-induced rocking", rigid(0.25, 0.75, 0.8), {0.1, 4.0, 5.0, 0.0, 0.0}, 4.0},
    };
    for (const Case& c : cases) {
        INFO(c.name);
        const auto e = dynamics::sine_excitation(c.sine);
        const auto m = flexible(c.block, c.f_hz);
        const auto ref = dynamics::simulate_flexible(m, e, quick()).summary;
        const auto coarse = dynamics::simulate_flexible(m, e, central_difference(1e-4)).summary;
        const auto fine = dynamics::simulate_flexible(m, e, central_difference(1e-5)).summary;
        CHECK(coarse.uplifted == ref.uplifted);
        CHECK(fine.uplifted == ref.uplifted);
        CHECK(peak_error(fine, ref) < kRatio * peak_error(coarse, ref));
        CHECK(peak_error(fine, ref) < 1e-3);
    }
}

TEST_CASE("strong rocking of the flexible body converges with the tolerance",
          "[dynamics][flexible]") {
    // El Centro at 0.9 g on a block of tan(alpha) = 0.5 with a 7.5 Hz mode: the body rocks to
    // 0.3 rad through ~100 impacts, flights and landings (mu 0.6), or overturns (mu 0.525).
    // Before the impact rule conserved the modal momentum and events rising out of zero were
    // located, its peaks moved by 0.2-4 between tolerances and by 10% under a 1e-12 change of
    // the input's scale (docs/methods.md s.10).
    core::Record rec = test::elcentro();
    rec.accel_mps2.resize(static_cast<std::size_t>(20.0 / rec.dt_s) + 1);
    for (double mu : {0.6, 0.525}) {
        INFO("mu " << mu);
        const auto m = flexible(rigid(0.3, 0.6, mu), 7.5);
        auto o = quick();
        o.tail_s = 10.0;
        std::vector<dynamics::FlexibleSummary> runs;
        for (double tol : {1e-9, 1e-12}) {
            o.rel_tol = tol;
            o.abs_tol = tol * 1e-2;
            for (double scale : {1.0, 1.0 + 1e-9})
                runs.push_back(
                    dynamics::simulate_flexible(m, test::scaled_to(rec, 0.9 * scale), o).summary);
        }
        REQUIRE(runs[2].base.impacts > 40);
        for (const auto& r : runs) {
            CHECK(r.base.overturned == runs[2].base.overturned);
            CHECK(peak_error(r, runs[2]) < 1e-5);
        }
    }
}

}  // namespace freestand_test_dynamics_test_flexible
