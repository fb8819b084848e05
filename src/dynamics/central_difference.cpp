// Fixed-step central-difference baseline (docs/methods.md s.3: "dt = 1e-4 s and sign checks").
// Velocities live at half steps (v_{n+1/2} = v_{n-1/2} + dt a_n, x_{n+1} = x_n + dt v_{n+1/2});
// velocity-dependent terms use v_n ~ v_{n-1/2} + dt/2 a_{n-1}. Switches are detected by sign
// checks at step ends only (no event location): stick / reversal when the slip velocity changes
// sign, impact when theta changes sign (reflected with the restitution), uplift and sliding from
// rest by the section 2 inequalities at the step start.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "dynamics/engine.hpp"
#include "dynamics/integrators.hpp"

namespace freestand::dynamics::detail {

namespace {

constexpr double half_pi = std::numbers::pi / 2.0;

class CdStepper {
public:
    CdStepper(const Geometry& g, const BaseMotion& bm, const Options& o, Recorder& rec,
              BlockState& st)
        : g_(g), bm_(bm), o_(o), rec_(rec), st_(st) {}

    // One step from t to t + h on segment k; returns false once overturned.
    bool step(std::size_t k, double t, double h) {
        const Base b = bm_.at(k, t);
        rec_.step();
        rec_.time_in(st_.mode, h);
        if (st_.mode == Mode::rest) {
            if (rest_holds(g_, b)) return true;
            enter(classify_from_rest(g_, b), t);
        }
        switch (st_.mode) {
            case Mode::rest: return true;
            case Mode::slide: slide(k, t, h, b); break;
            case Mode::rock:
            case Mode::slide_rock: contact(k, t, h, b); break;
            case Mode::flight: flight(k, t, h, b); break;
        }
        rec_.observe(st_);
        return !rec_.overturned();
    }

private:
    void enter(const Start& k, double t) {
        (void)t;
        enter_mode(g_, rec_, st_, k);
        th_dd_prev_ = 0.0;
    }

    void go_flat(const Base& b, double t) {
        st_.th = st_.om = 0.0;
        enter(st_.v != 0.0 ? classify_sliding(g_, st_.v) : classify_from_rest(g_, b), t);
    }

    void slide(std::size_t k, double t, double h, const Base& b) {
        const Accel a = slide_accel(g_, st_.sigma, b);
        const double v_new = st_.v + h * a.u_dd;
        st_.u += h * v_new;
        st_.v = v_new;
        if (static_cast<double>(st_.sigma) * v_new > 0.0) return;
        // Sign check: the slip velocity reversed inside the step.
        const Base b1 = bm_.at(k, t + h);
        const Start next = classify_from_rest(g_, b1);
        st_.v = (next.mode == Mode::slide && static_cast<double>(next.sigma) * v_new > 0.0) ? v_new : 0.0;
        enter(next, t + h);
    }

    void contact(std::size_t k, double t, double h, const Base& b) {
        const double om_n = st_.om + 0.5 * h * th_dd_prev_;
        Accel a = st_.mode == Mode::rock
                      ? rock_accel(g_, st_.s, st_.th, om_n, b)
                      : slide_rock_accel(g_, st_.s, st_.sigma, st_.th, om_n, b);
        if (a.N < 0.0) {
            enter({Mode::flight, st_.s, st_.sigma}, t);
            flight(k, t, h, b);
            return;
        }
        if (st_.mode == Mode::rock && std::abs(a.F) > g_.mu_s * a.N) {
            enter({Mode::slide_rock, st_.s, a.F > 0.0 ? -1 : 1}, t);
            a = slide_rock_accel(g_, st_.s, st_.sigma, st_.th, om_n, b);
        }
        const bool slip = st_.mode == Mode::slide_rock;
        if (slip) {
            st_.v += h * a.u_dd;
            st_.u += h * st_.v;
        }
        st_.om += h * a.th_dd;
        st_.th += h * st_.om;
        th_dd_prev_ = a.th_dd;
        const double t1 = t + h;
        rec_.check_overturn(st_, t1, t1 >= bm_.quiet_from_s());
        if (rec_.overturned()) return;
        const Base b1 = bm_.at(k, t1);
        if (st_.th < 0.0) {
            impact(b1, t1);
            return;
        }
        if (slip && static_cast<double>(st_.sigma) * st_.v <= 0.0) {
            const Start next = classify_on_edge(g_, st_.s, st_.th, st_.om, 0.0, b1);
            st_.v = (next.mode == Mode::slide_rock &&
                     static_cast<double>(next.sigma) * st_.v > 0.0) ? st_.v : 0.0;
            const double th_dd = th_dd_prev_;
            enter(next, t1);
            th_dd_prev_ = th_dd;
        }
    }

