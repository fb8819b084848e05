// Event-driven integrator: closed forms for rest, slide and flight on each piecewise-linear
// input segment; for rock and slide-rock one Taylor polynomial per segment (taylor.hpp), of the
// degree the tolerance needs, which is also the dense output; every switch located by root
// finding (Newton or TOMS 748) on the closed form or the polynomial, never by the next sample.
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <numbers>
#include <optional>
#include <utility>

#include "core/errors.hpp"
#include "core/steps.hpp"
#include "dynamics/engine.hpp"
#include "dynamics/event_search.hpp"
#include "dynamics/integrators.hpp"
#include "dynamics/taylor.hpp"

namespace freestand::dynamics::detail {

namespace {

using Vec = std::array<double, 4>;  // u, u', theta, theta'
constexpr double half_pi = std::numbers::pi / 2.0;
constexpr int landing_probes = 16;            // sub-samples per segment searching a landing

enum class Ev { none, impact, overturn, past_alpha, friction, lift, stop };

// False only if sigma (v + c0 t + c1 t^2 / 2) > 0 on all of (0, span]: the end value and, when
// the vertex t = -c0/c1 lies inside, the extremum are on the slip side. Saves the root solve
// on most segments.
bool may_stop(double v, double c0, double c1, double span, double sigma) {
    if (v == 0.0 || sigma * v <= 0.0) return true;
    if (sigma * (v + span * (c0 + 0.5 * c1 * span)) <= 0.0) return true;
    const bool vertex_inside = c0 * c1 < 0.0 && std::abs(c0) < std::abs(c1) * span;
    return vertex_inside && sigma * (v - c0 * c0 / (2.0 * c1)) <= 0.0;
}

class Engine {
public:
    Engine(const Geometry& g, const BaseMotion& bm, const Options& o, Recorder& rec, BlockState& st)
        : g_(g), bm_(bm), o_(o), rec_(rec), st_(st) {}

    // Advances from t towards tb on segment k; returns the time reached (tb or an event).
    double advance(std::size_t k, double t, double tb) {
        seg_ = bm_.linear_segment(k);
        tb_ = tb;
        switch (st_.mode) {
            case Mode::rest: return advance_rest(t);
            case Mode::slide: return advance_slide(t);
            case Mode::rock:
            case Mode::slide_rock: return advance_contact(k, t, tb);
            case Mode::flight: return advance_flight(t);
        }
        return tb;
    }

private:
    // Base a little after t, to classify a start exactly at a threshold (section 2 uses strict
    // inequalities, so at the threshold itself the block is still at rest).
    Base probe(double t) const { return seg_.at(t < tb_ ? probe_time(t, tb_) : t); }

    void set_mode(const Start& k, double t) {
        enter_mode(g_, rec_, st_, k);
        note_event(t);
    }

    // Chatter guard: many events inside settle_interval_s settle the block at rest.
    void note_event(double t) {
        if (!chatter_.note(t, o_.settle_interval_s, "event-driven integrator")) return;
        rec_.settlement();
        rec_.transition(st_.mode, Mode::rest);
        st_.mode = Mode::rest;
        st_.v = st_.th = st_.om = 0.0;
        rest_hold_until_ = t + settle_hold_s;
    }

    // Flat contact again (after settling or a flat landing): slide if slipping, else from rest.
    void go_flat(double t) {
        st_.th = st_.om = 0.0;
        if (st_.v != 0.0) {
            set_mode(classify_sliding(g_, st_.v), t);
        } else {
            set_mode(classify_from_rest(g_, probe(t)), t);
        }
    }

