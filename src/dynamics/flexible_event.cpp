// Event-driven integration of the flexible body (flexible.hpp). Rest: the base is held and the
// mode is the linear oscillator, advanced exactly over each linear input segment (Nigam &
// Jennings 1969); the rest inequalities are checked at the segment's end and a failure is
// located on the exact solution. Slide, rock, slide-rock and flight: Boost.Odeint's controlled
// Dormand-Prince 5(4) (as the biaxial slide, biaxial_event.cpp) on the mode's equations
// (flex_accel), steps ending at every input sample; events (impact, lift-off, friction
// exceeded, slip stop, an edge unloading, landing, theta = pi/2) are sign changes over a step,
// located by TOMS 748 on the stepper's dense output.
#include <algorithm>
#include <boost/math/tools/toms748_solve.hpp>
#include <boost/numeric/odeint/stepper/controlled_runge_kutta.hpp>
#include <boost/numeric/odeint/stepper/generation.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta_dopri5.hpp>
#include <chrono>
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <numbers>

#include "core/errors.hpp"
#include "dynamics/flexible_detail.hpp"
#include "dynamics/integrators.hpp"

namespace freestand::dynamics {

namespace detail {
namespace {

namespace odeint = boost::numeric::odeint;
// Contact modes: u, u', theta, theta', q, q' (last two unused); flight: X, X', Y, Y', phi,
// phi', q, q'.
using State = std::array<double, 8>;
using Stepper = odeint::runge_kutta_dopri5<State>;
using Controlled = odeint::controlled_runge_kutta<Stepper>;

constexpr double half_pi = std::numbers::pi / 2.0;
constexpr std::size_t burst_settle = 64;
constexpr std::size_t burst_fail = 100000;

template <class F>
double toms748_root(F f, double a, double b, double fa, double fb) {
    if (fb == 0.0) return b;
    std::uintmax_t iters = 200;
    const auto r = boost::math::tools::toms748_solve(
        f, a, b, fa, fb, boost::math::tools::eps_tolerance<double>(50), iters);
    return 0.5 * (r.first + r.second);
}

bool is_flight(Mode m) { return m == Mode::flight; }

struct Segment {
    double tk = 0, ax0 = 0, ax1 = 0, G0 = 0, G1 = 0;
    Base at(double t) const { return {ax0 + ax1 * (t - tk), G0 + G1 * (t - tk)}; }
};

class FlexEngine {
public:
    FlexEngine(const FlexGeometry& g, const Options& o, FlexibleResult& out)
        : g_(g), o_(o), out_(out), ctrl_(odeint::make_controlled(o.abs_tol, o.rel_tol, Stepper())) {}

    FlexMode mode() const { return m_; }
    const State& state() const { return x_; }

    void start(Base probe) { set_mode(classify_flat(g_, 0.0, 0.0, 0.0, probe), 0.0); }

    // Advances from t towards tb on segment seg; returns the time reached.
    double advance(const Segment& seg, double t, double tb) {
        seg_ = seg;
        tb_ = tb;
        const double te = m_.mode == Mode::rest ? advance_rest(t) : advance_ode(t);
        return te;
    }

    Pose pose(const State& x) const {
        if (is_flight(m_.mode)) return {x[0], x[2], x[4], x[6], x[1], x[3], x[5], x[7]};
        return contact_pose(g_, m_.s, x[0], x[1], x[2], x[3], x[4], x[5]);
    }
    double modal(const State& x) const { return is_flight(m_.mode) ? x[6] : x[4]; }

