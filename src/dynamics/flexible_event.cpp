// Event-driven integration of the flexible body (flexible.hpp). Rest: the base is held and the
// mode is the linear oscillator, advanced exactly over each linear input segment (Nigam &
// Jennings 1969); the rest inequalities are checked at the segment's end and a failure is
// located on the exact solution. Slide, rock, slide-rock and flight: Dormand-Prince 5(4) with
// error control (dopri5.hpp, as the biaxial slide) on the mode's equations (flex_rhs), steps
// ending at every input sample; events (impact, lift-off, friction exceeded, slip stop, an edge
// unloading, landing, theta = pi/2) are sign changes over a step, located by TOMS 748 on the
// continuous extension.
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <numbers>
#include <optional>

#include "core/contract.hpp"
#include "core/errors.hpp"
#include "core/steps.hpp"
#include "core/tolerances.hpp"
#include "dynamics/event_search.hpp"
#include "dynamics/dopri5.hpp"
#include "dynamics/flexible_detail.hpp"

namespace freestand::dynamics::detail {

namespace {

using Stepper = Dopri5<8>;

constexpr double half_pi = std::numbers::pi / 2.0;

enum class Ev { none, impact, overturn, lift, friction, stop, unload_left, unload_right, land };

// The accepted step [t, t + h]'s continuous extension at a time inside it: the state, one
// component (the root searches on theta' and q'), or a view that evaluates the components
// read of it (the events' root searches).
struct StepExtension {
    const Stepper& dp;
    double t, h;
    FlexState operator()(double tq) const { return dp.dense((tq - t) / h); }
    double at(double tq, std::size_t i) const { return dp.dense_component((tq - t) / h, i); }
    struct View {
        const StepExtension& ext;
        double tq;
        double operator[](std::size_t i) const { return ext.at(tq, i); }
    };
    View view(double tq) const { return {*this, tq}; }
};

class FlexEngine {
public:
    FlexEngine(const FlexGeometry& g, const Options& o, const BaseMotion& bm, FlexRecorder& rec,
               double rigid_limit_hz)
        : g_(g), o_(o), rec_(rec), full_step_(g.held, bm.dt()), g_mps2_(o.g_mps2),
          quiet_from_s_(bm.quiet_from_s()), rigid_limit_hz_(rigid_limit_hz) {}

    const FlexState& state() const { return x_; }
    const FlexMode& mode() const { return m_; }

    void start(Base probe) { set_mode(classify_flat(g_, 0.0, 0.0, 0.0, probe), 0.0); }

    // Advances from t towards tb on segment seg; returns the time reached.
    double advance(const Segment& seg, double t, double tb) {
        seg_ = seg;
        tb_ = tb;
        if (m_.mode == Mode::rest) return advance_rest(t);
        if (m_.mode == Mode::slide && g_.exact_slide) return advance_slide(t);
        return advance_ode(t);
    }

    // The sample at time t, with the accelerations of the step that ended there if it did.
    void sample(double t, Base base) {
        double acc = 0.0;
        if (m_.mode == Mode::rest) {
            const bool known = end_valid_ && end_t_ == t;
            acc = base.ax + (known ? a_end_.qdd : rest_accel(g_, x_[4], x_[5], base).qdd);
        } else {
            const Pose p = pose_of(g_, m_, x_);
            const FlexAccel a = end_valid_ && end_t_ == t ? a_end_ : flex_accel(g_, m_, p, base);
            acc = modal_abs_accel(g_, p, a, base);
        }
        rec_.sample(t, m_, x_, acc);
    }

    bool settled(double g_mps2) const {
        return m_.mode == Mode::rest && settled_for_good(g_, x_[4], x_[5], g_mps2);
    }