    double advance_rest(double t) {
        if (t < rest_hold_until_) {  // settled by the chatter rule: see settle_hold_s
            const double held = std::min(tb_, rest_hold_until_);
            rec_.time_in(Mode::rest, held - t);
            return held;
        }
        const Base a = seg_.at(t), b = seg_.at(tb_);
        const double cl = g_.c_rest[0], cr = g_.c_rest[1];
        // Rest holds while every function is <= 0 (section 2); each is linear on the segment.
        const double ha[3] = {a.ax - cl * a.G, -a.ax - cr * a.G, -a.G};
        const double hb[3] = {b.ax - cl * b.G, -b.ax - cr * b.G, -b.G};
        double t_ev = std::numeric_limits<double>::infinity();
        for (int i = 0; i < 3; ++i) {
            if (ha[i] > 0.0) t_ev = t;
            else if (hb[i] > 0.0) t_ev = std::min(t_ev, t + (tb_ - t) * (-ha[i]) / (hb[i] - ha[i]));
        }
        if (!(t_ev <= tb_)) {
            rec_.time_in(Mode::rest, tb_ - t);
            return tb_;
        }
        t_ev = std::clamp(t_ev, t, tb_);
        rec_.time_in(Mode::rest, t_ev - t);
        const Start k = classify_from_rest(g_, probe(t_ev));
        if (k.mode == Mode::rest) return std::min(tb_, probe_time(t_ev, tb_));
        set_mode(k, t_ev);
        return t_ev;
    }

    // Flat sliding, in closed form: u'' = -xg'' - sigma mu_k G is linear in tau on the segment,
    // u a cubic; to the segment's end or to the first event (slide_piece).
    double advance_slide(double t) {
        rec_.step();
        const Base a = seg_.at(t);
        const double dsig = static_cast<double>(st_.sigma);
        const double c0 = -a.ax - dsig * g_.mu_k * a.G;
        const double c1 = -seg_.ax1 - dsig * g_.mu_k * seg_.G1;
        const SlidePiece piece = slide_piece(a.G, c0, c1, tb_ - t);
        const double tau = piece.tau_s;
        st_.u += tau * (st_.v + tau * (0.5 * c0 + tau * c1 / 6.0));
        st_.v += tau * (c0 + 0.5 * c1 * tau);
        rec_.time_in(Mode::slide, tau);
        const double te = piece.ev == Ev::none ? tb_ : t + tau;
        rec_.observe(st_);
        end_slide(piece.ev, te);
        return te;
    }

    struct SlidePiece {
        double tau_s = 0.0;
        Ev ev = Ev::none;
    };

    // How long a flat slide lasts on the segment (span_s to its end, G0 at its start, u'' = c0
    // + c1 tau) and the event that ends it: a stop, lift-off (G = 0), or none at the end.
    SlidePiece slide_piece(double G0, double c0, double c1, double span_s) const {
        const double dsig = static_cast<double>(st_.sigma);
        // G = 0 (lift-off) at t + t_fly; never while G does not fall.
        const double t_fly = seg_.G1 < 0.0 ? -G0 / seg_.G1 : std::numeric_limits<double>::infinity();
        // Most segments of a slide can neither stop nor lift off (the hot path of sliding
        // records): the searches are skipped.
        const bool stop_possible = may_stop(st_.v, c0, c1, span_s, dsig);
        if (!stop_possible && t_fly >= span_s) return {span_s, Ev::none};
        // Starting from u' = 0 the direction was chosen at the probe time t + delta (the start
        // may sit exactly on the threshold, where u'' = 0 to round-off): ignore roots before it.
        const double delta = st_.v == 0.0 ? std::min(probe_delay_s, 0.5 * span_s) : 0.0;
        double tau = stop_possible ? first_quadratic_root(st_.v, c0, 0.5 * c1, delta, span_s)
                                   : std::numeric_limits<double>::infinity();
        Ev ev = tau <= span_s ? Ev::stop : Ev::none;
        if (st_.v == 0.0 && !(dsig * (c0 + c1 * delta) > 0.0)) {
            tau = 0.0;  // pushed against its slip direction: a stop now
            ev = Ev::stop;
        }
        if (t_fly >= 0.0 && t_fly < std::min(tau, span_s)) {
            tau = t_fly;
            ev = Ev::lift;
        }
        return {ev == Ev::none ? span_s : tau, ev};
    }

    // The mode after a slide's event at te: from rest after a stop, flight after lift-off.
    void end_slide(Ev ev, double te) {
        if (ev == Ev::stop) {
            st_.v = 0.0;
            set_mode(classify_from_rest(g_, probe(te)), te);
        } else if (ev == Ev::lift) {
            st_.th = 0.0;
            set_mode({Mode::flight, 1, 1}, te);
        }
    }

