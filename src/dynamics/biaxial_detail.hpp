#pragma once
/// Internal: base motion, state and bookkeeping shared by the two biaxial integrators.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

#include "dynamics/biaxial.hpp"
#include "dynamics/engine.hpp"
#include "core/steps.hpp"
#include "dynamics/vec2.hpp"

namespace freestand::dynamics::detail {

/// The slip speed relative to the load, tau = |v| / |a_g| (s), below which a slide step is
/// taken slaved to the load. The slip direction turns towards F = -a_g at the rate |a_g| / |v|
/// and the friction term's stiffness is mu_k G / |v|: near every start and stop under a turning
/// load an explicit method's steps shrink with |v| (a record whose |a_g| hovered at mu_k G kept
/// them at 4e-6 s for 2 ms). Slaved, the slip follows F and lags behind it by tau omega (omega
/// F's turning rate: Tikhonov's reduction of the fast direction equation); what is left out is
/// of order (tau omega)^2. The threshold shrinks with the tolerance, so that a tight reference
/// solves the full equation: 1e-5 s at rel_tol 1e-6, 1e-8 s at 1e-12.
inline double slaved_tau_s(double rel_tol) { return 1e-2 * std::sqrt(rel_tol); }

/// Whether a slide step starting with slip v under the base acceleration a_g is taken slaved:
/// friction (mu_k > 0), a load, |v| < tau_s |a_g| and v within 0.1 rad of F = -a_g (or nil: a
/// start). A slow slip against or across the load stops or turns within a few relaxation
/// times, and a slip against it must pass through rest (the static friction check), not be
/// turned onto the load.
inline bool takes_slaved(const Vec2& v, const Vec2& a_g, double mu_k, double tau_s) {
    const double F = norm(a_g), speed = norm(v);
    if (!(mu_k > 0.0 && F > 0.0 && speed < tau_s * F)) return false;
    constexpr double cos_max = 0.995;
    return speed == 0.0 || -dot(v, a_g) > cos_max * speed * F;
}

/// The load F = -a_g of a slaved slip: its magnitude, direction e and the direction's rate
/// e' = (F' - (e . F') e) / |F| on a segment whose acceleration has slope a1 (F' = -a1).
struct SlavedLoad {
    double F = 0.0;
    Vec2 e{}, de{};
};
inline SlavedLoad slaved_load(const Vec2& a_g, const Vec2& a1) {
    SlavedLoad L;
    L.F = norm(a_g);
    L.e = {-a_g[0] / L.F, -a_g[1] / L.F};
    const double along = dot(L.e, a1);  // -(e . F')
    L.de = {(-a1[0] + along * L.e[0]) / L.F, (-a1[1] + along * L.e[1]) / L.F};
    return L;
}

/// The slaved slip's lag behind the load, s^2 / |F| e' (the quasi-steady lag angle s omega / |F|
/// times s): the slip moves along s e minus this.
inline Vec2 slaved_lag(double s, const SlavedLoad& L) {
    const double k = s * s / L.F;
    return {k * L.de[0], k * L.de[1]};
}

/// Base acceleration on one input segment, linear in tau = t - tk: a_g = a0 + a1 tau (the two
/// horizontal components), G = g + yg'' = G0 + G1 tau.
struct BiaxialSegment {
    double tk = 0.0;
    Vec2 a0{}, a1{};
    double G0 = 0.0, G1 = 0.0;
    Vec2 a(double t) const {
        const double tau = t - tk;
        return {a0[0] + a1[0] * tau, a0[1] + a1[1] * tau};
    }
    double G(double t) const { return G0 + G1 * (t - tk); }
};

/// The excitation as segments; zero from sample n on (the base is at rest after the record).
class BiaxialBase {
public:
    BiaxialBase(const BiaxialExcitation& e, double g_mps2)
        : e_(e), g_(g_mps2), dt_(e.dt_s), inv_dt_(1.0 / e.dt_s) {
        // The base ramps to rest over the segment after the last non-zero sample.
        std::size_t last = 0;
        for (std::size_t i = 0; i < e.x_mps2.size(); ++i)
            if (x(i) != 0.0 || y(i) != 0.0 || v(i) != 0.0) last = i + 1;
        quiet_from_ = std::max(e.duration_s(), t_k(last));
    }
    double dt() const { return dt_; }
    double t_k(std::size_t k) const { return dt_ * static_cast<double>(k); }
    /// Time from which the simulation may stop once at rest, s: the record's end, or the end of
    /// the ramp to rest after its last non-zero sample (as the planar BaseMotion::min_end_s).
    double quiet_from_s() const { return quiet_from_; }
    std::size_t segments(double tail_s) const {
        return e_.x_mps2.size() + static_cast<std::size_t>(core::steps_covering(tail_s * inv_dt_));
    }
    BiaxialSegment segment(std::size_t k) const {
        BiaxialSegment s;
        s.tk = t_k(k);
        s.a0 = {x(k), y(k)};
        s.a1 = {(x(k + 1) - x(k)) * inv_dt_, (y(k + 1) - y(k)) * inv_dt_};
        s.G0 = g_ + v(k);
        s.G1 = (v(k + 1) - v(k)) * inv_dt_;
        return s;
    }

private:
    double x(std::size_t i) const { return i < e_.x_mps2.size() ? e_.x_mps2[i] : 0.0; }
    double y(std::size_t i) const { return i < e_.y_mps2.size() ? e_.y_mps2[i] : 0.0; }
    double v(std::size_t i) const { return i < e_.vertical_mps2.size() ? e_.vertical_mps2[i] : 0.0; }
    const BiaxialExcitation& e_;
    double g_, dt_, inv_dt_, quiet_from_ = 0.0;
};

/// Block state: slip u and its rate v relative to the base; in flight also the gap Y above the
/// base and its rate (the block translates only: no rocking in this model).
struct BiaxialState {
    Mode mode = Mode::rest;
    Vec2 u{}, v{};
    double Y = 0.0, Yd = 0.0;
};

/// Mode a block at rest enters under base acceleration a, G (docs/methods.md s.10): it stays
/// while |a| <= mu_s G (strict inequality to leave, as s.2), leaves the base when G < 0.
inline Mode biaxial_from_rest(const BiaxialModel& m, const Vec2& a, double G) {
    if (G < 0.0) return Mode::flight;
    return norm(a) > m.mu_s * G ? Mode::slide : Mode::rest;
}

/// Velocity after a flat landing with vertical speed Yd < 0: the Coulomb impulse removes at
/// most mu_k |Yd| from the horizontal speed, along -v (as the planar flat landing, s.3).
inline Vec2 biaxial_landing_velocity(const BiaxialModel& m, const Vec2& v, double Yd) {
    const double speed = norm(v);
    const double dv = std::min(speed, m.mu_k * std::max(0.0, -Yd));
    if (speed == 0.0) return v;
    const double f = (speed - dv) / speed;
    return {v[0] * f, v[1] * f};
}

/// Summary bookkeeping and the output series.
class BiaxialRecorder {
public:
    BiaxialRecorder(const Options& o, double pga_mps2) : record_series_(o.record_series) {
        summary_.pga_g = pga_mps2 / o.g_mps2;
    }
    BiaxialRecorder(const BiaxialRecorder&) = delete;  // the tally refers to its own summary
    BiaxialRecorder& operator=(const BiaxialRecorder&) = delete;
    /// Tracks the peaks of |u|, |u_x| and |u_y| at a state of the trajectory.
    void observe(const Vec2& u) {
        summary_.slide_max_m = std::max(summary_.slide_max_m, norm(u));
        summary_.slide_max_x_m = std::max(summary_.slide_max_x_m, std::abs(u[0]));
        summary_.slide_max_y_m = std::max(summary_.slide_max_y_m, std::abs(u[1]));
    }
    void transition(Mode from, Mode to) { tally_.transition(from, to); }
    void time_in(Mode m, double dt_s) { tally_.time_in(m, dt_s); }
    void step() { tally_.step(); }
    void rejected() { ++summary_.rejected_steps; }
    void sample(double t_s, const BiaxialState& st) {
        if (record_series_) series_.push_back({t_s, st.u[0], st.u[1], st.v[0], st.v[1], st.mode});
    }
    BiaxialResult finish(const BiaxialState& st, double end_time_s, const char* integrator) {
        observe(st.u);
        summary_.slide_residual_m = norm(st.u);
        summary_.slide_residual_x_m = st.u[0];
        summary_.slide_residual_y_m = st.u[1];
        summary_.end_time_s = end_time_s;
        summary_.integrator = integrator;
        return {summary_, std::move(series_)};
    }

private:
    bool record_series_ = true;
    BiaxialSummary summary_;
    std::vector<BiaxialSample> series_;
    ModeTally<BiaxialSummary> tally_{summary_};
};

/// Throws InputError naming the excitation's field that is not valid: dt_s, sample counts,
/// accelerations (core::limits).
void require_biaxial_excitation(const BiaxialExcitation& e);

BiaxialResult run_biaxial_event(const BiaxialModel& m, const BiaxialBase& base, const Options& o);
BiaxialResult run_biaxial_cd(const BiaxialModel& m, const BiaxialBase& base, const Options& o);

}  // namespace freestand::dynamics::detail
