// Fixed-step central-difference baseline of the flexible body (flexible.hpp), the planar
// scheme of central_difference.cpp on the flexible body's state: rates live at half steps
// (x'_{n+1/2} = x'_{n-1/2} + dt x''_n, x_{n+1} = x_n + dt x'_{n+1/2}); rate-dependent terms use
// x'_n ~ x'_{n-1/2} + dt/2 x''_{n-1}. The mode is stepped the same way at rest (no closed form).
// Switches are sign checks at step ends (no event location): a stop or reversal when the slip
// rate changes sign, an impact when theta does (the overshoot reflected with the impact's
// ratio of rates, flexible_impact.cpp), a landing when the lowest corner reaches the base; and
// the rest inequalities, lift-off (N < 0), an edge unloading (slide) and friction exceeded
// (rock) at the step's start.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "dynamics/flexible_detail.hpp"

namespace freestand::dynamics::detail {

namespace {

constexpr double half_pi = std::numbers::pi / 2.0;

class FlexCdStepper {
public:
    FlexCdStepper(const FlexGeometry& g, const BaseMotion& bm, const Options& o, FlexRecorder& rec)
        : g_(g), bm_(bm), o_(o), rec_(rec) {}

    const FlexState& state() const { return x_; }
    const FlexMode& mode() const { return m_; }

    void start(Base b) { enter(classify_flat(g_, 0.0, 0.0, 0.0, b)); }

    // One step from t to t + h on segment k.
    void step(std::size_t k, double t, double h) {
        const Base b = bm_.at(k, t);
        rec_.step();
        rec_.time_in(m_.mode, h);
        if (m_.mode == Mode::rest && rest_step(b, h)) {
            rec_.observe(m_, x_);
            return;
        }
        switch (m_.mode) {
            case Mode::rest: break;
            case Mode::slide: slide(k, t, h, b); break;
            case Mode::rock:
            case Mode::slide_rock: contact(k, t, h, b); break;
            case Mode::flight: flight(k, t, h, b); break;
        }
        rec_.observe(m_, x_);
    }

    // The sample at time t: the modal mass's absolute acceleration at the state.
    void sample(double t, Base b) {
        double acc = 0.0;
        if (m_.mode == Mode::rest) {
            acc = b.ax + rest_accel(g_, x_[4], rate_now(5, 0.0), b).qdd;
        } else {
            const Pose p = pose_of(g_, m_, x_);
            acc = modal_abs_accel(g_, p, flex_accel(g_, m_, p, b), b);
        }
        rec_.sample(t, m_, x_, acc);
    }

    bool settled(double g_mps2) const {
        return m_.mode == Mode::rest && settled_for_good(g_, x_[4], x_[5], g_mps2);
    }

private:
    double rate_now(std::size_t i, double h) const { return x_[i] + 0.5 * h * acc_prev_[i]; }

    // The state with its rates estimated at the step's start, x'_n.
    FlexState at_start(double h) const {
        FlexState y = x_;
        for (std::size_t i = 1; i < 8; i += 2) y[i] = rate_now(i, h);
        return y;
    }

    // Rates then positions (the half-step rates of the scheme).
    void advance(const FlexState& dx, double h) {
        for (std::size_t i = 1; i < 8; i += 2) {
            x_[i] += h * dx[i];
            x_[i - 1] += h * x_[i];
            acc_prev_[i] = dx[i];
        }
    }

    void enter(const FlexMode& next) {
        rec_.transition(m_.mode, next.mode);
        if (is_flight(next.mode) && !is_flight(m_.mode)) {
            x_ = flight_state(pose_of(g_, m_, x_));
            armed_ = false;
        }
        m_ = next;
        if (m_.mode == Mode::rest) x_[1] = 0.0;
        acc_prev_ = {};
    }

