// Biaxial sliding (docs/methods.md s.10): the planar limit, rotational invariance, the steady
// circle under a circular base acceleration, sticking under a rotating load, convergence of the
// central-difference baseline, and errors naming the parameter.
#include <catch2/catch.hpp>

#include <algorithm>
#include <functional>
#include <numbers>
#include <cmath>
#include <string>

#include "support/paths.hpp"
#include "core/errors.hpp"
#include "core/readers.hpp"
#include "dynamics/biaxial.hpp"
#include "dynamics/biaxial_detail.hpp"
#include "dynamics/helpers.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_dynamics_test_biaxial {

using namespace freestand;
using dynamics::Integrator;

namespace {

constexpr double g = 9.81;

// Squat enough (tan(alpha) = 0.5) that a block with mu = 0.2 only slides.
dynamics::BlockModel planar_block(double mu) {
    return dynamics::make_block_model(block::Block::uniform(0.3, 0.6, 100.0), mu);
}

dynamics::Excitation elcentro_at(double pga_g, double seconds) {
    dynamics::Excitation e = test::scaled_to(test::elcentro(), pga_g);
    e.horizontal_mps2.resize(static_cast<std::size_t>(std::lround(seconds / e.dt_s)) + 1);
    return e;
}

std::string message_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    }
    return "no InputError";
}

}  // namespace

TEST_CASE("biaxial: y = 0 reproduces the planar slide (both integrators)", "[biaxial]") {
    const dynamics::Excitation x = elcentro_at(0.5, 20.0);
    const dynamics::BiaxialExcitation xy =
        dynamics::biaxial_excitation(x, std::vector<double>(x.horizontal_mps2.size(), 0.0));
    for (Integrator integ : {Integrator::event, Integrator::central_difference}) {
        const auto o = test::opts(integ, 1e-4);
        const auto planar = dynamics::simulate(planar_block(0.2), x, o).summary;
        const auto bi = dynamics::simulate_biaxial(dynamics::make_biaxial_model(0.2), xy, o).summary;
        INFO(dynamics::integrator_name(integ));
        REQUIRE(planar.slide_max_m > 0.01);  // it slides far: a test of the sliding phases
        CHECK(bi.slide_max_m == Approx(planar.slide_max_m).epsilon(1e-9));
        CHECK(bi.slide_residual_m == Approx(planar.slide_residual_m).epsilon(1e-9));
        CHECK(bi.slide_max_x_m == Approx(planar.slide_max_m).epsilon(1e-9));
        CHECK(bi.slide_max_y_m == 0.0);
        CHECK(bi.mode_changes == planar.mode_changes);
        CHECK(bi.end_time_s == planar.end_time_s);
    }
}

TEST_CASE("biaxial: only a slow slip along the load, or a start, is taken slaved", "[biaxial]") {
    using dynamics::detail::takes_slaved;
    const double tau_s = dynamics::detail::slaved_tau_s(1e-6);
    const dynamics::detail::Vec2 a_g{-2.0, 0.0};  // load F = -a_g along +x, 2 m/s^2
    const double slow = 0.5 * tau_s * 2.0;
    CHECK(takes_slaved({0.0, 0.0}, a_g, 0.2, tau_s));
    CHECK(takes_slaved({slow, 0.0}, a_g, 0.2, tau_s));
    CHECK(takes_slaved({slow * std::cos(0.09), slow * std::sin(0.09)}, a_g, 0.2, tau_s));
    CHECK_FALSE(takes_slaved({slow * std::cos(0.2), slow * std::sin(0.2)}, a_g, 0.2, tau_s));
    CHECK_FALSE(takes_slaved({-slow, 0.0}, a_g, 0.2, tau_s));  // against the load: it stops
    CHECK_FALSE(takes_slaved({0.0, slow}, a_g, 0.2, tau_s));
    CHECK_FALSE(takes_slaved({4.0 * slow, 0.0}, a_g, 0.2, tau_s));  // fast: the full equation
    CHECK_FALSE(takes_slaved({slow, 0.0}, a_g, 0.0, tau_s));        // no friction: not stiff
    CHECK_FALSE(takes_slaved({0.0, 0.0}, {0.0, 0.0}, 0.2, tau_s));  // no load
    CHECK(dynamics::detail::slaved_tau_s(1e-12) == Approx(1e-8));
}

