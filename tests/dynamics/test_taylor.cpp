// Taylor-series steps of the contact phases (taylor.hpp): the polynomials against an RK4
// reference with 20000 sub-steps, the fixed-degree and adaptive kernels against each other,
// the step shortening, and the zero searches used for impacts.
#include <array>
#include <catch2/catch.hpp>
#include <cmath>

#include "dynamics/mechanics.hpp"
#include "dynamics/taylor.hpp"
#include "helpers.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_dynamics_test_taylor {

using namespace freestand;
using namespace freestand::dynamics::detail;
using dynamics::Mode;

namespace {

using State = std::array<double, 4>;  // u, u', theta, theta'

// Classical RK4 on the contact equations with the base linear in tau, n sub-steps: a reference
// whose error (h/n)^4 is far below the tolerances tested.
State rk4_reference(const Geometry& g, const ContactStart& x0, double h, int n) {
    auto f = [&](double tau, const State& y) {
        const double a = g.alpha[static_cast<std::size_t>(Geometry::index(x0.s))] - y[2];
        const Base b{x0.ax0 + x0.ax1 * tau, x0.G0 + x0.G1 * tau};
        const Accel acc = x0.mode == Mode::rock
                              ? rock_accel_sc(g, x0.s, std::sin(a), std::cos(a), y[3], b)
                              : slide_rock_accel_sc(g, x0.s, x0.sigma, std::sin(a), std::cos(a), y[3], b);
        const bool slip = x0.mode == Mode::slide_rock;
        return State{slip ? y[1] : 0.0, slip ? acc.u_dd : 0.0, y[3], acc.th_dd};
    };
    State y{x0.u, x0.v, x0.th, x0.om};
    const double dt = h / n;
    for (int i = 0; i < n; ++i) {
        const double tau = dt * i;
        auto add = [](const State& a, const State& b, double c) {
            return State{a[0] + c * b[0], a[1] + c * b[1], a[2] + c * b[2], a[3] + c * b[3]};
        };
        const State k1 = f(tau, y), k2 = f(tau + dt / 2, add(y, k1, dt / 2)),
                    k3 = f(tau + dt / 2, add(y, k2, dt / 2)), k4 = f(tau + dt, add(y, k3, dt));
        for (std::size_t j = 0; j < 4; ++j) y[j] += dt / 6 * (k1[j] + 2 * k2[j] + 2 * k3[j] + k4[j]);
    }
    return y;
}

ContactStart start(const Geometry& g, Mode mode, int s, double th, double om) {
    ContactStart x0;
    x0.mode = mode;
    x0.s = s;
    x0.sigma = 1;
    x0.th = th;
    x0.om = om;
    x0.u = 0.01;
    x0.v = mode == Mode::slide_rock ? 0.2 : 0.0;
    const double a = g.alpha[static_cast<std::size_t>(Geometry::index(s))] - th;
    x0.sn = std::sin(a);
    x0.c = std::cos(a);
    // A steep piece of a strong record: 0.9 g rising by 60 g/s, vertical 0.4 g falling.
    x0.ax0 = -0.9 * 9.81;
    x0.ax1 = 60 * 9.81;
    x0.G0 = 9.81 * 1.4;
    x0.G1 = -30 * 9.81;
    return x0;
}

}  // namespace

TEST_CASE("Taylor rock step matches an RK4 reference and its own derivatives",
          "[dynamics][taylor]") {
    const Geometry g = make_geometry(dynamics::make_block_model(block::Block::uniform(0.15, 0.6, 38.0), 0.8));
    for (int s : {1, -1}) {
        for (double th : {0.0, 0.02, 0.2}) {
            const ContactStart x0 = start(g, Mode::rock, s, th, th == 0.0 ? 0.3 : -0.5);
            ContactSeries S;
            RockDegree rock;
            const double h = taylor_contact_step(g, x0, 0.005, 1e-12, 1e-14, S, rock);
            REQUIRE(h == 0.005);
            const State ref = rk4_reference(g, x0, h, 20000);
            CHECK(S.th_end == Approx(ref[2]).margin(1e-13));
            CHECK(S.om_end == Approx(ref[3]).margin(1e-11));
            CHECK(S.theta(h) == Approx(S.th_end).margin(1e-15));
            CHECK(S.omega(h) == Approx(S.om_end).margin(1e-14));
            // theta''(0) of the polynomial is the equation of motion's.
            const Accel a0 = rock_accel_sc(g, s, x0.sn, x0.c, x0.om, {x0.ax0, x0.G0});
            CHECK(S.theta_dd(0.0) == Approx(a0.th_dd).epsilon(1e-14));
        }
    }
}

