// The flexible body's impact rule and equations (dynamics/flexible_detail.hpp, docs/methods.md
// s.10): an impact conserves the angular momentum about the struck edge and, for a mode slow
// against the contact pulse, the modal mass's velocity along the body; it never creates
// kinetic energy; a mode much faster than the pulse moves with the base (the rigid block's
// restitution). The structured solve of the equations against the full system; the exact flat
// slide against the equations and against Dormand-Prince.
#include <catch2/catch.hpp>
#include <Eigen/Dense>
#include <cmath>
#include <numbers>
#include <random>

#include "dynamics/flexible_detail.hpp"

// The file's own namespace: the test files of a stage compile in unity batches.
namespace freestand_test_dynamics_test_flexible_equations {

using namespace freestand;
using namespace freestand::dynamics::detail;

namespace {

// Round-off of the momentum and energy balances, relative.
constexpr double kBalanceRel = 1e-12;

dynamics::FlexibleModel model(double f_hz, double impact_s = dynamics::default_impact_duration_s,
                              std::optional<double> restitution = std::nullopt,
                              double half_width_m = 0.3) {
    const auto rigid = dynamics::make_block_model(block::Block::uniform(half_width_m, 0.6, 38.0),
                                                  0.6, std::nullopt, restitution);
    dynamics::FlexibleMode m;
    m.frequency_hz = f_hz;
    auto fm = dynamics::make_flexible_model(rigid, m);
    fm.impact_duration_s = impact_s;
    return fm;
}

// Body-axis velocity of the modal mass.
double modal_axis_velocity(const FlexGeometry& g, const Pose& p) {
    const double rs0 = p.cphi * p.q - p.sphi * g.hs, rs1 = p.sphi * p.q + p.cphi * g.hs;
    return (p.Xd - p.phid * rs1) * p.cphi + (p.Yd + p.phid * rs0) * p.sphi + p.qd;
}

struct ImpactCase {
    Pose before, after;
    int s_new = 1;
};

// A body on edge s at theta = 0 rotating towards the other edge at om, its mode at (q, qd).
ImpactCase strike(const FlexGeometry& g, int s, double om, double q, double qd) {
    ImpactCase c;
    c.before = contact_pose(g, s, 0.0, 0.0, 0.0, -std::abs(om), q, qd);
    c.s_new = -s;
    const EdgeState e = edge_impact(g, c.before, c.s_new, 0.0, 0.0);
    c.after = contact_pose(g, e.s, e.u, e.v, e.th, e.om, e.q, e.qd);
    return c;
}

}  // namespace

TEST_CASE("an impact conserves the angular momentum about the struck edge and never creates "
          "energy", "[dynamics][flexible]") {
    // A slender body (tan(alpha) = 1/6): its base rebounds from some of these impacts. From
    // most, and from all of a squatter one's with the mode at rest, it is left flat: the modal
    // mass carries most of the angular momentum on, the base alone nearly none.
    const FlexGeometry g =
        make_flex_geometry(model(7.5, dynamics::default_impact_duration_s, std::nullopt, 0.1));
    REQUIRE(g.modal_free == Approx(1.0).epsilon(1e-5));  // 7.5 Hz against a 0.1 ms pulse
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> om(0.001, 2.0), q(-0.01, 0.01), qd(-0.3, 0.3);
    int raised_by_holding_qd = 0, rebounds = 0;
    for (int i = 0; i < 200; ++i) {
        const int s = i % 2 == 0 ? 1 : -1;
        // One draw per statement: argument order is unspecified, the states must not depend on
        // the compiler.
        const double om0 = om(rng);
        const double q0 = q(rng);
        const double qd0 = qd(rng);
        const ImpactCase c = strike(g, s, om0, q0, qd0);
        const double xc = s > 0 ? -g.b[0] : g.b[1];
        const double H0 = angular_momentum_about(g, c.before, xc);
        INFO("case " << i);
        // A rebound against the struck edge (theta' < 0) is impossible: the body is left flat,
        // the other edge taking the rest of the angular momentum.
        if (c.after.phid != 0.0) {
            ++rebounds;
            CHECK(angular_momentum_about(g, c.after, xc) ==
                  Approx(H0).epsilon(kBalanceRel).margin(1e-12));
        }
        // The mode keeps its velocity to 1e-5 (modal_free's deviation from 1) of the impact's
        // velocity scale, the struck edge's speed; a small modal velocity is held to that
        // absolute margin, not to 1e-5 of itself.
        const double edge_speed_mps = om0 * std::max(g.rigid.R[0], g.rigid.R[1]);
        CHECK(modal_axis_velocity(g, c.after) ==
              Approx(modal_axis_velocity(g, c.before)).epsilon(1e-5).margin(1e-5 * edge_speed_mps));
        const double e0 = kinetic_energy(g, c.before);
        CHECK(kinetic_energy(g, c.after) <= e0 * (1.0 + kBalanceRel));
        // The rule it replaces, theta' times Housner's restitution with q' held, raises the
        // energy at some of these states.
        const double r = g.rigid.r_onto[static_cast<std::size_t>(Geometry::index(c.s_new))];
        const Pose held = contact_pose(g, c.s_new, 0.0, 0.0, 0.0, r * std::abs(c.before.phid),
                                       c.before.q, c.before.qd);
        if (kinetic_energy(g, held) > e0 * (1.0 + 1e-6)) ++raised_by_holding_qd;
    }
    CHECK(rebounds > 20);
    CHECK(raised_by_holding_qd > 0);
}

TEST_CASE("a mode much faster than the impact moves with the base: Housner's restitution",
          "[dynamics][flexible]") {
    // 2 kHz against a 10 ms pulse: omega T = 126, the mode keeps (pi / 126)^2 of the jump.
    const FlexGeometry g = make_flex_geometry(model(2000.0, 0.01));
    CHECK(g.modal_free < 1e-3);
    const ImpactCase c = strike(g, 1, 0.8, 0.0, 0.0);
    const double r = g.rigid.r_onto[0];
    CHECK(c.after.phid / c.before.phid == Approx(r).epsilon(2e-3));
    CHECK(std::abs(c.after.qd) < 1e-3 * std::abs(c.before.phid) * g.hs);
    // A measured restitution multiplies theta' whatever the mode does.
    const FlexGeometry m = make_flex_geometry(model(7.5, dynamics::default_impact_duration_s, 0.5));
    const ImpactCase cm = strike(m, -1, 0.8, 0.002, 0.1);
    CHECK(cm.after.phid / cm.before.phid == Approx(0.5).epsilon(1e-12));
    CHECK(kinetic_energy(m, cm.after) <= kinetic_energy(m, cm.before));
}

TEST_CASE("the mode's share of an impact follows the half-sine pulse's residual spectrum",
          "[dynamics][flexible]") {
    constexpr double pi = std::numbers::pi;
    CHECK(impact_modal_share(0.0) == 1.0);
    CHECK(impact_modal_share(1e-3) == Approx(1.0).epsilon(1e-6));
    CHECK(impact_modal_share(pi) == Approx(pi / 4.0));
    CHECK(impact_modal_share(pi * (1.0 + 1e-7)) == Approx(pi / 4.0).epsilon(1e-6));
    CHECK(impact_modal_share(3.0 * pi) == Approx(0.0).margin(1e-15));
    CHECK(impact_modal_share(40.0 * pi) <= 1.0 / (40.0 * 40.0 - 1.0));
}

namespace {
// The full system of the mode's equations, (4 + nf) unknowns assembled and solved by LU: the
// reference for flex_accel's structured solve (mass matrix by its Schur complement, contact
// forces by the reduced system).
FlexAccel full_system(const FlexGeometry& g, const FlexMode& m, const Pose& p, Base base) {
    using V2 = Eigen::Vector2d;
    const auto rot = [&](V2 v) { return V2(p.cphi * v[0] - p.sphi * v[1], p.sphi * v[0] + p.cphi * v[1]); };
    const auto perp = [](V2 v) { return V2(-v[1], v[0]); };
    const auto cross = [](V2 a, V2 b) { return a[0] * b[1] - a[1] * b[0]; };
    const double w = p.phid, w2 = w * w;
    const V2 e1(p.cphi, p.sphi), rr = rot(V2(0.0, g.hr)), rs = rot(V2(p.q, g.hs));
    const V2 gv(-base.ax, -base.G);
    const V2 vr = -w2 * rr, vs = -w2 * rs + 2.0 * w * p.qd * perp(e1);
    struct Force { V2 rc, d; };
    std::vector<Force> f;
    std::vector<std::pair<V2, int>> rows;  // point and component; component 2: phi'' = 0
    const auto edge = [&](int s) { return rot(V2(s > 0 ? g.b[1] : -g.b[0], 0.0)); };
    const double mu = g.rigid.mu_k;
    switch (m.mode) {
        case dynamics::Mode::flight: break;
        case dynamics::Mode::rock:
            f = {{edge(m.s), V2(1, 0)}, {edge(m.s), V2(0, 1)}};
            rows = {{edge(m.s), 0}, {edge(m.s), 1}};
            break;
        case dynamics::Mode::slide_rock:
            f = {{edge(m.s), V2(-m.sigma * mu, 1)}};
            rows = {{edge(m.s), 1}};
            break;
        case dynamics::Mode::slide:
            f = {{edge(-1), V2(-m.sigma * mu, 1)}, {edge(1), V2(-m.sigma * mu, 1)}};
            rows = {{edge(-1), 1}, {V2(0, 0), 2}};
            break;
        case dynamics::Mode::rest:
            f = {{edge(-1), V2(1, 0)}, {edge(-1), V2(0, 1)}, {edge(1), V2(0, 1)}};
            rows = {{edge(-1), 0}, {edge(-1), 1}, {V2(0, 0), 2}};
            break;
    }
    const int n = 4 + static_cast<int>(f.size());
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n);
    Eigen::VectorXd b = Eigen::VectorXd::Zero(n);
    const V2 S = g.Mr * rr + g.ms * rs;
    for (int i = 0; i < 2; ++i) {
        A(i, i) = g.M;
        A(i, 2) = g.Mr * perp(rr)[i] + g.ms * perp(rs)[i];
        A(i, 3) = g.ms * e1[i];
        b(i) = g.M * gv[i] - g.Mr * vr[i] - g.ms * vs[i];
    }
    A(2, 0) = -S[1];
    A(2, 1) = S[0];
    A(2, 2) = g.Mr * rr.squaredNorm() + g.ms * rs.squaredNorm() + g.Ir;
    A(2, 3) = g.ms * cross(rs, e1);
    b(2) = -g.Mr * cross(rr, vr) - g.ms * cross(rs, vs) + cross(S, gv);
    A(3, 0) = g.ms * e1[0];
    A(3, 1) = g.ms * e1[1];
    A(3, 2) = -g.ms * g.hs;
    A(3, 3) = g.ms;
    b(3) = -g.k * p.q - g.c * p.qd + g.ms * gv.dot(e1) + g.ms * w2 * p.q;
    for (std::size_t j = 0; j < f.size(); ++j) {
        const int c = 4 + static_cast<int>(j);
        A(0, c) = -f[j].d[0];
        A(1, c) = -f[j].d[1];
        A(2, c) = -cross(f[j].rc, f[j].d);
        const auto& [rc, comp] = rows[j];
        if (comp == 2) {
            A(c, 2) = 1.0;
        } else {
            A(c, comp) = 1.0;
            A(c, 2) = perp(rc)[comp];
            b(c) = w2 * rc[comp];
        }
    }
    const Eigen::VectorXd x = A.partialPivLu().solve(b);
    FlexAccel a;
    a.Xdd = x(0);
    a.Ydd = x(1);
    a.phidd = x(2);
    a.qdd = x(3);
    for (std::size_t j = 0; j < f.size(); ++j) {
        a.F += x(4 + static_cast<int>(j)) * f[j].d[0];
        a.N += x(4 + static_cast<int>(j)) * f[j].d[1];
    }
    return a;
}
}  // namespace