    // Sign change of theta: the block struck the other edge inside the step. The overshoot is
    // reflected onto the new edge with the restitution (first order in the impact time).
    void impact(const Base& b1, double t1) {
        const int s_new = -st_.s;
        const double r = g_.r_onto[static_cast<std::size_t>(Geometry::index(s_new))];
        const double w_before = std::abs(st_.om);
        const double w_after = r * w_before;
        if (!(st_.om < 0.0) || rebound_angle(g_, s_new, w_after, b1.G) < o_.settle_rebound_rad) {
            rec_.impact(t1, w_before, 0.0, true);
            rec_.settlement();
            go_flat(b1, t1);
            return;
        }
        rec_.impact(t1, w_before, w_after, false);
        st_.s = s_new;
        st_.th = -r * st_.th;
        st_.om = w_after;
        const double v = st_.v;
        enter(classify_on_edge(g_, st_.s, st_.th, st_.om, v, b1), t1);
        st_.v = v;
    }

    void flight(std::size_t k, double t, double h, const Base& b) {
        Flight& f = st_.fl;
        f.Xd += -h * b.ax;
        f.X += h * f.Xd;
        f.Yd += -h * b.G;
        f.Y += h * f.Yd;
        f.phi += h * f.phid;
        const double t1 = t + h;
        if (std::abs(f.phi) >= half_pi) {
            rec_.overturn(t1, OverturnCriterion::angle_half_pi);
            return;
        }
        int s_low = 1;
        const double y = lowest_corner(g_, f, s_low);
        if (y > 0.0) {
            armed_ = true;
            return;
        }
        if (!armed_) return;
        armed_ = false;
        const Contact c = land(g_, f, o_.flat_landing_window_s);
        rec_.impact(t1, std::abs(f.phid), std::abs(c.om), false);
        st_.u = c.u;
        st_.v = c.v;
        st_.s = c.s;
        st_.th = c.th;
        st_.om = c.om;
        const Base b1 = bm_.at(k, t1);
        if (c.flat) {
            go_flat(b1, t1);
        } else {
            enter(classify_on_edge(g_, c.s, c.th, c.om, 0.0, b1), t1);
        }
    }

    const Geometry& g_;
    const BaseMotion& bm_;
    const Options& o_;
    Recorder& rec_;
    BlockState& st_;
    double th_dd_prev_ = 0.0;
    bool armed_ = false;
};

}  // namespace

SimulationResult run_central_difference(const Geometry& g, const BaseMotion& bm,
                                        const Options& o) {
    Recorder rec(g, o, bm.pga_mps2());
    const double h = central_difference_step_s(bm.dt(), o.cd_dt_s);
    const std::size_t n_seg = bm.segments(o.tail_s);
    const Base b0 = bm.at(0, 0.0);
    BlockState st = start_block(g, o, rec, b0, b0);
    CdStepper stepper(g, bm, o, rec, st);
    const RunEnd run = run_fixed_steps(
        bm.dt(), h, n_seg,
        [&](std::size_t k, double t, double dt) { return stepper.step(k, t, dt); },
        [&](std::size_t k, double tb) {
            rec.sample(tb, st, bm.at(k, tb));
            return st.mode == Mode::rest && tb >= bm.min_end_s();
        });
    return finish_block(rec, st, bm, run, integrator_name(Integrator::central_difference));
}

}  // namespace freestand::dynamics::detail