    // The sample at time t (the state's accelerations evaluated afresh).
    void sample(double t, Base base) {
        const double q = modal(x_);
        observe(x_);
        double acc = 0.0;
        if (m_.mode == Mode::rest) {
            acc = base.ax + rest_accel(g_, x_[4], x_[5], base).qdd;
        } else {
            const Pose p = pose(x_);
            acc = modal_abs_accel(g_, p, flex_accel(g_, m_, p, base), base);
        }
        acc_peak_ = std::max(acc_peak_, std::abs(acc));
        if (!o_.record_series) return;
        FlexibleSample s;
        s.time_s = t;
        s.mode = m_.mode;
        s.modal_m = q;
        if (is_flight(m_.mode)) {
            s.slide_m = x_[0];
            s.rotation_rad = -x_[4];
        } else {
            s.slide_m = x_[0];
            s.rotation_rad = static_cast<double>(m_.s) * x_[2];
        }
        out_.series.push_back(s);
    }

    double accel_peak() const { return acc_peak_; }
    bool overturned() const { return out_.summary.base.overturned; }

    // At rest with a mode too small ever to unsettle the base again: the free vibration's
    // amplitude bounds q and omega q, so the rest inequalities hold for good.
    bool settled_for_good(double g_mps2) const {
        if (m_.mode != Mode::rest) return false;
        const double amp = std::hypot(x_[4], x_[5] / g_.omega);
        const double shear = g_.ms * g_.omega * g_.omega * amp * (1.0 + 2.0 * g_.zeta);
        const double moment = shear * g_.hs + g_mps2 * g_.ms * amp;
        return shear <= g_.rigid.mu_s * g_.M * g_mps2 &&
               moment <= g_.M * g_mps2 * std::min(g_.b[0], g_.b[1]);
    }

private:
    void set_mode(const FlexMode& next, double t) {
        if (next.mode != m_.mode) ++out_.summary.base.mode_changes;
        if (is_flight(next.mode) && !is_flight(m_.mode)) {
            const Pose p = pose(x_);
            x_ = {p.X, p.Xd, p.Y, p.Yd, p.phi, p.phid, p.q, p.qd};
        }
        if (next.mode == Mode::rock || next.mode == Mode::slide_rock || is_flight(next.mode))
            out_.summary.uplifted = true;
        m_ = next;
        if (m_.mode == Mode::rest) x_[1] = 0.0;
        note_event(t);
    }

    void note_event(double t) {
        burst_ = (t - last_event_ < o_.settle_interval_s) ? burst_ + 1 : 0;
        last_event_ = t;
        if (burst_ == burst_settle) {
            ++out_.summary.base.settlements;
            m_ = {Mode::rest, 1, 1};
            x_[1] = x_[2] = x_[3] = 0.0;
            hold_until_ = t + 1e-6;
        }
        if (burst_ > burst_fail)
            throw NumericalError(fmt::format(
                "flexible-body integrator: events accumulate at t = {} s without settling", t));
    }

    void time_in(double dt) {
        out_.summary.base.time_in_mode_s[static_cast<std::size_t>(m_.mode)] += dt;
    }

    void observe(const State& x) {
        Summary& s = out_.summary.base;
        const double q = std::abs(modal(x));
        out_.summary.modal_max_m = std::max(out_.summary.modal_max_m, q);
        if (is_flight(m_.mode)) {
            s.slide_max_m = std::max(s.slide_max_m, std::abs(x[0]));
            return;
        }
        s.slide_max_m = std::max(s.slide_max_m, std::abs(x[0]));
        if (x[2] <= 0.0) return;
        s.rock_max_rad = std::max(s.rock_max_rad, x[2]);
        const double alpha = g_.rigid.alpha[static_cast<std::size_t>(Geometry::index(m_.s))];
        s.rock_max_over_alpha = std::max(s.rock_max_over_alpha, x[2] / alpha);
    }

