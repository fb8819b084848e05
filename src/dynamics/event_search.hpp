#pragma once
/// Internal: the skeleton's event search (engine.hpp). An engine's events are functions of its
/// state, positive while its contact state holds; an event is a sign change from + to - inside
/// a step, located on the step's dense output (or a segment's closed form) with the root
/// finders of roots.hpp. The engine supplies the functions, their order at a tie and, where the
/// general search does not suit a function, its own locator; the skeleton supplies the scan
/// for the first event, the sign-change and dip brackets, the start of a rise out of 0 and the
/// probes of a flight's landing.
#include <array>
#include <cstddef>
#include <optional>

#include "dynamics/roots.hpp"

namespace freestand::dynamics::detail {

/// Where in a step, as a fraction of it, an event function that starts at 0 is probed for the
/// rise out of it (theta after an impact, a slip after a reversal, a corner at lift-off).
inline constexpr double rise_probe_fraction = 1e-6;

/// Probes a scan for the rise out of 0 takes across a step (rise_scan).
inline constexpr int rise_scan_probes = 8;

/// The first event of a step and its time (Ev{} and the step's end when none).
template <class Ev>
struct EventAt {
    Ev event{};
    double t_s = 0.0;
};

/// The first of an engine's events in a step ending at t_end_s: `events` in the order ties are
/// resolved (Ev{}, the engine's "none", skipped), locate(e) the time of event e inside the step
/// or nullopt.
template <class Ev, std::size_t N, class Locate>
EventAt<Ev> first_event(const std::array<Ev, N>& events, double t_end_s, Locate&& locate) {
    EventAt<Ev> first{Ev{}, t_end_s};
    for (Ev e : events) {
        if (e == Ev{}) continue;
        const std::optional<double> te = locate(e);
        if (te && (first.event == Ev{} || *te < first.t_s)) first = {e, *te};
    }
    return first;
}

/// Time at which f, f(a) = f0 and f(b) = f1, crosses from + to - in [a, b] (TOMS 748), or
/// nullopt while f1 >= 0. From f0 = 0 (the state an event just set) the crossing is the next
/// one after f rises out of 0 (probed rise_probe_fraction into the step); f0 < 0, or no rise,
/// is an event at a.
template <class F>
std::optional<double> sign_change(F&& f, double a, double b, double f0, double f1) {
    if (!(f1 < 0.0)) return std::nullopt;
    if (f0 > 0.0) return toms748_root(f, a, b, f0, f1);
    if (f0 == 0.0) {
        const double ta = a + rise_probe_fraction * (b - a);
        const double fa = f(ta);
        if (fa > 0.0) return toms748_root(f, ta, b, fa, f1);
    }
    return a;
}

/// Time at which f, positive at both ends of [a, b] (f(a) = f0), dips below 0 inside it: where
/// its slope df turns from - (df0) to + (df1) f has its minimum, and if that is negative the
/// crossing before it is the event. nullopt when f does not dip below 0.
template <class F, class DF>
std::optional<double> dip_below_zero(F&& f, DF&& df, double a, double b, double f0, double df0,
                                     double df1) {
    if (!(f0 > 0.0 && df0 < 0.0 && df1 > 0.0)) return std::nullopt;
    const double tm = toms748_root(df, a, b, df0, df1);
    const double fm = f(tm);
    if (!(fm < 0.0)) return std::nullopt;
    return toms748_root(f, a, tm, f0, fm);
}

/// What a rise scan does at a probe where f < 0: the function was pushed below 0 at once (the
/// event is at the start), or it may still rise later in the step.
enum class BelowZero { ends_scan, scan_on };

/// Start of the bracket of an event function f that is 0 at a: the first of the probes
/// a + (b - a) j / rise_scan_probes inside the step where f > 0, with f there; {a, 0} (an event
/// at a) when none is before the scan ends.
struct RiseStart {
    double t_s = 0.0;
    double f = 0.0;
};
template <class F>
RiseStart rise_scan(F&& f, double a, double b, BelowZero below) {
    for (int j = 1; j < rise_scan_probes; ++j) {
        const double tm = a + (b - a) * j / static_cast<double>(rise_scan_probes);
        const double fm = f(tm);
        if (fm > 0.0) return {tm, fm};
        if (fm < 0.0 && below == BelowZero::ends_scan) break;
    }
    return {a, 0.0};
}

/// The probes of a flight over (0, span_s]: at tau_j = span_s j / n, j = 1..n, in turn,
/// probe(tau_prev, tau_j) returns true where an event lies in (tau_prev, tau_j] and ends the
/// scan. Returns whether one did.
template <class Probe>
bool scan_flight(double span_s, int n, Probe&& probe) {
    double prev = 0.0;
    for (int j = 1; j <= n; ++j) {
        const double tau = span_s * j / n;
        if (probe(prev, tau)) return true;
        prev = tau;
    }
    return false;
}

}  // namespace freestand::dynamics::detail
