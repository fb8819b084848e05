// Equations of motion of the flexible body in each mode the integrators step, in the mode's own
// coordinates (flexible.hpp, docs/methods.md s.10): rock and slide-rock in those of the contact
// point P of edge s, flight in those of O, the flat slide in closed form, and the state's
// derivative. They solve the equations of flex_accel_general with the constraints eliminated
// instead of projected: rocking has two degrees of freedom (phi, q), slide-rock a third (P's
// slip u, its friction force proportional to N), flight two more (O's translation, the CG's
// free fall). tests/dynamics/test_flexible_equations.cpp holds them to flex_accel_general.
#include <array>
#include <cmath>

#include "core/errors.hpp"
#include "dynamics/flexible_detail.hpp"

namespace freestand::dynamics::detail {

namespace {

// The body seen from a point P on its base line at body-frame (b_x, 0) (an edge's contact
// point, or O): with the body-frame vectors from P to the remainder's CG, d_r = (-b_x, h_r), and
// to the modal mass, d_s = (q - b_x, h_s), their first moment S = M_r d_r + m_s d_s =
// (m_s q - M b_x, M h) rotated by phi (R S), and D = I_P + m_s (q - b_x)^2 = det K / m_s of the
// mass matrix of (phi, q) about P, K = [[D + m_s h_s^2, -m_s h_s], [-m_s h_s, m_s]] (I_P: the
// remainder's second moment about P).
struct AboutPoint {
    double qb = 0.0;  // q - b_x
    double RS0 = 0.0, RS1 = 0.0, D = 0.0;
};

inline AboutPoint about_point(const FlexGeometry& g, double bx, double Ip, const Attitude& p) {
    const double qb = p.q - bx;
    const double S0 = g.ms * p.q - g.M * bx, S1 = g.Mh;
    return {qb, p.cphi * S0 - p.sphi * S1, p.sphi * S0 + p.cphi * S1, Ip + g.ms * qb * qb};
}

inline AboutPoint about_edge(const FlexGeometry& g, int s, const Attitude& p) {
    return about_point(g, edge_x(g, s), g.Ir_edge[static_cast<std::size_t>(Geometry::index(s))],
                       p);
}

// Rate of the body's momentum relative to P (sum m a less M a_P):
//   B = phi'' J R S - phi'^2 R S + m_s (q'' R e1 + 2 phi' q' J R e1),
// J the quarter turn, R e1 = (cos phi, sin phi).
inline std::array<double, 2> momentum_rate(const FlexGeometry& g, const Attitude& p,
                                           const AboutPoint& e, double phidd, double qdd) {
    const double w2 = p.phid * p.phid, cor = 2.0 * p.phid * p.qd;
    return {-phidd * e.RS1 - w2 * e.RS0 + g.ms * (qdd * p.cphi - cor * p.sphi),
            phidd * e.RS0 - w2 * e.RS1 + g.ms * (qdd * p.sphi + cor * p.cphi)};
}

// P fixed: Lagrange's equations of (phi, q), K (phi'', q'') = (Q_phi, Q_q), with the generalised
// forces of the field g_v = (-xg'', -G) per kg, the spring, the dashpot and the velocity terms
// of K(q),
//   Q_phi = (R S) x g_v - 2 m_s (q - b_x) q' phi',
//   Q_q = m_s (R e1 . g_v + (q - b_x) phi'^2) - k q - c q',
// so phi'' = (Q_phi + h_s Q_q) / D and q'' = Q_q / m_s + h_s phi''; the reactions at P,
// (F, N) = M (u'' + xg'', G) + B (u'' = 0 here).
inline EdgeAccel pivot_fixed(const FlexGeometry& g, const Attitude& p, const AboutPoint& e,
                             Base base) {
    const double w = p.phid;
    const double Qphi = e.RS1 * base.ax - e.RS0 * base.G - 2.0 * g.ms * e.qb * p.qd * w;
    const double Qq = g.ms * (e.qb * w * w - base.ax * p.cphi - base.G * p.sphi) - g.k * p.q -
                      g.c * p.qd;
    EdgeAccel a;
    a.phidd = (Qphi + g.hs * Qq) / e.D;
    a.qdd = Qq / g.ms + g.hs * a.phidd;
    const auto B = momentum_rate(g, p, e, a.phidd, a.qdd);
    a.F = g.M * base.ax + B[0];
    a.N = g.M * base.G + B[1];
    return a;
}

inline Attitude attitude_at(double phi, double phid, double q, double qd) {
    const CosSin t = cos_sin(phi);
    return {t.c, t.s, phid, q, qd};
}

inline EdgeAccel slide_rock(const FlexGeometry& g, int s, int sigma, const Attitude& p,
                            Base base) {
    const AboutPoint e = about_edge(g, s, p);
    EdgeAccel a = pivot_fixed(g, p, e, base);
    // P's slip u'' puts the frame's inertia force -u'' per kg into the field: K (phi'', q'')
    // gains u'' (R S . e2, -m_s cos phi), so (phi'', q'') gains u'' (phi_u, q_u), and (F, N)
    // gains u'' (M, 0) + u'' B(phi_u, q_u) = u'' (m_x, m_y); F = -sigma mu_k N fixes u''.
    const double phi_u = (e.RS1 - g.ms * g.hs * p.cphi) / e.D;
    const double q_u = g.hs * phi_u - p.cphi;
    const double m_x = g.M - phi_u * e.RS1 + g.ms * q_u * p.cphi;
    const double m_y = phi_u * e.RS0 + g.ms * q_u * p.sphi;
    const double smu = static_cast<double>(sigma) * g.rigid.mu_k;
    const double den = m_x + smu * m_y;
    if (!(std::abs(den) > 0.0))
        throw NumericalError("flexible-body equations: the contact forces are indeterminate");
    a.udd = -(a.F + smu * a.N) / den;
    a.phidd += a.udd * phi_u;
    a.qdd += a.udd * q_u;
    a.N += a.udd * m_y;
    a.F = -smu * a.N;
    return a;
}

inline EdgeAccel rock(const FlexGeometry& g, int s, const Attitude& p, Base base) {
    return pivot_fixed(g, p, about_edge(g, s, p), base);
}

inline FlexAccel pose_accel(const FlexGeometry& g, int s, const Attitude& p, const EdgeAccel& e) {
    // O = P - R (b_x, 0): O'' = P'' - phi'' J R (b_x, 0) + phi'^2 R (b_x, 0).
    const double bx = edge_x(g, s), w2 = p.phid * p.phid;
    FlexAccel a;
    a.Xdd = e.udd + bx * (e.phidd * p.sphi + w2 * p.cphi);
    a.Ydd = bx * (w2 * p.sphi - e.phidd * p.cphi);
    a.phidd = e.phidd;
    a.qdd = e.qdd;
    a.F = e.F;
    a.N = e.N;
    return a;
}

}  // namespace

// The named entry points of the helpers above, which flex_rhs, run six times a step, inlines.
EdgeAccel flex_rock_accel(const FlexGeometry& g, int s, const Attitude& p, Base base) {
    return rock(g, s, p, base);
}

EdgeAccel flex_slide_rock_accel(const FlexGeometry& g, int s, int sigma, const Attitude& p,
                                Base base) {
    return slide_rock(g, s, sigma, p, base);
}

FlexAccel flex_accel_of(const FlexGeometry& g, int s, const Attitude& p, const EdgeAccel& e) {
    return pose_accel(g, s, p, e);
}

FlexAccel flex_slide_accel(const FlexGeometry& g, int sigma, double q, double qd, Base base) {
    // The modal mass against the sliding remainder: m_s (u'' + q'') = -m_s xg'' - k q - c q' and
    // M u'' + m_s q'' = F - M xg'', F = -sigma mu_k M G.
    const double smu = static_cast<double>(sigma) * g.rigid.mu_k;
    const double spring = g.k * q + g.c * qd;
    FlexAccel a;
    a.N = g.M * base.G;
    a.F = -smu * a.N;
    a.Xdd = -base.ax + (spring + a.F) / g.Mr;
    a.qdd = -spring / g.ms - base.ax - a.Xdd;
    // Moment about O of the remainder at (0, h_r) and the modal mass at (q, h_s) under their
    // accelerations and the base frame's gravity (0, -G) and inertia (-xg'', 0).
    const double mo = -g.Mr * g.hr * (a.Xdd + base.ax) +
                      g.ms * (q * base.G - g.hs * (a.Xdd + a.qdd + base.ax));
    a.NR = (a.N * g.b[0] + mo) * g.inv_width;
    a.NL = (a.N * g.b[1] - mo) * g.inv_width;
    return a;
}

FlexAccel flex_flight_accel(const FlexGeometry& g, const Attitude& p, Base base) {
    // No contact force: O accelerates at g_v - B / M. In the equations of (phi, q) about O
    // (pivot_fixed's with the field g_v - a_O = B / M) the field drops out and the terms of B
    // leave the system of the body about its CG, h the CG's height:
    //   [[D + m_s h_s^2 - |S|^2 / M, m_s (h - h_s)], [m_s (h - h_s), m_s M_r / M]] (phi'', q'')
    //     = (-2 m_s (M_r / M) q q' phi', m_s (M_r / M) q phi'^2 - k q - c q').
    const AboutPoint e = about_point(g, 0.0, g.Ir_base, p);
    const double rm = g.Mr / g.M, S0 = g.ms * p.q;
    const double a11 = e.D + g.ms * g.hs * g.hs - (S0 * S0 + g.Mh * g.Mh) / g.M;
    const double a12 = g.ms * (g.Mh / g.M - g.hs), a22 = g.ms * rm;
    const double r1 = -2.0 * g.ms * rm * p.q * p.qd * p.phid;
    const double r2 = g.ms * rm * p.q * p.phid * p.phid - g.k * p.q - g.c * p.qd;
    const auto [phidd, qdd] = solve_phi_q(a11, a12, a22, r1, r2, "mass matrix");
    FlexAccel a;
    a.phidd = phidd;
    a.qdd = qdd;
    const auto B = momentum_rate(g, p, e, a.phidd, a.qdd);
    a.Xdd = -base.ax - B[0] / g.M;
    a.Ydd = -base.G - B[1] / g.M;
    return a;
}

FlexAccel flex_accel(const FlexGeometry& g, const FlexMode& m, const Pose& p, Base base) {
    const Attitude at = attitude(p);
    switch (m.mode) {
        case Mode::rest: return rest_accel(g, p.q, p.qd, base);
        case Mode::slide: return flex_slide_accel(g, m.sigma, p.q, p.qd, base);
        case Mode::rock: return flex_accel_of(g, m.s, at, flex_rock_accel(g, m.s, at, base));
        case Mode::slide_rock:
            return flex_accel_of(g, m.s, at, flex_slide_rock_accel(g, m.s, m.sigma, at, base));
        case Mode::flight: break;
    }
    return flex_flight_accel(g, at, base);
}

void flex_rhs(const FlexGeometry& g, const FlexMode& m, const FlexState& x, Base base,
              FlexState& dx, FlexAccel& a) {
    switch (m.mode) {
        case Mode::flight:
            a = flex_flight_accel(g, attitude_at(x[4], x[5], x[6], x[7]), base);
            dx = {x[1], a.Xdd, x[3], a.Ydd, x[5], a.phidd, x[7], a.qdd};
            return;
        case Mode::rest:
        case Mode::slide:
            a = m.mode == Mode::rest ? rest_accel(g, x[4], x[5], base)
                                     : flex_slide_accel(g, m.sigma, x[4], x[5], base);
            dx = {x[1], a.Xdd, x[3], 0.0, x[5], a.qdd, 0.0, 0.0};
            return;
        case Mode::rock:
        case Mode::slide_rock: break;
    }
    // On edge s: phi = -s theta, phi' = -s theta'.
    const double sd = static_cast<double>(m.s);
    const Attitude p = attitude_at(-sd * x[2], -sd * x[3], x[4], x[5]);
    const EdgeAccel e = m.mode == Mode::rock ? rock(g, m.s, p, base)
                                             : slide_rock(g, m.s, m.sigma, p, base);
    a = pose_accel(g, m.s, p, e);
    dx = {x[1], e.udd, x[3], -sd * e.phidd, x[5], e.qdd, 0.0, 0.0};
}

}  // namespace freestand::dynamics::detail