TEST_CASE("fixed-degree and adaptive rock kernels agree, the degree follows the tolerance",
          "[dynamics][taylor]") {
    const Geometry g = make_geometry(dynamics::make_block_model(block::Block::uniform(0.3, 0.6, 38.0), 0.8));
    const ContactStart x0 = start(g, Mode::rock, 1, 0.05, 0.4);
    ContactSeries fixed, adaptive;
    RockDegree rock{rock_degree_min, 0};
    taylor_contact_step(g, x0, 0.005, 1e-9, 1e-11, fixed, rock);
    taylor_detail::rock_step(g, x0, 0.005, 1e-9, 1e-11, adaptive);
    // Raised from the lowest degree to the one the adaptive loop stops at.
    CHECK(fixed.n == adaptive.n);
    CHECK(rock.degree == adaptive.n);
    CHECK(fixed.th_end == Approx(adaptive.th_end).epsilon(1e-15));
    CHECK(fixed.om_end == Approx(adaptive.om_end).epsilon(1e-15));
    ContactSeries tight;
    taylor_detail::rock_step(g, x0, 0.005, 1e-14, 1e-16, tight);
    CHECK(tight.n > adaptive.n);
}

TEST_CASE("Taylor slide-rock step matches an RK4 reference", "[dynamics][taylor]") {
    const Geometry g = make_geometry(dynamics::make_block_model(block::Block::uniform(0.15, 0.6, 38.0), 0.3));
    for (int s : {1, -1}) {
        for (double th : {0.01, 0.3}) {
          for (int sigma : {-s, s}) {
            ContactStart x0 = start(g, Mode::slide_rock, s, th, 0.6);
            x0.sigma = sigma;
            if (th > 0.1) x0.v = 0.0;  // slip starting from rest too
            ContactSeries S;
            RockDegree rock;
            const double h = taylor_contact_step(g, x0, 0.005, 1e-12, 1e-14, S, rock);
            REQUIRE(h == 0.005);
            const State ref = rk4_reference(g, x0, h, 20000);
            CHECK(S.slip(h) == Approx(ref[0]).margin(1e-13));
            CHECK(S.slip_velocity(h) == Approx(ref[1]).margin(1e-11));
            CHECK(S.th_end == Approx(ref[2]).margin(1e-13));
            CHECK(S.om_end == Approx(ref[3]).margin(1e-11));
            const Accel a0 =
                slide_rock_accel_sc(g, s, x0.sigma, x0.sn, x0.c, x0.om, {x0.ax0, x0.G0});
            CHECK(S.theta_dd(0.0) == Approx(a0.th_dd).epsilon(1e-13));
            CHECK(S.slip_accel(0.0) == Approx(a0.u_dd).epsilon(1e-13));
          }
        }
    }
}

TEST_CASE("a step too long for the highest degree is shortened to one that meets the tolerance",
          "[dynamics][taylor]") {
    // A small block spinning fast: 2 s is far beyond the series' radius of convergence.
    const Geometry g = make_geometry(dynamics::make_block_model(block::Block::uniform(0.02, 0.05, 1.0), 0.8));
    ContactStart x0 = start(g, Mode::rock, 1, 0.1, 20.0);
    ContactSeries S;
    RockDegree rock;
    const double h = taylor_contact_step(g, x0, 2.0, 1e-10, 1e-12, S, rock);
    CHECK(h < 0.1);
    CHECK(h > 1e-4);
    CHECK(S.n == taylor_max_order);
    const State ref = rk4_reference(g, x0, h, 20000);
    CHECK(S.th_end == Approx(ref[2]).epsilon(1e-9));
    CHECK(S.om_end == Approx(ref[3]).epsilon(1e-9));
    // Just past alpha under gravity alone, spinning, over 0.1 s: there every other
    // coefficient nearly vanishes, the last one too, and the shortening must still come out
    // below the requested step (from the last coefficient alone it once returned 0.121 s).
    x0 = start(g, Mode::rock, 1, g.alpha[1] + 1e-9, 20.0);
    x0.ax0 = x0.ax1 = x0.G1 = 0.0;
    x0.G0 = 9.81;
    const double h2 = taylor_detail::rock_step(g, x0, 0.1, 1e-10, 1e-12, S);
    CHECK(h2 < 0.1);
    CHECK(h2 > 0.0);
    const State ref2 = rk4_reference(g, x0, h2, 20000);
    CHECK(S.theta(h2) == Approx(ref2[2]).epsilon(1e-8));
}