    double event_value(Ev e, const Vec& x, const Accel& a) const {
        switch (e) {
            case Ev::impact: return x[2];
            case Ev::overturn: return half_pi - x[2];
            case Ev::past_alpha:
                return g_.alpha[static_cast<std::size_t>(Geometry::index(st_.s))] - x[2];
            case Ev::friction: return g_.mu_s * a.N - std::abs(a.F);
            case Ev::lift: return a.N;
            case Ev::stop: return static_cast<double>(st_.sigma) * x[1];
            case Ev::none: break;
        }
        return 1.0;
    }

public:
    /// Rock / slide-rock from t (inside segment k) until an event or `horizon` (a sample time).
    /// Each step is one Taylor polynomial (taylor.hpp) on one linear piece of the input: while
    /// the excitation lasts steps end at every sample, where the input's slope jumps, and the
    /// sample is recorded from the step's end; after it the base is at rest and steps run up to
    /// Options::max_contact_step_s, the samples inside them evaluated on the polynomial.
    /// next_sample() is the first sample not recorded (the caller records the one at the time
    /// reached if it is a sample time).
    // The events a contact step watches, in the order ties are resolved: impact, overturn,
    // lift-off, then friction failure (rock) or slip stop (slide-rock), and after the
    // excitation the pass beyond alpha.
    std::array<Ev, 5> contact_events(bool tail) const {
        std::array<Ev, 5> events = {Ev::impact, Ev::overturn, Ev::lift, Ev::none, Ev::none};
        if (st_.mode == Mode::rock) {
            events[3] = Ev::friction;
            if (tail) events[4] = Ev::past_alpha;
        } else {
            events[3] = Ev::stop;
        }
        return events;
    }

    // The Taylor stepper's start state on the active edge ia, phi0 = alpha - theta.
    ContactStart contact_start(std::size_t ia, double phi0) const {
        ContactStart x0;
        x0.mode = st_.mode;
        x0.s = st_.s;
        x0.sigma = st_.sigma;
        x0.sn = st_.th == 0.0 ? g_.sin_alpha[ia] : std::sin(phi0);  // after an impact: theta = 0
        x0.c = st_.th == 0.0 ? g_.cos_alpha[ia] : std::cos(phi0);
        return x0;
    }

    // Peak rotation inside a step (theta' from + to -): Newton on theta' with theta'' from the
    // same polynomial; recorded unless an event ends the step before it.
    void observe_peak_in_step(const ContactSeries& S, double t, double t1, double om0,
                              double om1, Ev first, double t_ev) {
        if (!(om0 > 0.0 && om1 <= 0.0)) return;
        auto w = [&](double tt) {
            return std::pair<double, double>{S.omega(tt - t), S.theta_dd(tt - t)};
        };
        // theta is stationary there: an error dt in the time moves it by theta'' dt^2 / 2,
        // ~1e-16 rad for dt = 1e-6 of the step.
        const double tp = newton_root(w, t, t1, om0, om1, 1e-6 * (t1 - t));
        if (first == Ev::none || tp <= t_ev) {
            BlockState peak = st_;
            peak.th = S.theta(tp - t);
            rec_.observe(peak);
        }
    }

    // The first event of `events` inside the step [t, t1] (or none, at t1): the step-end values
    // flag whether any can have happened; only then is each located on the step's polynomials.
    template <class Dense, class AccelOnStep>
    EventAt<Ev> first_contact_event(const std::array<Ev, 5>& events, const ContactSeries& S,
                                  double t, double t1, double h, const Vec& x, const Vec& xn,
                                  const Accel& acc0, const Accel& acc1, double alpha,
                                  const Dense& dense, const AccelOnStep& accel_on_step) const {
        // The event functions of `events` at the step end, written out: on a routine step
        // none is negative and the loop below is skipped.
        // sigma u' of a slide-rock step, whose zero is the stop event.
        std::array<double, taylor_max_order + 1> sv;
        Poly slip_poly{sv.data(), 0};
        if (st_.mode == Mode::slide_rock) {
            const double sig = static_cast<double>(st_.sigma);
            slip_poly.n = S.nu - 1;
            for (int j = 0; j < S.nu; ++j)
                sv[static_cast<std::size_t>(j)] = sig * (j + 1) * S.u[static_cast<std::size_t>(j + 1)];
        }
        // Whether theta (impact) or sigma u' (slip stop) may drop below 0 in the step; see
        // first_zero.
        auto may_cross = [&](Poly f, double f1) {
            if (f.a[0] > 0.0) return !stays_positive(f, h);
            return f1 < 0.0 || (f.n >= 1 && f.a[1] > 0.0 && !stays_positive(f, h));
        };
        const double sig = static_cast<double>(st_.sigma);
        const bool flagged =
            may_cross(S.theta_poly(), xn[2]) || xn[2] > half_pi || acc1.N < 0.0 ||
            (st_.mode == Mode::rock ? g_.mu_s * acc1.N < std::abs(acc1.F)
                                    : may_cross(slip_poly, sig * xn[1])) ||
            (events[4] == Ev::past_alpha && xn[2] > alpha);
        if (!flagged) return {Ev::none, t1};
        return first_event(events, t1, [&](Ev e) -> std::optional<double> {
            if (e == Ev::impact || e == Ev::stop) {
                const double te = first_zero(e, e == Ev::impact ? S.theta_poly() : slip_poly, t,
                                             t1, h, dense, accel_on_step, S);
                if (te < 0.0) return std::nullopt;
                return te;
            }
            const double v1 = event_value(e, xn, acc1);
            if (!(v1 < 0.0)) return std::nullopt;
            return locate_event(e, t, t1, event_value(e, x, acc0), v1, dense, accel_on_step, S);
        });
    }

