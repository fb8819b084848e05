// Event-driven biaxial sliding (docs/methods.md s.10). Rest and flight are exact on each linear
// input segment (a quadratic for |a_g|^2 - (mu_s G)^2, cubics for flight). Sliding has no
// closed form in two components (the friction direction v / |v| turns), so it is integrated by
// a controlled Dormand-Prince 5(4) with its dense output (dopri5.hpp): an explicit method with
// error control whose steps end at every input sample (the input's slope jumps there), and
// whose order-4 interpolant locates the events inside a step. Dormand-Prince rather than the
// Taylor machinery of taylor.hpp: the right-hand side is non-polynomial in v, and a stage-based
// method needs only its values. In one component the right-hand side is linear in t, which
// Dormand-Prince and its interpolant integrate exactly: the planar closed form to round-off.
//
// The stop |v| = 0 is located through a continuation of the friction direction: within a step
// the direction is sgn(v . d) v / |v|, d the direction at the step's start, which is smooth
// through a stop (v ~ c (t_s - t) there), so the step crosses it without upsetting the error
// control and the stop is the root of v . d on the interpolant. A root where |v| is not nil is
// a turn of more than 90 degrees inside one step (a near miss of a stop); the step is rejected
// and retried up to half the way to it.
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>

#include "core/errors.hpp"
#include "core/steps.hpp"
#include "dynamics/engine.hpp"
#include "dynamics/event_search.hpp"
#include "dynamics/biaxial_detail.hpp"
#include "dynamics/dopri5.hpp"

namespace freestand::dynamics::detail {

namespace {

using Stepper = Dopri5<4>;
using State = Stepper::State;  // u_x, u_y, v_x, v_y

constexpr std::size_t max_stalled_events = 100000;  // events at one instant before giving up
constexpr int flight_probes = 16;                   // sub-samples per segment for a landing

Vec2 vel(const State& x) { return {x[2], x[3]}; }
Vec2 pos(const State& x) { return {x[0], x[1]}; }

// Below this slip speed a slip is treated quasi-statically. Its direction relaxes towards
// -a_g in |v| / (mu_k G) (the equation's stiffness: 1e-10 s at 1e-10 m/s), which an explicit
// method cannot follow at a useful step: a record whose |a_g| hovers at mu_k G kept v near
// 1e-10 m/s for 0.16 s in 3e7 steps. So a step that starts this slow either stops the block
// (|a_g| <= mu_k G: friction would bring it to rest within |v| / (mu_k G - |a_g|)) or slides
// it with friction along -a_g / |a_g| until it is faster than this. The slip this changes is
// below v_slaved times the time so spent. A slip along the load is taken slaved well above
// this (takes_slaved, biaxial_detail.hpp); this floor is for slips the slaved equation leaves
// (across or against the load, or mu_k G or |a_g| tiny).
constexpr double v_slaved_mps = 1e-6;

// u'' = -a_g - mu_k G n (docs/methods.md s.10), n the continued friction direction. Slaved
// (takes_slaved), the slip is held along F = -a_g: v = s F^ with s' = |F| - mu_k G and
// v' = s' F^ + s F^', and the position moves with the lagging slip (slaved_lag).
struct SlideRhs {
    const BiaxialSegment* seg = nullptr;
    double mu_k = 0.0;
    Vec2 d{1.0, 0.0};  // direction at the step's start
    bool slaved = false;
    void operator()(const State& x, State& dxdt, double t) const {
        const Vec2 a = seg->a(t);
        const double G = seg->G(t);
        const Vec2 v = vel(x);
        if (slaved) {
            const SlavedLoad L = slaved_load(a, seg->a1);
            const double sp = dot(v, L.e);
            const double ds = L.F - mu_k * G;
            const Vec2 lag = slaved_lag(sp, L);
            dxdt = {v[0] - lag[0], v[1] - lag[1], ds * L.e[0] + sp * L.de[0],
                    ds * L.e[1] + sp * L.de[1]};
            return;
        }
        const double s = std::sqrt(v[0] * v[0] + v[1] * v[1]);
        Vec2 n = d;
        const double a_norm = std::sqrt(a[0] * a[0] + a[1] * a[1]);
        if (s < v_slaved_mps && a_norm > mu_k * G) {
            n = {-a[0] / a_norm, -a[1] / a_norm};
        } else if (s > 0.0) {
            const double sg = dot(v, d) >= 0.0 ? 1.0 / s : -1.0 / s;
            n = {sg * v[0], sg * v[1]};
        }
        dxdt = {v[0], v[1], -a[0] - mu_k * G * n[0], -a[1] - mu_k * G * n[1]};
    }
};

class BiaxialEngine {
public:
    BiaxialEngine(const BiaxialModel& m, const Options& o, BiaxialRecorder& rec, BiaxialState& st)
        : m_(m), o_(o), rec_(rec), st_(st) {
        rhs_.mu_k = m.mu_k;
        tau_s_ = slaved_tau_s(o.rel_tol);
    }

