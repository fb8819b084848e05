#pragma once
/// Internal: the skeleton every time-history engine of this stage is built on, and its contract.
///
/// An engine (planar event_driven.cpp / central_difference.cpp, biaxial biaxial_event.cpp /
/// biaxial_cd.cpp, flexible flexible_event.cpp / flexible_cd.cpp) supplies only
///   - its state and its equations of motion in each contact state (mechanics.hpp,
///     biaxial_detail.hpp, flexible_detail.hpp),
///   - its contact states (Mode: rest, slide, rock, slide-rock, flight) and the functions whose
///     sign change ends one (docs/methods.md s.2, s.3, s.10),
///   - its impact rule (what a contact or landing does to the rates, and the settling rule),
/// and takes from the skeleton
///   - the input: piecewise-linear base acceleration per sample segment (BaseMotion and its
///     Segment, BiaxialBase and its BiaxialSegment, integrators.hpp and biaxial_detail.hpp);
///     every step ends at a sample time, where the input's slope jumps;
///   - step control: run_fixed_steps() for the fixed-step baselines (n_sub steps per segment,
///     then the segment-end sample), AdaptiveStep for an error-controlled stepper (dopri5.hpp)
///     with its step limits (1e-14 s floor, Options::max_contact_step_s, the snap onto the
///     segment's end);
///   - event location: toms748_root / newton_root / first_quadratic_root (roots.hpp) on the
///     step's dense output, and probe_time() to classify a start exactly at a threshold;
///   - the chatter rule (ChatterGuard: a burst of events inside Options::settle_interval_s
///     settles the body, a longer one is a NumericalError);
///   - the recorder's shared bookkeeping (ModeTally: mode changes, time in each mode, steps;
///     ContactLog: impacts, settlements, overturning, rotation peaks), under which each engine's
///     recorder keeps its own series and peaks.
/// The contract an engine keeps: it advances from t towards a sample time tb and returns the time
/// reached (tb, or the time of the first event, handled before it returns); it reports every
/// step, mode change and time spent to the recorder; equal inputs give bit-identical results
/// (no wall-clock, no unordered iteration, one fixed order of the events at a tie).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <fmt/format.h>
#include <limits>
#include <vector>

#include "core/errors.hpp"
#include "core/steps.hpp"
#include "dynamics/simulate.hpp"

