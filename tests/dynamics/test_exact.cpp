// Exactness of the event-driven integrator against closed forms (docs/methods.md s.3).
#include <catch2/catch.hpp>
#include <cmath>

#include "helpers.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_dynamics_test_exact {

using namespace freestand;
using dynamics::Integrator;

TEST_CASE("pure sliding under a triangular pulse matches the closed form to round-off",
          "[dynamics][exact]") {
    // Base pulse xg'' = a t / tp, then a (2 - t/tp), zero after 2 tp (piecewise linear, exact in
    // the samples). Sliding starts at t0 where xg'' = mu g, with the block carried at the base
    // velocity vg(t0); its absolute velocity then grows at mu g until it meets the base
    // velocity again (after the pulse, at ts) and sticks.
    const double g = 9.81, mu = 0.2, a = 0.5 * g, tp = 0.5, dt = 0.01;
    std::vector<double> ax(301, 0.0);
    for (std::size_t i = 0; i <= 100; ++i) {
        const double t = dt * static_cast<double>(i);
        ax[i] = a * std::min(t / tp, 2.0 - t / tp);
    }
    const double t0 = tp * mu * g / a;
    const double vg0 = a * t0 * t0 / (2.0 * tp);
    const double ts = t0 + (a * tp - vg0) / (mu * g);
    const double i1 = a * (tp * tp * tp - t0 * t0 * t0) / (6.0 * tp);  // int vg, t0..tp
    const double i2 = a * tp * tp * 5.0 / 6.0;                        // tp..2tp
    const double i3 = a * tp * (ts - 2.0 * tp);                       // 2tp..ts
    const double u_res = vg0 * (ts - t0) + mu * g * (ts - t0) * (ts - t0) / 2.0 - (i1 + i2 + i3);
    const auto model = dynamics::make_block_model(block::Block::uniform(0.5, 0.5, 10.0), mu);
    const auto r = dynamics::simulate(model, test::samples(dt, ax), test::opts());
    CHECK(u_res < 0.0);
    CHECK(r.summary.slide_residual_m == Approx(-u_res).epsilon(1e-12));
    CHECK(r.summary.slide_max_m == Approx(-u_res).epsilon(1e-12));
    CHECK(r.summary.time_in_mode_s[1] == Approx(ts - t0).epsilon(1e-12));
    CHECK(r.summary.mode_changes == 2);
    CHECK(r.summary.rock_max_rad == 0.0);
}

TEST_CASE("frictionless block stays put in space: slip = -base displacement",
          "[dynamics][exact][hard]") {
    std::vector<double> ax;
    for (int i = 0; i <= 400; ++i) ax.push_back(3.0 * std::sin(0.05 * i) + 1.0 * std::cos(0.13 * i));
    const double dt = 0.005;
    const auto model = dynamics::make_block_model(block::Block::uniform(0.3, 0.6, 10.0), 0.0);
    const auto r = dynamics::simulate(model, test::samples(dt, ax), test::opts());
    // Exact double integral of piecewise-linear acceleration.
    double v = 0.0, d = 0.0, worst = 0.0;
    for (std::size_t i = 0; i + 1 < ax.size() && i + 1 < r.series.size(); ++i) {
        d += dt * v + dt * dt * (2.0 * ax[i] + ax[i + 1]) / 6.0;
        v += dt * (ax[i] + ax[i + 1]) / 2.0;
        worst = std::max(worst, std::abs(r.series[i + 1].slide_m + d));
    }
    CHECK(worst < 1e-11);
}

TEST_CASE("constant base acceleration above uplift: linearised Housner solution at small angles",
          "[dynamics][exact]") {
    // Slender block alpha ~ 0.02; xg'' = -0.03 g (to the left: tips over the right edge).
    // Linearised (Housner 1963): theta'' = p^2 (theta - alpha + a/g), theta = (a/g - alpha)
    // (cosh p t - 1). Linearisation error ~ (a/g) alpha^2 / 2 / (a/g - alpha) ~ 6e-4.
    const auto blk = block::Block::uniform(0.01, 0.5, 5.0);
    const double alpha = blk.alpha_rad(block::Edge::right), p = blk.p_radps(block::Edge::right);
    const double ag = 0.03;
    std::vector<double> ax(101, -ag * 9.81);
    const auto model = dynamics::make_block_model(blk, 1.0);
    const auto r = dynamics::simulate(model, test::samples(0.002, ax), test::opts());
    int checked = 0;
    for (const auto& s : r.series) {
        if (s.time_s < 0.02 || s.time_s > 0.2) continue;
        const double lin = (ag - alpha) * (std::cosh(p * s.time_s) - 1.0);
        REQUIRE(s.mode == dynamics::Mode::rock);
        CHECK(s.rotation_rad == Approx(lin).epsilon(2e-3));
        ++checked;
    }
    CHECK(checked > 50);
}