    // Advances from t towards tb (the end of segment seg); returns the time reached (tb or an
    // event).
    double advance(const BiaxialSegment& seg, double t, double tb) {
        seg_ = seg;
        tb_ = tb;
        rhs_.seg = &seg_;
        const double te = st_.mode == Mode::rest    ? advance_rest(t)
                          : st_.mode == Mode::slide ? advance_slide(t)
                                                    : advance_flight(t);
        stalled_ = te > t ? 0 : stalled_ + 1;

        if (stalled_ > max_stalled_events)
            throw NumericalError(fmt::format(
                "biaxial event-driven integrator: events accumulate at t = {} s", t));
        return te;
    }

private:
    // A start exactly at a threshold is classified a little after it (strict inequalities).
    double probe_time(double t) const { return detail::probe_time(t, tb_); }

    void set_mode(Mode next) {
        rec_.transition(st_.mode, next);
        fsal_ = false;
        if (next == Mode::flight && st_.mode != Mode::flight) {
            st_.Y = st_.Yd = 0.0;
            armed_ = false;
        }
        if (next == Mode::rest) st_.v = {0.0, 0.0};
        rhs_.slaved = false;
        st_.mode = next;
    }

    // From rest (v = 0) at t: stick, restart along -a_g, or leave the base.
    void start_from_rest(double t) {
        const double tp = probe_time(t);
        const Vec2 a = seg_.a(tp);
        const Mode next = biaxial_from_rest(m_, a, seg_.G(tp));
        if (next == Mode::slide) {
            const double s = norm(a);
            d_start_ = {-a[0] / s, -a[1] / s};
            redirected_ = false;
        }
        set_mode(next);
    }

    // Rest holds while |a|^2 - (mu_s G)^2 <= 0 and G >= 0; both are polynomials on the segment
    // (quadratic, linear), so the first failure is a root found in closed form.
    double advance_rest(double t) {
        const Vec2 a = seg_.a(t), a1 = seg_.a1;
        const double G = seg_.G(t), G1 = seg_.G1, mu2 = m_.mu_s * m_.mu_s;
        const double c0 = dot(a, a) - mu2 * G * G;
        const double c1 = 2.0 * (dot(a, a1) - mu2 * G * G1);
        const double c2 = dot(a1, a1) - mu2 * G1 * G1;
        const double span = tb_ - t;
        auto q = [&](double tau) { return c0 + tau * (c1 + tau * c2); };
        double t_ev = std::numeric_limits<double>::infinity();
        if (c0 > 0.0 || G < 0.0) t_ev = 0.0;
        if (G1 < 0.0 && -G / G1 <= span) t_ev = std::min(t_ev, std::max(0.0, -G / G1));
        // Roots of q in (0, span]; q > 0 just after one is a failure of the friction bound.
        double roots[2] = {-1.0, -1.0};
        if (c2 != 0.0) {
            const double disc = c1 * c1 - 4.0 * c2 * c0;
            if (disc >= 0.0) {
                const double qq = -0.5 * (c1 + std::copysign(std::sqrt(disc), c1));
                roots[0] = qq / c2;
                roots[1] = qq != 0.0 ? c0 / qq : -1.0;
            }
        } else if (c1 != 0.0) {
            roots[0] = -c0 / c1;
        }
        std::sort(std::begin(roots), std::end(roots));
        for (int i = 0; i < 2; ++i) {
            const double r = roots[i];
            if (!(r > 0.0 && r <= span)) continue;
            const double next = (i == 0 && roots[1] > r && roots[1] <= span) ? roots[1] : span;
            if (q(0.5 * (r + next)) > 0.0 || (next == r && q(r + probe_delay_s) > 0.0)) {
                t_ev = std::min(t_ev, r);
                break;
            }
        }
        if (!(t_ev <= span)) {
            rec_.time_in(Mode::rest, span);
            return tb_;
        }
        const double te = t + t_ev;
        rec_.time_in(Mode::rest, t_ev);
        start_from_rest(te);
        if (st_.mode == Mode::rest) return probe_time(te);  // touched the bound only
        return te;
    }