namespace freestand::dynamics::detail {

/// How far after t a start is classified (at most 1e-9 s, never past half the way to the
/// segment's end tb): docs/methods.md s.2 leaves rest by strict inequalities, so at a threshold
/// itself the body still holds; just after it, the sign decides.
inline double probe_time(double t_s, double tb_s) {
    return t_s + std::min(1e-9, 0.5 * (tb_s - t_s));
}

/// How long a body settled by the chatter rule stays at rest before the rest criteria are
/// evaluated again. A burst can be a loop at one instant: a rock onset whose excursion lies
/// below the impact search's resolution (the base grazing g tan(alpha)) returns to theta = 0
/// at once, settles, and starts again at the same t. In 1 us such an onset lifts the block by
/// about (A - g tan alpha) t^2 / (2 R): far below any angle that matters.
inline constexpr double settle_hold_s = 1e-6;

/// The chatter rule (Options::settle_interval_s): 64 consecutive events each within the interval
/// of the previous one settle the body; 100000 mean the integration is stuck.
class ChatterGuard {
public:
    static constexpr std::size_t burst_settle = 64;
    static constexpr std::size_t burst_fail = 100000;
    /// Notes an event at t_s; true when it completes a burst (the caller sets the body at rest).
    /// Throws NumericalError naming the integrator when events accumulate without settling.
    bool note(double t_s, double interval_s, const char* integrator) {
        burst_ = (t_s - last_event_s_ < interval_s) ? burst_ + 1 : 0;
        last_event_s_ = t_s;
        if (burst_ > burst_fail)
            throw NumericalError(fmt::format(
                "{}: events accumulate at t = {} s without settling", integrator, t_s));
        return burst_ == burst_settle;
    }

private:
    double last_event_s_ = -1.0;
    std::size_t burst_ = 0;
};

/// Step size of an error-controlled stepper (dopri5.hpp) between events: the step to try, then
/// accept or reject by the error it measured.
class AdaptiveStep {
public:
    /// The step to try from t_s towards end_s (a segment's end or an event horizon), at most
    /// max_step_s and the proposal of the last step; a step within round-off of end_s is
    /// stretched onto it. Throws NumericalError naming the integrator when the proposal fell
    /// below 1e-14 s (relative to t_s beyond 1 s).
    double propose(double t_s, double end_s, double max_step_s, const char* integrator) {
        if (h_next_s_ < 1e-14 * std::max(1.0, t_s))
            throw NumericalError(fmt::format(
                "{}: the step fell below 1e-14 s at t = {} s", integrator, t_s));
        h_s_ = std::min({h_next_s_, end_s - t_s, max_step_s});
        h_s_ = core::step_to_sample(t_s, h_s_, end_s);
        clipped_ = h_s_ < h_next_s_;
        return h_s_;
    }
    /// The step tried was rejected; factor is the stepper's step factor for its error.
    void reject(double factor) { h_next_s_ = h_s_ * std::min(1.0, factor); }
    /// The step tried was accepted; a step cut short by the segment's end keeps the longer step
    /// it was allowed.
    void accept(double factor) {
        h_next_s_ = clipped_ ? std::max(h_next_s_, h_s_ * factor) : h_s_ * factor;
    }
    /// The next step tries at most h_s (a retry short of a point found inside the step).
    void retry_with(double h_s) { h_next_s_ = h_s; }
    /// End of the step tried from t_s: exactly end_s when the step was stretched onto it.
    double step_end(double t_s, double end_s) const {
        return (h_s_ == end_s - t_s) ? end_s : t_s + h_s_;
    }

private:
    double h_next_s_ = 1e-3;
    double h_s_ = 0.0;
    bool clipped_ = false;
};

/// Where a fixed-step run stopped: at end_s, early (step or at_sample asked) or after the last
/// segment.
struct FixedRun {
    double end_s = 0.0;
    bool stopped = false;
};

/// The fixed-step skeleton (the central-difference baselines): in each of n_seg input segments
/// of dt_s, n_sub = dt_s / h_s steps step(k, t, h_s) (false: the run ends at t + h_s), then
/// at_sample(k, tb) at the segment's end tb (true: the run ends at tb).
template <class Step, class AtSample>
FixedRun run_fixed_steps(double dt_s, double h_s, std::size_t n_seg, Step&& step,
                         AtSample&& at_sample) {
    const auto n_sub = static_cast<std::size_t>(std::lround(dt_s / h_s));
    for (std::size_t k = 0; k < n_seg; ++k) {
        const double tk = dt_s * static_cast<double>(k);
        for (std::size_t j = 0; j < n_sub; ++j) {
            const double t = tk + h_s * static_cast<double>(j);
            if (!step(k, t, h_s)) return {t + h_s, true};
        }
        const double tb = dt_s * static_cast<double>(k + 1);
        if (at_sample(k, tb)) return {tb, true};
    }
    return {dt_s * static_cast<double>(n_seg), false};
}

/// The recorder's bookkeeping of modes on an engine's summary (Summary, BiaxialSummary): mode
/// changes, time in each mode, steps taken.
template <class SummaryT>
class ModeTally {
public:
    explicit ModeTally(SummaryT& summary) : s_(summary) {}
    /// A mode change at a transition (counts only changes of Mode).
    void transition(Mode from, Mode to) {
        if (from != to) ++s_.mode_changes;
    }
    void time_in(Mode m, double dt_s) { s_.time_in_mode_s[static_cast<std::size_t>(m)] += dt_s; }
    void step(std::size_t n = 1) { s_.steps += n; }

private:
    SummaryT& s_;
};

/// The recorder's bookkeeping of a body that rocks (Summary and its impact log): impacts,
/// settlements, overturning, and the peak rotation over the active edge's alpha.
class ContactLog {
public:
    ContactLog(Summary& summary, std::vector<ImpactEvent>& impacts)
        : s_(summary), impacts_(impacts) {}
    void impact(double t_s, double omega_before, double omega_after, bool settled) {
        ++s_.impacts;
        impacts_.push_back({t_s, omega_before, omega_after, settled});
    }
    void settlement() { ++s_.settlements; }
    /// Overturned at t_s by criterion c: mode 1 after an impact, 2 without.
    void overturn(double t_s, OverturnCriterion c) {
        s_.overturned = true;
        s_.overturn_time_s = t_s;
        s_.overturn_mode = s_.impacts > 0 ? 1 : 2;
        s_.overturn_criterion = c;
    }
    bool overturned() const { return s_.overturned; }
    /// A rotation theta_rad about an edge whose alpha is alpha_rad.
    void rotation_peak(double theta_rad, double alpha_rad) {
        s_.rock_max_rad = std::max(s_.rock_max_rad, theta_rad);
        s_.rock_max_over_alpha = std::max(s_.rock_max_over_alpha, theta_rad / alpha_rad);
    }

private:
    Summary& s_;
    std::vector<ImpactEvent>& impacts_;
};

}  // namespace freestand::dynamics::detail