TEST_CASE("the flexible body's structured solve matches the full system", "[dynamics][flexible]") {
    const FlexGeometry g = make_flex_geometry(model(7.5));
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> th(0.0, 0.5), rate(-2.0, 2.0), q(-0.02, 0.02),
        ax(-8.0, 8.0), G(2.0, 15.0);
    using dynamics::Mode;
    const FlexMode modes[] = {{Mode::rest, 1, 1},       {Mode::slide, 1, 1},
                              {Mode::slide, -1, -1},    {Mode::rock, 1, 1},
                              {Mode::rock, -1, 1},      {Mode::slide_rock, 1, -1},
                              {Mode::slide_rock, -1, 1}, {Mode::flight, 1, 1}};
    for (int i = 0; i < 100; ++i) {
        for (const FlexMode& m : modes) {
            const bool flat = m.mode == Mode::rest || m.mode == Mode::slide;
            // Drawn one statement each: the order of a call's arguments is unspecified, and
            // the same states must be drawn whatever the compiler.
            const double v = rate(rng);
            const double theta = flat ? 0.0 : th(rng);
            const double omega = flat ? 0.0 : rate(rng);
            const double q0 = q(rng);
            const double qd0 = rate(rng);
            Pose p = contact_pose(g, m.s, 0.01, v, theta, omega, q0, qd0);
            if (m.mode == Mode::flight) {
                p.Y = 0.05;
                p.Yd = rate(rng);
            }
            const Base base{ax(rng), G(rng)};
            const FlexAccel a = flex_accel(g, m, p, base), r = full_system(g, m, p, base);
            INFO("mode " << dynamics::to_string(m.mode) << ", case " << i);
            const double scale = 10.0;  // m/s^2, rad/s^2 of these states
            CHECK(a.Xdd == Approx(r.Xdd).margin(1e-10 * scale));
            CHECK(a.Ydd == Approx(r.Ydd).margin(1e-10 * scale));
            CHECK(a.phidd == Approx(r.phidd).margin(1e-10 * scale));
            CHECK(a.qdd == Approx(r.qdd).margin(1e-10 * scale));
            CHECK(a.N == Approx(r.N).margin(1e-10 * g.M * scale));
            CHECK(a.F == Approx(r.F).margin(1e-10 * g.M * scale));
        }
    }
}