    // Dormand-Prince steps to the segment's end, lift-off (G = 0) or a stop.
    double advance_slide(double t) {
        const double G = seg_.G(t);
        if (G < 0.0) {
            set_mode(Mode::flight);
            return t;
        }
        double t_end = tb_;
        const bool lifts = seg_.G1 < 0.0 && t - G / seg_.G1 < tb_;
        if (lifts) t_end = t - G / seg_.G1;
        while (t < t_end) {
            const double speed = norm(st_.v);
            if (speed > 0.0 && speed < v_slaved_mps && !(norm(seg_.a(t)) > m_.mu_k * seg_.G(t))) {
                // A slow slip the friction holds: it stops here (see v_slaved_mps).
                st_.v = {0.0, 0.0};
                start_from_rest(t);
                return t;
            }
            if (slide_step(t, t_end, speed) == SlideStep::stopped) return t;
        }
        if (lifts) set_mode(Mode::flight);
        return t_end;
    }

    enum class SlideStep { retried, taken, stopped };

    // One Dormand-Prince step of the slide from t towards t_end (speed: |v| at t): rejected by
    // the error control, a turn or a redirected restart (retried), or accepted up to t_end or to
    // a stop (stopped), t then the time reached.
    SlideStep slide_step(double& t, double t_end, double speed) {
        set_slaved(t);
        const double speed_now = norm(st_.v);
        rhs_.d = speed_now > 0.0 ? Vec2{st_.v[0] / speed_now, st_.v[1] / speed_now} : d_start_;
        const State x0 = {st_.u[0], st_.u[1], st_.v[0], st_.v[1]};
        if (!fsal_) rhs_(x0, k1_, t);
        const double h =
            step_.propose(t, t_end, o_.max_contact_step_s, "biaxial event-driven integrator");
        const double err = dp_.step(rhs_, t, x0, k1_, h, o_.rel_tol, o_.abs_tol);
        if (!(err <= 1.0)) {
            rec_.rejected();
            fsal_ = true;
            step_.reject(Stepper::factor(err));
            return SlideStep::retried;
        }
        step_.accept(Stepper::factor(err));
        const double t0 = t, t1 = step_.step_end(t0, t_end);
        const State x1 = dp_.x1();
        auto dense = [&](double te) { return dp_.dense((te - t0) / h); };
        const double t_stop = stop_in_step(dense, x0, x1, t0, t1);
        if (t_stop < 0.0) {  // a turn, not a stop: retry up to half the way to it
            rec_.rejected();
            fsal_ = true;
            step_.retry_with(0.5 * (-t_stop - t0));
            return SlideStep::retried;
        }
        if (t_stop == t0 && speed == 0.0 && !redirected_ && norm(vel(x1)) > 0.0) {
            // A restart whose load turns within the step (a frictionless base under a load
            // passing through zero): it leaves along the slip it gains, not along -a_g.
            redirected_ = true;
            rec_.rejected();
            d_start_ = {x1[2] / norm(vel(x1)), x1[3] / norm(vel(x1))};
            fsal_ = false;
            return SlideStep::retried;
        }
        const double te = t_stop < t1 ? t_stop : t1;
        const State xe = t_stop < t1 ? dense(te) : x1;
        rec_.step();
        rec_.time_in(Mode::slide, te - t0);
        observe_peaks(dense, x0, xe, t0, te);
        st_.u = pos(xe);
        st_.v = vel(xe);
        t = te;
        if (t_stop < t1) {
            fsal_ = false;
            st_.v = {0.0, 0.0};
            start_from_rest(te);
            return SlideStep::stopped;
        }
        k1_ = dp_.k7();  // f(x1, t1) with x1 . d > 0: the next step's first stage
        fsal_ = true;
        return SlideStep::taken;
    }