TEST_CASE("impact search: a dip below zero between the end points is found", "[dynamics][taylor]") {
    // theta = (tau - 1.0e-3)(tau - 1.2e-3): positive at both ends of a 5 ms step and at every one
    // of the 8 sample points, negative between 1.0 and 1.2 ms.
    ContactSeries S;
    S.n = 2;
    S.th[0] = 1.2e-6;
    S.th[1] = -2.2e-3;
    S.th[2] = 1.0;
    const double h = 0.005;
    CHECK(S.theta(h) > 0.0);
    CHECK_FALSE(stays_positive(S.theta_poly(), h));
    const ZeroBracket z = zero_bracket(S.theta_poly(), h);
    REQUIRE(z.found);
    CHECK(z.f_a >= 0.0);
    CHECK(z.f_b < 0.0);
    CHECK(z.a <= 1.0e-3);
    CHECK(z.b >= 1.0e-3);
    CHECK(z.b <= 1.2e-3);
    // Shifted up by 2e-8 the minimum (-1e-8) stays above zero: no impact.
    S.th[0] += 2e-8;
    CHECK_FALSE(zero_bracket(S.theta_poly(), h).found);
}

TEST_CASE("impact search: quick tests of positivity and of a single zero", "[dynamics][taylor]") {
    ContactSeries S;
    S.n = 3;
    // Rising from an edge after an impact: stays positive over the step.
    S.th = {};
    S.th[0] = 0.0;
    S.th[1] = 0.2;
    S.th[2] = -5.0;
    S.th[3] = 1.0;
    CHECK(stays_positive(S.theta_poly(), 0.01));
    // ... but not over 0.05 s, where it falls back through zero (0.2 - 5 tau ~ 0 at 40 ms).
    CHECK_FALSE(stays_positive(S.theta_poly(), 0.05));
    CHECK(zero_bracket(S.theta_poly(), 0.05).found);
    // Falling with theta'' < 0 all along: concave, so at most one zero.
    S.th[0] = 0.001;
    S.th[1] = -0.3;
    CHECK(monotone_or_concave(S.theta_poly(), 0.005));
    // A dip and rise (theta'' > 0, theta' changing sign): neither monotone nor concave.
    S.th[1] = -2.2e-3;
    S.th[2] = 1.0;
    S.th[3] = 0.0;
    CHECK_FALSE(monotone_or_concave(S.theta_poly(), 0.005));
}

TEST_CASE("impact search: a short excursion just off an edge is bracketed on its peak",
          "[dynamics][taylor]") {
    // theta = 1e-4 tau - tau^2 after an impact (theta(0) = 0, theta'(0) > 0): up for 0.1 ms and
    // down for the rest of the 5 ms step. The bracket must start on the excursion (theta > 0),
    // not at tau = 0 where theta = 0 (that would be an impact at the step start with theta' > 0).
    ContactSeries S;
    S.n = 2;
    S.th[0] = 0.0;
    S.th[1] = 1e-4;
    S.th[2] = -1.0;
    const ZeroBracket z = zero_bracket(S.theta_poly(), 0.005, 1e-14);
    REQUIRE(z.found);
    CHECK(z.a > 0.0);
    CHECK(z.f_a > 0.0);
    CHECK(z.a < 1e-4);
    CHECK(z.b > 1e-4);
    CHECK(z.f_b < 0.0);
    // At a rock onset (theta'(0) = 0) a round-off dip is below the depth: nothing to find.
    S.th[1] = 0.0;
    S.th[2] = -1e-30;
    CHECK_FALSE(zero_bracket(S.theta_poly(), 0.005, 1e-14).found);
}

}  // namespace freestand_test_dynamics_test_taylor