    // Rest: the exact oscillator to the segment's end, or to the first failure of rest.
    double advance_rest(double t) {
        if (t < hold_until_) {
            const double held = std::min(tb_, hold_until_);
            step_rest(t, held);
            return held;
        }
        const State x0 = x_;
        const Base b0 = seg_.at(t);
        auto state_at = [&](double tt) {
            double q = x0[4], qd = x0[5];
            oscillator_step(g_, q, qd, b0.ax, seg_.ax1, tt - t);
            return std::pair<double, double>{q, qd};
        };
        auto margin = [&](double tt) {
            const auto [q, qd] = state_at(tt);
            const Base b = seg_.at(tt);
            return rest_margin(g_, rest_accel(g_, q, qd, b), b);
        };
        const double m1 = margin(tb_);
        if (!(m1 < 0.0)) {
            step_rest(t, tb_);
            return tb_;
        }
        const double m0 = margin(t);
        const double te = m0 < 0.0 ? t : toms748_root(margin, t, tb_, m0, m1);
        step_rest(t, te);
        const double tp = std::min(tb_, te + std::min(1e-9, 0.5 * (tb_ - te)));
        const auto [qp, qdp] = state_at(tp);
        const FlexMode next = classify_flat(g_, qp, qdp, 0.0, seg_.at(tp));
        if (next.mode == Mode::rest) {
            step_rest(te, tp);
            return tp;
        }
        set_mode(next, te);
        return te;
    }

    // Exact rest step [t, te], with the peak of |q| where q' changes sign inside it.
    void step_rest(double t, double te) {
        const Base b0 = seg_.at(t);
        const double q0 = x_[4], qd0 = x_[5];
        double q = q0, qd = qd0;
        oscillator_step(g_, q, qd, b0.ax, seg_.ax1, te - t);
        if ((qd0 > 0.0) != (qd > 0.0) && qd0 != 0.0) {
            auto rate = [&](double tt) {
                double qq = q0, qqd = qd0;
                oscillator_step(g_, qq, qqd, b0.ax, seg_.ax1, tt - t);
                return qqd;
            };
            const double tp = toms748_root(rate, t, te, qd0, qd);
            double qq = q0, qqd = qd0;
            oscillator_step(g_, qq, qqd, b0.ax, seg_.ax1, tp - t);
            out_.summary.modal_max_m = std::max(out_.summary.modal_max_m, std::abs(qq));
        }
        x_[4] = q;
        x_[5] = qd;
        time_in(te - t);
        ++out_.summary.base.steps;
    }

    // The state's time derivative in the current mode.
    void rhs(const State& x, State& dx, double t) const {
        const Base b = seg_.at(t);
        const Pose p = pose(x);
        const FlexAccel a = flex_accel(g_, m_, p, b);
        if (is_flight(m_.mode)) {
            dx = {x[1], a.Xdd, x[3], a.Ydd, x[5], a.phidd, x[7], a.qdd};
            return;
        }
        const double ds = static_cast<double>(m_.s);
        const double slip = m_.mode == Mode::rock ? 0.0 : contact_slip_accel(g_, m_.s, p, a);
        const double thdd = m_.mode == Mode::slide ? 0.0 : -ds * a.phidd;
        dx = {x[1], slip, x[3], thdd, x[5], a.qdd, 0.0, 0.0};
    }

    enum class Ev { none, impact, overturn, lift, friction, stop, unload_left, unload_right, land };

    // Event functions of the mode, positive while it holds.
    double event_value(Ev e, const State& x, double t) const {
        const Base b = seg_.at(t);
        switch (e) {
            case Ev::impact: return x[2];
            case Ev::overturn: return half_pi - (is_flight(m_.mode) ? std::abs(x[4]) : x[2]);
            case Ev::stop: return static_cast<double>(m_.sigma) * x[1];
            case Ev::land: return lowest_corner_y(x);
            default: break;
        }
        const FlexAccel a = flex_accel(g_, m_, pose(x), b);
        switch (e) {
            case Ev::lift: return a.N;
            case Ev::friction: return g_.rigid.mu_s * a.N - std::abs(a.F);
            case Ev::unload_left: return a.NL;
            case Ev::unload_right: return a.NR;
            default: return 1.0;
        }
    }

    double lowest_corner_y(const State& x) const {
        const double sp = std::sin(x[4]);
        return std::min(x[2] + sp * g_.b[1], x[2] - sp * g_.b[0]);
    }