    double advance_contact(std::size_t k, double t, double horizon) {
        next_sample_ = k + 1;
        const bool tail = t >= bm_.quiet_from_s();
        const std::size_t ia = static_cast<std::size_t>(Geometry::index(st_.s));
        rec_.check_overturn(st_, t, tail);
        if (rec_.overturned()) return t;
        const std::array<Ev, 5> events = contact_events(tail);
        const double alpha = g_.alpha[ia];
        double phi0 = alpha - st_.th;
        ContactStart x0 = contact_start(ia, phi0);
        std::size_t kseg = k;
        enter_segment(kseg);
        Accel acc0 = contact_accel(x0, x0.sn, x0.c, st_.om, seg_.at(t));
        ContactSeries S;
        while (t < horizon) {
            load_step_start(x0, t);
            const double stop_at = tail ? horizon : std::min(tb_, horizon);
            const double h = taylor_step(x0, t, stop_at, S);
            const double t1 = (h == stop_at - t) ? stop_at : t + h;
            const Vec x = {x0.u, x0.v, x0.th, x0.om};
            const Vec xn = {S.slip(h), S.slip_velocity(h), S.th_end, S.om_end};
            double sn1, c1;
            sin_cos_shift(x0.sn, x0.c, phi0, xn[2] - x0.th, sn1, c1);
            const Accel acc1 = contact_accel(x0, sn1, c1, xn[3], seg_.at(t1));
            auto dense = [&](double tt) {
                const double tau = tt - t;
                return Vec{S.slip(tau), S.slip_velocity(tau), S.theta(tau), S.omega(tau)};
            };
            auto accel_on_step = [&](double tt, const Vec& y) {
                double sn, c;
                sin_cos_shift(x0.sn, x0.c, phi0, y[2] - x0.th, sn, c);
                return contact_accel(x0, sn, c, y[3], seg_.at(tt));
            };
            const EventAt<Ev> ev = first_contact_event(events, S, t, t1, h, x, xn, acc0, acc1,
                                                       alpha, dense, accel_on_step);
            const Ev first = ev.event;
            const double t_ev = ev.t_s;
            observe_peak_in_step(S, t, t1, x[3], xn[3], first, t_ev);
            // Steps cross sample times only after the excitation.
            if (tail) record_samples(dense, first == Ev::none ? t1 : t_ev);
            if (first != Ev::none) return end_at_event(first, t, t_ev, t_ev == t1 ? xn : dense(t_ev));
            if (commit_step(t, t1, xn, tail)) return t1;
            t = t1;
            x0.sn = sn1;
            x0.c = c1;
            phi0 = alpha - xn[2];
            acc0 = acc1;
            known_ = {acc1, sn1, c1};
            if (t == tb_ && t < horizon) {
                // A sample time inside the run: record it from the step's end.
                rec_.sample_contact(t, st_, bm_.sample(next_sample_), known_);
                ++next_sample_;
                enter_segment(++kseg);
            }
        }
        keep_known(horizon);
        return horizon;
    }

