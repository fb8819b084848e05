// Fixed-step central-difference baseline of biaxial sliding, the planar scheme of
// central_difference.cpp in two components: v_{n+1/2} = v_{n-1/2} + dt a_n,
// u_{n+1} = u_n + dt v_{n+1/2}, friction along v_{n-1/2} (or the start direction -a_g / |a_g|
// from rest); a stop is a sign check at the step end (v turned against the direction it had),
// after which the block sticks or restarts by docs/methods.md s.10 at the step end. In one
// component it takes exactly the planar steps.
#include <cmath>

#include "dynamics/biaxial_detail.hpp"

namespace freestand::dynamics::detail {

namespace {

Vec2 unit_or(const Vec2& v, const Vec2& fallback) {
    const double s = norm(v);
    return s > 0.0 ? Vec2{v[0] / s, v[1] / s} : fallback;
}

class BiaxialCdStepper {
public:
    BiaxialCdStepper(const BiaxialModel& m, BiaxialRecorder& rec, BiaxialState& st)
        : m_(m), rec_(rec), st_(st) {}

    void step(const BiaxialSegment& seg, double t, double h) {
        const Vec2 a = seg.a(t);
        const double G = seg.G(t);
        rec_.step();
        rec_.time_in(st_.mode, h);
        if (st_.mode == Mode::rest) {
            const Mode next = biaxial_from_rest(m_, a, G);
            if (next == Mode::rest) return;
            enter(next, a);
        }
        if (st_.mode == Mode::slide && G < 0.0) enter(Mode::flight, a);
        if (st_.mode == Mode::slide) slide(seg, t, h, a, G);
        else flight(seg, t, h, a, G);
        rec_.observe(st_.u);
    }

private:
    void enter(Mode next, const Vec2& a) {
        rec_.transition(st_.mode, next);
        if (next == Mode::slide && norm(st_.v) == 0.0) d_ = unit_or({-a[0], -a[1]}, d_);
        if (next == Mode::flight && st_.mode != Mode::flight) st_.Y = st_.Yd = 0.0;
        if (next == Mode::rest) st_.v = {0.0, 0.0};
        st_.mode = next;
    }

    void slide(const BiaxialSegment& seg, double t, double h, const Vec2& a, double G) {
        const Vec2 n = unit_or(st_.v, d_);
        const Vec2 v_new = {st_.v[0] + h * (-a[0] - m_.mu_k * G * n[0]),
                            st_.v[1] + h * (-a[1] - m_.mu_k * G * n[1])};
        st_.u[0] += h * v_new[0];
        st_.u[1] += h * v_new[1];
        st_.v = v_new;
        if (dot(v_new, n) > 0.0) return;
        // Sign check: the slip velocity turned against its direction inside the step. As the
        // planar scheme, a restart in the direction the overshoot already has keeps it.
        const Vec2 a1 = seg.a(t + h);
        const Mode next = biaxial_from_rest(m_, a1, seg.G(t + h));
        if (next == Mode::slide) {
            d_ = unit_or({-a1[0], -a1[1]}, d_);
            if (!(dot(d_, v_new) > 0.0)) st_.v = {0.0, 0.0};
        } else {
            st_.v = {0.0, 0.0};
        }
        enter(next, a1);
    }

    // Ballistic: the base's acceleration alone moves the block relative to it.
    void flight(const BiaxialSegment& seg, double t, double h, const Vec2& a, double G) {
        st_.v[0] -= h * a[0];
        st_.v[1] -= h * a[1];
        st_.u[0] += h * st_.v[0];
        st_.u[1] += h * st_.v[1];
        st_.Yd -= h * G;
        st_.Y += h * st_.Yd;
        if (st_.Y > 0.0) {
            armed_ = true;
            return;
        }
        if (!armed_) return;
        armed_ = false;
        st_.v = biaxial_landing_velocity(m_, st_.v, st_.Yd);
        st_.Y = st_.Yd = 0.0;
        const Vec2 a1 = seg.a(t + h);
        if (norm(st_.v) > 0.0) {
            enter(Mode::slide, a1);
        } else {
            enter(biaxial_from_rest(m_, a1, seg.G(t + h)), a1);
        }
    }

    const BiaxialModel& m_;
    BiaxialRecorder& rec_;
    BiaxialState& st_;
    Vec2 d_{1.0, 0.0};  // slip direction while v = 0 (a start from rest)
    bool armed_ = false;
};

}  // namespace

BiaxialResult run_biaxial_cd(const BiaxialModel& m, const BiaxialBase& base, const Options& o) {
    constexpr const char* name = "cd";
    BiaxialRecorder rec(o, 0.0);
    const double h = central_difference_step_s(base.dt(), o.cd_dt_s);
    const std::size_t n_seg = base.segments(o.tail_s);
    BiaxialState st;
    rec.sample(0.0, st);
    BiaxialCdStepper stepper(m, rec, st);
    std::size_t k_seg = 0;
    BiaxialSegment seg = base.segment(0);
    const RunEnd run = run_fixed_steps(
        base.dt(), h, n_seg,
        [&](std::size_t k, double t, double dt) {
            if (k != k_seg) seg = base.segment(k_seg = k);
            stepper.step(seg, t, dt);
            return true;
        },
        [&](std::size_t, double tb) {
            rec.sample(tb, st);
            return st.mode == Mode::rest && tb >= base.quiet_from_s();
        });
    return rec.finish(st, run.end_s, name);
}

}  // namespace freestand::dynamics::detail
