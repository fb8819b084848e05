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
///   - a body for the driver: how it advances within one input segment, passes segments at
///     rest, samples and tells that it has settled or overturned (SegmentBody),
/// and takes from the skeleton
///   - the drivers: run_segments() for the event-driven engines (segment by segment, event by
///     event, the rest runs, the sample at each segment's end, the early end once settled for
///     good or overturned), run_fixed_steps() for the fixed-step baselines (n_sub steps per
///     segment, then the segment-end sample); both return the RunEnd the engine finishes with;
///   - the input: piecewise-linear base acceleration per sample segment (BaseMotion and its
///     Segment, BiaxialBase and its BiaxialSegment, integrators.hpp and biaxial_detail.hpp);
///     every step ends at a sample time, where the input's slope jumps;
///   - step control: AdaptiveStep for an error-controlled stepper (dopri5.hpp) with its step
///     limits (min_step_s floor, Options::max_contact_step_s, the snap onto the segment's end);
///     SeriesStep for a stepper that sizes its own step (taylor.hpp; SeriesStep says why it is
///     not an AdaptiveStep), on the same request and floor;
///   - event location (event_search.hpp): the first of the engine's events in a step at one
///     tie order (first_event), the sign change and the dip below 0 of an event function on the
///     step's dense output (sign_change, dip_below_zero), the rise out of 0 of a function an
///     event has just set (rise_scan), the probes of a flight for its landing (scan_flight),
///     on the root finders of roots.hpp; and probe_time() to classify a start exactly at a
///     threshold;
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
#include <concepts>
#include <cstddef>
#include <fmt/format.h>
#include <limits>
#include <vector>

#include "core/errors.hpp"
#include "core/steps.hpp"
#include "dynamics/event_search.hpp"
#include "dynamics/simulate.hpp"

