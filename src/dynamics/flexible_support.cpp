// What the two flexible-body integrators share (flexible_detail.hpp): the exact oscillator of
// the rest phase, the exact flat slide, the summary bookkeeping.
#include <algorithm>
#include <cmath>

#include "dynamics/flexible_detail.hpp"
#include "dynamics/overturn.hpp"

namespace freestand::dynamics::detail {

void oscillator_step(const Oscillator& osc, double& q, double& qd, double a0, double a1,
                     double tau) {
    OscillatorStep(osc, tau).apply(q, qd, a0, a1);
}

OscillatorStep::OscillatorStep(const Oscillator& osc, double tau_s) : tau(tau_s) {
    const double w = osc.omega, z = osc.zeta;
    w2_ = w * w;
    inv_w2_ = 1.0 / w2_;
    two_zw_ = 2.0 * z * w;
    wd_ = w * std::sqrt(1.0 - z * z);
    sig_ = z * w;
    if (tau == 0.0) {  // exp, cos and sin of 0, exact (a slide segment's start)
        e_ = 1.0;
        c_ = 1.0;
        s_ = 0.0;
        return;
    }
    e_ = std::exp(-sig_ * tau);
    const CosSin t = cos_sin(wd_ * tau);
    c_ = t.c;
    s_ = t.s / wd_;
}

void OscillatorStep::apply(double& q, double& qd, double a0, double a1) const {
    // Particular solution A + B tau of q'' + 2 zeta w q' + w^2 q = -(a0 + a1 tau), plus the
    // damped free vibration of the rest.
    const double B = -a1 * inv_w2_, A = (-a0 - two_zw_ * B) * inv_w2_;
    const double y0 = q - A, yd0 = qd - B;
    q = A + B * tau + e_ * (y0 * c_ + (yd0 + sig_ * y0) * s_);
    qd = B + e_ * (yd0 * c_ - (sig_ * yd0 + w2_ * y0) * s_);
}

SlideSegment::SlideSegment(const FlexGeometry& g, int sigma, const std::array<double, 8>& x,
                           Base b0, double ax1, double G1)
    : g_(g), sigma_(sigma), u0_(x[0]), q0_(x[4]), qd0_(x[5]),
      p0_(g.M * x[1] + g.ms * x[5]), ax0_(b0.ax), ax1_(ax1), G0_(b0.G), G1_(G1) {}

SlideSegment::Point SlideSegment::at(double tau) const {
    const FlexGeometry& g = g_;
    const double smu = static_cast<double>(sigma_) * g.rigid.mu_k, kappa = g.M / g.Mr;
    Point p;
    p.q = q0_;
    p.qd = qd0_;
    oscillator_step(g.sliding, p.q, p.qd, -smu * kappa * G0_, -smu * kappa * G1_, tau);
    const double t2 = tau * tau / 2.0, t3 = tau * tau * tau / 6.0;
    const double P = p0_ - g.M * (ax0_ * tau + ax1_ * t2) - smu * g.M * (G0_ * tau + G1_ * t2);
    p.v = (P - g.ms * p.qd) / g.M;
    p.u = u0_ + (p0_ * tau - g.M * (ax0_ * t2 + ax1_ * t3) - smu * g.M * (G0_ * t2 + G1_ * t3) -
                 g.ms * (p.q - q0_)) / g.M;
    p.a = flex_slide_accel(g, sigma_, p.q, p.qd, {ax0_ + ax1_ * tau, G0_ + G1_ * tau});
    return p;
}

Pose pose_of(const FlexGeometry& g, const FlexMode& m, const FlexState& x) {
    if (is_flight(m.mode)) {
        Pose p{x[0], x[2], x[4], x[6], x[1], x[3], x[5], x[7]};
        with_phi(p, x[4]);
        return p;
    }
    return contact_pose(g, m.s, x[0], x[1], x[2], x[3], x[4], x[5]);
}

void FlexRecorder::record(double t, const FlexMode& m, const FlexState& x) {
    FlexibleSample s;
    s.time_s = t;
    s.mode = m.mode;
    s.modal_m = modal_of(m.mode, x);
    s.slide_m = x[0];
    s.rotation_rad = is_flight(m.mode) ? -x[4] : static_cast<double>(m.s) * x[2];
    out_.series.push_back(s);
}

void FlexRecorder::transition(Mode from, Mode to) {
    tally_.transition(from, to);
    if (to == Mode::rock || to == Mode::slide_rock || is_flight(to)) out_.summary.uplifted = true;
}

FlexRecorder::FlexRecorder(const FlexGeometry& g, const Options& o, FlexibleResult& out)
    : g_(g), o_(o), out_(out),
      ridge_energy_J_{ridge_energy_J(g, -1, o.g_mps2), ridge_energy_J(g, 1, o.g_mps2)} {}

void FlexRecorder::end_run(const FlexMode& m, const FlexState& x, double end_s,
                           const BaseMotion& bm, const char* integrator) {
    if (!overturned()) check_overturn(m, x, end_s, end_s >= bm.quiet_from_s());
    if (overturned()) end_s = out_.summary.base.overturn_time_s.value_or(end_s);
    finish(integrator, end_s, bm.pga_mps2(), std::abs(x[0]), 0.0);
}

void FlexRecorder::check_overturn(const FlexMode& m, const FlexState& x, double t_s,
                                  bool input_ended) {
    if (m.mode != Mode::rock && m.mode != Mode::slide_rock) return;
    const auto i = static_cast<std::size_t>(Geometry::index(m.s));
    if (!overturn_possible(x[2], x[3], g_.rigid.alpha[i], input_ended)) return;
    const Pose p = pose_of(g_, m, x);
    // The mode moves the CG along the body's axis by m_s q / M: beyond the pivot is the CG's
    // own position, not theta > alpha.
    const double x_cg = p.X + (g_.ms * p.cphi * p.q - p.sphi * g_.Mh) / g_.M;
    const double height_J = o_.g_mps2 * (g_.M * p.Y + p.cphi * g_.Mh + p.sphi * g_.ms * p.q);
    Tilt tilt;
    tilt.theta_rad = x[2];
    tilt.omega_radps = x[3];
    tilt.alpha_rad = g_.rigid.alpha[i];
    tilt.cg_beyond_pivot_m = static_cast<double>(m.s) * (x_cg - (x[0] + edge_x(g_, m.s)));
    tilt.energy_J = kinetic_energy(g_, p) + 0.5 * g_.k * p.q * p.q + height_J;
    tilt.ridge_energy_J = ridge_energy_J_[i];
    const OverturnCriterion c = overturn_criterion(tilt, input_ended);
    if (c != OverturnCriterion::none) overturn(t_s, c);
}

double ridge_energy_J(const FlexGeometry& g, int s, double g_mps2) {
    // z = s q moves the CG towards the pivot: R(z)^2 = (b - c z)^2 + h^2 with c = m_s / M.
    const double b = g.b[static_cast<std::size_t>(Geometry::index(s))];
    const double c = g.ms / g.M, h = g.Mh / g.M, Mg = g.M * g_mps2;
    auto energy = [&](double z) { return Mg * std::hypot(b - c * z, h) + 0.5 * g.k * z * z; };
    auto slope = [&](double z) { return -Mg * c * (b - c * z) / std::hypot(b - c * z, h) + g.k * z; };
    // The slope is < 0 at z = 0 and > 0 at z = b / c (the CG over the pivot at theta = 0):
    // bisection to the minimum.
    double lo = 0.0, hi = b / c;
    for (int it = 0; it < 200 && hi - lo > 1e-15 * (b / c); ++it) {
        const double mid = 0.5 * (lo + hi);
        (slope(mid) < 0.0 ? lo : hi) = mid;
    }
    return energy(0.5 * (lo + hi));
}

void FlexRecorder::finish(const char* integrator, double end_time_s, double pga_mps2,
                          double residual_m, double wall_s) {
    Summary& b = out_.summary.base;
    b.integrator = integrator;
    b.end_time_s = end_time_s;
    b.pga_g = pga_mps2 / o_.g_mps2;
    b.slide_residual_m = residual_m;
    out_.summary.modal_drift_max = out_.summary.modal_max_m / g_.hs;
    out_.summary.modal_accel_max_g = accel_peak_ / o_.g_mps2;
    b.wall_s = wall_s;
}

bool settled_for_good(const FlexGeometry& g, double q, double qd, double g_mps2) {
    const double amp = std::hypot(q, qd / g.omega);
    const double shear = g.ms * g.omega * g.omega * amp * (1.0 + 2.0 * g.zeta);
    const double moment = shear * g.hs + g_mps2 * g.ms * amp;
    return shear <= g.rigid.mu_s * g.M * g_mps2 &&
           moment <= g.M * g_mps2 * std::min(g.b[0], g.b[1]);
}

}  // namespace freestand::dynamics::detail