    std::array<Ev, 4> events() const {
        switch (m_.mode) {
            case Mode::rock: return {Ev::impact, Ev::overturn, Ev::lift, Ev::friction};
            case Mode::slide_rock: return {Ev::impact, Ev::overturn, Ev::lift, Ev::stop};
            case Mode::slide: return {Ev::unload_left, Ev::unload_right, Ev::stop, Ev::none};
            case Mode::flight: return {Ev::overturn, Ev::land, Ev::none, Ev::none};
            case Mode::rest: break;
        }
        return {Ev::none, Ev::none, Ev::none, Ev::none};
    }

    double advance_ode(double t) {
        const auto sys = [this](const State& x, State& dx, double tt) { rhs(x, dx, tt); };
        for (;;) {
            if (m_.mode == Mode::rest) return t;
            if (!(t < tb_)) return tb_;
            const State x0 = x_;
            State dx0{}, x1{}, dx1{};
            rhs(x0, dx0, t);
            if (h_next_ < 1e-14 * std::max(1.0, t))
                throw NumericalError(fmt::format(
                    "flexible-body integrator: the step fell below 1e-14 s at t = {} s", t));
            double h = std::min({h_next_, tb_ - t, o_.max_contact_step_s});
            if (tb_ - (t + h) < 1e-12 * h + 8.0 * eps_ * tb_) h = tb_ - t;
            double tt = t, hh = h;
            if (ctrl_.try_step(sys, x0, dx0, tt, x1, dx1, hh) == odeint::fail) {
                ++out_.summary.rejected_steps;
                h_next_ = hh;
                continue;
            }
            h_next_ = hh;
            ++out_.summary.base.steps;
            const double t1 = (h == tb_ - t) ? tb_ : t + h;
            auto dense = [&](double te) {
                State y{};
                ctrl_.stepper().calc_state(te, y, x0, dx0, t, x1, dx1, t + h);
                return y;
            };
            // The first event of the step.
            Ev first = Ev::none;
            double t_ev = t1;
            for (Ev e : events()) {
                if (e == Ev::none) continue;
                const double f1 = event_value(e, x1, t1);
                if (!(f1 < 0.0)) continue;
                const double f0 = event_value(e, x0, t);
                double te = t;
                if (f0 > 0.0) {
                    auto f = [&](double tq) { return event_value(e, dense(tq), tq); };
                    te = toms748_root(f, t, t1, f0, f1);
                }
                if (te < t_ev || first == Ev::none) {
                    if (te <= t_ev) {
                        first = e;
                        t_ev = te;
                    }
                }
            }
            const State xe = first == Ev::none ? x1 : dense(t_ev);
            observe_peaks(dense, x0, xe, t, t_ev);
            time_in(t_ev - t);
            x_ = xe;
            if (first == Ev::none) {
                t = t1;
                continue;
            }
            handle(first, t_ev);
            return t_ev;
        }
    }

    // Peaks of theta and |q| inside a step: where theta' or q' changes sign.
    template <class Dense>
    void observe_peaks(const Dense& dense, const State& x0, const State& xe, double t, double te) {
        const bool fl = is_flight(m_.mode);
        const std::size_t iq = fl ? 7 : 5;
        for (std::size_t i : {std::size_t{3}, iq}) {
            if (fl && i == 3) continue;
            const double f0 = x0[i], f1 = xe[i];
            if (f0 == 0.0 || (f0 > 0.0) == (f1 > 0.0) || !(te > t)) continue;
            auto f = [&](double tq) { return dense(tq)[i]; };
            observe(dense(toms748_root(f, t, te, f0, f1)));
        }
        observe(xe);
    }

    void go_flat(double t, double v) {
        const double q = x_[4], qd = x_[5];
        x_ = {x_[0], v, 0.0, 0.0, q, qd, 0.0, 0.0};
        set_mode(classify_flat(g_, q, qd, v, probe(t)), t);
    }