namespace freestand::dynamics::detail {

/// How far after a threshold a start is classified, s: docs/methods.md s.2 leaves rest by strict
/// inequalities, so at a threshold itself the body still holds; just after it, the sign decides.
inline constexpr double probe_delay_s = 1e-9;

/// Shortest step an engine takes, s (relative to t beyond 1 s): a step the error control cuts
/// below it means the integration is stuck.
inline constexpr double min_step_s = 1e-14;

/// A contact state's rotation theta is not negative to within this, rad: the event search
/// stops on the impact theta = 0 to round-off.
inline constexpr double theta_round_off_rad = 1e-9;

/// The time a start at t_s is classified at: probe_delay_s after it, never past half the way
/// to the segment's end tb_s.
inline double probe_time(double t_s, double tb_s) {
    return t_s + std::min(probe_delay_s, 0.5 * (tb_s - t_s));
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

/// The step to try from t_s towards end_s (a segment's end or an event horizon): at most cap_s
/// and max_step_s; a step within round-off of end_s is stretched onto it.
inline double step_towards(double t_s, double end_s, double max_step_s, double cap_s) {
    return core::step_to_sample(t_s, std::min({cap_s, end_s - t_s, max_step_s}), end_s);
}

/// Step size of an error-controlled stepper (dopri5.hpp) between events: the step to try, then
/// accept or reject by the error it measured.
class AdaptiveStep {
public:
    /// The step to try from t_s towards end_s (a segment's end or an event horizon), at most
    /// max_step_s and the proposal of the last step; a step within round-off of end_s is
    /// stretched onto it. Throws NumericalError naming the integrator when the proposal fell
    /// below min_step_s.
    double propose(double t_s, double end_s, double max_step_s, const char* integrator) {
        if (h_next_s_ < min_step_s * std::max(1.0, t_s))
            throw NumericalError(fmt::format(
                "{}: the step fell below 1e-14 s at t = {} s", integrator, t_s));
        h_s_ = step_towards(t_s, end_s, max_step_s, h_next_s_);
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

/// Step size of a stepper that sizes its own step from its series (the Taylor stepper,
/// taylor.hpp). It cannot run under AdaptiveStep: the series' tail bounds the error before the
/// step is taken, so the stepper returns the step asked or a shorter one its tolerance allows
/// and never rejects one; there is no error after the step to accept or reject by, and the
/// step it shortened is the one to start the next from. It shares AdaptiveStep's request
/// (step_towards) and its floor (min_step_s, which the engine checks on the shortened step).
class SeriesStep {
public:
    explicit SeriesStep(double cap_s) : cap_s_(cap_s) {}
    /// The step to ask for from t_s towards end_s: at most max_step_s and the cap.
    double request(double t_s, double end_s, double max_step_s) const {
        return step_towards(t_s, end_s, max_step_s, cap_s_);
    }
    /// The stepper took h_s of the h_asked_s: the cap is 1.25 x a step the tolerance shortened,
    /// and doubles (up to 1 s) after a step it did not.
    void took(double h_s, double h_asked_s) {
        cap_s_ = h_s < h_asked_s ? 1.25 * h_s : std::min(2.0 * cap_s_, 1.0);
    }

private:
    double cap_s_;
};

/// Where a run ended: at end_s, stopped early (the body settled for good or overturned) or at
/// the end of its last input segment (then the overturning rule still applies to the state).
struct RunEnd {
    double end_s = 0.0;
    bool stopped = false;
};

/// The fixed-step driver (the central-difference baselines): in each of n_seg input segments
/// of dt_s, n_sub = dt_s / h_s steps step(k, t, h_s) (false: the run ends at t + h_s), then
/// at_sample(k, tb) at the segment's end tb (true: the run ends at tb).
template <class Step, class AtSample>
RunEnd run_fixed_steps(double dt_s, double h_s, std::size_t n_seg, Step&& step,
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

/// A body's pass over input segments it holds at rest without stepping: the first segment k
/// still to take, or ended: the run ends at the sample time t_k(k).
struct RestRun {
    std::size_t k = 0;
    bool ended = false;
};

/// What an event-driven engine supplies to run_segments (B a body of planar, biaxial, flexible
/// or a later kind), k indexing input segments [t_k(k), t_k(k + 1)]:
///   - t_k(k): the sample time k;
///   - rest_run(k, n_seg): the segments from k it passes at rest in one go (recording their
///     samples), or {k, false} when it is not at rest;
///   - advance(k, t, tb): from t towards the segment's end tb to the time reached (tb, or an
///     event it handled before returning); a run that records the samples it passes may move
///     k on (the segment that holds the time reached, its start sample recorded);
///   - overturned(): the run ends at the time reached;
///   - sample(k, tb): the output sample at the end tb of segment k;
///   - ends_at(tb): after that sample, the body has settled for good (the run ends at tb).
template <class B>
concept SegmentBody = requires(B& body, const B& cbody, std::size_t& k, double t) {
    { cbody.t_k(k) } -> std::same_as<double>;
    { body.rest_run(k, k) } -> std::same_as<RestRun>;
    { body.advance(k, t, t) } -> std::same_as<double>;
    { cbody.overturned() } -> std::same_as<bool>;
    body.sample(k, t);
    { cbody.ends_at(t) } -> std::same_as<bool>;
};

/// The event-driven driver: each of n_seg input segments is passed at rest, or advanced event
/// by event to its end and sampled there; the run stops at an overturn or once the body has
/// settled for good.
template <SegmentBody B>
RunEnd run_segments(B& body, std::size_t n_seg) {
    for (std::size_t k = 0; k < n_seg; ++k) {
        const RestRun rest = body.rest_run(k, n_seg);
        if (rest.ended) return {body.t_k(rest.k), true};
        k = rest.k;
        if (k == n_seg) break;
        double t = body.t_k(k), tb = body.t_k(k + 1);
        while (t < tb) {
            t = body.advance(k, t, tb);
            if (body.overturned()) return {t, true};
            tb = body.t_k(k + 1);
        }
        body.sample(k, tb);
        if (body.ends_at(tb)) return {tb, true};
    }
    return {body.t_k(n_seg), false};
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