TEST_CASE("cos_sin is within an ulp of libm's cosine and sine", "[dynamics][flexible]") {
    // Taylor polynomials to |x| = 0.5, libm itself beyond (flexible_detail.hpp).
    const auto within_ulp = [](double a, double ref) {
        return a == ref || a == std::nextafter(ref, 2.0) || a == std::nextafter(ref, -2.0);
    };
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> x(-0.5, 0.5);
    int off_c = 0, off_s = 0;
    for (int i = 0; i < 200000; ++i) {
        const double v = i % 4 == 0 ? 1e-3 * x(rng) : x(rng);
        const CosSin r = cos_sin(v);
        INFO("x = " << v);
        REQUIRE(within_ulp(r.c, std::cos(v)));
        REQUIRE(within_ulp(r.s, std::sin(v)));
        off_c += r.c != std::cos(v);
        off_s += r.s != std::sin(v);
    }
    // libm is (nearly) correctly rounded, the polynomials within 0.7 ulp: they round the
    // other way at a few percent of the points.
    CHECK(off_c < 200000 / 20);
    CHECK(off_s < 200000 / 20);
    CHECK(cos_sin(0.0).c == 1.0);
    CHECK(cos_sin(0.0).s == 0.0);
    for (double v : {0.5, -0.5}) {
        CHECK(within_ulp(cos_sin(v).c, std::cos(v)));
        CHECK(within_ulp(cos_sin(v).s, std::sin(v)));
    }
    for (double v : {0.5000001, -0.7, 1.5707963267948966, 3.0, -40.0}) {
        CHECK(cos_sin(v).c == std::cos(v));
        CHECK(cos_sin(v).s == std::sin(v));
    }
}