TEST_CASE("free rocking reproduces Housner's period", "[dynamics][exact]") {
    // T = (4/p) arccosh(1 / (1 - theta0/alpha)) (docs/methods.md s.1), from the linearised
    // equation: for alpha = 0.02 the exact period differs by O(alpha^2) ~ 1e-4.
    const auto blk = block::Block::uniform(0.01, 0.5, 5.0);
    const double alpha = blk.alpha_rad(block::Edge::right), p = blk.p_radps(block::Edge::right);
    for (double frac : {0.2, 0.5, 0.9}) {
        const double T = 4.0 / p * std::acosh(1.0 / (1.0 - frac));
        auto o = test::opts();
        o.initial_rotation_rad = frac * alpha;
        o.tail_s = 2.5 * T;
        const auto model = dynamics::make_block_model(blk, 1.0, std::nullopt, 1.0);
        const auto r = dynamics::simulate(model, test::samples(0.001, {0.0, 0.0}), o);
        REQUIRE(r.impact_log.size() >= 4);
        CHECK(r.impact_log[0].time_s == Approx(T / 4.0).epsilon(5e-4));
        CHECK(r.impact_log[3].time_s - r.impact_log[1].time_s == Approx(T).epsilon(5e-4));
        CHECK(r.summary.rock_max_over_alpha == Approx(frac).epsilon(1e-9));
    }
}

TEST_CASE("kinetic energy after each impact scales by r^2", "[dynamics][exact]") {
    const auto blk = block::Block::uniform(0.2, 0.6, 20.0);
    for (double rr : {0.9, 0.7}) {
        auto o = test::opts();
        o.initial_rotation_rad = 0.5 * blk.alpha_rad(block::Edge::right);
        const auto model = dynamics::make_block_model(blk, 1.0, std::nullopt, rr);
        const auto r = dynamics::simulate(model, test::samples(0.001, {0.0, 0.0}), o);
        REQUIRE(r.impact_log.size() >= 6);
        for (std::size_t i = 0; i + 1 < 6; ++i) {
            // Energy is conserved between impacts (no excitation), so E_{n+1} / E_n = r^2.
            const double e0 = std::pow(r.impact_log[i].omega_before_radps, 2);
            const double e1 = std::pow(r.impact_log[i + 1].omega_before_radps, 2);
            CHECK(e1 / e0 == Approx(rr * rr).epsilon(1e-8));
        }
        CHECK(r.summary.settlements >= 1);
        CHECK(r.series.back().mode == dynamics::Mode::rest);
    }
}

TEST_CASE("default restitution is Housner's for a symmetric block", "[dynamics][exact]") {
    // r = 1 - 1.5 sin^2(alpha) for a uniform block (docs/methods.md s.1).
    const auto blk = block::Block::uniform(0.2, 0.6, 20.0);
    auto o = test::opts();
    o.initial_rotation_rad = -0.3;
    const auto model = dynamics::make_block_model(blk, 1.0);
    const auto r = dynamics::simulate(model, test::samples(0.001, {0.0, 0.0}), o);
    REQUIRE(!r.impact_log.empty());
    const double s = std::sin(blk.alpha_rad(block::Edge::left));
    CHECK(r.impact_log[0].omega_after_radps / r.impact_log[0].omega_before_radps ==
          Approx(1.0 - 1.5 * s * s).epsilon(1e-14));
}

TEST_CASE("a block below both thresholds never moves, at any frequency", "[dynamics][exact]") {
    const auto blk = block::Block::uniform(0.15, 0.6, 38.0);  // tan(alpha) = 0.25
    for (double mu : {0.15, 0.5}) {
        const double a_g = 0.99 * std::min(mu, 0.25);
        const auto model = dynamics::make_block_model(blk, mu);
        for (double f : {0.2, 1.0, 3.0, 10.0, 30.0, 100.0}) {
            const auto e = dynamics::sine_excitation({a_g, f, 3.0, 0.0, 0.0});
            for (auto integ : {Integrator::event, Integrator::central_difference}) {
                const auto r = dynamics::simulate(model, e, test::opts(integ));
                CHECK(r.summary.slide_max_m == 0.0);
                CHECK(r.summary.rock_max_rad == 0.0);
                CHECK(r.summary.mode_changes == 0);
            }
        }
    }
}

TEST_CASE("free rocking: output samples from the dense output conserve energy",
          "[dynamics][exact]") {
    // No excitation, r = 1, symmetric block: E = I_O w^2 / 2 + M g R (cos(alpha - |theta|) -
    // cos(alpha)) is constant through the run (docs/methods.md s.1). The steps cross many samples
    // here (no input kinks), so most samples come from the Taylor polynomials (dense output).
    const auto blk = block::Block::uniform(0.2, 0.6, 20.0);
    const double alpha = blk.alpha_rad(block::Edge::right), R = blk.R_m(block::Edge::right);
    const double IO = blk.inertia_edge_kgm2(block::Edge::right), M = 20.0, g = 9.81;
    auto o = test::opts();
    o.initial_rotation_rad = 0.5 * alpha;
    o.tail_s = 5.0;
    const auto model = dynamics::make_block_model(blk, 1.0, std::nullopt, 1.0);
    const auto r = dynamics::simulate(model, test::samples(0.001, {0.0, 0.0}), o);
    REQUIRE(r.series.size() > 4000);
    REQUIRE(r.summary.impacts >= 4);
    CHECK(r.summary.steps < r.series.size() / 4);
    auto energy = [&](double th, double om) {
        return 0.5 * IO * om * om + M * g * R * (std::cos(alpha - std::abs(th)) - std::cos(alpha));
    };
    const double e0 = energy(0.5 * alpha, 0.0);
    double worst = 0.0;
    for (const auto& s : r.series)
        worst = std::max(worst, std::abs(energy(s.rotation_rad, s.angular_velocity_radps) - e0) / e0);
    INFO("worst relative energy drift " << worst);
    CHECK(worst < 1e-8);  // measured 8.9e-10 at the default rel_tol 1e-9
}

}  // namespace freestand_test_dynamics_test_exact