    // The hot loop of long records: whole input segments from k at rest while the rest
    // inequalities hold at their ends, each with its sample, as advance() and sample() would
    // take them. Returns the first segment not taken (n_seg, or the one where rest fails or the
    // body has settled for good: then settled_at is its end).
    std::size_t rest_run(const BaseMotion& bm, std::size_t k, std::size_t n_seg, double& settled_at) {
        if (m_.mode != Mode::rest || bm.t_k(k) < hold_until_) return k;
        const double min_end = bm.min_end_s();
        for (; k < n_seg; ++k) {
            seg_ = bm.linear_segment(k);
            tb_ = bm.t_k(k + 1);
            if (!is_full_step(seg_.tk, tb_)) return k;
            double q = x_[4], qd = x_[5];
            full_step_.apply(q, qd, seg_.ax0, seg_.ax1);
            const Base b = seg_.at(tb_);
            const FlexAccel a = rest_accel(g_, q, qd, b);
            if (rest_margin(g_, a, b) < 0.0) return k;
            commit_rest(seg_.tk, tb_, q, qd);
            const Base bs = bm.sample(k + 1);
            rec_.sample(tb_, m_, x_, bs.ax + a.qdd);
            if (tb_ >= min_end && settled_for_good(g_, q, qd, g_mps2_)) {
                settled_at = tb_;
                return k + 1;
            }
        }
        return k;
    }

private:
    void set_mode(const FlexMode& next, double t) {
        rec_.transition(m_.mode, next.mode);
        if (is_flight(next.mode) && !is_flight(m_.mode)) x_ = flight_state(pose_of(g_, m_, x_));
        m_ = next;
        if (m_.mode == Mode::rest) x_[1] = 0.0;
        fsal_ = false;
        end_valid_ = false;
        note_event(t);
    }

    // The base set flat with slip rate v (q' by the impact rule), then classified.
    void go_flat(double t, double v) {
        const Pose p = pose_of(g_, m_, x_);
        const double u = is_flight(m_.mode) ? p.X : x_[0];
        x_ = {u, v, 0.0, 0.0, p.q, flat_modal_rate(g_, p, u, v), 0.0, 0.0};
        if (is_flight(m_.mode)) m_ = {Mode::slide, 1, 1};
        set_mode(classify_flat(g_, x_[4], x_[5], v, probe(t)), t);
    }

    // Chatter guard: many events inside settle_interval_s settle the body at rest.
    void note_event(double t) {
        if (!chatter_.note(t, o_.settle_interval_s, integrator_name_)) return;
        rec_.settlement();
        const Pose p = pose_of(g_, m_, x_);
        const double u = is_flight(m_.mode) ? p.X : x_[0];
        x_ = {u, 0.0, 0.0, 0.0, p.q, flat_modal_rate(g_, p, u, 0.0), 0.0, 0.0};
        rec_.transition(m_.mode, Mode::rest);
        m_ = {Mode::rest, 1, 1};
        hold_until_ = t + settle_hold_s;
    }

    // [t, tb] is the whole input step full_step_ advances over.
    bool is_full_step(double t, double tb) const {
        return std::abs(tb - t - full_step_.tau) <= core::tol::relative * full_step_.tau;
    }

    Base probe(double t) const { return seg_.at(std::min(tb_, probe_time(t, tb_))); }

    // Rest: the exact oscillator to the segment's end, or to the first failure of rest.
    double advance_rest(double t) {
        if (t < hold_until_) {
            const double held = std::min(tb_, hold_until_);
            step_rest(t, held);
            return held;
        }
        const double q0 = x_[4], qd0 = x_[5];
        const Base b0 = seg_.at(t);
        const bool full = t == seg_.tk && is_full_step(t, tb_);
        auto state_at = [&](double tt) {
            double q = q0, qd = qd0;
            if (full && tt == tb_)
                full_step_.apply(q, qd, b0.ax, seg_.ax1);
            else
                oscillator_step(g_.held, q, qd, b0.ax, seg_.ax1, tt - t);
            return std::pair<double, double>{q, qd};
        };
        auto margin_of = [&](double q, double qd, double tt) {
            const Base b = seg_.at(tt);
            a_end_ = rest_accel(g_, q, qd, b);
            return rest_margin(g_, a_end_, b);
        };
        auto margin = [&](double tt) {
            const auto [q, qd] = state_at(tt);
            return margin_of(q, qd, tt);
        };
        const auto [q1, qd1] = state_at(tb_);
        const double m1 = margin_of(q1, qd1, tb_);
        if (!(m1 < 0.0)) {
            commit_rest(t, tb_, q1, qd1);
            end_valid_ = true;  // a_end_: the accelerations at tb_
            end_t_ = tb_;
            return tb_;
        }
        end_valid_ = false;
        const double m0 = margin_of(q0, qd0, t);
        const double te = m0 < 0.0 ? t : toms748_root(margin, t, tb_, m0, m1);
        step_rest(t, te);
        const double tp = std::min(tb_, probe_time(te, tb_));
        const auto [qp, qdp] = state_at(tp);
        const FlexMode next = classify_flat(g_, qp, qdp, 0.0, seg_.at(tp));
        if (next.mode == Mode::rest) {
            step_rest(te, tp);
            return tp;
        }
        set_mode(next, te);
        return te;
    }