TEST_CASE("each mode's own equations agree with the general formulation",
          "[dynamics][flexible]") {
    // flex_accel and flex_rhs solve each mode in its own coordinates (flexible_modes.cpp);
    // flex_accel_general assembles the 4 x 4 mass matrix with the contact constraints. Both are
    // exact: they differ by round-off. A symmetric and an asymmetric body (CG nearer the right
    // edge, its mode high and heavy), several tilts, rates and base accelerations.
    const auto asym = dynamics::make_block_model(
        block::Block::general(0.35, 0.2, 0.7, 450.0, 60.0), 0.7);
    dynamics::FlexibleMode heavy;
    heavy.frequency_hz = 3.0;
    heavy.mass_fraction = 0.5;
    heavy.height_m = 0.9;
    const FlexGeometry geometries[] = {make_flex_geometry(model(7.5)),
                                       make_flex_geometry(dynamics::make_flexible_model(asym, heavy))};
    std::mt19937 rng(23);
    std::uniform_real_distribution<double> th(0.0, 1.5), rate(-3.0, 3.0), q(-0.05, 0.05),
        ax(-10.0, 10.0), G(-5.0, 20.0);
    using dynamics::Mode;
    const FlexMode modes[] = {{Mode::rest, 1, 1},        {Mode::slide, 1, 1},
                              {Mode::slide, -1, -1},     {Mode::rock, 1, 1},
                              {Mode::rock, -1, 1},       {Mode::slide_rock, 1, -1},
                              {Mode::slide_rock, 1, 1},  {Mode::slide_rock, -1, 1},
                              {Mode::slide_rock, -1, -1}, {Mode::flight, 1, 1}};
    // Relative to the largest term of each quantity (m/s^2, rad/s^2 and N of these states);
    // Approx's own relative epsilon (1e-5 by default) is switched off.
    constexpr double kRel = 1e-12, kAccelScale = 100.0;
    const auto exact = [](double v) { return Approx(v).epsilon(0.0); };
    for (const FlexGeometry& g : geometries) {
        for (int i = 0; i < 200; ++i) {
            for (const FlexMode& m : modes) {
                const bool flat = m.mode == Mode::rest || m.mode == Mode::slide;
                const double tilt = flat ? 0.0 : th(rng), tilt_rate = flat ? 0.0 : rate(rng);
                const double slip_rate = m.mode == Mode::rock || m.mode == Mode::rest ? 0.0
                                                                                     : rate(rng);
                FlexState x = {0.01, slip_rate, tilt, tilt_rate, q(rng), rate(rng), 0.0, 0.0};
                Pose p = contact_pose(g, m.s, x[0], x[1], x[2], x[3], x[4], x[5]);
                if (m.mode == Mode::flight) {
                    p.Y = 0.05;
                    p.Yd = rate(rng);
                    with_phi(p, rate(rng));
                    x = flight_state(p);
                }
                const Base base{ax(rng), G(rng)};
                const FlexAccel a = flex_accel(g, m, p, base);
                const FlexAccel r = flex_accel_general(g, m, p, base);
                INFO("mode " << dynamics::to_string(m.mode) << " s " << m.s << " sigma "
                             << m.sigma << ", case " << i);
                const double force_scale = g.M * kAccelScale;
                CHECK(a.Xdd == exact(r.Xdd).margin(kRel * kAccelScale));
                CHECK(a.Ydd == exact(r.Ydd).margin(kRel * kAccelScale));
                CHECK(a.phidd == exact(r.phidd).margin(kRel * kAccelScale));
                CHECK(a.qdd == exact(r.qdd).margin(kRel * kAccelScale));
                CHECK(a.F == exact(r.F).margin(kRel * force_scale));
                CHECK(a.N == exact(r.N).margin(kRel * force_scale));
                CHECK(a.NL == exact(r.NL).margin(kRel * force_scale));
                CHECK(a.NR == exact(r.NR).margin(kRel * force_scale));
                // The state's derivative: the contact point's slip from the general pose
                // accelerations, theta'' = -s phi''.
                FlexState dx;
                FlexAccel ar;
                flex_rhs(g, m, x, base, dx, ar);
                CHECK(ar.qdd == a.qdd);
                if (m.mode == Mode::flight) {
                    CHECK(dx[1] == exact(r.Xdd).margin(kRel * kAccelScale));
                    CHECK(dx[3] == exact(r.Ydd).margin(kRel * kAccelScale));
                    CHECK(dx[5] == exact(r.phidd).margin(kRel * kAccelScale));
                    continue;
                }
                const double slip = contact_slip_accel(g, m.s, p, r);
                CHECK(dx[1] == exact(m.mode == Mode::rock ? 0.0 : slip)
                                   .margin(kRel * kAccelScale));
                CHECK(dx[3] == exact(-m.s * r.phidd).margin(kRel * kAccelScale));
                CHECK(dx[5] == exact(r.qdd).margin(kRel * kAccelScale));
            }
        }
    }
}

