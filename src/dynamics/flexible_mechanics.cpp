// Equations of motion of the flexible body (flexible.hpp, docs/methods.md s.10) in their general
// form, the contact pose and the classification of the contact modes; each mode's own equations,
// which the integrators use, are in flexible_modes.cpp.
#include <cmath>
#include <fmt/format.h>
#include <numbers>

#include "core/errors.hpp"
#include "core/units.hpp"
#include "dynamics/flexible_detail.hpp"
#include "dynamics/modal_checks.hpp"
#include "dynamics/vec2.hpp"

namespace freestand::dynamics {

FlexibleModel make_flexible_model(const BlockModel& rigid, const FlexibleMode& mode) {
    const auto bad = [](const char* field, const std::string& what) {
        return InputError({"", 0, field}, what);
    };
    detail::require_modal_frequency(mode.frequency_hz, "flexible.f");
    detail::require_modal_damping(mode.damping);
    const block::Block& blk = rigid.block;
    FlexibleModel m;
    m.rigid = rigid;
    m.frequency_hz = mode.frequency_hz;
    m.damping = mode.damping;
    m.mass_fraction_default = !mode.mass_fraction;
    m.height_default = !mode.height_m;
    m.mass_fraction = mode.mass_fraction.value_or(cantilever_modal_mass_fraction);
    // The body's height is the rigid model's top (2 h unless given).
    m.height_m = mode.height_m.value_or(cantilever_modal_height_ratio * rigid.top_height_m);
    detail::require_modal_mass_fraction(m.mass_fraction);
    detail::require_modal_height(m.height_m);
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
using Mat4 = std::array<std::array<double, 4>, 4>;

double dot4(const std::array<double, 4>& a, const std::array<double, 4>& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
}

// The mass matrix of (X, Y, phi, q) is [[M I, B], [B^T, E]] (the translation block is the
// whole mass): solved through the Schur complement S = E - B^T B / M of that block, 2 x 2.
// Positive definite as a kinetic energy's matrix (S inherits it).
class MassSolve {
public:
    // From the upper triangle of A; false unless S is positive definite.
    bool factor(const Mat4& A) {
        inv_m_ = 1.0 / A[0][0];
        b_ = {{{A[0][2], A[0][3]}, {A[1][2], A[1][3]}}};
        const double s00 = A[2][2] - (b_[0][0] * b_[0][0] + b_[1][0] * b_[1][0]) * inv_m_;
        const double s01 = A[2][3] - (b_[0][0] * b_[0][1] + b_[1][0] * b_[1][1]) * inv_m_;
        const double s11 = A[3][3] - (b_[0][1] * b_[0][1] + b_[1][1] * b_[1][1]) * inv_m_;
        const double det = s00 * s11 - s01 * s01;
        if (!(s00 > 0.0 && det > 0.0)) return false;
        const double inv_det = 1.0 / det;
        inv_ = {s11 * inv_det, -s01 * inv_det, s00 * inv_det};
        return true;
    }
    // Solves A y = r in place.
    void solve(std::array<double, 4>& r) const {
        const double r2 = r[2] - (b_[0][0] * r[0] + b_[1][0] * r[1]) * inv_m_;
        const double r3 = r[3] - (b_[0][1] * r[0] + b_[1][1] * r[1]) * inv_m_;
        r[2] = inv_[0] * r2 + inv_[1] * r3;
        r[3] = inv_[1] * r2 + inv_[2] * r3;
        r[0] = (r[0] - b_[0][0] * r[2] - b_[0][1] * r[3]) * inv_m_;
        r[1] = (r[1] - b_[1][0] * r[2] - b_[1][1] * r[3]) * inv_m_;
    }

private:
    double inv_m_ = 1.0;
    std::array<std::array<double, 2>, 2> b_{};
    std::array<double, 3> inv_{};  // S^-1: [0][0], [0][1], [1][1]
};

// Solves the leading n x n block of K x = b (n <= 3) in place (Cramer's rule: the contact
// systems are small and well conditioned); false if singular.
bool solve_small(const std::array<std::array<double, 3>, 3>& K, std::array<double, 3>& b,
                 std::size_t n) {
    if (n == 0) return true;
    if (n == 1) {
        if (!(std::abs(K[0][0]) > 0.0)) return false;
        b[0] /= K[0][0];
        return true;
    }
    if (n == 2) {
        const double det = K[0][0] * K[1][1] - K[0][1] * K[1][0];
        if (!(std::abs(det) > 0.0)) return false;
        const double x0 = (b[0] * K[1][1] - K[0][1] * b[1]) / det;
        b[1] = (K[0][0] * b[1] - K[1][0] * b[0]) / det;
        b[0] = x0;
        return true;
    }
    const double c00 = K[1][1] * K[2][2] - K[1][2] * K[2][1];
    const double c01 = K[1][2] * K[2][0] - K[1][0] * K[2][2];
    const double c02 = K[1][0] * K[2][1] - K[1][1] * K[2][0];
    const double det = K[0][0] * c00 + K[0][1] * c01 + K[0][2] * c02;
    if (!(std::abs(det) > 0.0)) return false;
    const double inv = 1.0 / det;
    const double x0 = (b[0] * c00 + b[1] * (K[0][2] * K[2][1] - K[0][1] * K[2][2]) +
                       b[2] * (K[0][1] * K[1][2] - K[0][2] * K[1][1])) * inv;
    const double x1 = (b[0] * c01 + b[1] * (K[0][0] * K[2][2] - K[0][2] * K[2][0]) +
                       b[2] * (K[0][2] * K[1][0] - K[0][0] * K[1][2])) * inv;
    const double x2 = (b[0] * c02 + b[1] * (K[0][1] * K[2][0] - K[0][0] * K[2][1]) +
                       b[2] * (K[0][0] * K[1][1] - K[0][1] * K[1][0])) * inv;
    b = {x0, x1, x2};
    return true;
}

// Rocking on the pivot at rc from O: its acceleration vanishes, (X'', Y'') = phi'^2 rc -
// J rc phi'', so a = c + J (phi'', q'') and, the pivot's force doing no work along J,
// (J^T A J) (phi'', q'') = J^T (f - A c): two unknowns. The pivot's force (F, N) from the
// translation rows, A_0,1 . a - f_0,1. A: upper triangle.
FlexAccel rock_by_projection(const Mat4& A, const std::array<double, 4>& f, Vec2 rc, double w2) {
    const auto sym = [&](std::size_t i, std::size_t j) { return i <= j ? A[i][j] : A[j][i]; };
    const Vec2 jr = perp(rc);
    const std::array<double, 4> c = {w2 * rc[0], w2 * rc[1], 0.0, 0.0};
    const std::array<double, 4> jphi = {-jr[0], -jr[1], 1.0, 0.0};
    std::array<double, 4> r{}, ajphi{};  // f - A c, A J_phi
    for (std::size_t i = 0; i < 4; ++i) {
        r[i] = f[i] - sym(i, 0) * c[0] - sym(i, 1) * c[1];
        ajphi[i] = sym(i, 0) * jphi[0] + sym(i, 1) * jphi[1] + sym(i, 2);
    }
    // J^T A J = [[jphi . A jphi, A jphi . e_q], [., A_qq]]; J^T r = [jphi . r, r_q].
    const double k00 = dot4(jphi, ajphi), k01 = ajphi[3], k11 = A[3][3];
    const double r0 = dot4(jphi, r), r1 = r[3];
    const auto [phidd, qdd] = solve_phi_q(k00, k01, k11, r0, r1, "rocking mass matrix");
    FlexAccel a;
    a.phidd = phidd;
    a.qdd = qdd;
    a.Xdd = c[0] + jphi[0] * a.phidd;
    a.Ydd = c[1] + jphi[1] * a.phidd;
    const std::array<double, 4> acc = {a.Xdd, a.Ydd, a.phidd, a.qdd};
    a.F = sym(0, 0) * acc[0] + sym(0, 1) * acc[1] + sym(0, 2) * acc[2] + sym(0, 3) * acc[3] - f[0];
    a.N = sym(1, 0) * acc[0] + sym(1, 1) * acc[1] + sym(1, 2) * acc[2] + sym(1, 3) * acc[3] - f[1];
    return a;
}

// A contact force lambda d applied at body point pc (rotated: rc).
struct ForceCol {
    Vec2 rc{}, d{};
};

// The NF contact forces lambda of (C A^-1 D) lambda = gamma - C A^-1 f, with acc = A^-1 f on
// entry and A^-1 (f + D lambda) on return; false if the contact system is singular.
template <std::size_t NF>
bool contact_forces(const MassSolve& mass, const std::array<ForceCol, 3>& fc,
                    const std::array<std::array<double, 4>, 3>& C, const std::array<double, 3>& gamma,
                    std::array<double, 4>& acc, std::array<double, 3>& lambda) {
    std::array<std::array<double, 4>, NF> y;  // A^-1 D_j
    for (std::size_t j = 0; j < NF; ++j) {
        y[j] = {fc[j].d[0], fc[j].d[1], cross(fc[j].rc, fc[j].d), 0.0};
        mass.solve(y[j]);
    }
    std::array<std::array<double, 3>, 3> K;
    for (std::size_t i = 0; i < NF; ++i) {
        lambda[i] = gamma[i] - dot4(C[i], acc);
        for (std::size_t j = 0; j < NF; ++j) K[i][j] = dot4(C[i], y[j]);
    }
    if (!solve_small(K, lambda, NF)) return false;
    for (std::size_t j = 0; j < NF; ++j)
        for (std::size_t i = 0; i < 4; ++i) acc[i] += y[j][i] * lambda[j];
    return true;
}

}  // namespace

double impact_modal_share(double x) {
    // Residual shock spectrum of a half-sine pulse of duration T (e.g. Harris & Piersol, Shock
    // and Vibration Handbook, ch. 8): an undamped oscillator is left vibrating with the velocity
    // amplitude |cos(x / 2)| / |1 - (x / pi)^2| of the pulse's velocity change, x = omega T
    // (pi / 4 at x = pi, where both vanish).
    constexpr double pi = std::numbers::pi;
    if (std::abs(x - pi) < 1e-6) return pi / 4.0;
    return std::abs(std::cos(0.5 * x)) / std::abs(1.0 - (x / pi) * (x / pi));
}

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
    g.held = {g.omega, g.zeta};
    const double root_kappa = std::sqrt(g.M / g.Mr);
    g.sliding = {g.omega * root_kappa, g.zeta * root_kappa};
    g.exact_slide = g.sliding.zeta < 1.0;
    g.b = {blk.b_left_m, blk.b_right_m};
    g.inv_width = 1.0 / (g.b[0] + g.b[1]);
    g.Ir_base = g.Ir + g.Mr * g.hr * g.hr;
    for (std::size_t i = 0; i < 2; ++i) g.Ir_edge[i] = g.Ir_base + g.Mr * g.b[i] * g.b[i];
    g.measured_restitution = m.rigid.restitution.has_value();
    g.modal_free = impact_modal_share(g.omega * m.impact_duration_s);
    return g;
}

