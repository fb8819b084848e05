// Free flight under strong downward base motion lands when the closed-form
// ballistic motion says, whatever the friction, in both integrators.
#include <catch2/catch.hpp>

#include <cmath>

#include "helpers.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_dynamics_test_flight {

using namespace freestand;
using dynamics::Integrator;

namespace {

constexpr double g = 9.81;
constexpr double dt = 0.005;
constexpr int hold = 400;  // samples at full strength: 2 s

// Base accelerations: 0 at sample 0, then 0.01 g horizontal and -1.5 g vertical held for 2 s,
// then 0 at the next sample and after (the piecewise-linear convention, fully explicit).
std::vector<double> pulse(double value) {
    std::vector<double> a(hold + 3, 0.0);
    for (int i = 1; i <= hold + 1; ++i) a[static_cast<std::size_t>(i)] = value;
    return a;
}

// Exact motion of a free body relative to the base, u'' = -a(t), with a piecewise linear
// through samples a_k at k dt, from u = u' = 0 at t0 (inside segment k0).
struct Ballistic {
    double u = 0.0;
    double v = 0.0;
};

Ballistic integrate(const std::vector<double>& a, double t0, double t1, double offset = 0.0) {
    Ballistic b;
    double t = t0;
    auto accel = [&](double s) {
        const auto k = static_cast<std::size_t>(std::floor(s / dt));
        if (k + 1 >= a.size()) return 0.0;
        const double w = s / dt - static_cast<double>(k);
        return a[k] + w * (a[k + 1] - a[k]);
    };
    while (t < t1) {
        const double next = std::min(t1, (std::floor(t / dt + 1e-12) + 1.0) * dt);
        const double h = next - t;
        const double a0 = offset - accel(t);
        const double a1 = offset - accel(next - 1e-15 * dt);
        const double slope = (a1 - a0) / h;
        b.u += b.v * h + a0 * h * h / 2.0 + slope * h * h * h / 6.0;
        b.v += a0 * h + slope * h * h / 2.0;
        t = next;
    }
    return b;
}

}  // namespace

TEST_CASE("flight under -1.5 g lands at the closed-form time, whatever the friction",
          "[dynamics][hard][flight][hardening]") {
    const std::vector<double> ax = pulse(0.01 * g);
    const std::vector<double> ay = pulse(-1.5 * g);
    // Lift-off when g + yg'' reaches 0 on the first ramp: t = dt / 1.5.
    const double t_lift = dt / 1.5;
    const double t_end = (hold + 2) * dt;  // the base is at rest from here
    // Vertical, relative to the base: z'' = -(g + yg''); horizontal x'' = -xg''.
    const Ballistic z = integrate(ay, t_lift, t_end, -g);
    const Ballistic x = integrate(ax, t_lift, t_end);
    // After t_end: z = z0 + v0 tau - g tau^2 / 2 = 0.
    const double tau = (z.v + std::sqrt(z.v * z.v + 2.0 * g * z.u)) / g;
    const double t_land = t_end + tau;
    const double x_land = x.u + x.v * tau;
    // 2 s rising at 0.5 g relative to the base, then ballistic: about 2 + 1 + sqrt(3) s.
    CHECK(t_land == Approx(4.744).margin(0.002));
    for (double mu : {0.3, 1.0, 2.0}) {
        INFO("mu = " << mu);
        const auto model = dynamics::make_block_model(block::Block::uniform(0.15, 0.6, 38.0), mu);
        const auto e = test::samples(dt, ax, ay);
        const auto ev = dynamics::simulate(model, e, test::opts());
        REQUIRE(ev.impact_log.size() == 1);
        CHECK(ev.impact_log[0].time_s == Approx(t_land).epsilon(1e-9));
        // Below mu 2 the block tips a little as the effective gravity vanishes before lift-off
        // (tilt 1.5e-5 rad in flight); it still lands flat, and the landing impulse
        // (mu_k x 17 m/s) stops the 0.2 m/s slip at once: no friction dependence.
        // The slip and tilt just before lift-off (A grows without bound as g + yg'' -> 0) add
        // at most 8 micrometres to the ballistic drift.
        CHECK(ev.summary.slide_residual_m == Approx(std::abs(x_land)).margin(1e-5));
        const auto cd = dynamics::simulate(model, e, test::opts(Integrator::central_difference));
        REQUIRE(cd.impact_log.size() == 1);
        CHECK(cd.impact_log[0].time_s == Approx(t_land).margin(2e-4));
        CHECK(cd.summary.slide_residual_m == Approx(std::abs(x_land)).epsilon(1e-3));
    }
}

}  // namespace freestand_test_dynamics_test_flight
