#include <algorithm>
#include <cmath>

#include "dynamics/integrators.hpp"
#include "core/steps.hpp"
#include "dynamics/overturn.hpp"

namespace freestand::dynamics::detail {

BaseMotion::BaseMotion(const Excitation& e, double g_mps2)
    : dt_(e.dt_s), inv_dt_(1.0 / e.dt_s), g_(g_mps2), x_(e.horizontal_mps2), y_(e.vertical_mps2) {
    std::size_t last = x_.size();  // one past the last non-zero sample
    while (last > 0 && x_[last - 1] == 0.0) --last;
    std::size_t last_v = y_.size();
    while (last_v > 0 && y_[last_v - 1] == 0.0) --last_v;
    last = std::max(last, last_v);
    // A local accumulator: a member could alias the samples, forcing a store per sample.
    double pga = 0.0;
    for (double a : x_) pga = std::max(pga, std::abs(a));
    pga_ = pga;
    quiet_from_ = dt_ * static_cast<double>(last);
    duration_ = e.duration_s();
}

std::size_t BaseMotion::rest_until(std::size_t i0, std::size_t i1, const Geometry& g,
                                   double& peak_ax) const {
    const std::size_t n = std::min(i1, x_.size());
    const double* x = x_.data();
    double peak = peak_ax;
    std::size_t i = i0;
    if (!y_.empty()) {
        const double* y = y_.data();
        for (; i < n; ++i) {
            if (!rest_holds(g, {x[i], g_ + y[i]})) break;
            peak = std::max(peak, std::abs(x[i]));
        }
    } else {
        // G = g on every sample: rest_holds's limits are constants.
        const double hi = g.c_rest[0] * g_, lo = -(g.c_rest[1] * g_);
        for (; i < n; ++i) {
            const double ax = x[i];
            if (!(ax <= hi && ax >= lo)) break;
            peak = std::max(peak, std::abs(ax));
        }
    }
    peak_ax = peak;
    // Past the record the base is at rest (xg'' = 0, G = g > 0): rest holds.
    return i < n ? i : std::max(i0, i1);
}

std::size_t BaseMotion::segments(double tail_s) const {
    const double end = std::max(duration_, quiet_from_) + std::max(0.0, tail_s);
    return static_cast<std::size_t>(core::steps_covering(end / dt_));
}

Accel accel_of(const Geometry& g, const BlockState& st, Base base) {
    switch (st.mode) {
        case Mode::rest: {
            Accel a;
            a.N = g.M * base.G;
            a.F = g.M * base.ax;
            return a;
        }
        case Mode::slide: return slide_accel(g, st.sigma, base);
        case Mode::rock: return rock_accel(g, st.s, st.th, st.om, base);
        case Mode::slide_rock: return slide_rock_accel(g, st.s, st.sigma, st.th, st.om, base);
        case Mode::flight: {
            Accel a;
            a.u_dd = -base.ax;
            return a;
        }
    }
    return {};
}

Recorder::Recorder(const Geometry& g, const Options& o, double pga_mps2)
    : g_(g), g_mps2_(o.g_mps2), record_series_(o.record_series) {
    summary_.pga_g = pga_mps2 / o.g_mps2;
}

void Recorder::check_overturn(const BlockState& st, double t_s, bool input_ended) {
    if (st.mode != Mode::rock && st.mode != Mode::slide_rock) return;
    const auto i = static_cast<std::size_t>(Geometry::index(st.s));
    if (!overturn_possible(st.th, st.om, g_.alpha[i], input_ended)) return;
    Tilt tilt;
    tilt.theta_rad = st.th;
    tilt.omega_radps = st.om;
    tilt.alpha_rad = g_.alpha[i];
    tilt.cg_beyond_pivot_m = g_.R[i] * std::sin(st.th - g_.alpha[i]);
    if (st.mode == Mode::slide_rock) {
        // A slipping pivot: friction acts on the base, its moment about the CG can turn theta'
        // back, so the energy decides. The CG relative to the contact point is
        // (-s R sin(alpha - theta), R cos(alpha - theta)) (docs/methods.md s.3).
        const double ph = g_.alpha[i] - st.th, ds = static_cast<double>(st.s);
        const double vx = st.v + ds * g_.R[i] * std::cos(ph) * st.om;
        const double vy = g_.R[i] * std::sin(ph) * st.om;
        tilt.energy_J = 0.5 * g_.M * (vx * vx + vy * vy) + 0.5 * g_.Ic * st.om * st.om +
                        g_.M * g_mps2_ * g_.R[i] * std::cos(ph);
        tilt.ridge_energy_J = g_.M * g_mps2_ * g_.R[i];
    }
    const OverturnCriterion c = overturn_criterion(tilt, input_ended);
    if (c != OverturnCriterion::none) overturn(t_s, c);
}

void Recorder::sample(double t_s, const BlockState& st, Base base, const Known* known) {
    if (st.mode == Mode::rest) {  // carried by the base: the hot path of long records
        top_peak_ = std::max(top_peak_, std::abs(base.ax));
        if (!record_series_) return;
        Sample smp;
        smp.time_s = t_s;
        smp.slide_m = st.u;
        smp.normal_force_N = g_.M * base.G;
        smp.friction_force_N = g_.M * base.ax;
        smp.top_accel_mps2 = base.ax;
        series_.push_back(smp);
        return;
    }
    const Accel a = known != nullptr ? known->a : accel_of(g_, st, base);
    double top = base.ax;
    switch (st.mode) {
        case Mode::rest: break;
        case Mode::slide: top = base.ax + a.u_dd; break;
        case Mode::rock:
        case Mode::slide_rock: {
            if (known != nullptr) {
                sample_contact(t_s, st, base, *known);
                return;
            }
            const auto i = static_cast<std::size_t>(Geometry::index(st.s));
            const double ph = g_.alpha[i] - st.th;
            top = contact_top_accel(g_, st, base, {a, std::sin(ph), std::cos(ph)});
            break;
        }
        case Mode::flight:
            top = top_corner_accel(g_, base.ax, -base.ax, st.fl.phi, st.fl.phid, 0.0);
            break;
    }
    top_peak_ = std::max(top_peak_, std::abs(top));
    if (record_series_) push(t_s, st, a, top);
}

void Recorder::push(double t_s, const BlockState& st, const Accel& a, double top) {
    Sample smp;
    smp.time_s = t_s;
    smp.mode = st.mode;
    const double ds = static_cast<double>(st.s);
    if (st.mode == Mode::flight) {
        smp.slide_m = st.fl.X;
        smp.slide_velocity_mps = st.fl.Xd;
        smp.rotation_rad = -st.fl.phi;
        smp.angular_velocity_radps = -st.fl.phid;
    } else {
        smp.slide_m = st.u;
        smp.slide_velocity_mps = st.v;
        smp.rotation_rad = ds * st.th;
        smp.angular_velocity_radps = ds * st.om;
    }
    smp.normal_force_N = a.N;
    smp.friction_force_N = a.F;
    smp.top_accel_mps2 = top;
    series_.push_back(smp);
}

void Recorder::rest_samples(const BaseMotion& bm, std::size_t i0, std::size_t i1,
                            const BlockState& st, double peak_ax_mps2) {
    top_peak_ = std::max(top_peak_, peak_ax_mps2);
    if (!record_series_) return;
    for (std::size_t i = i0; i < i1; ++i) sample(bm.t_k(i), st, bm.sample(i));
}

SimulationResult Recorder::finish(const BlockState& st, double end_time_s, const char* integrator) {
    summary_.integrator = integrator;
    summary_.top_accel_max_g = top_peak_ / g_mps2_;
    summary_.end_time_s = end_time_s;
    summary_.slide_residual_m = std::abs(st.mode == Mode::flight ? st.fl.X : st.u);
    summary_.amplification = summary_.pga_g > 0.0 ? summary_.top_accel_max_g / summary_.pga_g : 0.0;
    SimulationResult r;
    r.summary = summary_;
    r.series = std::move(series_);
    r.impact_log = std::move(impacts_);
    return r;
}

BlockState initial_state(const Geometry& g, const Options& o, Base base0, Base probe) {
    BlockState st;
    const double th0 = o.initial_rotation_rad, v0 = o.initial_slide_velocity_mps;
    if (th0 != 0.0) {
        st.s = th0 > 0.0 ? 1 : -1;
        st.th = std::abs(th0);
        st.v = v0;
        const Start k = classify_on_edge(g, st.s, st.th, 0.0, v0, base0);
        st.mode = k.mode;
        st.sigma = k.sigma;
        if (k.mode == Mode::flight) st.fl = to_flight(g, st.s, 0.0, v0, st.th, 0.0);
        return st;
    }
    if (v0 != 0.0) {
        const Start k = classify_sliding(g, v0);
        st.v = v0;
        st.mode = k.mode;
        st.s = k.s;
        st.sigma = k.sigma;
        return st;
    }
    const Start k = classify_from_rest(g, probe);
    st.mode = k.mode;
    st.s = k.s;
    st.sigma = k.sigma;
    return st;
}

BlockState start_block(const Geometry& g, const Options& o, Recorder& rec, Base base0,
                       Base probe) {
    BlockState st = initial_state(g, o, base0, probe);
    rec.transition(Mode::rest, st.mode);
    if (st.mode == Mode::flight) st.fl = to_flight(g, st.s, st.u, st.v, st.th, st.om);
    rec.observe(st);
    rec.sample(0.0, st, base0);
    return st;
}

SimulationResult finish_block(Recorder& rec, const BlockState& st, const BaseMotion& bm,
                              RunEnd run, const char* integrator) {
    // The run ends with the body as it is: the rule applies to that state too.
    if (!run.stopped) rec.check_overturn(st, run.end_s, run.end_s >= bm.quiet_from_s());
    return rec.finish(st, run.end_s, integrator);
}

}  // namespace freestand::dynamics::detail