TEST_CASE("biaxial: y = 0 keeps the planar slide's stops at the default tolerance too",
          "[biaxial]") {
    // biaxial_options() takes slow slips along the load slaved (biaxial_event.cpp): in one
    // component the slaved equation is the planar one, and every stop is kept.
    const dynamics::Excitation x = elcentro_at(0.5, 20.0);
    const dynamics::BiaxialExcitation xy =
        dynamics::biaxial_excitation(x, std::vector<double>(x.horizontal_mps2.size(), 0.0));
    auto o = dynamics::biaxial_options();
    o.record_series = false;
    const auto planar = dynamics::simulate(planar_block(0.2), x, test::opts()).summary;
    const auto bi = dynamics::simulate_biaxial(dynamics::make_biaxial_model(0.2), xy, o).summary;
    CHECK(bi.mode_changes == planar.mode_changes);
    CHECK(bi.slide_max_m == Approx(planar.slide_max_m).epsilon(1e-6));
    CHECK(bi.slide_residual_m == Approx(planar.slide_residual_m).epsilon(1e-6));
}

TEST_CASE("biaxial: a slip that follows a turning load is taken slaved at the default "
          "tolerance, at a fraction of the steps and within it", "[biaxial]") {
    // El Centro #12, 140 as x (0.5 g) and 230 as y, mu 0.2: the approach to each start and stop
    // under a turning load is stiff (the direction relaxes in |v| / |a_g|): taken with the full
    // equation, 11658 steps; slaved below tau_s |a_g|, 4798, within 7e-8 of rel_tol 1e-12.
    auto x = core::read_at2(freestand::test::data_dir() + "/RSN175_IMPVALL.H_H-E12140.AT2");
    auto y = core::read_at2(freestand::test::data_dir() + "/RSN175_IMPVALL.H_H-E12230.AT2");
    const std::size_t n = static_cast<std::size_t>(20.0 / x.dt_s) + 1;
    x.accel_mps2.resize(n);
    y.accel_mps2.resize(n);
    double peak = 0.0;
    for (double a : x.accel_mps2) peak = std::max(peak, std::abs(a));
    const auto e = dynamics::biaxial_excitation_from_records(x, y, 0.5 * g / peak);
    const auto model = dynamics::make_biaxial_model(0.2);
    auto o = dynamics::biaxial_options();
    o.record_series = false;
    const auto fast = dynamics::simulate_biaxial(model, e, o).summary;
    o.rel_tol = 1e-12;
    o.abs_tol = 1e-14;
    const auto tight = dynamics::simulate_biaxial(model, e, o).summary;
    CHECK(fast.steps < 6000);
    CHECK(fast.slide_max_m == Approx(tight.slide_max_m).epsilon(1e-7));
}

TEST_CASE("biaxial: a 45-degree one-directional input equals the planar result along it",
          "[biaxial]") {
    const dynamics::Excitation x = elcentro_at(0.5, 20.0);
    const double c = std::sqrt(0.5);
    dynamics::Excitation diag_x = x;
    for (double& a : diag_x.horizontal_mps2) a *= c;
    const dynamics::BiaxialExcitation diag =
        dynamics::biaxial_excitation(diag_x, diag_x.horizontal_mps2);
    const auto planar = dynamics::simulate(planar_block(0.2), x).summary;
    const auto bi = dynamics::simulate_biaxial(dynamics::make_biaxial_model(0.2), diag).summary;
    CHECK(bi.slide_max_m == Approx(planar.slide_max_m).epsilon(1e-9));
    CHECK(bi.slide_residual_m == Approx(planar.slide_residual_m).epsilon(1e-9));
    CHECK(bi.slide_max_x_m == Approx(c * planar.slide_max_m).epsilon(1e-9));
    CHECK(bi.slide_max_y_m == Approx(c * planar.slide_max_m).epsilon(1e-9));
}