    // Rest: the mode stepped under the held base; false when the rest inequalities fail at the
    // step's start (the body has entered another mode).
    bool rest_step(Base b, double h) {
        const double qd_n = rate_now(5, h);
        const FlexAccel a = rest_accel(g_, x_[4], qd_n, b);
        if (rest_margin(g_, a, b) >= 0.0) {
            x_[5] += h * a.qdd;
            x_[4] += h * x_[5];
            acc_prev_[5] = a.qdd;
            return true;
        }
        x_[5] = qd_n;
        enter(classify_flat(g_, x_[4], qd_n, 0.0, b));
        return false;
    }

    void slide(std::size_t k, double t, double h, Base b) {
        FlexState dx;
        FlexAccel a;
        flex_rhs(g_, m_, at_start(h), b, dx, a);
        if (a.NL < 0.0 || a.NR < 0.0) {
            // An edge unloads: the body slide-rocks on the other one.
            const int s = a.NL < a.NR ? 1 : -1;
            m_.s = s;
            enter({Mode::slide_rock, s, m_.sigma});
            contact(k, t, h, b);
            return;
        }
        advance(dx, h);
        if (static_cast<double>(m_.sigma) * x_[1] > 0.0) return;
        // Sign check: the slip rate reversed inside the step.
        const Base b1 = bm_.at(k, t + h);
        const double v = x_[1];
        const FlexMode next = classify_flat(g_, x_[4], x_[5], 0.0, b1);
        x_[1] = (next.mode == Mode::slide && static_cast<double>(next.sigma) * v > 0.0) ? v : 0.0;
        const double kept = x_[1];
        enter(next);
        x_[1] = kept;
    }

    void contact(std::size_t k, double t, double h, Base b) {
        FlexState dx;
        FlexAccel a;
        flex_rhs(g_, m_, at_start(h), b, dx, a);
        if (a.N < 0.0) {
            enter({Mode::flight, m_.s, m_.sigma});
            flight(k, t, h, b);
            return;
        }
        if (m_.mode == Mode::rock && std::abs(a.F) > g_.rigid.mu_s * a.N) {
            enter({Mode::slide_rock, m_.s, a.F > 0.0 ? -1 : 1});
            flex_rhs(g_, m_, at_start(h), b, dx, a);
        }
        advance(dx, h);
        const double t1 = t + h;
        rec_.check_overturn(m_, x_, t1, t1 >= bm_.quiet_from_s());
        if (rec_.overturned()) return;
        const Base b1 = bm_.at(k, t1);
        if (x_[2] < 0.0) {
            impact(b1, t1);
            return;
        }
        if (m_.mode == Mode::slide_rock && static_cast<double>(m_.sigma) * x_[1] <= 0.0) {
            // Sign check: the slip stopped or reversed; a restart the way the overshoot goes
            // keeps it (as the planar scheme), and the rotation's x''_{n-1} carries on.
            const double v = x_[1];
            x_[1] = 0.0;
            const FlexMode next = classify_edge(g_, m_.s, pose_of(g_, m_, x_), 0.0, b1);
            const FlexState prev = acc_prev_;
            enter(next);
            if (is_flight(next.mode)) return;
            acc_prev_ = prev;
            acc_prev_[1] = 0.0;
            if (next.mode == Mode::slide_rock && static_cast<double>(next.sigma) * v > 0.0)
                x_[1] = v;
        }
    }

    // Sign change of theta: the body struck the other edge inside the step. The overshoot is
    // reflected onto the new edge with the ratio of the rates after and before the impact.
    void impact(Base b1, double t1) {
        const double om = x_[3];
        const double th = x_[2];
        x_[2] = 0.0;
        if (!(om < 0.0)) {
            settle(b1);
            return;
        }
        const int s_new = -m_.s;
        const EdgeState after = edge_impact(g_, pose_of(g_, m_, x_), s_new, x_[0], x_[1]);
        if (rebound_angle(g_.rigid, s_new, after.om, b1.G) < o_.settle_rebound_rad) {
            rec_.impact(t1, -om, 0.0, true);
            settle(b1);
            return;
        }
        rec_.impact(t1, -om, after.om, false);
        x_ = edge_state(after);
        x_[2] = th * after.om / om;
        m_.s = s_new;
        enter(classify_edge(g_, s_new, pose_of(g_, m_, x_), x_[1], b1));
    }

