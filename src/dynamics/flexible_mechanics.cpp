// Equations of motion of the flexible body (flexible.hpp, docs/methods.md s.10).
#include <Eigen/Dense>
#include <cmath>
#include <fmt/format.h>

#include "core/errors.hpp"
#include "core/units.hpp"
#include "dynamics/flexible_detail.hpp"

namespace freestand::dynamics {

FlexibleModel make_flexible_model(const BlockModel& rigid, const FlexibleMode& mode) {
    const auto bad = [](const char* field, const std::string& what) {
        return InputError({"", 0, field}, what);
    };
    if (!std::isfinite(mode.frequency_hz) || mode.frequency_hz <= 0.0)
        throw bad("flexible.f", fmt::format("fixed-base frequency must be > 0 Hz; got {}",
                                            mode.frequency_hz));
    if (!std::isfinite(mode.damping) || mode.damping < 0.0 || mode.damping >= 1.0)
        throw bad("flexible.zeta",
                  fmt::format("modal damping ratio must be in [0, 1); got {}", mode.damping));
    const block::Block& blk = rigid.block;
    FlexibleModel m;
    m.rigid = rigid;
    m.frequency_hz = mode.frequency_hz;
    m.damping = mode.damping;
    m.mass_fraction_default = !mode.mass_fraction;
    m.height_default = !mode.height_m;
    m.mass_fraction = mode.mass_fraction.value_or(cantilever_modal_mass_fraction);
    m.height_m = mode.height_m.value_or(cantilever_modal_height_ratio * 2.0 * blk.h_m);
    if (!std::isfinite(m.mass_fraction) || m.mass_fraction <= 0.0 || m.mass_fraction >= 1.0)
        throw bad("flexible.mass", fmt::format("modal mass fraction must be in (0, 1); got {}",
                                               m.mass_fraction));
    if (!std::isfinite(m.height_m) || m.height_m <= 0.0)
        throw bad("flexible.height",
                  fmt::format("modal height must be > 0 m; got {}", m.height_m));
    // Second moment of the rigid remainder about its own CG (flexible.hpp): must not be < 0.
    const double M = blk.mass_kg, ms = m.mass_fraction * M, Mr = M - ms;
    const double first = M * blk.h_m - ms * m.height_m;
    const double Ir = blk.inertia_cg_kgm2 + M * blk.h_m * blk.h_m -
                      ms * m.height_m * m.height_m - first * first / Mr;
    if (!(Ir >= 0.0))
        throw bad("flexible.height",
                  fmt::format("a modal mass of {} M at {} m carries more second moment than the "
                              "body has (CG height {} m, I_c {} kg m^2): lower the mass fraction "
                              "or the height",
                              m.mass_fraction, m.height_m, blk.h_m, blk.inertia_cg_kgm2));
    return m;
}

namespace detail {

namespace {
using Vec2 = std::array<double, 2>;
Vec2 rot(double c, double s, Vec2 p) { return {c * p[0] - s * p[1], s * p[0] + c * p[1]}; }
Vec2 perp(Vec2 v) { return {-v[1], v[0]}; }
double cross(Vec2 a, Vec2 b) { return a[0] * b[1] - a[1] * b[0]; }

// A contact force lambda d applied at body point pc (rotated: rc).
struct ForceCol {
    Vec2 rc{}, d{};
};

constexpr int kDof = 4;  // X'', Y'', phi'', q''
}  // namespace

FlexGeometry make_flex_geometry(const FlexibleModel& m) {
    FlexGeometry g;
    g.rigid = make_geometry(m.rigid);
    const block::Block& blk = m.rigid.block;
    g.M = blk.mass_kg;
    g.ms = m.mass_fraction * g.M;
    g.Mr = g.M - g.ms;
    g.hs = m.height_m;
    g.Mh = g.M * blk.h_m;
    g.hr = (g.Mh - g.ms * g.hs) / g.Mr;
    g.Ir = blk.inertia_cg_kgm2 + g.M * blk.h_m * blk.h_m - g.ms * g.hs * g.hs - g.Mr * g.hr * g.hr;
    g.Ir = std::max(0.0, g.Ir);
    g.omega = units::two_pi * m.frequency_hz;
    g.zeta = m.damping;
    g.k = g.ms * g.omega * g.omega;
    g.c = 2.0 * g.zeta * g.ms * g.omega;
    g.b = {blk.b_left_m, blk.b_right_m};
    return g;
}

FlexAccel flex_accel(const FlexGeometry& g, const FlexMode& m, const Pose& p, Base base) {
    const double cp = std::cos(p.phi), sp = std::sin(p.phi), w = p.phid, w2 = w * w;
    const Vec2 e1 = {cp, sp};
    const Vec2 rr = rot(cp, sp, {0.0, g.hr});       // O to the rigid remainder's CG
    const Vec2 rs = rot(cp, sp, {p.q, g.hs});       // O to the modal mass
    const Vec2 gv = {-base.ax, -base.G};            // gravity and the base's inertia, per kg
    const Vec2 je1 = perp(e1);
    const Vec2 vr = {-w2 * rr[0], -w2 * rr[1]};
    const Vec2 vs = {-w2 * rs[0] + 2.0 * w * p.qd * je1[0], -w2 * rs[1] + 2.0 * w * p.qd * je1[1]};
    const Vec2 jr = perp(rr), js = perp(rs);

    // Contact forces and constraints of the mode (docs/methods.md s.3).
    std::array<ForceCol, 3> f{};
    int nf = 0;
    const auto edge_r = [&](int s) {
        const double bx = s > 0 ? g.b[1] : -g.b[0];
        return rot(cp, sp, {bx, 0.0});
    };
    const double mu = g.rigid.mu_k;
    switch (m.mode) {
        case Mode::flight: break;
        case Mode::rock:
            f[0] = {edge_r(m.s), {1.0, 0.0}};
            f[1] = {edge_r(m.s), {0.0, 1.0}};
            nf = 2;
            break;
        case Mode::slide_rock:
            f[0] = {edge_r(m.s), {-m.sigma * mu, 1.0}};
            nf = 1;
            break;
        case Mode::slide:
            f[0] = {edge_r(-1), {-m.sigma * mu, 1.0}};
            f[1] = {edge_r(1), {-m.sigma * mu, 1.0}};
            nf = 2;
            break;
        case Mode::rest:
            f[0] = {edge_r(-1), {1.0, 0.0}};
            f[1] = {edge_r(-1), {0.0, 1.0}};
            f[2] = {edge_r(1), {0.0, 1.0}};
            nf = 3;
            break;
    }
    const int n = kDof + nf;
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 7, 7> A =
        Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 7, 7>::Zero(n, n);
    Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 7, 1> rhs =
        Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 7, 1>::Zero(n);
    // Linear momentum of the whole body.
    const Vec2 S = {g.Mr * rr[0] + g.ms * rs[0], g.Mr * rr[1] + g.ms * rs[1]};
    for (int i = 0; i < 2; ++i) {
        const auto iu = static_cast<std::size_t>(i);
        A(i, i) = g.M;
        A(i, 2) = g.Mr * jr[iu] + g.ms * js[iu];
        A(i, 3) = g.ms * e1[iu];
        rhs(i) = g.M * gv[iu] - g.Mr * vr[iu] - g.ms * vs[iu];
    }
    // Angular momentum about O (r x a summed, plus the remainder's spin).
    A(2, 0) = -S[1];
    A(2, 1) = S[0];
    A(2, 2) = g.Mr * (rr[0] * rr[0] + rr[1] * rr[1]) + g.ms * (rs[0] * rs[0] + rs[1] * rs[1]) + g.Ir;
    A(2, 3) = g.ms * cross(rs, e1);
    rhs(2) = -g.Mr * cross(rr, vr) - g.ms * cross(rs, vs) + cross(S, gv);
    // The modal mass along e1: m_s (X'' . e1 - h_s phi'' + q'' - phi'^2 q) = -k q - c q' + m_s g . e1.
    A(3, 0) = g.ms * e1[0];
    A(3, 1) = g.ms * e1[1];
    A(3, 2) = -g.ms * g.hs;
    A(3, 3) = g.ms;
    rhs(3) = -g.k * p.q - g.c * p.qd + g.ms * (gv[0] * e1[0] + gv[1] * e1[1]) + g.ms * w2 * p.q;
    for (int j = 0; j < nf; ++j) {
        const auto ju = static_cast<std::size_t>(j);
        A(0, kDof + j) = -f[ju].d[0];
        A(1, kDof + j) = -f[ju].d[1];
        A(2, kDof + j) = -cross(f[ju].rc, f[ju].d);
    }
    // Constraint rows: acceleration of a contact point, X'' + J r phi'' - phi'^2 r.
    const auto point_row = [&](int row, Vec2 rc, int comp) {
        const auto cu = static_cast<std::size_t>(comp);
        A(row, comp) = 1.0;
        A(row, 2) = perp(rc)[cu];
        rhs(row) = w2 * rc[cu];
    };
    switch (m.mode) {
        case Mode::flight: break;
        case Mode::rock:
            point_row(4, f[0].rc, 0);
            point_row(5, f[0].rc, 1);
            break;
        case Mode::slide_rock: point_row(4, f[0].rc, 1); break;
        case Mode::slide:
            point_row(4, f[0].rc, 1);
            A(5, 2) = 1.0;
            break;
        case Mode::rest:
            point_row(4, f[0].rc, 0);
            point_row(5, f[0].rc, 1);
            A(6, 2) = 1.0;
            break;
    }
    const auto x = A.partialPivLu().solve(rhs).eval();
    FlexAccel a;
    a.Xdd = x(0);
    a.Ydd = x(1);
    a.phidd = x(2);
    a.qdd = x(3);
    for (int j = 0; j < nf; ++j) {
        const auto ju = static_cast<std::size_t>(j);
        a.F += x(kDof + j) * f[ju].d[0];
        a.N += x(kDof + j) * f[ju].d[1];
    }
    if (m.mode == Mode::slide) {
        a.NL = x(4);
        a.NR = x(5);
    } else if (m.mode == Mode::rest) {
        a.NL = x(5);
        a.NR = x(6);
    }
    return a;
}

FlexAccel rest_accel(const FlexGeometry& g, double q, double qd, Base base) {
    FlexAccel a;
    a.qdd = -base.ax - 2.0 * g.zeta * g.omega * qd - g.omega * g.omega * q;
    a.F = g.M * base.ax + g.ms * a.qdd;
    a.N = g.M * base.G;
    // Moment about O: N_R b_R - N_L b_L = -m_s h_s q'' + G m_s q - xg'' M h.
    const double mo = -g.ms * g.hs * a.qdd + base.G * g.ms * q - base.ax * g.Mh;
    const double w = g.b[0] + g.b[1];
    a.NR = (a.N * g.b[0] + mo) / w;
    a.NL = (a.N * g.b[1] - mo) / w;
    return a;
}

Pose contact_pose(const FlexGeometry& g, int s, double u, double v, double th, double om,
                  double q, double qd) {
    Pose p;
    p.phi = -static_cast<double>(s) * th;
    p.phid = -static_cast<double>(s) * om;
    p.q = q;
    p.qd = qd;
    const double bx = s > 0 ? g.b[1] : -g.b[0];
    const double cp = std::cos(p.phi), sp = std::sin(p.phi);
    const Vec2 re = rot(cp, sp, {bx, 0.0});
    // The contact point sits at (u + bx, 0) and slips at v: O = contact - r_e.
    p.X = u + bx - re[0];
    p.Y = -re[1];
    const Vec2 jre = perp(re);
    p.Xd = v - p.phid * jre[0];
    p.Yd = -p.phid * jre[1];
    return p;
}

double contact_slip_accel(const FlexGeometry& g, int s, const Pose& p, const FlexAccel& a) {
    const double bx = s > 0 ? g.b[1] : -g.b[0];
    const Vec2 re = rot(std::cos(p.phi), std::sin(p.phi), {bx, 0.0});
    return a.Xdd + perp(re)[0] * a.phidd - p.phid * p.phid * re[0];
}

namespace {
// Slide-rock on edge s in direction sigma if it lifts the edge (theta'' > 0), else slide.
FlexMode slide_rock_or_slide(const FlexGeometry& g, int s, int sigma, const Pose& p, Base base) {
    const FlexMode sr{Mode::slide_rock, s, sigma};
    if (-static_cast<double>(s) * flex_accel(g, sr, p, base).phidd > 0.0) return sr;
    return {Mode::slide, s, sigma};
}
}  // namespace

FlexMode classify_flat(const FlexGeometry& g, double q, double qd, double v, Base base) {
    if (base.G < 0.0) return {Mode::flight, 1, 1};
    const Pose p = contact_pose(g, 1, 0.0, v, 0.0, 0.0, q, qd);
    if (v != 0.0) {
        const int sigma = v > 0.0 ? 1 : -1;
        const FlexAccel a = flex_accel(g, {Mode::slide, sigma, sigma}, p, base);
        if (a.NL < 0.0) return {Mode::slide_rock, 1, sigma};
        if (a.NR < 0.0) return {Mode::slide_rock, -1, sigma};
        return {Mode::slide, sigma, sigma};
    }
    const FlexAccel r = rest_accel(g, q, qd, base);
    if (r.NL < 0.0 || r.NR < 0.0) {
        // The unloaded edge lifts: the body pivots on the other one (s = +1 when NL < 0).
        const int s = r.NL < r.NR ? 1 : -1;
        const FlexAccel a = flex_accel(g, {Mode::rock, s, 1}, p, base);
        if (std::abs(a.F) <= g.rigid.mu_s * a.N) return {Mode::rock, s, 1};
        return slide_rock_or_slide(g, s, a.F > 0.0 ? -1 : 1, p, base);
    }
    if (std::abs(r.F) > g.rigid.mu_s * r.N) {
        const int sigma = r.F > 0.0 ? -1 : 1;
        const FlexAccel a = flex_accel(g, {Mode::slide, sigma, sigma}, p, base);
        if (a.NL < 0.0) return {Mode::slide_rock, 1, sigma};
        if (a.NR < 0.0) return {Mode::slide_rock, -1, sigma};
        return {Mode::slide, sigma, sigma};
    }
    return {Mode::rest, 1, 1};
}

FlexMode classify_edge(const FlexGeometry& g, int s, const Pose& p, double v, Base base) {
    if (v != 0.0) return {Mode::slide_rock, s, v > 0.0 ? 1 : -1};
    const FlexAccel a = flex_accel(g, {Mode::rock, s, 1}, p, base);
    if (a.N < 0.0) return {Mode::flight, s, 1};
    if (std::abs(a.F) <= g.rigid.mu_s * a.N) return {Mode::rock, s, 1};
    return {Mode::slide_rock, s, a.F > 0.0 ? -1 : 1};
}

double angular_momentum_about(const FlexGeometry& g, const Pose& p, double xc) {
    const double cp = std::cos(p.phi), sp = std::sin(p.phi);
    const Vec2 rr = rot(cp, sp, {0.0, g.hr}), rs = rot(cp, sp, {p.q, g.hs});
    const Vec2 e1 = {cp, sp};
    const Vec2 o = {p.X - xc, p.Y};
    const Vec2 vr = {p.Xd - p.phid * rr[1], p.Yd + p.phid * rr[0]};
    const Vec2 vs = {p.Xd - p.phid * rs[1] + p.qd * e1[0], p.Yd + p.phid * rs[0] + p.qd * e1[1]};
    const Vec2 pr = {o[0] + rr[0], o[1] + rr[1]}, ps = {o[0] + rs[0], o[1] + rs[1]};
    return g.Mr * cross(pr, vr) + g.ms * cross(ps, vs) + g.Ir * p.phid;
}

double modal_abs_accel(const FlexGeometry& g, const Pose& p, const FlexAccel& a, Base base) {
    const double cp = std::cos(p.phi), sp = std::sin(p.phi);
    const Vec2 rs = rot(cp, sp, {p.q, g.hs});
    const double w = p.phid;
    // x of X'' + J rs phi'' - phi'^2 rs + 2 phi' q' J e1 + q'' e1, plus the base's xg''.
    return base.ax + a.Xdd - rs[1] * a.phidd - w * w * rs[0] - 2.0 * w * p.qd * sp +
           a.qdd * cp;
}

void oscillator_step(const FlexGeometry& g, double& q, double& qd, double a0, double a1,
                     double tau) {
    const double w = g.omega, z = g.zeta, w2 = w * w;
    const double wd = w * std::sqrt(1.0 - z * z), sig = z * w;
    // Particular solution A + B tau of q'' + 2 zeta w q' + w^2 q = -(a0 + a1 tau).
    const double B = -a1 / w2, A = (-a0 - 2.0 * z * w * B) / w2;
    const double y0 = q - A, yd0 = qd - B;
    const double e = std::exp(-sig * tau), c = std::cos(wd * tau), s = std::sin(wd * tau);
    q = A + B * tau + e * (y0 * c + (yd0 + sig * y0) / wd * s);
    qd = B + e * (yd0 * c - (sig * yd0 + w2 * y0) / wd * s);
}

}  // namespace detail
}  // namespace freestand::dynamics