TEST_CASE("biaxial: friction is isotropic: the vector, not each component, decides a start",
          "[biaxial]") {
    // 0.25 g at 45 degrees: each component 0.177 g is below mu g = 0.2 g, the vector is not.
    dynamics::SineSpec spec{0.25 * std::sqrt(0.5), 2.0, 2.0};
    const auto moving = dynamics::simulate_biaxial(dynamics::make_biaxial_model(0.2),
                                                   dynamics::biaxial_sine_excitation(spec, 0.0));
    CHECK(moving.summary.slide_max_m > 1e-3);
    spec.amplitude_g = 0.19 * std::sqrt(0.5);
    const auto still = dynamics::simulate_biaxial(dynamics::make_biaxial_model(0.2),
                                                  dynamics::biaxial_sine_excitation(spec, 0.0));
    CHECK(still.summary.slide_max_m == 0.0);
}

TEST_CASE("biaxial: a circular base acceleration above mu g settles on the steady circle",
          "[biaxial]") {
    // a_g = A (sin wt, cos wt): x = A sin(2 pi f t), y with phase 90 degrees. Radius
    // sqrt(A^2 - (mu g)^2) / w^2 (docs/methods.md s.10).
    const double A_g = 0.5, mu = 0.2, f = 1.0, w = 2.0 * std::numbers::pi * f;
    const double radius = std::sqrt(std::pow(A_g * g, 2) - std::pow(mu * g, 2)) / (w * w);
    const dynamics::SineSpec spec{A_g, f, 20.0};
    auto o = test::opts();
    o.tail_s = 0.0;
    const auto r = dynamics::simulate_biaxial(dynamics::make_biaxial_model(mu),
                                              dynamics::biaxial_sine_excitation(spec, 90.0), o);
    // The last two cycles: half the peak-to-peak slip in each direction, and |v| / w.
    double x_lo = 1e9, x_hi = -1e9, y_lo = 1e9, y_hi = -1e9, v_min = 1e9, v_max = 0.0;
    for (const auto& s : r.series) {
        if (s.time_s < 18.0 || s.time_s > 20.0) continue;  // the last two cycles
        REQUIRE(s.sliding());
        x_lo = std::min(x_lo, s.slip_x_m);
        x_hi = std::max(x_hi, s.slip_x_m);
        y_lo = std::min(y_lo, s.slip_y_m);
        y_hi = std::max(y_hi, s.slip_y_m);
        const double speed = std::hypot(s.v_x_mps, s.v_y_mps);
        v_min = std::min(v_min, speed);
        v_max = std::max(v_max, speed);
    }
    // Samples every 1/400 cycle see the extremes within (pi/400)^2 / 2 = 3e-5.
    CHECK(0.5 * (x_hi - x_lo) == Approx(radius).epsilon(1e-3));
    CHECK(0.5 * (y_hi - y_lo) == Approx(radius).epsilon(1e-3));
    CHECK(v_min == Approx(radius * w).epsilon(1e-3));
    CHECK(v_max == Approx(radius * w).epsilon(1e-3));
}

TEST_CASE("biaxial: a rotating load below mu_s g does not move the block", "[biaxial]") {
    const dynamics::SineSpec spec{0.15, 2.0, 5.0};
    for (Integrator integ : {Integrator::event, Integrator::central_difference}) {
        const auto r = dynamics::simulate_biaxial(dynamics::make_biaxial_model(0.2, 0.1),
                                                  dynamics::biaxial_sine_excitation(spec, 90.0),
                                                  test::opts(integ));
        INFO(dynamics::integrator_name(integ));
        CHECK(r.summary.slide_max_m == 0.0);
        CHECK(r.summary.mode_changes == 0);
        CHECK(r.summary.time_in_mode_s[static_cast<std::size_t>(dynamics::Mode::slide)] == 0.0);
        CHECK(r.summary.end_time_s < 5.01);  // at rest from the end of the record
    }
}