    // Chooses the slaved or the full equation for the step starting at t (takes_slaved) and
    // carries the slip across a change: onto -a_g entering, the lagging slip leaving.
    void set_slaved(double t) {
        const bool slaved = takes_slaved(st_.v, seg_.a(t), m_.mu_k, tau_s_);
        if (slaved == rhs_.slaved) return;
        fsal_ = false;
        rhs_.slaved = slaved;
        const SlavedLoad L = slaved_load(seg_.a(t), seg_.a1);
        if (slaved) {
            const double speed = norm(st_.v);
            st_.v = {speed * L.e[0], speed * L.e[1]};
            return;
        }
        const Vec2 lag = slaved_lag(dot(st_.v, L.e), L);
        st_.v = {st_.v[0] - lag[0], st_.v[1] - lag[1]};
    }

    // The stop inside the accepted step [t, t1]: its time, or t1 + 1 if none, or -(root time)
    // for a root of v . d that is a turn (|v| not nil there).
    template <class Dense>
    double stop_in_step(const Dense& dense, const State& x0, const State& x1, double t,
                        double t1) const {
        const Vec2 d = rhs_.d;
        const double f1 = dot(vel(x1), d);
        if (f1 > 0.0) return t1 + 1.0;
        auto f = [&](double te) { return dot(vel(dense(te)), d); };
        double ta = t, fa = dot(vel(x0), d);
        if (!(fa > 0.0)) {
            // A restart from v = 0: look for the excursion along d inside the step.
            const RiseStart rise = rise_scan(f, t, t1, BelowZero::scan_on);
            if (!(rise.f > 0.0)) return t;  // pushed against d at once: a stop now
            ta = rise.t_s;
            fa = rise.f;
        }
        const double ts = toms748_root(f, ta, t1, fa, f1);
        const double vmax = std::max(norm(vel(x0)), norm(vel(x1)));
        const double tol = 10.0 * (o_.abs_tol + o_.rel_tol * vmax);
        if (norm(vel(dense(ts))) <= tol || ts - t <= 1e-12) return ts;
        return -ts;
    }

    // Peaks of |u|, |u_x|, |u_y| inside [t, te]: where u . v, u_x v_x or u_y v_y (half the rate
    // of |u|^2, u_x^2, u_y^2) passes from + to -.
    template <class Dense>
    void observe_peaks(const Dense& dense, const State& x0, const State& xe, double t,
                       double te) {
        auto rate = [](const State& x, std::size_t which) {
            return which == 0 ? x[0] * x[2] + x[1] * x[3] : x[which - 1] * x[which + 1];
        };
        for (std::size_t which = 0; which < 3; ++which) {
            const double f0 = rate(x0, which), f1 = rate(xe, which);
            if (!(f0 > 0.0 && f1 <= 0.0)) continue;
            auto f = [&](double tt) { return rate(dense(tt), which); };
            rec_.observe(pos(dense(toms748_root(f, t, te, f0, f1))));
        }
        rec_.observe(pos(xe));
    }

    // Ballistic translation: u'' = -a_g, Y'' = -G, both cubic on the segment.
    BiaxialState flight_at(const BiaxialState& s0, double t0, double tau) const {
        const Vec2 a = seg_.a(t0), a1 = seg_.a1;
        const double G = seg_.G(t0), G1 = seg_.G1;
        const double t2 = tau * tau, t3 = t2 * tau;
        BiaxialState s = s0;
        for (std::size_t i = 0; i < 2; ++i) {
            s.u[i] += s0.v[i] * tau - a[i] * t2 / 2.0 - a1[i] * t3 / 6.0;
            s.v[i] += -a[i] * tau - a1[i] * t2 / 2.0;
        }
        s.Y += s0.Yd * tau - G * t2 / 2.0 - G1 * t3 / 6.0;
        s.Yd += -G * tau - G1 * t2 / 2.0;
        return s;
    }

