#pragma once
/// Internal: equations of motion of the flexible body (flexible.hpp) in each contact mode, its
/// impact and landing rules and the bookkeeping its two integrators (flexible_event.cpp,
/// flexible_cd.cpp) share.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

#include "core/errors.hpp"
#include "dynamics/engine.hpp"
#include "dynamics/flexible.hpp"
#include "dynamics/integrators.hpp"
#include "dynamics/mechanics.hpp"

namespace freestand::dynamics::detail {

/// A damped linear oscillator: circular frequency omega (rad/s), damping ratio zeta in [0, 1).
struct Oscillator {
    double omega = 0.0;
    double zeta = 0.0;
};

/// Constants of the split body. Body frame: origin O on the base plane below the CG, x along
/// the base to the right, y up; edges at (-b_L, 0) and (b_R, 0); the rigid remainder's CG at
/// (0, hr); the modal mass at (q, hs).
struct FlexGeometry {
    Geometry rigid;  ///< the whole block as the rigid model sees it (restitution, alpha, mu)
    double M = 0.0, Mr = 0.0, ms = 0.0, hr = 0.0, Ir = 0.0, hs = 0.0, Mh = 0.0;
    double omega = 0.0, zeta = 0.0, k = 0.0, c = 0.0;
    /// The mode on the held base (omega, zeta) and against the flat-sliding remainder
    /// (omega sqrt(M / M_r), zeta sqrt(M / M_r)); exact_slide when the latter is underdamped.
    Oscillator held, sliding;
    bool exact_slide = false;
    std::array<double, 2> b{};  ///< [0] left, [1] right half-widths
    double inv_width = 0.0;     ///< 1 / (b_L + b_R)
    /// Second moment of the rigid remainder about each edge, I_r + M_r (b^2 + h_r^2), and
    /// about O, I_r + M_r h_r^2, kg m^2.
    std::array<double, 2> Ir_edge{};
    double Ir_base = 0.0;
    /// The restitution was measured (BlockModel::restitution): an impact multiplies theta' by
    /// it; otherwise angular momentum about the striking edge is conserved.
    bool measured_restitution = false;
    /// Share of a base velocity change at an impact that the mode does not follow (the modal
    /// mass keeps its velocity): impact_modal_share(omega T), T the model's impact duration.
    double modal_free = 1.0;
};
FlexGeometry make_flex_geometry(const FlexibleModel& m);

/// The velocity an undamped oscillator of frequency omega keeps vibrating with after a
/// half-sine pulse of duration T, per unit of the pulse's velocity change, x = omega T: 1 for
/// x -> 0 (a slow mode does not follow the pulse), ~ (pi / x)^2 for x >> pi (a fast one does).
double impact_modal_share(double x);

/// Body-frame abscissa of edge s's contact point: b_R (s = +1) or -b_L (s = -1).
inline double edge_x(const FlexGeometry& g, int s) { return s > 0 ? g.b[1] : -g.b[0]; }

/// Mode of the base with its edge s (rock, slide-rock) and slip direction sigma.
struct FlexMode {
    Mode mode = Mode::rest;
    int s = 1;
    int sigma = 1;
};

/// cos(x) and sin(x). For |x| <= 0.5 (the tilts of a standing body) their Taylor polynomials
/// to x^14 and x^15 (truncation below 1e-18 relative; within 0.7 ulp of the exact values after
/// rounding, tests/dynamics/test_flexible_equations.cpp), std::cos and std::sin beyond: libm's
/// sincos, with its rounding-mode guard, costs as much as the equations of motion it feeds.
struct CosSin {
    double c = 1.0, s = 0.0;
};
inline CosSin cos_sin(double x) {
    if (!(std::abs(x) <= 0.5)) return {std::cos(x), std::sin(x)};
    constexpr auto inv_factorial = [](int n) {
        double f = 1.0;
        for (int i = 2; i <= n; ++i) f *= i;  // exact to 18!
        return 1.0 / f;
    };
    constexpr double c2 = inv_factorial(2), c3 = inv_factorial(3), c4 = inv_factorial(4),
                     c5 = inv_factorial(5), c6 = inv_factorial(6), c7 = inv_factorial(7),
                     c8 = inv_factorial(8), c9 = inv_factorial(9), c10 = inv_factorial(10),
                     c11 = inv_factorial(11), c12 = inv_factorial(12), c13 = inv_factorial(13),
                     c14 = inv_factorial(14), c15 = inv_factorial(15);
    const double z = x * x;
    const double s =
        x + x * z * (-c3 + z * (c5 + z * (-c7 + z * (c9 + z * (-c11 + z * (c13 - z * c15))))));
    const double c =
        1.0 + z * (-c2 + z * (c4 + z * (-c6 + z * (c8 + z * (-c10 + z * (c12 - z * c14))))));
    return {c, s};
}

/// Pose of the body relative to the moving base frame: O's position (X, Y), rotation phi
/// (counter-clockwise), modal coordinate q, and their rates; cphi and sphi are cos(phi) and
/// sin(phi), set with phi (contact_pose, pose_of, with_phi) so the equations need not repeat
/// the trigonometry.
struct Pose {
    double X = 0, Y = 0, phi = 0, q = 0, Xd = 0, Yd = 0, phid = 0, qd = 0;
    double cphi = 1.0, sphi = 0.0;
};
/// The pose's phi and its cosine and sine.
inline void with_phi(Pose& p, double phi) {
    p.phi = phi;
    const CosSin t = cos_sin(phi);
    p.cphi = t.c;
    p.sphi = t.s;
}

/// Accelerations of the pose and the base reactions (F horizontal, N vertical, on the body);
/// NL, NR the normal forces at the left and right edges in the flat modes.
struct FlexAccel {
    double Xdd = 0, Ydd = 0, phidd = 0, qdd = 0, F = 0, N = 0, NL = 0, NR = 0;
};

/// (phi'', q'') of the two-unknown systems [[k00, k01], [k01, k11]] (phi'', q'') = (r0, r1) the
/// equations of motion reduce to; NumericalError naming `matrix` when it is not positive
/// definite.
inline std::array<double, 2> solve_phi_q(double k00, double k01, double k11, double r0,
                                         double r1, const char* matrix) {
    const double det = k00 * k11 - k01 * k01;
    if (!(det > 0.0))
        throw NumericalError(std::string("flexible-body equations: the ") + matrix +
                             " is not positive definite");
    return {(r0 * k11 - k01 * r1) / det, (k00 * r1 - k01 * r0) / det};
}

/// Newton-Euler equations of the two bodies (linear and angular momentum of the whole about O,
/// the modal mass along the body's x axis: m_s a_s . e1 = -k q - c q' + forces . e1) with the
/// mode's contact forces and constraints: M a - D lambda = f, C a = gamma (a the four pose
/// accelerations, lambda the contact forces), solved through the 4 x 4 mass matrix M and the
/// at most 3 x 3 system C M^-1 D lambda = gamma - C M^-1 f; rocking by projection on the
/// pivot's null space (two unknowns). Any mode and pose: the reference the specialised
/// equations below are tested against.
FlexAccel flex_accel_general(const FlexGeometry& g, const FlexMode& m, const Pose& p, Base base);

/// What the equations of motion read of a pose: cos(phi), sin(phi), phi', q and q' (the base
/// point's position and velocity do not enter them).
struct Attitude {
    double cphi = 1.0, sphi = 0.0, phid = 0.0, q = 0.0, qd = 0.0;
};
inline Attitude attitude(const Pose& p) { return {p.cphi, p.sphi, p.phid, p.q, p.qd}; }

/// Accelerations on edge s in the contact point P's coordinates: P's slip u'' (0 rocking),
/// phi'', q'', and the reactions F, N at P.
struct EdgeAccel {
    double udd = 0, phidd = 0, qdd = 0, F = 0, N = 0;
};
/// Rock about edge s (P fixed): Lagrange's equations of (phi, q) about P, a 2 x 2 system in
/// closed form (flexible_modes.cpp).
EdgeAccel flex_rock_accel(const FlexGeometry& g, int s, const Attitude& p, Base base);
/// Slide-rock on edge s in direction sigma: the rocking solution plus P's slip u'', which
/// shifts phi'', q'', F and N linearly; u'' makes F = -sigma mu_k N. Throws NumericalError
/// when the contact force is indeterminate (u'' has no coefficient: Painleve's paradox).
EdgeAccel flex_slide_rock_accel(const FlexGeometry& g, int s, int sigma, const Attitude& p,
                                Base base);
/// The pose accelerations of an edge mode's solution (O = P - R (b_x, 0)).
FlexAccel flex_accel_of(const FlexGeometry& g, int s, const Attitude& p, const EdgeAccel& e);
/// Flat slide in direction sigma (phi = phi' = 0, N = M G, F = -sigma mu_k N): X'' = u'',
/// q'' and the edge forces N_L, N_R in closed form.
FlexAccel flex_slide_accel(const FlexGeometry& g, int sigma, double q, double qd, Base base);
/// Flight: the CG falls freely (X'', Y'' from the linear momentum) and (phi, q) obey the 2 x 2
/// system of the body about its CG, in closed form.
FlexAccel flex_flight_accel(const FlexGeometry& g, const Attitude& p, Base base);

/// The accelerations of mode m at pose p by the mode's own equations above (rest_accel at rest;
/// the flat modes read q and q' only).
FlexAccel flex_accel(const FlexGeometry& g, const FlexMode& m, const Pose& p, Base base);

/// Rest (base held flat, docs/methods.md s.2 generalised): the modal equation and the base
/// reactions in closed form, F = M xg'' + m_s q'', N = M G and the moment about O (inline: once
/// per input sample of a resting record).
inline FlexAccel rest_accel(const FlexGeometry& g, double q, double qd, Base base) {
    FlexAccel a;
    a.qdd = -base.ax - 2.0 * g.zeta * g.omega * qd - g.omega * g.omega * q;
    a.F = g.M * base.ax + g.ms * a.qdd;
    a.N = g.M * base.G;
    // Moment about O: N_R b_R - N_L b_L = -m_s h_s q'' + G m_s q - xg'' M h.
    const double mo = -g.ms * g.hs * a.qdd + base.G * g.ms * q - base.ax * g.Mh;
    a.NR = (a.N * g.b[0] + mo) * g.inv_width;
    a.NL = (a.N * g.b[1] - mo) * g.inv_width;
    return a;
}
/// Rest holds: |F| <= mu_s N, both edges pressed (NL, NR >= 0) and G >= 0.
inline double rest_margin(const FlexGeometry& g, const FlexAccel& a, Base base) {
    double m = g.rigid.mu_s * a.N - std::abs(a.F);
    m = std::min(m, a.NL);
    m = std::min(m, a.NR);
    return std::min(m, base.G);
}

/// Pose of a contact state on edge s: slip u of the contact point (flat: of O), uplift theta.
Pose contact_pose(const FlexGeometry& g, int s, double u, double v, double th, double om,
                  double q, double qd);
/// Horizontal acceleration of the edge-s contact point from the pose accelerations.
double contact_slip_accel(const FlexGeometry& g, int s, const Pose& p, const FlexAccel& a);

/// Mode entered from flat contact (theta = 0, theta' = 0) with slip velocity v (0: from rest)
/// under base acceleration base, by docs/methods.md s.2 and s.3 generalised: flight if G < 0;
/// if an edge unloads, rock about the other when static friction holds there, else slide-rock
/// (slide when the edge does not lift under kinetic friction); a slip continues as slide (or
/// slide-rock if an edge unloads); rest if the rest inequalities hold, else slide.
FlexMode classify_flat(const FlexGeometry& g, double q, double qd, double v, Base base);
/// Mode on edge s with slip velocity v: flight if N < 0, slide-rock if v != 0, rock if static
/// friction holds, else slide-rock in the direction it is pushed.
FlexMode classify_edge(const FlexGeometry& g, int s, const Pose& p, double v, Base base);

/// Angular momentum of the body about the base-plane point (xc, 0), counter-clockwise.
double angular_momentum_about(const FlexGeometry& g, const Pose& p, double xc);
/// Absolute horizontal acceleration of the modal mass, m/s^2.
double modal_abs_accel(const FlexGeometry& g, const Pose& p, const FlexAccel& a, Base base);
/// Kinetic energy of the body relative to the base, J (a check of the impact rules).
double kinetic_energy(const FlexGeometry& g, const Pose& p);

/// q' after an impact changed the base's velocity from `before` to `after` (after.qd is not
/// read): the modal mass's velocity along the body axis changes by (1 - modal_free) times its
/// attachment's (the generalised momentum of q is conserved when the mode is free).
double modal_rate_after(const FlexGeometry& g, const Pose& before, const Pose& after);

/// A contact state on edge s: slip u and its rate v, uplift theta and its rate (both >= 0 on
/// the edge), q and q'.
struct EdgeState {
    int s = 1;
    double u = 0, v = 0, th = 0, om = 0, q = 0, qd = 0;
};

/// The body strikes edge s_new at theta = 0 while rotating towards it (pose p on the other
/// edge, slip u, v kept): theta' about s_new after the impact (>= 0; 0 when it cannot rebound)
/// and q'. Housner's rule generalised, conserving the angular momentum about s_new, or the
/// measured restitution on theta'; the mode by modal_rate_after (docs/methods.md s.10).
EdgeState edge_impact(const FlexGeometry& g, const Pose& p, int s_new, double u, double v);

/// The end of a flight with the lowest corner touching (pose p in the flight's frame): a
/// sticking impact on that corner conserving the angular momentum about it (s.3), or a flat
/// landing (both edges, Coulomb impulse on the slip) when the tilt is nil or the far edge's gap
/// closes within flat_window_s at the vertical speed; q' by modal_rate_after.
struct Landing {
    EdgeState st;
    bool flat = false;
    double om_before = 0.0;  ///< |phi'| before, rad/s
};
Landing land_flexible(const FlexGeometry& g, const Pose& p, double flat_window_s);

/// The base set flat (theta = theta' = 0) with slip rate v, from pose p (an impact too small
/// to rebound, or chatter settled): q' by modal_rate_after.
double flat_modal_rate(const FlexGeometry& g, const Pose& p, double u, double v);

/// The oscillator q'' + 2 zeta omega q' + omega^2 q = -(a0 + a1 tau) advanced exactly by tau
/// (Nigam & Jennings 1969).
void oscillator_step(const Oscillator& osc, double& q, double& qd, double a0, double a1,
                     double tau);

/// The same with the free-vibration factors of one step length tau precomputed (the rest
/// phase's full input steps, all of one length).
struct OscillatorStep {
    OscillatorStep() = default;
    OscillatorStep(const Oscillator& osc, double tau);
    void apply(double& q, double& qd, double a0, double a1) const;
    double tau = 0.0;

private:
    double w2_ = 0.0, inv_w2_ = 0.0, two_zw_ = 0.0, sig_ = 0.0, wd_ = 0.0, e_ = 0.0, c_ = 0.0,
           s_ = 0.0;
};

/// Flat sliding in direction sigma, exact on a linear input segment: with phi = Y = 0 and
/// N = M G the equations are linear. The modal mass against the sliding remainder is the
/// oscillator FlexGeometry::sliding, q'' + (c q' + k q) M / (m_s M_r) = sigma mu_k G M / M_r;
/// the momentum M u' + m_s q' changes at -M xg'' - sigma mu_k M G, a polynomial.
class SlideSegment {
public:
    /// From the state x (slip u, u', q, q') at the segment's point where the base is b0, the
    /// input's slopes ax1 and G1 on it.
    SlideSegment(const FlexGeometry& g, int sigma, const std::array<double, 8>& x, Base b0,
                 double ax1, double G1);
    /// The state and the quantities of the slide's events at tau after the start.
    struct Point {
        double u = 0, v = 0, q = 0, qd = 0;
        FlexAccel a;  ///< Xdd = u'', qdd, F, N, NL, NR
    };
    Point at(double tau) const;

private:
    const FlexGeometry& g_;
    int sigma_;
    double u0_, q0_, qd0_, p0_, ax0_, ax1_, G0_, G1_;
};

/// Integrator state. Contact modes: (u, u', theta, theta', q, q', 0, 0) on the mode's edge
/// (u of the contact point; flat: of O); flight: (X, X', Y, Y', phi, phi', q, q') of O.
using FlexState = std::array<double, 8>;

inline bool is_flight(Mode m) { return m == Mode::flight; }
inline double modal_of(Mode m, const FlexState& x) { return is_flight(m) ? x[6] : x[4]; }
inline double modal_rate_of(Mode m, const FlexState& x) { return is_flight(m) ? x[7] : x[5]; }
Pose pose_of(const FlexGeometry& g, const FlexMode& m, const FlexState& x);
inline FlexState flight_state(const Pose& p) {
    return {p.X, p.Xd, p.Y, p.Yd, p.phi, p.phid, p.q, p.qd};
}
inline FlexState edge_state(const EdgeState& e) { return {e.u, e.v, e.th, e.om, e.q, e.qd, 0, 0}; }

/// The state's time derivative in mode m and the accelerations it came from (flexible_modes.cpp).
void flex_rhs(const FlexGeometry& g, const FlexMode& m, const FlexState& x, Base base,
              FlexState& dx, FlexAccel& a);

/// Summary bookkeeping and the output series of both integrators.
class FlexRecorder {
public:
    FlexRecorder(const FlexGeometry& g, const Options& o, FlexibleResult& out);
    FlexRecorder(const FlexRecorder&) = delete;  // the tallies refer to out's summary
    FlexRecorder& operator=(const FlexRecorder&) = delete;
    /// Peaks of slip, uplift and |q| at the state x in mode m (inline: once per step and
    /// sample). The tilt in flight counts as a rotation (phi < 0 leans over the right edge).
    void observe(const FlexMode& m, const FlexState& x) {
        Summary& s = out_.summary.base;
        modal_peak(modal_of(m.mode, x));
        s.slide_max_m = std::max(s.slide_max_m, std::abs(x[0]));
        if (is_flight(m.mode)) {
            rotation_peak(std::abs(x[4]), x[4] < 0.0 ? 1 : -1);
            return;
        }
        if (x[2] > 0.0) rotation_peak(x[2], m.s);
    }
    /// Applies the overturning rule (overturn.hpp) to a rock / slide-rock state x at t_s.
    void check_overturn(const FlexMode& m, const FlexState& x, double t_s, bool input_ended);
    /// A peak of |q| found between the integrator's points.
    void modal_peak(double q) {
        out_.summary.modal_max_m = std::max(out_.summary.modal_max_m, std::abs(q));
    }
    double modal_max() const { return out_.summary.modal_max_m; }
    /// Output sample at time t: the modal mass's absolute acceleration (peak) and the series.
    void sample(double t, const FlexMode& m, const FlexState& x, double modal_abs_accel_mps2) {
        observe(m, x);
        accel_peak_ = std::max(accel_peak_, std::abs(modal_abs_accel_mps2));
        if (o_.record_series) record(t, m, x);
    }
    void transition(Mode from, Mode to);
    void time_in(Mode m, double dt_s) { tally_.time_in(m, dt_s); }
    void step() { tally_.step(); }
    void rejected() { ++out_.summary.rejected_steps; }
    void impact(double t_s, double omega_before, double omega_after, bool settled) {
        log_.impact(t_s, omega_before, omega_after, settled);
    }
    void settlement() { log_.settlement(); }
    void overturn(double t_s, OverturnCriterion criterion) { log_.overturn(t_s, criterion); }
    bool overturned() const { return log_.overturned(); }
    /// Ends a run at end_s with the body in mode m at x: the overturning rule applies to that
    /// state too, an overturned run ends at its overturn; then finish().
    void end_run(const FlexMode& m, const FlexState& x, double end_s, const BaseMotion& bm,
                 const char* integrator);
    /// Fills the summary's totals; slide_residual_m from the final state.
    void finish(const char* integrator, double end_time_s, double pga_mps2, double residual_m,
                double wall_s);

private:
    void record(double t, const FlexMode& m, const FlexState& x);
    void rotation_peak(double theta_rad, int s) {
        log_.rotation_peak(theta_rad, g_.rigid.alpha[static_cast<std::size_t>(Geometry::index(s))]);
    }