namespace {

// The body without contact at pose p: the mass matrix A of (X'', Y'', phi'', q'') (upper
// triangle) and the forces f.
struct FreeBody {
    Mat4 A{};
    std::array<double, 4> f{};
};
FreeBody free_body(const FlexGeometry& g, const Pose& p, Base base) {
    const double cp = p.cphi, sp = p.sphi, w = p.phid, w2 = w * w;
    const Vec2 e1 = {cp, sp};
    const Vec2 rr = rot(cp, sp, {0.0, g.hr});       // O to the rigid remainder's CG
    const Vec2 rs = rot(cp, sp, {p.q, g.hs});       // O to the modal mass
    const Vec2 gv = {-base.ax, -base.G};            // gravity and the base's inertia, per kg
    const Vec2 je1 = perp(e1);
    const Vec2 vr = {-w2 * rr[0], -w2 * rr[1]};
    const Vec2 vs = {-w2 * rs[0] + 2.0 * w * p.qd * je1[0], -w2 * rs[1] + 2.0 * w * p.qd * je1[1]};
    const Vec2 jr = perp(rr), js = perp(rs);

    // Mass matrix of (X'', Y'', phi'', q'') and the forces without contact: the linear momentum
    // of the whole, its angular momentum about O (r x a summed, plus the remainder's spin) and
    // the modal mass along e1, m_s (X'' . e1 - h_s phi'' + q'' - phi'^2 q) = -k q - c q' +
    // m_s g . e1 (cross(rs, e1) = -h_s).
    const Vec2 S = {g.Mr * rr[0] + g.ms * rs[0], g.Mr * rr[1] + g.ms * rs[1]};
    FreeBody body;
    Mat4& A = body.A;
    std::array<double, 4>& f = body.f;
    for (std::size_t i = 0; i < 2; ++i) {
        A[i][i] = g.M;
        A[i][2] = g.Mr * jr[i] + g.ms * js[i];
        A[i][3] = g.ms * e1[i];
        f[i] = g.M * gv[i] - g.Mr * vr[i] - g.ms * vs[i];
    }
    A[2][2] = g.Mr * (rr[0] * rr[0] + rr[1] * rr[1]) + g.ms * (rs[0] * rs[0] + rs[1] * rs[1]) + g.Ir;
    A[2][3] = -g.ms * g.hs;
    A[3][3] = g.ms;
    f[2] = -g.Mr * cross(rr, vr) - g.ms * cross(rs, vs) + cross(S, gv);
    f[3] = -g.k * p.q - g.c * p.qd + g.ms * (gv[0] * e1[0] + gv[1] * e1[1]) + g.ms * w2 * p.q;
    return body;
}

// The contact forces and constraints of mode m at pose p.
struct ContactSet {
    std::array<ForceCol, 3> fc{};
    std::size_t nf = 0;
    std::array<std::array<double, 4>, 3> C{};
    std::array<double, 3> gamma{};
};
Vec2 edge_point(const FlexGeometry& g, const Pose& p, int s) {
    const double bx = s > 0 ? g.b[1] : -g.b[0];
    return rot(p.cphi, p.sphi, {bx, 0.0});
}
ContactSet contact_set(const FlexGeometry& g, const FlexMode& m, const Pose& p) {
    const double w = p.phid, w2 = w * w;
    ContactSet cs;
    std::array<ForceCol, 3>& fc = cs.fc;
    std::size_t& nf = cs.nf;
    std::array<std::array<double, 4>, 3>& C = cs.C;
    std::array<double, 3>& gamma = cs.gamma;
    // Contact forces of the mode (docs/methods.md s.3): force j acts along d_j at the body
    // point r_j (column D_j of its generalised force), constraint i fixes the acceleration of a
    // contact point (row C_i: X'' + J r phi'' - phi'^2 r, one component) or phi'' = 0.
    const auto edge_r = [&](int s) { return edge_point(g, p, s); };
    const double mu = g.rigid.mu_k;
    const auto point_row = [&](std::size_t row, Vec2 rc, std::size_t comp) {
        C[row][comp] = 1.0;
        C[row][2] = perp(rc)[comp];
        gamma[row] = w2 * rc[comp];
    };
    switch (m.mode) {
        case Mode::flight: break;
        case Mode::rock:
            fc[0] = {edge_r(m.s), {1.0, 0.0}};
            fc[1] = {edge_r(m.s), {0.0, 1.0}};
            nf = 2;
            point_row(0, fc[0].rc, 0);
            point_row(1, fc[0].rc, 1);
            break;
        case Mode::slide_rock:
            fc[0] = {edge_r(m.s), {-m.sigma * mu, 1.0}};
            nf = 1;
            point_row(0, fc[0].rc, 1);
            break;
        case Mode::slide:
            fc[0] = {edge_r(-1), {-m.sigma * mu, 1.0}};
            fc[1] = {edge_r(1), {-m.sigma * mu, 1.0}};
            nf = 2;
            point_row(0, fc[0].rc, 1);
            C[1][2] = 1.0;
            break;
        case Mode::rest:
            fc[0] = {edge_r(-1), {1.0, 0.0}};
            fc[1] = {edge_r(-1), {0.0, 1.0}};
            fc[2] = {edge_r(1), {0.0, 1.0}};
            nf = 3;
            point_row(0, fc[0].rc, 0);
            point_row(1, fc[0].rc, 1);
            C[2][2] = 1.0;
            break;
    }
    return cs;
}

// The accelerations and contact forces of mode m (not rocking: rock_by_projection).
FlexAccel solve_with_contacts(const FlexMode& m, const FreeBody& body, const ContactSet& cs) {
    const Mat4& A = body.A;
    const std::array<double, 4>& f = body.f;
    const std::array<ForceCol, 3>& fc = cs.fc;
    const std::size_t nf = cs.nf;
    const std::array<std::array<double, 4>, 3>& C = cs.C;
    const std::array<double, 3>& gamma = cs.gamma;
    // A a - D lambda = f, C a = gamma: a = A^-1 (f + D lambda), (C A^-1 D) lambda = gamma -
    // C A^-1 f.
    MassSolve mass;
    if (!mass.factor(A))
        throw NumericalError("flexible-body equations: the mass matrix is not positive definite");
    std::array<double, 4> acc = f;
    mass.solve(acc);
    std::array<double, 3> lambda{};
    const bool ok = nf == 0   ? true
                    : nf == 1 ? contact_forces<1>(mass, fc, C, gamma, acc, lambda)
                    : nf == 2 ? contact_forces<2>(mass, fc, C, gamma, acc, lambda)
                              : contact_forces<3>(mass, fc, C, gamma, acc, lambda);
    if (!ok)
        throw NumericalError("flexible-body equations: the contact forces are indeterminate");
    FlexAccel a;
    a.Xdd = acc[0];
    a.Ydd = acc[1];
    a.phidd = acc[2];
    a.qdd = acc[3];
    for (std::size_t j = 0; j < nf; ++j) {
        a.F += lambda[j] * fc[j].d[0];
        a.N += lambda[j] * fc[j].d[1];
    }
    if (m.mode == Mode::slide) {
        a.NL = lambda[0];
        a.NR = lambda[1];
    } else if (m.mode == Mode::rest) {
        a.NL = lambda[1];
        a.NR = lambda[2];
    }
    return a;
}

}  // namespace