    Base probe(double t) const { return seg_.at(std::min(tb_, t + std::min(1e-9, 0.5 * (tb_ - t)))); }

    void handle(Ev e, double t) {
        const Base base = seg_.at(t);
        switch (e) {
            case Ev::overturn: {
                Summary& s = out_.summary.base;
                s.overturned = true;
                s.overturn_time_s = t;
                s.overturn_mode = s.impacts > 0 ? 1 : 2;
                s.overturn_criterion = OverturnCriterion::angle_half_pi;
                return;
            }
            case Ev::impact: {
                x_[2] = 0.0;
                const double om = x_[3];
                if (!(om < 0.0)) {
                    ++out_.summary.base.settlements;
                    go_flat(t, x_[1]);
                    return;
                }
                const int s_new = -m_.s;
                const double w_before = -om;
                const double w_after =
                    g_.rigid.r_onto[static_cast<std::size_t>(Geometry::index(s_new))] * w_before;
                ++out_.summary.base.impacts;
                if (rebound_angle(g_.rigid, s_new, w_after, base.G) < o_.settle_rebound_rad) {
                    out_.impact_log.push_back({t, w_before, 0.0, true});
                    ++out_.summary.base.settlements;
                    go_flat(t, x_[1]);
                    return;
                }
                out_.impact_log.push_back({t, w_before, w_after, false});
                m_.s = s_new;
                x_[3] = w_after;
                set_mode(classify_edge(g_, s_new, pose(x_), x_[1], base), t);
                return;
            }
            case Ev::lift: set_mode({Mode::flight, m_.s, m_.sigma}, t); return;
            case Ev::friction: {
                const FlexAccel a = flex_accel(g_, m_, pose(x_), base);
                x_[1] = 0.0;
                set_mode({Mode::slide_rock, m_.s, a.F > 0.0 ? -1 : 1}, t);
                return;
            }
            case Ev::stop:
                x_[1] = 0.0;
                if (m_.mode == Mode::slide) {
                    set_mode(classify_flat(g_, x_[4], x_[5], 0.0, probe(t)), t);
                } else {
                    set_mode(classify_edge(g_, m_.s, pose(x_), 0.0, probe(t)), t);
                }
                return;
            case Ev::unload_left:
            case Ev::unload_right: {
                // The unloaded edge lifts: the body slide-rocks on the other one.
                const int s = e == Ev::unload_left ? 1 : -1;
                m_.s = s;
                set_mode({Mode::slide_rock, s, m_.sigma}, t);
                return;
            }
            case Ev::land: land(t); return;
            case Ev::none: return;
        }
    }

    // Landing from flight on the lowest corner: flat (both edges, Coulomb impulse) when the
    // tilt is nil or the far edge's gap closes within Options::flat_landing_window_s, else a
    // sticking impact conserving angular momentum about the corner (s.3), q and q' unchanged.
    void land(double t) {
        const Pose p = pose(x_);
        const double sp = std::sin(p.phi);
        const int s = p.Y + sp * g_.b[1] <= p.Y - sp * g_.b[0] ? 1 : -1;
        const double th = std::max(0.0, -static_cast<double>(s) * p.phi);
        const double bx = s > 0 ? g_.b[1] : -g_.b[0];
        const double xc = p.X + std::cos(p.phi) * bx;
        ++out_.summary.base.impacts;
        const double far_gap = (g_.b[0] + g_.b[1]) * std::sin(th);
        if (th <= 1e-12 || (p.Yd < 0.0 && far_gap <= -p.Yd * o_.flat_landing_window_s)) {
            const double dv = std::min(std::abs(p.Xd), g_.rigid.mu_k * std::max(0.0, -p.Yd));
            const double v = p.Xd - std::copysign(dv, p.Xd);
            out_.impact_log.push_back({t, std::abs(p.phid), 0.0, false});
            m_.s = s;
            x_ = {p.X, v, 0.0, 0.0, p.q, p.qd, 0.0, 0.0};
            m_.mode = Mode::slide;
            set_mode(classify_flat(g_, p.q, p.qd, v, probe(t)), t);
            return;
        }
        const double H = angular_momentum_about(g_, p, xc);
        const double u = xc - bx;
        const double H0 = angular_momentum_about(g_, contact_pose(g_, s, u, 0.0, th, 0.0, p.q, p.qd), xc);
        const double H1 = angular_momentum_about(g_, contact_pose(g_, s, u, 0.0, th, 1.0, p.q, p.qd), xc);
        const double om = (H - H0) / (H1 - H0);
        out_.impact_log.push_back({t, std::abs(p.phid), std::abs(om), false});
        m_.s = s;
        m_.mode = Mode::rock;
        x_ = {u, 0.0, th, om, p.q, p.qd, 0.0, 0.0};
        set_mode(classify_edge(g_, s, pose(x_), 0.0, seg_.at(t)), t);
    }