    const FlexGeometry& g_;
    const Options& o_;
    FlexibleResult& out_;
    ModeTally<Summary> tally_{out_.summary.base};
    ContactLog log_{out_.summary.base, out_.impact_log};
    double accel_peak_ = 0.0;
    /// Least potential energy of a pose with the CG over edge [i] (left, right), J.
    std::array<double, 2> ridge_energy_J_{};
};

/// Least potential energy (gravity g_mps2 above the base plane and the mode's strain energy) of
/// a pose of the body on edge s with its CG over the pivot, J: the barrier the body must climb
/// to bring a CG beyond the pivot back inside. The CG sits at R(q) above the pivot, R(q) the
/// distance from the edge to the CG of the body deflected by q: min over q of
/// M g R(q) + k q^2 / 2, a convex function of q.
double ridge_energy_J(const FlexGeometry& g, int s, double g_mps2);

/// At rest with a mode too small ever to unsettle the base again: the free vibration's
/// amplitude bounds q and omega q, so the rest inequalities hold for good.
bool settled_for_good(const FlexGeometry& g, double q, double qd, double g_mps2);

/// Throws NumericalError once steps (Dormand-Prince, accepted and rejected) exceed
/// core::limits::max_adaptive_steps, naming the time t_s reached, the mode's frequency and
/// the rigid limit above which the rigid block would run.
void require_step_budget(std::size_t steps, double t_s, double f_hz, double rigid_limit_hz);

/// cd_stable_step_s (flexible.hpp) of the split body.
double cd_stable_step_s(const FlexGeometry& g, double g_mps2);

/// The event-driven run; rigid_limit_hz (flexible.hpp) names where the rigid block would take
/// over when the step budget runs out.
FlexibleResult run_flexible_event(const FlexGeometry& g, const BaseMotion& bm, const Options& o,
                                  double rigid_limit_hz = std::numeric_limits<double>::infinity());
FlexibleResult run_flexible_cd(const FlexGeometry& g, const BaseMotion& bm, const Options& o);

}  // namespace freestand::dynamics::detail