    // A step from t without event, to t1 in state xn; true when the body overturned there.
    bool commit_step(double t, double t1, const Vec& xn, bool tail) {
        rec_.time_in(st_.mode, t1 - t);
        set_contact(xn);
        rec_.observe(st_);
        // Rock's pass beyond alpha is located as an event; a slide-rock's energy is only
        // checked at step ends.
        if (tail) rec_.check_overturn(st_, t1, true);
        return rec_.overturned();
    }

    // The step's start from the state at t and the segment's input.
    void load_step_start(ContactStart& x0, double t) const {
        x0.u = st_.u;
        x0.v = st_.v;
        x0.th = st_.th;
        x0.om = st_.om;
        const Base b0 = seg_.at(t);
        x0.ax0 = b0.ax;
        x0.G0 = b0.G;
        x0.ax1 = seg_.ax1;
        x0.G1 = seg_.G1;
    }

    // One Taylor step (taylor.hpp) from x0 at t towards stop_at; returns its length. A tiny
    // remainder up to a sample (an event an ulp before it) is stepped over; only a step the
    // tolerance itself cut below min_step_s means the integration is stuck.
    double taylor_step(const ContactStart& x0, double t, double stop_at, ContactSeries& S) {
        const double h_full = step_.request(t, stop_at, o_.max_contact_step_s);
        const double h = taylor_contact_step(g_, x0, h_full, o_.rel_tol, o_.abs_tol, S, rock_degree_);
        if (h < min_step_s && h < h_full)
            throw NumericalError(fmt::format(
                "event-driven integrator: step below 1e-14 s at t = {} s ({})", t,
                to_string(st_.mode)));
        step_.took(h, h_full);
        rec_.step();
        return h;
    }

    // The contact run from t ends at its event e at t_ev, in state y.
    double end_at_event(Ev e, double t, double t_ev, const Vec& y) {
        rec_.time_in(st_.mode, t_ev - t);
        set_contact(y);
        rec_.observe(st_);
        handle_contact_event(e, t_ev);
        return t_ev;
    }

    // The accelerations of the state a contact run ended in at horizon stay valid (known_at).
    void keep_known(double horizon) {
        known_ok_ = true;
        known_t_ = horizon;
        known_x_ = {st_.u, st_.v, st_.th, st_.om};
        known_mode_ = st_.mode;
    }

    /// Flat sliding from t (inside segment k) until an event or `horizon` (a sample time), one
    /// closed-form piece per segment, recording the samples passed; next_sample() as for
    /// advance_contact.
    double advance_slide_run(std::size_t k, double t, double horizon) {
        next_sample_ = k + 1;
        enter_segment(k);
        for (;;) {
            const double te = advance_slide(t);
            if (st_.mode != Mode::slide || te < tb_ || te >= horizon) return te;
            rec_.sample_slide(te, st_, bm_.sample(next_sample_));
            enter_segment(next_sample_++);
            t = te;
        }
    }

    /// Accelerations (and trigonometry) of the current contact state if a contact run ended at
    /// t, else null.
    const Known* known_at(double t) const {
        const bool contact = st_.mode == Mode::rock || st_.mode == Mode::slide_rock;
        const Vec x = {st_.u, st_.v, st_.th, st_.om};
        return contact && known_ok_ && known_mode_ == st_.mode && known_t_ == t && known_x_ == x
                   ? &known_
                   : nullptr;
    }

    /// First output sample not yet recorded by advance_contact.
    std::size_t next_sample() const { return next_sample_; }

private:
    Accel contact_accel(const ContactStart& x0, double sn, double c, double om, Base base) const {
        return x0.mode == Mode::rock ? rock_accel_sc(g_, x0.s, sn, c, om, base)
                                     : slide_rock_accel_sc(g_, x0.s, x0.sigma, sn, c, om, base);
    }