    // An impact too small to rebound: the base is set flat, q' by the impact rule.
    void settle(Base b1) {
        rec_.settlement();
        const Pose p = pose_of(g_, m_, x_);
        const double v = x_[1];
        x_ = {x_[0], v, 0.0, 0.0, p.q, flat_modal_rate(g_, p, x_[0], v), 0.0, 0.0};
        enter(classify_flat(g_, x_[4], x_[5], v, b1));
    }

    void flight(std::size_t k, double t, double h, Base b) {
        FlexState dx;
        FlexAccel a;
        flex_rhs(g_, m_, at_start(h), b, dx, a);
        advance(dx, h);
        const double t1 = t + h;
        if (std::abs(x_[4]) >= half_pi) {
            rec_.overturn(t1, OverturnCriterion::angle_half_pi);
            return;
        }
        // The lowest corner and its vertical rate: it lands on reaching the base from above,
        // or at once if it was already going down on leaving it (the other edge struck).
        const double sp = std::sin(x_[4]), cp = std::cos(x_[4]);
        const bool right = x_[2] + sp * g_.b[1] <= x_[2] - sp * g_.b[0];
        const double bx = right ? g_.b[1] : -g_.b[0];
        const double y = x_[2] + sp * bx, yd = x_[3] + cp * x_[5] * bx;
        if (y > 0.0) {
            armed_ = true;
            return;
        }
        if (!armed_ && !(yd < 0.0)) return;
        armed_ = false;
        const Landing l = land_flexible(g_, pose_of(g_, m_, x_), o_.flat_landing_window_s);
        rec_.impact(t1, l.om_before, l.flat ? 0.0 : l.st.om, false);
        x_ = edge_state(l.st);
        const Base b1 = bm_.at(k, t1);
        if (l.flat) {
            m_ = {Mode::slide, l.st.s, m_.sigma};
            enter(classify_flat(g_, x_[4], x_[5], x_[1], b1));
        } else {
            m_ = {Mode::rock, l.st.s, 1};
            enter(classify_edge(g_, l.st.s, pose_of(g_, m_, x_), 0.0, b1));
        }
    }

    const FlexGeometry& g_;
    const BaseMotion& bm_;
    const Options& o_;
    FlexRecorder& rec_;
    FlexMode m_{};
    FlexState x_{};
    FlexState acc_prev_{};  // x''_{n-1} (rates' entries), reset at every switch
    bool armed_ = false;
};

}  // namespace

FlexibleResult run_flexible_cd(const FlexGeometry& g, const BaseMotion& bm, const Options& o) {
    FlexibleResult out;
    FlexRecorder rec(g, o, out);
    const double h = central_difference_step_s(bm.dt(), o.cd_dt_s);
    const std::size_t n_seg = bm.segments(o.tail_s);
    FlexCdStepper stepper(g, bm, o, rec);
    stepper.start(bm.at(0, 0.0));
    stepper.sample(0.0, bm.sample(0));
    const RunEnd run = run_fixed_steps(
        bm.dt(), h, n_seg,
        [&](std::size_t k, double t, double dt) {
            stepper.step(k, t, dt);
            return !rec.overturned();
        },
        [&](std::size_t k, double tb) {
            stepper.sample(tb, bm.sample(k + 1));
            return tb >= bm.min_end_s() && stepper.settled(o.g_mps2);
        });
    rec.end_run(stepper.mode(), stepper.state(), run.end_s, bm, "cd");
    return out;
}

}  // namespace freestand::dynamics::detail