    void step_rest(double t, double te) {
        double q = x_[4], qd = x_[5];
        oscillator_step(g_.held, q, qd, seg_.at(t).ax, seg_.ax1, te - t);
        commit_rest(t, te, q, qd);
    }

    // A rest step [t, te] ending at (q1, qd1), with the peak of |q| where q' changes sign inside
    // it, located when it could exceed the peak so far: |q| <= |A| + |B| tau + the free
    // vibration's amplitude about the particular solution A + B tau (oscillator_step).
    void commit_rest(double t, double te, double q1, double qd1) {
        const double q0 = x_[4], qd0 = x_[5];
        const double a0 = seg_.at(t).ax, a1 = seg_.ax1;
        if (qd0 != 0.0 && (qd0 > 0.0) != (qd1 > 0.0)) {
            const double w2 = g_.omega * g_.omega;
            const double B = -a1 / w2, A = (-a0 - 2.0 * g_.zeta * g_.omega * B) / w2;
            const double amp = std::hypot(q0 - A, (qd0 - B + g_.zeta * g_.omega * (q0 - A)) /
                                                      (g_.omega * std::sqrt(1.0 - g_.zeta * g_.zeta)));
            if (std::abs(A) + std::abs(B) * (te - t) + amp > rec_.modal_max()) {
                auto rate = [&](double tt) {
                    double q = q0, qd = qd0;
                    oscillator_step(g_.held, q, qd, a0, a1, tt - t);
                    return qd;
                };
                const double tp = toms748_root(rate, t, te, qd0, qd1);
                double q = q0, qd = qd0;
                oscillator_step(g_.held, q, qd, a0, a1, tp - t);
                rec_.modal_peak(q);
            }
        }
        x_[4] = q1;
        x_[5] = qd1;
        rec_.modal_peak(q1);
        rec_.time_in(Mode::rest, te - t);
        rec_.step();
    }

    // Flat sliding, exact (SlideSegment) to the segment's end or to the first event: the slip
    // stopping (sigma u' reaching 0, also where it dips below 0 inside the segment) or an edge
    // unloading, located by TOMS 748 on the exact solution.
    double advance_slide(double t) {
        const SlideSegment sl(g_, m_.sigma, x_, seg_.at(t), seg_.ax1, seg_.G1);
        const double tau1 = tb_ - t;
        const SlideSegment::Point p0 = sl.at(0.0), p1 = sl.at(tau1);
        const EventAt<Ev> ev = slide_event(sl, p0, p1, tau1);
        const SlideSegment::Point pe = ev.event == Ev::none ? p1 : sl.at(ev.t_s);
        commit_slide(sl, p0, pe, ev.t_s);
        if (ev.event == Ev::none) {
            a_end_ = pe.a;
            end_valid_ = true;
            end_t_ = tb_;
            return tb_;
        }
        const double te = t + ev.t_s;
        end_valid_ = false;
        handle(ev.event, te);
        return te;
    }

    // The first event of the slide sl over (0, tau1] (p0, p1 its ends): an edge unloading or
    // the slip stopping, also where sigma u' dips below 0 inside the segment.
    EventAt<Ev> slide_event(const SlideSegment& sl, const SlideSegment::Point& p0,
                            const SlideSegment::Point& p1, double tau1) const {
        const double sg = static_cast<double>(m_.sigma);
        auto value = [&](Ev e, const SlideSegment::Point& p) {
            return e == Ev::stop ? sg * p.v : e == Ev::unload_left ? p.a.NL : p.a.NR;
        };
        const std::array<Ev, 3> events = {Ev::unload_left, Ev::unload_right, Ev::stop};
        return first_event(events, tau1, [&](Ev e) -> std::optional<double> {
            auto f = [&](double tau) { return value(e, sl.at(tau)); };
            const double f0 = value(e, p0), f1 = value(e, p1);
            // A slip starting from 0 (a reversal) stops at its next crossing.
            if (f1 < 0.0) return sign_change(f, 0.0, tau1, f0, f1);
            if (e != Ev::stop) return std::nullopt;
            auto slope = [&](double tau) { return sg * sl.at(tau).a.Xdd; };
            return dip_below_zero(f, slope, 0.0, tau1, f0, sg * p0.a.Xdd, sg * p1.a.Xdd);
        });
    }