    // First time in [t, t1] (h = t1 - t) at which f, theta (impact) or sigma u' (slip stop),
    // drops below 0; -1 if none. From f(0) > 0 the polynomial is searched for a dip inside the
    // step. From f(0) = 0 only a definite departure is searched (f'(0) > 0: just off the other
    // edge after an impact, whose rebound can fall back and be lifted again within a step) and
    // only a dip deeper than 1e-3 abs_tol counts; at a rock or slip onset f'(0) = 0 to
    // round-off and the end value decides.
    template <class Dense, class AccelOn>
    double first_zero(Ev e, Poly f, double t, double t1, double h, const Dense& dense,
                      const AccelOn& accel_on, const ContactSeries& S) const {
        auto f_at = [&](double tt) { return f.value_d1(tt - t); };
        const double f0 = f.a[0], f1 = f.value(h);
        const bool from_zero = !(f0 > 0.0);
        if (!from_zero && f1 < 0.0) {
            // The usual case: a sign change over the step, its root the first one when f is
            // monotone or concave up to it.
            const double te = newton_root(f_at, t, t1, f0, f1);
            if (monotone_or_concave(f, te - t)) return te;
        }
        if (!from_zero || (f.n >= 1 && f.a[1] > 0.0)) {
            const ZeroBracket z = zero_bracket(f, h, from_zero ? 1e-3 * o_.abs_tol : 0.0);
            if (z.found)
                return z.f_a == 0.0 && z.a == 0.0
                           ? locate_event(e, t, t + z.b, 0.0, z.f_b, dense, accel_on, S)
                           : newton_root(f_at, t + z.a, t + z.b, z.f_a, z.f_b);
        }
        return f1 < 0.0 ? locate_event(e, t, t1, f0, f1, dense, accel_on, S) : -1.0;
    }

    // Time of the event e in [t, t1] where it goes from v0 to v1 < 0. Angle events and the
    // slip stop use Newton on the polynomial (theta' or u'' is the slope); the force events,
    // TOMS 748 on the forces the polynomial's state implies.
    template <class Dense, class AccelOn>
    double locate_event(Ev e, double t, double t1, double v0, double v1, const Dense& dense,
                        const AccelOn& accel_on, const ContactSeries& S) const {
        const bool force = e == Ev::friction || e == Ev::lift;
        auto f = [&](double tt) {
            const Vec y = dense(tt);
            return event_value(e, y, force ? accel_on(tt, y) : Accel{});
        };
        double ta = t, fa = v0;
        if (v0 == 0.0) {
            // Starting on the boundary: look for the excursion inside the step.
            const RiseStart rise = rise_scan(f, t, t1, BelowZero::ends_scan);
            ta = rise.t_s;
            fa = rise.f;
        }
        if (fa < 0.0) return t;
        if (force) return toms748_root(f, ta, t1, fa, v1);
        auto fd = [&](double tt) {
            const double tau = tt - t;
            switch (e) {
                case Ev::impact: return S.theta_omega(tau);
                case Ev::stop: {
                    const double sig = static_cast<double>(st_.sigma);
                    return std::pair<double, double>{sig * S.slip_velocity(tau), sig * S.slip_accel(tau)};
                }
                default: return std::pair<double, double>{f(tt), -S.omega(tau)};
            }
        };
        return newton_root(fd, ta, t1, fa, v1);
    }

    void enter_segment(std::size_t k) {
        seg_ = bm_.linear_segment(k);
        tb_ = bm_.t_k(k + 1);
    }

    void set_contact(const Vec& y) {
        st_.u = y[0];
        st_.v = y[1];
        st_.th = y[2];
        st_.om = y[3];
    }

    // Output samples strictly before t_stop, from the step's dense output.
    template <class Dense>
    void record_samples(const Dense& dense, double t_stop) {
        for (double tj = bm_.t_k(next_sample_); tj < t_stop; tj = bm_.t_k(++next_sample_)) {
            BlockState at = st_;
            const Vec y = dense(tj);
            at.u = y[0];
            at.v = y[1];
            at.th = y[2];
            at.om = y[3];
            rec_.observe(at);
            rec_.sample(tj, at, bm_.sample(next_sample_));
        }
    }