TEST_CASE("the exact flat slide solves the slide's equations", "[dynamics][flexible]") {
    const FlexGeometry g = make_flex_geometry(model(7.5));
    REQUIRE(g.exact_slide);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> v(-0.5, 0.5), q(-0.01, 0.01), ax(-6.0, 6.0),
        slope(-200.0, 200.0), G(5.0, 14.0);
    for (int i = 0; i < 50; ++i) {
        const int sigma = i % 2 == 0 ? 1 : -1;
        const FlexState x = {0.02, v(rng), 0.0, 0.0, q(rng), v(rng), 0.0, 0.0};
        const Base b0{ax(rng), G(rng)};
        const double ax1 = slope(rng), G1 = slope(rng);
        const SlideSegment sl(g, sigma, x, b0, ax1, G1);
        INFO("case " << i);
        // At its start: the state, and the accelerations and edge forces of flex_accel.
        const auto p = sl.at(0.0);
        const FlexAccel a = flex_accel(g, {dynamics::Mode::slide, sigma, sigma},
                                       contact_pose(g, 1, x[0], x[1], 0.0, 0.0, x[4], x[5]), b0);
        CHECK(p.u == x[0]);
        CHECK(p.v == Approx(x[1]).margin(1e-15));
        CHECK(p.a.Xdd == Approx(a.Xdd).margin(1e-10));
        CHECK(p.a.qdd == Approx(a.qdd).margin(1e-10));
        CHECK(p.a.NL == Approx(a.NL).epsilon(1e-10).margin(1e-8));
        CHECK(p.a.NR == Approx(a.NR).epsilon(1e-10).margin(1e-8));
        // Inside the segment: u' and u'' are the derivatives of u and u' (central differences,
        // truncation ~h^2 u'''').
        const double tau = 0.003, h = 1e-5;
        const auto m = sl.at(tau), lo = sl.at(tau - h), hi = sl.at(tau + h);
        CHECK((hi.u - lo.u) / (2.0 * h) == Approx(m.v).margin(1e-7));
        CHECK((hi.v - lo.v) / (2.0 * h) == Approx(m.a.Xdd).margin(1e-5));
        CHECK((hi.qd - lo.qd) / (2.0 * h) == Approx(m.a.qdd).margin(1e-5));
        const Base bt{b0.ax + ax1 * tau, b0.G + G1 * tau};
        const FlexAccel at = flex_accel(g, {dynamics::Mode::slide, sigma, sigma},
                                        contact_pose(g, 1, m.u, m.v, 0.0, 0.0, m.q, m.qd), bt);
        CHECK(m.a.Xdd == Approx(at.Xdd).margin(1e-10));
        CHECK(m.a.qdd == Approx(at.qdd).margin(1e-10));
    }
}

