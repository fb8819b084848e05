#pragma once
/// Internal: state, excitation access and bookkeeping shared by the two integrators.
#include <cmath>

#include "core/contract.hpp"
#include "core/units.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "dynamics/engine.hpp"
#include "dynamics/mechanics.hpp"

namespace freestand::dynamics::detail {

/// Base acceleration on one input segment, linear in t - tk: ax = ax0 + ax1 (t - tk), G likewise.
struct Segment {
    double tk = 0, ax0 = 0, ax1 = 0, G0 = 0, G1 = 0;
    Base at(double t) const { return {ax0 + ax1 * (t - tk), G0 + G1 * (t - tk)}; }
};

/// Piecewise-linear base acceleration; sample i at i dt, zero from sample n on (the base is at
/// rest after the record).
class BaseMotion {
public:
    BaseMotion(const Excitation& e, double g_mps2);
    double dt() const { return dt_; }
    double t_k(std::size_t k) const { return dt_ * static_cast<double>(k); }
    /// Base acceleration at sample i.
    Base sample(std::size_t i) const { return {h(i), g_ + v(i)}; }
    /// Base acceleration at time t inside segment k = [t_k, t_k+1] (linear interpolation).
    Base at(std::size_t k, double t) const {
        double ax0, ax1, G0, G1;
        segment(k, ax0, ax1, G0, G1);
        const double tau = t - t_k(k);
        return {ax0 + ax1 * tau, G0 + G1 * tau};
    }
    /// Segment containing time t >= 0 (the earlier one at a sample time, to round-off).
    std::size_t segment_of(double t) const { return static_cast<std::size_t>(t * inv_dt_); }
    /// Value and slope on segment k: ax = ax0 + ax1 (t - t_k), G likewise.
    void segment(std::size_t k, double& ax0, double& ax1, double& G0, double& G1) const {
        ax0 = h(k);
        ax1 = (h(k + 1) - ax0) * inv_dt_;
        G0 = g_ + v(k);
        G1 = (v(k + 1) - v(k)) * inv_dt_;
    }
    /// Segment k with its start time.
    Segment linear_segment(std::size_t k) const {
        Segment s;
        segment(k, s.ax0, s.ax1, s.G0, s.G1);
        s.tk = t_k(k);
        return s;
    }
    /// First time from which the base is at rest for good, s.
    double quiet_from_s() const { return quiet_from_; }
    /// Time after which the simulation may stop once the block is at rest, s.
    double min_end_s() const { return duration_ > quiet_from_ ? duration_ : quiet_from_; }
    /// First sample index in [i0, i1) at which a block at rest no longer satisfies the rest
    /// inequalities |xg''| <= c G towards each edge and G >= 0 (rest_holds), or i1 if none;
    /// peak_ax is raised to the largest |xg''| of the samples before it. The hot loop of long
    /// records: raw samples, no interpolation.
    std::size_t rest_until(std::size_t i0, std::size_t i1, const Geometry& g,
                           double& peak_ax) const;
    /// Number of segments to cover the record and the tail.
    std::size_t segments(double tail_s) const;
    double pga_mps2() const { return pga_; }

private:
    double h(std::size_t i) const { return i < x_.size() ? x_[i] : 0.0; }
    double v(std::size_t i) const { return i < y_.size() ? y_[i] : 0.0; }
    double dt_ = 0.0, inv_dt_ = 0.0, g_ = 0.0, quiet_from_ = 0.0, duration_ = 0.0, pga_ = 0.0;
    const std::vector<double>& x_;
    const std::vector<double>& y_;
};

/// Block state in every mode. Contact modes use (u, v, theta, omega) on edge s (slip direction
/// sigma); flight uses fl.
struct BlockState {
    Mode mode = Mode::rest;
    int s = 1, sigma = 1;
    double u = 0, v = 0, th = 0, om = 0;
    Flight fl;
};

/// Contact accelerations and forces of the state in its mode.
Accel accel_of(const Geometry& g, const BlockState& st, Base base);

/// A contact state's accelerations already evaluated by the integrator, with sn = sin(alpha_s -
/// theta) and c = cos(alpha_s - theta) (spares the recorder the trigonometry).
struct Known {
    Accel a;
    double sn = 0.0, c = 1.0;
};

/// Absolute horizontal acceleration of the larger top corner of a rock / slide-rock state. With
/// sn, c of alpha - theta known, phi = -s theta follows by the angle-difference formulas.
inline double contact_top_accel(const Geometry& g, const BlockState& st, Base base, const Known& k) {
    const double ds = static_cast<double>(st.s);
    const auto i = static_cast<std::size_t>(Geometry::index(st.s));
    const double sin_th = g.sin_alpha[i] * k.c - g.cos_alpha[i] * k.sn;
    const double cos_th = g.cos_alpha[i] * k.c + g.sin_alpha[i] * k.sn;
    const double xdd_cg = k.a.u_dd + ds * g.R[i] * (k.c * k.a.th_dd + k.sn * st.om * st.om);
    return top_corner_accel_cs(g, base.ax, xdd_cg, cos_th, -ds * sin_th, -ds * st.om,
                               -ds * k.a.th_dd);
}

/// Summary bookkeeping and the output series.
class Recorder {
public:
    Recorder(const Geometry& g, const Options& o, double pga_mps2);
    Recorder(const Recorder&) = delete;  // the tallies refer to its own summary
    Recorder& operator=(const Recorder&) = delete;
    /// Tracks peak slip and rotation of the state.
    void observe(const BlockState& st) {
        // Contracts of every integrator's state at the points it reports.
        FREESTAND_EXPECT(std::isfinite(st.u) && std::isfinite(st.v) && std::isfinite(st.th) &&
                             std::isfinite(st.om),
                         "integrator state is finite");
        FREESTAND_EXPECT(st.s == 1 || st.s == -1, "active edge is +1 or -1");
        FREESTAND_EXPECT(st.mode == Mode::flight || st.th >= -theta_round_off_rad,
                         "uplift angle is not negative in contact");
        FREESTAND_EXPECT(st.mode != Mode::rest || (st.v == 0.0 && st.th == 0.0 && st.om == 0.0),
                         "a block at rest does not move");
        if (st.mode == Mode::flight) {
            summary_.slide_max_m = std::max(summary_.slide_max_m, std::abs(st.fl.X));
            // The tilt in flight is a rotation like any other: phi < 0 leans over the right
            // edge (Sample::rotation_rad = -phi).
            rotation_peak(std::abs(st.fl.phi), st.fl.phi < 0.0 ? 1 : -1);
            return;
        }
        summary_.slide_max_m = std::max(summary_.slide_max_m, std::abs(st.u));
        if (st.th <= 0.0) return;
        rotation_peak(st.th, st.s);
    }
    /// Applies the overturning rule (overturn.hpp) to a rock / slide-rock state at t_s.
    void check_overturn(const BlockState& st, double t_s, bool input_ended);
    /// A mode change at a transition (counts only changes of Mode).
    void transition(Mode from, Mode to) { tally_.transition(from, to); }
    void time_in(Mode m, double dt_s) { tally_.time_in(m, dt_s); }
    void impact(double t_s, double omega_before, double omega_after, bool settled) {
        log_.impact(t_s, omega_before, omega_after, settled);
    }
    void settlement() { log_.settlement(); }
    void step(std::size_t n = 1) { tally_.step(n); }
    void overturn(double t_s, OverturnCriterion c) { log_.overturn(t_s, c); }
    bool overturned() const { return log_.overturned(); }
    /// Output sample at time t (also tracks the peak top acceleration); `known`, if given, holds
    /// the contact state's accelerations and trigonometry already evaluated by the integrator.
    void sample(double t_s, const BlockState& st, Base base, const Known* known = nullptr);
    /// The same for a flat sliding state (inline: once per segment of a sliding record). Its
    /// absolute acceleration is xg'' + u'' = -sigma mu_k G.
    void sample_slide(double t_s, const BlockState& st, Base base) {
        const Accel a = slide_accel(g_, st.sigma, base);
        top_peak_ = std::max(top_peak_, std::abs(base.ax + a.u_dd));
        if (record_series_) push(t_s, st, a, base.ax + a.u_dd);
    }
    /// The same for a rock / slide-rock state with its accelerations known (inline: once per
    /// step of a rocking record).
    void sample_contact(double t_s, const BlockState& st, Base base, const Known& k) {
        const double top = contact_top_accel(g_, st, base, k);
        top_peak_ = std::max(top_peak_, std::abs(top));
        if (record_series_) push(t_s, st, k.a, top);
    }
    /// Samples i0 <= i < i1 of a block at rest (the hot path of long records); peak_ax_mps2 is
    /// the largest |xg''| among them.
    void rest_samples(const BaseMotion& bm, std::size_t i0, std::size_t i1, const BlockState& st,
                      double peak_ax_mps2);
    SimulationResult finish(const BlockState& st, double end_time_s, const char* integrator);

private:
    void rotation_peak(double theta_rad, int s) {
        log_.rotation_peak(theta_rad, g_.alpha[static_cast<std::size_t>(Geometry::index(s))]);
    }
    void push(double t_s, const BlockState& st, const Accel& a, double top);
    const Geometry& g_;
    double g_mps2_ = units::g_mps2;
    double top_peak_ = 0.0;  ///< peak |top acceleration|, m/s^2
    bool record_series_ = true;
    Summary summary_;
    std::vector<Sample> series_;
    std::vector<ImpactEvent> impacts_;
    ModeTally<Summary> tally_{summary_};
    ContactLog log_{summary_, impacts_};
};

/// Enters the mode k starts (a transition on rec): a body leaving contact takes its flight
/// state, one coming to rest stops slipping.
inline void enter_mode(const Geometry& g, Recorder& rec, BlockState& st, const Start& k) {
    rec.transition(st.mode, k.mode);
    if (k.mode == Mode::flight && st.mode != Mode::flight)
        st.fl = to_flight(g, st.s, st.u, st.v, st.th, st.om);
    st.mode = k.mode;
    st.s = k.s;
    st.sigma = k.sigma;
    if (k.mode == Mode::rest) st.v = 0.0;
}

/// Initial mode from Options (initial rotation / slide velocity) or from rest.
BlockState initial_state(const Geometry& g, const Options& o, Base base0, Base probe);

/// The initial state (initial_state) entered, observed and sampled at t = 0 on rec.
BlockState start_block(const Geometry& g, const Options& o, Recorder& rec, Base base0,
                       Base probe);

/// The result of a run that ended as run says: a run that reached its input's end applies the
/// overturning rule to the state it ends in.
SimulationResult finish_block(Recorder& rec, const BlockState& st, const BaseMotion& bm,
                              RunEnd run, const char* integrator);

SimulationResult run_event_driven(const Geometry& g, const BaseMotion& base, const Options& o);
SimulationResult run_central_difference(const Geometry& g, const BaseMotion& base,
                                        const Options& o);

}  // namespace freestand::dynamics::detail