    // The slide sl taken from p0 to pe, tau_s later: the state, the peak of |q| where q'
    // changes sign inside it, the time and the step.
    void commit_slide(const SlideSegment& sl, const SlideSegment::Point& p0,
                      const SlideSegment::Point& pe, double tau_s) {
        if ((p0.qd > 0.0) != (pe.qd > 0.0) && p0.qd != 0.0 && tau_s > 0.0) {
            auto rate = [&](double tau) { return sl.at(tau).qd; };
            rec_.modal_peak(sl.at(toms748_root(rate, 0.0, tau_s, p0.qd, pe.qd)).q);
        }
        x_[0] = pe.u;
        x_[1] = pe.v;
        x_[4] = pe.q;
        x_[5] = pe.qd;
        rec_.observe(m_, x_);
        rec_.time_in(Mode::slide, tau_s);
        rec_.step();
    }

    // Event functions of the mode, positive while it holds; a the accelerations at x (a state,
    // or a view of the continuous extension that evaluates only the components read).
    template <class State>
    double event_value(Ev e, const State& x, const FlexAccel& a) const {
        switch (e) {
            case Ev::impact: return x[2];
            case Ev::overturn: return half_pi - (is_flight(m_.mode) ? std::abs(x[4]) : x[2]);
            case Ev::stop: return static_cast<double>(m_.sigma) * x[1];
            case Ev::land: return lowest_corner_y(x);
            case Ev::lift: return a.N;
            case Ev::friction: return g_.rigid.mu_s * a.N - std::abs(a.F);
            case Ev::unload_left: return a.NL;
            case Ev::unload_right: return a.NR;
            case Ev::none: break;
        }
        return 1.0;
    }
    static bool needs_forces(Ev e) {
        return e == Ev::lift || e == Ev::friction || e == Ev::unload_left || e == Ev::unload_right;
    }
    // The event function at tq inside the accepted step.
    double event_at(Ev e, const StepExtension& dense, double tq) const {
        if (!needs_forces(e)) return event_value(e, dense.view(tq), {});
        const FlexState x = dense(tq);
        return event_value(e, x, flex_accel(g_, m_, pose_of(g_, m_, x), seg_.at(tq)));
    }

    template <class State>
    double lowest_corner_y(const State& x) const {
        const double sp = cos_sin(x[4]).s;
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
        const auto f = [this](const FlexState& x, FlexState& dx, double tt) {
            flex_rhs(g_, m_, x, seg_.at(tt), dx, a_last_);
        };
        for (;;) {
            if (m_.mode == Mode::rest) return t;
            if (!(t < tb_)) return tb_;
            if (!fsal_) {
                f(x_, k1_, t);
                a0_ = a_last_;
                fsal_ = true;
            }
            const double h = step_.propose(t, tb_, o_.max_contact_step_s, integrator_name_);
            // The steps a stiff mode needs grow with its frequency: bounded, not run for ever.
            require_step_budget(++dp_steps_, t, g_.omega / (2.0 * std::numbers::pi), rigid_limit_hz_);
            const double err = dp_step(f, t, x_, h);
            if (!(err <= 1.0)) {
                rec_.rejected();
                step_.reject(Stepper::factor(err));
                continue;
            }
            step_.accept(Stepper::factor(err));
            rec_.step();
            const double t1 = step_.step_end(t, tb_);
            const FlexState& x0 = dp_.x0();
            const FlexState& x1 = dp_.x1();
            const FlexAccel& a1 = a_last_;  // f(x1, t1), the last stage
            const StepExtension dense{dp_, t, h};
            const EventAt<Ev> ev = first_event_in(dense, x0, x1, a1, t, t1);
            const Ev first = ev.event;
            const double t_ev = ev.t_s;
            x_ = first == Ev::none ? x1 : dense(t_ev);
            observe_peaks(dense, x0, x_, t, t_ev);
            rec_.time_in(m_.mode, t_ev - t);
            if (first == Ev::none) {
                k1_ = dp_.k7();
                a0_ = a1;
                a_end_ = a1;
                end_valid_ = true;
                end_t_ = t1;
                t = t1;
                rec_.check_overturn(m_, x_, t1, t1 >= quiet_from_s_);
                if (rec_.overturned()) return t1;
                continue;
            }
            handle(first, t_ev);
            return t_ev;
        }
    }