FlexAccel flex_accel_general(const FlexGeometry& g, const FlexMode& m, const Pose& p,
                             Base base) {
    const FreeBody body = free_body(g, p, base);
    if (m.mode == Mode::rock)
        return rock_by_projection(body.A, body.f, edge_point(g, p, m.s), p.phid * p.phid);
    return solve_with_contacts(m, body, contact_set(g, m, p));
}

Pose contact_pose(const FlexGeometry& g, int s, double u, double v, double th, double om,
                  double q, double qd) {
    Pose p;
    with_phi(p, -static_cast<double>(s) * th);
    p.phid = -static_cast<double>(s) * om;
    p.q = q;
    p.qd = qd;
    const double bx = s > 0 ? g.b[1] : -g.b[0];
    const double cp = p.cphi, sp = p.sphi;
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
    const Vec2 re = rot(p.cphi, p.sphi, {bx, 0.0});
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
    const double cp = p.cphi, sp = p.sphi;
    const Vec2 rr = rot(cp, sp, {0.0, g.hr}), rs = rot(cp, sp, {p.q, g.hs});
    const Vec2 e1 = {cp, sp};
    const Vec2 o = {p.X - xc, p.Y};
    const Vec2 vr = {p.Xd - p.phid * rr[1], p.Yd + p.phid * rr[0]};
    const Vec2 vs = {p.Xd - p.phid * rs[1] + p.qd * e1[0], p.Yd + p.phid * rs[0] + p.qd * e1[1]};
    const Vec2 pr = {o[0] + rr[0], o[1] + rr[1]}, ps = {o[0] + rs[0], o[1] + rs[1]};
    return g.Mr * cross(pr, vr) + g.ms * cross(ps, vs) + g.Ir * p.phid;
}

double modal_abs_accel(const FlexGeometry& g, const Pose& p, const FlexAccel& a, Base base) {
    const double cp = p.cphi, sp = p.sphi;
    const Vec2 rs = rot(cp, sp, {p.q, g.hs});
    const double w = p.phid;
    // x of X'' + J rs phi'' - phi'^2 rs + 2 phi' q' J e1 + q'' e1, plus the base's xg''.
    return base.ax + a.Xdd - rs[1] * a.phidd - w * w * rs[0] - 2.0 * w * p.qd * sp +
           a.qdd * cp;
}

}  // namespace detail
}  // namespace freestand::dynamics