TEST_CASE("biaxial: central difference converges to the event-driven answer", "[biaxial]") {
    const core::Record x = test::elcentro();
    const core::Record y = core::read_at2(freestand::test::data_dir() + "/RSN175_IMPVALL.H_H-E12230.AT2");
    dynamics::BiaxialExcitation e = dynamics::biaxial_excitation_from_records(x, y, 3.0);
    const auto n = static_cast<std::size_t>(std::lround(20.0 / e.dt_s)) + 1;
    e.x_mps2.resize(n);
    e.y_mps2.resize(n);
    const auto model = dynamics::make_biaxial_model(0.2);
    const double ref = dynamics::simulate_biaxial(model, e).summary.slide_max_m;
    REQUIRE(ref > 0.01);
    double last_err = 1e9;
    for (double dt : {1e-3, 1e-4, 1e-5}) {
        const double cd =
            dynamics::simulate_biaxial(model, e, test::opts(Integrator::central_difference, dt))
                .summary.slide_max_m;
        const double err = std::abs(cd - ref) / ref;
        INFO("dt " << dt << " error " << err);
        CHECK(err < 0.5 * last_err);
        last_err = err;
    }
    CHECK(last_err < 1e-3);
}

TEST_CASE("biaxial: the peak of |u| is found between samples", "[biaxial]") {
    // On the steady circle |u - centre| is constant, but |u| peaks where u . v = 0, generally
    // between samples: the peak must be at least every sampled |u|.
    const auto r = dynamics::simulate_biaxial(dynamics::make_biaxial_model(0.2),
                                              dynamics::biaxial_sine_excitation({0.5, 1.0, 5.0}, 90.0));
    double sampled = 0.0;
    for (const auto& s : r.series) sampled = std::max(sampled, std::hypot(s.slip_x_m, s.slip_y_m));
    CHECK(r.summary.slide_max_m >= sampled);
    CHECK(r.summary.slide_max_m < sampled * (1.0 + 1e-4));
}

TEST_CASE("biaxial: lift-off is free flight and landing as the planar slide", "[biaxial]") {
    // A vertical sine beyond g: the block leaves the base each cycle and lands flat.
    dynamics::Excitation x = dynamics::sine_excitation({0.4, 2.0, 4.0});
    dynamics::SineSpec vs{1.3, 2.0, 4.0};
    vs.phase_deg = 30.0;
    x.vertical_mps2 = dynamics::sine_excitation(vs).horizontal_mps2;
    const auto planar = dynamics::simulate(planar_block(0.2), x).summary;
    const auto bi = dynamics::simulate_biaxial(
        dynamics::make_biaxial_model(0.2),
        dynamics::biaxial_excitation(x, std::vector<double>(x.horizontal_mps2.size(), 0.0)));
    REQUIRE(planar.time_in_mode_s[static_cast<std::size_t>(dynamics::Mode::flight)] > 0.1);
    CHECK(bi.summary.time_in_mode_s[static_cast<std::size_t>(dynamics::Mode::flight)] ==
          Approx(planar.time_in_mode_s[static_cast<std::size_t>(dynamics::Mode::flight)]).epsilon(1e-6));
    CHECK(bi.summary.slide_max_m == Approx(planar.slide_max_m).epsilon(1e-6));
}

TEST_CASE("biaxial: the rocking screen names the component or the friction", "[biaxial]") {
    const block::Block slender = block::Block::uniform(0.15, 0.6);  // tan(alpha) = 0.25
    const auto e = dynamics::biaxial_sine_excitation({0.3, 2.0, 2.0}, 90.0);
    const auto rocks =
        dynamics::biaxial_rocking_reason(slender, dynamics::make_biaxial_model(0.6, 0.2), e);
    REQUIRE(rocks);
    CHECK(rocks->find("component reaches") != std::string::npos);
    // mu_s below tan(alpha): the block slides before it can tip.
    CHECK_FALSE(dynamics::biaxial_rocking_reason(slender, dynamics::make_biaxial_model(0.2), e));
    const auto lifts =
        dynamics::biaxial_rocking_reason(slender, dynamics::make_biaxial_model(0.4, 0.3), e);
    REQUIRE(lifts);
    CHECK(lifts->find("mu_k") != std::string::npos);
}