    // A Dormand-Prince step on the components the mode moves: rocking holds the slip (u, u' = 0),
    // every contact mode the last two (flight's q, q').
    template <class F>
    double dp_step(const F& f, double t, const FlexState& x0, double h) {
        FREESTAND_EXPECT(is_flight(m_.mode) || (x0[6] == 0.0 && x0[7] == 0.0),
                         "a contact mode's state ends in two zeros");
        FREESTAND_EXPECT(m_.mode != Mode::rock || x0[1] == 0.0, "rocking holds the slip");
        switch (m_.mode) {
            case Mode::rock: return dp_.step<2, 6>(f, t, x0, k1_, h, o_.rel_tol, o_.abs_tol);
            case Mode::flight: return dp_.step<0, 8>(f, t, x0, k1_, h, o_.rel_tol, o_.abs_tol);
            case Mode::rest:
            case Mode::slide:
            case Mode::slide_rock: break;
        }
        return dp_.step<0, 6>(f, t, x0, k1_, h, o_.rel_tol, o_.abs_tol);
    }

    // The first event inside the accepted step [t, t1]: a sign change of its function from
    // positive (or from 0 while rising: the state an event just set) to negative; an impact
    // also where theta dips below 0 and rises again inside the step.
    EventAt<Ev> first_event_in(const StepExtension& dense, const FlexState& x0,
                               const FlexState& x1, const FlexAccel& a1, double t,
                               double t1) const {
        return first_event(events(), t1, [&](Ev e) -> std::optional<double> {
            auto fe = [&](double tq) { return event_at(e, dense, tq); };
            const double f1 = event_value(e, x1, a1);
            if (f1 < 0.0) return sign_change(fe, t, t1, event_value(e, x0, a0_), f1);
            if (e != Ev::impact) return std::nullopt;
            auto rate = [&](double tq) { return dense.at(tq, 3); };
            return dip_below_zero(fe, rate, t, t1, x0[2], x0[3], x1[3]);
        });
    }

    // Peaks of theta and |q| inside a step: where theta' or q' changes sign.
    void observe_peaks(const StepExtension& dense, const FlexState& x0, const FlexState& xe,
                       double t, double te) {
        // theta' and q' in contact, phi' and q' in flight (the tilt in flight is a rotation
        // the peak counts, and phi'' does not vanish there: the mode pulls on it).
        const bool fl = is_flight(m_.mode);
        const std::size_t ith = fl ? 5 : 3, iq = fl ? 7 : 5;
        for (std::size_t i : {ith, iq}) {
            const double f0 = x0[i], f1 = xe[i];
            if (f0 == 0.0 || (f0 > 0.0) == (f1 > 0.0) || !(te > t)) continue;
            auto f = [&](double tq) { return dense.at(tq, i); };
            rec_.observe(m_, dense(toms748_root(f, t, te, f0, f1)));
        }
        rec_.observe(m_, xe);
    }