TEST_CASE("the exact flat slide agrees with Dormand-Prince on the slide's equations",
          "[dynamics][flexible]") {
    // A sliding body (mu 0.2 < tan(alpha)) stopping and reversing under a 0.5 g, 2 Hz sine.
    const auto rigid = dynamics::make_block_model(block::Block::uniform(0.4, 0.6, 1000.0), 0.2);
    dynamics::FlexibleMode mode;
    mode.frequency_hz = 7.5;
    FlexGeometry g = make_flex_geometry(dynamics::make_flexible_model(rigid, mode));
    const auto e = dynamics::sine_excitation({0.5, 2.0, 2.0, 0.0, 0.0});
    dynamics::Options o;
    o.tail_s = 2.0;
    o.record_series = false;
    const BaseMotion bm(e, o.g_mps2);
    REQUIRE(g.exact_slide);
    const auto exact = run_flexible_event(g, bm, o).summary;
    g.exact_slide = false;
    const auto stepped = run_flexible_event(g, bm, o).summary;
    REQUIRE(exact.base.slide_max_m > 0.05);
    CHECK_FALSE(exact.uplifted);
    CHECK(exact.base.slide_max_m == Approx(stepped.base.slide_max_m).epsilon(1e-7));
    CHECK(exact.base.slide_residual_m == Approx(stepped.base.slide_residual_m).epsilon(1e-7));
    CHECK(exact.modal_max_m == Approx(stepped.modal_max_m).epsilon(1e-7));
    CHECK(exact.base.mode_changes == stepped.base.mode_changes);
}

}  // namespace freestand_test_dynamics_test_flexible_equations