TEST_CASE("biaxial: bad inputs name the parameter", "[biaxial]") {
    CHECK(message_of([] { dynamics::make_biaxial_model(-0.1); }).find("mu_s") != std::string::npos);
    CHECK(message_of([] { dynamics::make_biaxial_model(0.2, 0.3); }).find("mu_k") != std::string::npos);
    CHECK(message_of([] { dynamics::biaxial_sine_excitation({0.2, 1.0, 1.0}, NAN); })
              .find("phase_deg") != std::string::npos);
    const dynamics::Excitation x = test::samples(0.01, {0.0, 1.0, 0.0});
    CHECK(message_of([&] { dynamics::biaxial_excitation(x, {0.0, 1.0, 0.0, 1.0}); })
              .find("y_mps2") != std::string::npos);
    const auto model = dynamics::make_biaxial_model(0.2);
    dynamics::BiaxialExcitation e = dynamics::biaxial_excitation(x, {0.0, 1.0, 0.0});
    dynamics::BiaxialExcitation short_y = e;
    short_y.y_mps2.pop_back();
    CHECK(message_of([&] { dynamics::simulate_biaxial(model, short_y); }).find("y_mps2") !=
          std::string::npos);
    dynamics::BiaxialExcitation nan_y = e;
    nan_y.y_mps2[1] = NAN;
    CHECK(message_of([&] { dynamics::simulate_biaxial(model, nan_y); }).find("finite") !=
          std::string::npos);
    dynamics::BiaxialExcitation no_dt = e;
    no_dt.dt_s = 0.0;
    CHECK(message_of([&] { dynamics::simulate_biaxial(model, no_dt); }).find("dt_s") !=
          std::string::npos);
    auto o = test::opts();
    o.initial_rotation_rad = 0.01;
    CHECK(message_of([&] { dynamics::simulate_biaxial(model, e, o); })
              .find("initial_rotation_rad") != std::string::npos);
    o = test::opts();
    o.rel_tol = 0.0;
    CHECK(message_of([&] { dynamics::simulate_biaxial(model, e, o); }).find("rel_tol") !=
          std::string::npos);
}

TEST_CASE("biaxial: a slow slip under El Centro x and y is settled quasi-statically, not chased",
          "[biaxial][hard]") {
    // Both El Centro #12 components, x scaled to 0.5 g, mu 0.2: a slip near 1e-10 m/s while
    // |a_g| hovered at mu_k G took 3.6e7 Dormand-Prince steps (9 s) at the default tolerance
    // and threw "step below 1e-14 s" at rel_tol 1e-12, before slow slips (< 1e-6 m/s) stopped
    // or followed -a_g. Now both tolerances finish in tens of thousands of steps and agree.
    auto x = core::read_at2(freestand::test::data_dir() + "/RSN175_IMPVALL.H_H-E12140.AT2");
    auto y = core::read_at2(freestand::test::data_dir() + "/RSN175_IMPVALL.H_H-E12230.AT2");
    const std::size_t n = static_cast<std::size_t>(20.0 / x.dt_s) + 1;
    x.accel_mps2.resize(n);
    y.accel_mps2.resize(n);
    double peak = 0.0;
    for (double a : x.accel_mps2) peak = std::max(peak, std::abs(a));
    const auto e = dynamics::biaxial_excitation_from_records(x, y, 0.5 * g / peak);
    const auto model = dynamics::make_biaxial_model(0.2);
    dynamics::Options o;
    o.record_series = false;
    const auto loose = dynamics::simulate_biaxial(model, e, o);
    o.rel_tol = 1e-12;
    o.abs_tol = 1e-14;
    const auto tight = dynamics::simulate_biaxial(model, e, o);
    CHECK(loose.summary.steps < 200000);
    CHECK(tight.summary.steps < 2000000);
    CHECK(loose.summary.slide_max_m == Approx(tight.summary.slide_max_m).epsilon(1e-8));
    CHECK(loose.summary.slide_max_m > 0.02);
}

}  // namespace freestand_test_dynamics_test_biaxial