    void handle(Ev e, double t) {
        const Base base = seg_.at(t);
        switch (e) {
            case Ev::overturn: rec_.overturn(t, OverturnCriterion::angle_half_pi); return;
            case Ev::impact: impact(t, base); return;
            case Ev::lift: set_mode({Mode::flight, m_.s, m_.sigma}, t); return;
            case Ev::friction: {
                const FlexAccel a = flex_accel(g_, m_, pose_of(g_, m_, x_), base);
                x_[1] = 0.0;
                set_mode({Mode::slide_rock, m_.s, a.F > 0.0 ? -1 : 1}, t);
                return;
            }
            case Ev::stop:
                x_[1] = 0.0;
                if (m_.mode == Mode::slide) {
                    set_mode(classify_flat(g_, x_[4], x_[5], 0.0, probe(t)), t);
                } else {
                    set_mode(classify_edge(g_, m_.s, pose_of(g_, m_, x_), 0.0, probe(t)), t);
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

    // theta = 0 on edge s: the body strikes the other edge (flexible_impact.cpp), or settles
    // flat when it was not rotating towards it or would rebound less than settle_rebound_rad.
    void impact(double t, Base base) {
        x_[2] = 0.0;
        const double om = x_[3];
        if (!(om < 0.0)) {
            rec_.settlement();
            go_flat(t, x_[1]);
            return;
        }
        const int s_new = -m_.s;
        const EdgeState after = edge_impact(g_, pose_of(g_, m_, x_), s_new, x_[0], x_[1]);
        if (rebound_angle(g_.rigid, s_new, after.om, base.G) < o_.settle_rebound_rad) {
            rec_.impact(t, -om, 0.0, true);
            rec_.settlement();
            go_flat(t, x_[1]);
            return;
        }
        rec_.impact(t, -om, after.om, false);
        x_ = edge_state(after);
        m_.s = s_new;
        set_mode(classify_edge(g_, s_new, pose_of(g_, m_, x_), x_[1], base), t);
    }

    void land(double t) {
        const Landing l = land_flexible(g_, pose_of(g_, m_, x_), o_.flat_landing_window_s);
        rec_.impact(t, l.om_before, l.flat ? 0.0 : l.st.om, false);
        x_ = edge_state(l.st);
        if (l.flat) {
            m_ = {Mode::slide, l.st.s, m_.sigma};
            set_mode(classify_flat(g_, x_[4], x_[5], x_[1], probe(t)), t);
            return;
        }
        m_ = {Mode::rock, l.st.s, 1};
        set_mode(classify_edge(g_, l.st.s, pose_of(g_, m_, x_), 0.0, seg_.at(t)), t);
    }

    static constexpr const char* integrator_name_ = "flexible-body integrator";
    const FlexGeometry& g_;
    const Options& o_;
    FlexRecorder& rec_;
    const OscillatorStep full_step_;  // the rest phase's whole input step
    const double g_mps2_;
    const double quiet_from_s_;  // the input has ended from here (BaseMotion::quiet_from_s)
    const double rigid_limit_hz_;  // rigid_limit_hz of the model and the input
    std::size_t dp_steps_ = 0;     // Dormand-Prince steps tried
    Stepper dp_;
    Segment seg_;
    double tb_ = 0.0;
    FlexMode m_{};
    FlexState x_{};
    FlexState k1_{};          // f(x_, t): the next step's first stage when fsal_
    bool fsal_ = false;
    FlexAccel a_last_{};      // accelerations of the stepper's last evaluation
    FlexAccel a0_{};          // ... at x_ (valid with fsal_)
    FlexAccel a_end_{};       // ... at the end of the last step that met no event
    bool end_valid_ = false;
    double end_t_ = -1.0;
    AdaptiveStep step_;
    ChatterGuard chatter_;
    double hold_until_ = -1.0;
};

// The flexible engine as run_segments drives it: rest runs on the exact oscillator, the other
// modes one segment at a time.
class FlexBody {
public:
    FlexBody(const BaseMotion& bm, const Options& o, FlexRecorder& rec, FlexEngine& engine)
        : bm_(bm), g_mps2_(o.g_mps2), rec_(rec), engine_(engine) {}

    double t_k(std::size_t k) const { return bm_.t_k(k); }
    bool overturned() const { return rec_.overturned(); }
    void sample(std::size_t k, double tb) { engine_.sample(tb, bm_.sample(k + 1)); }
    bool ends_at(double tb) const { return tb >= bm_.min_end_s() && engine_.settled(g_mps2_); }
    RestRun rest_run(std::size_t k, std::size_t n_seg) {
        double settled_at = -1.0;
        const std::size_t next = engine_.rest_run(bm_, k, n_seg, settled_at);
        return {next, settled_at >= 0.0};
    }
    double advance(std::size_t& k, double t, double tb) {
        if (k != k_seg_) seg_ = bm_.linear_segment(k_seg_ = k);
        return engine_.advance(seg_, t, tb);
    }

private:
    const BaseMotion& bm_;
    const double g_mps2_;
    FlexRecorder& rec_;
    FlexEngine& engine_;
    std::size_t k_seg_ = std::numeric_limits<std::size_t>::max();
    Segment seg_;
};

}  // namespace

FlexibleResult run_flexible_event(const FlexGeometry& g, const BaseMotion& bm, const Options& o,
                                  double rigid_limit_hz) {
    FlexibleResult out;
    FlexRecorder rec(g, o, out);
    FlexEngine engine(g, o, bm, rec, rigid_limit_hz);
    engine.start(bm.linear_segment(0).at(probe_time(0.0, bm.dt())));
    engine.sample(0.0, bm.sample(0));
    FlexBody body(bm, o, rec, engine);
    const RunEnd run = run_segments(body, bm.segments(o.tail_s));
    rec.end_run(engine.mode(), engine.state(), run.end_s, bm, "event");
    return out;
}

}  // namespace freestand::dynamics::detail