    static constexpr double eps_ = std::numeric_limits<double>::epsilon();
    const FlexGeometry& g_;
    const Options& o_;
    FlexibleResult& out_;
    Controlled ctrl_;
    Segment seg_;
    double tb_ = 0.0;
    FlexMode m_{};
    State x_{};
    double h_next_ = 1e-3;
    double acc_peak_ = 0.0;
    double last_event_ = -1.0;
    std::size_t burst_ = 0;
    double hold_until_ = -1.0;
};

}  // namespace
}  // namespace detail

FlexibleResult simulate_flexible(const FlexibleModel& model, const Excitation& excitation,
                                 const Options& options) {
    if (options.initial_rotation_rad != 0.0 || options.initial_slide_velocity_mps != 0.0)
        throw InputError({"", 0, "initial condition"},
                         "the flexible-body model starts at rest (no initial rotation or slip)");
    if (options.integrator != Integrator::event)
        throw InputError({"", 0, "integrator"},
                         "the flexible-body model has the event-driven integrator only");
    if (excitation.horizontal_mps2.size() < 2 || !(excitation.dt_s > 0.0))
        throw InputError({"", 0, "excitation"}, "needs at least two samples and a step > 0 s");
    const auto wall0 = std::chrono::steady_clock::now();
    const detail::FlexGeometry g = detail::make_flex_geometry(model);
    const detail::BaseMotion bm(excitation, options.g_mps2);
    FlexibleResult out;
    detail::FlexEngine engine(g, options, out);
    const std::size_t n_seg = bm.segments(options.tail_s);
    auto segment = [&](std::size_t k) {
        detail::Segment s;
        bm.segment(k, s.ax0, s.ax1, s.G0, s.G1);
        s.tk = bm.t_k(k);
        return s;
    };
    {
        const detail::Segment s0 = segment(0);
        engine.start(s0.at(std::min(1e-9, 0.5 * bm.dt())));
    }
    engine.sample(0.0, bm.sample(0));
    double t_end = bm.t_k(n_seg);
    for (std::size_t k = 0; k < n_seg; ++k) {
        const detail::Segment s = segment(k);
        const double tb = bm.t_k(k + 1);
        for (double t = bm.t_k(k); t < tb && !engine.overturned();) t = engine.advance(s, t, tb);
        if (engine.overturned()) {
            t_end = out.summary.base.overturn_time_s.value_or(tb);
            break;
        }
        engine.sample(tb, bm.sample(k + 1));
        if (tb >= bm.min_end_s() && engine.settled_for_good(options.g_mps2)) {
            t_end = tb;
            break;
        }
    }
    Summary& b = out.summary.base;
    b.integrator = "event";
    b.end_time_s = t_end;
    b.pga_g = bm.pga_mps2() / options.g_mps2;
    b.slide_residual_m = std::abs(engine.state()[0]);
    out.summary.modal_drift_max = out.summary.modal_max_m / model.height_m;
    out.summary.modal_accel_max_g = engine.accel_peak() / options.g_mps2;
    b.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
    return out;
}

}  // namespace freestand::dynamics