    void handle_contact_event(Ev e, double t) {
        const Base base = seg_.at(t);
        switch (e) {
            case Ev::impact: {
                st_.th = 0.0;
                if (!(st_.om < 0.0)) {  // grazing return: it lands without rebound
                    rec_.settlement();
                    go_flat(t);
                    return;
                }
                const int s_new = -st_.s;
                const double w_before = -st_.om;
                const double w_after =
                    g_.r_onto[static_cast<std::size_t>(Geometry::index(s_new))] * w_before;
                if (rebound_angle(g_, s_new, w_after, base.G) < o_.settle_rebound_rad) {
                    rec_.impact(t, w_before, 0.0, true);
                    rec_.settlement();
                    go_flat(t);
                    return;
                }
                rec_.impact(t, w_before, w_after, false);
                st_.s = s_new;
                st_.om = w_after;
                set_mode(classify_on_edge(g_, st_.s, 0.0, st_.om, st_.v, base), t);
                return;
            }
            case Ev::overturn: rec_.overturn(t, OverturnCriterion::angle_half_pi); return;
            case Ev::past_alpha:
                rec_.overturn(t, OverturnCriterion::past_alpha_after_excitation);
                return;
            case Ev::friction: {
                const Accel a = rock_accel(g_, st_.s, st_.th, st_.om, base);
                set_mode({Mode::slide_rock, st_.s, a.F > 0.0 ? -1 : 1}, t);
                st_.v = 0.0;
                return;
            }
            case Ev::lift: set_mode({Mode::flight, st_.s, st_.sigma}, t); return;
            case Ev::stop:
                st_.v = 0.0;
                set_mode(classify_on_edge(g_, st_.s, st_.th, st_.om, 0.0, base), t);
                return;
            case Ev::none: return;
        }
    }

    // Ballistic flight: X'' = -xg'', Y'' = -G (linear on the segment), phi' constant.
    Flight flight_at(const Flight& f0, double tau, double ax0, double ax1, double G0,
                     double G1) const {
        Flight f = f0;
        const double t2 = tau * tau, t3 = t2 * tau;
        f.X += f0.Xd * tau - ax0 * t2 / 2.0 - ax1 * t3 / 6.0;
        f.Xd += -ax0 * tau - ax1 * t2 / 2.0;
        f.Y += f0.Yd * tau - G0 * t2 / 2.0 - G1 * t3 / 6.0;
        f.Yd += -G0 * tau - G1 * t2 / 2.0;
        f.phi += f0.phid * tau;
        return f;
    }

    double advance_flight(double t) {
        rec_.step();
        const Base a = seg_.at(t);
        const Flight f0 = st_.fl;
        const double span = tb_ - t;
        int s_low = 1;
        auto height = [&](double tau) {
            return lowest_corner(g_, flight_at(f0, tau, a.ax, seg_.ax1, a.G, seg_.G1), s_low);
        };
        auto tilt = [&](double tau) {
            return half_pi - std::abs(flight_at(f0, tau, a.ax, seg_.ax1, a.G, seg_.G1).phi);
        };
        // Armed once the lowest corner has risen: the lift-off point itself is at height 0.
        double hprev = height(0.0);
        if (hprev > 0.0) armed_ = true;
        double tau_ev = -1.0;
        bool over = false;
        scan_flight(span, landing_probes, [&](double prev, double tau) {
            const double hj = height(tau);
            if (tilt(tau) < 0.0) {
                tau_ev = toms748_root(tilt, prev, tau, tilt(prev), tilt(tau));
                over = true;
                return true;
            }
            if (armed_ && hj < 0.0) {
                tau_ev = toms748_root(height, prev, tau, hprev, hj);
                return true;
            }
            if (hj > 0.0) armed_ = true;
            hprev = hj;
            return false;
        });
        if (tau_ev < 0.0) {
            st_.fl = flight_at(f0, span, a.ax, seg_.ax1, a.G, seg_.G1);
            rec_.time_in(Mode::flight, span);
            rec_.observe(st_);
            return tb_;
        }
        const double te = t + tau_ev;
        st_.fl = flight_at(f0, tau_ev, a.ax, seg_.ax1, a.G, seg_.G1);
        rec_.time_in(Mode::flight, tau_ev);
        rec_.observe(st_);
        if (over) {
            rec_.overturn(te, OverturnCriterion::angle_half_pi);
            return te;
        }
        land_at(te);
        return te;
    }

    // The landing at te (mechanics.hpp land): an impact onto an edge, or flat.
    void land_at(double te) {
        armed_ = false;
        const Contact c = land(g_, st_.fl, o_.flat_landing_window_s);
        rec_.impact(te, std::abs(st_.fl.phid), std::abs(c.om), false);
        st_.u = c.u;
        st_.v = c.v;
        st_.s = c.s;
        st_.th = c.th;
        st_.om = c.om;
        if (c.flat) {
            go_flat(te);
        } else {
            set_mode(classify_on_edge(g_, c.s, c.th, c.om, 0.0, seg_.at(te)), te);
        }
    }