    double advance_flight(double t) {
        rec_.step();
        const BiaxialState s0 = st_;
        const double span = tb_ - t;
        auto height = [&](double tau) { return flight_at(s0, t, tau).Y; };
        double hprev = s0.Y, tau_land = -1.0;
        if (hprev > 0.0) armed_ = true;
        scan_flight(span, flight_probes, [&](double prev, double tau) {
            const double hj = height(tau);
            rec_.observe(flight_at(s0, t, tau).u);
            if (armed_ && hj <= 0.0) {
                tau_land = hprev > 0.0 ? toms748_root(height, prev, tau, hprev, hj) : prev;
                return true;
            }
            if (hj > 0.0) armed_ = true;
            hprev = hj;
            return false;
        });
        if (tau_land < 0.0) {
            st_ = flight_at(s0, t, span);
            rec_.time_in(Mode::flight, span);
            rec_.observe(st_.u);
            return tb_;
        }
        const double te = t + tau_land;
        st_ = flight_at(s0, t, tau_land);
        rec_.time_in(Mode::flight, tau_land);
        rec_.observe(st_.u);
        // Flat landing (no rotation in this model): a Coulomb impulse against the slip.
        st_.v = biaxial_landing_velocity(m_, st_.v, st_.Yd);
        st_.Y = st_.Yd = 0.0;
        armed_ = false;
        const double speed = norm(st_.v);
        if (speed > 0.0) {
            set_mode(Mode::slide);
        } else {
            start_from_rest(te);
        }
        return te;
    }

    const BiaxialModel& m_;
    const Options& o_;
    BiaxialRecorder& rec_;
    BiaxialState& st_;
    Stepper dp_;
    State k1_{};
    bool fsal_ = false;  // k1_ holds f at the current slide state
    SlideRhs rhs_;
    BiaxialSegment seg_;
    double tb_ = 0.0;
    AdaptiveStep step_;
    double tau_s_ = 0.0;      // slaved_tau_s of the options' tolerance
    Vec2 d_start_{1.0, 0.0};  // slip direction of a start from v = 0
    bool redirected_ = false; // d_start_ was taken from the first step's slip
    bool armed_ = false;      // in flight, the block has left the base
    std::size_t stalled_ = 0;
};

// The biaxial engine as run_segments drives it: one segment at a time, no rest runs (the rest
// test is a quadratic per segment) and no overturning (the body only slides).
class BiaxialBody {
public:
    BiaxialBody(const BiaxialBase& base, BiaxialRecorder& rec, BiaxialState& st,
                BiaxialEngine& engine)
        : base_(base), rec_(rec), st_(st), engine_(engine) {}

    double t_k(std::size_t k) const { return base_.t_k(k); }
    RestRun rest_run(std::size_t k, std::size_t) const { return {k, false}; }
    bool overturned() const { return false; }
    void sample(std::size_t, double tb) { rec_.sample(tb, st_); }
    bool ends_at(double tb) const { return st_.mode == Mode::rest && tb >= base_.quiet_from_s(); }
    double advance(std::size_t& k, double t, double tb) {
        if (k != k_seg_) seg_ = base_.segment(k_seg_ = k);
        return engine_.advance(seg_, t, tb);
    }

private:
    const BiaxialBase& base_;
    BiaxialRecorder& rec_;
    BiaxialState& st_;
    BiaxialEngine& engine_;
    std::size_t k_seg_ = std::numeric_limits<std::size_t>::max();
    BiaxialSegment seg_;
};

}  // namespace

BiaxialResult run_biaxial_event(const BiaxialModel& m, const BiaxialBase& base,
                                const Options& o) {
    BiaxialRecorder rec(o, 0.0);
    BiaxialState st;
    rec.sample(0.0, st);
    BiaxialEngine engine(m, o, rec, st);
    BiaxialBody body(base, rec, st, engine);
    return rec.finish(st, run_segments(body, base.segments(o.tail_s)).end_s, "event");
}

}  // namespace freestand::dynamics::detail