    const Geometry& g_;
    const BaseMotion& bm_;
    const Options& o_;
    Recorder& rec_;
    BlockState& st_;
    Segment seg_;
    double tb_ = 0.0;
    SeriesStep step_{o_.max_contact_step_s};  // the contact steps' cap
    RockDegree rock_degree_;  // Taylor degree carried between rock steps
    std::size_t next_sample_ = 0;
    Known known_;
    bool known_ok_ = false;
    double known_t_ = 0.0;
    Vec known_x_{};
    Mode known_mode_ = Mode::rest;
    ChatterGuard chatter_;
    double rest_hold_until_ = -1.0;
    bool armed_ = false;
};

// The planar engine as run_segments drives it: rest runs over raw samples, contact and slide
// runs that record the samples they pass, the other modes one segment at a time.
class PlanarBody {
public:
    PlanarBody(const Geometry& g, const BaseMotion& bm, const Options& o, Recorder& rec,
               BlockState& st, std::size_t n_seg)
        : g_(g), bm_(bm), rec_(rec), st_(st), engine_(g, bm, o, rec, st), n_seg_(n_seg) {}

    double t_k(std::size_t k) const { return bm_.t_k(k); }
    bool overturned() const { return rec_.overturned(); }
    bool ends_at(double tb) const { return st_.mode == Mode::rest && tb >= bm_.min_end_s(); }
    void sample(std::size_t k, double tb) {
        rec_.sample(tb, st_, bm_.sample(k + 1), engine_.known_at(tb));
    }

    // The rest inequalities are linear on a segment: holding at both samples, they hold
    // throughout, so whole runs of such segments are passed without the engine.
    RestRun rest_run(std::size_t k, std::size_t n_seg) {
        if (st_.mode != Mode::rest || !rest_holds(g_, bm_.sample(k))) return {k, false};
        const double min_end = bm_.min_end_s(), dt = bm_.dt();
        // Last segment end the run may reach: the first sample at or after min_end.
        const auto j_max = std::min<std::size_t>(
            n_seg, std::max<std::size_t>(k + 1, static_cast<std::size_t>(core::steps_covering(min_end / dt))));
        double peak = 0.0;
        // Segments k..j-1 stay at rest: samples k+1..j hold.
        const std::size_t j = bm_.rest_until(k + 1, j_max + 1, g_, peak) - 1;
        rec_.rest_samples(bm_, k + 1, j + 1, st_, peak);
        rec_.time_in(Mode::rest, dt * static_cast<double>(j - k));
        return {j, j == n_seg || (j > k && bm_.t_k(j) >= min_end)};
    }

    double advance(std::size_t& k, double t, double tb) {
        if (st_.mode == Mode::rock || st_.mode == Mode::slide_rock) {
            // Contact runs stop where the excitation ends (their steps then stop ending at
            // samples) and at events.
            const double quiet = bm_.quiet_from_s();
            t = engine_.advance_contact(k, t, t < quiet ? quiet : bm_.t_k(n_seg_));
            k = engine_.next_sample() - 1;
            return t;
        }
        if (st_.mode == Mode::slide) {
            t = engine_.advance_slide_run(k, t, bm_.t_k(n_seg_));
            k = engine_.next_sample() - 1;
            return t;
        }
        return engine_.advance(k, t, tb);
    }

private:
    const Geometry& g_;
    const BaseMotion& bm_;
    Recorder& rec_;
    BlockState& st_;
    Engine engine_;
    std::size_t n_seg_;
};

}  // namespace

SimulationResult run_event_driven(const Geometry& g, const BaseMotion& bm, const Options& o) {
    Recorder rec(g, o, bm.pga_mps2());
    const std::size_t n_seg = bm.segments(o.tail_s);
    BlockState st = start_block(g, o, rec, bm.at(0, 0.0), bm.at(0, probe_time(0.0, bm.dt())));
    PlanarBody body(g, bm, o, rec, st, n_seg);
    return finish_block(rec, st, bm, run_segments(body, n_seg),
                        integrator_name(Integrator::event));
}

}  // namespace freestand::dynamics::detail
