#pragma once
/// The exact peak slip of a rigid block on a sinusoidally moving base (Newmark 1965's
/// piecewise solution), written independently of the simulator, for the fragility tests and
/// bench_fragility: a pure-sliding scene whose failure probability is known in closed form.
#include <algorithm>
#include <cmath>

namespace freestand::test {

inline constexpr double kG = 9.81;

/// Peak |relative slip| of a rigid block with friction mu (static = kinetic) on a base
/// accelerating as A g sin(w t) for 0 <= t <= T, at rest after, the block at rest at t = 0:
/// the textbook piecewise solution (Newmark 1965), written independently of the simulator.
/// Each sliding phase starts at rest at t_s in direction s and has, in closed form,
///   u'(t) = (A g / w)(cos w t - cos w t_s) - s mu g (t - t_s)     (t <= T),
/// its end (u' = 0) found by bisection on a 0.1 ms grid; after T the slip decelerates at mu g.
inline double peak_slip_m(double A, double f, double T, double mu) {
    const double w = 2.0 * M_PI * f;
    const auto ag = [&](double t) { return t <= T ? A * kG * std::sin(w * t) : 0.0; };
    double u = 0.0, peak = 0.0, t = 0.0;
    const double h = 1e-4;
    while (t < T) {
        if (std::abs(ag(t)) <= mu * kG) {  // stuck
            t += h;
            continue;
        }
        const double s = ag(t) > 0.0 ? -1.0 : 1.0;  // the block lags the base
        const double ts = t, us = u;
        const auto vel = [&](double x) {
            const double tc = std::min(x, T);
            double v = (A * kG / w) * (std::cos(w * tc) - std::cos(w * ts)) - s * mu * kG * (tc - ts);
            if (x > T) v -= s * mu * kG * (x - T);
            return v;
        };
        const auto disp = [&](double x) {
            const double tc = std::min(x, T);
            // u(ts) plus the integral of u' from ts.
            double d = us + (A * kG / w) * ((std::sin(w * tc) - std::sin(w * ts)) / w -
                                     std::cos(w * ts) * (tc - ts)) -
                0.5 * s * mu * kG * (tc - ts) * (tc - ts);
            if (x > T) {
                const double v_T = vel(T);
                d += v_T * (x - T) - 0.5 * s * mu * kG * (x - T) * (x - T);
            }
            return d;
        };
        double a = ts + h, b = a;
        while (vel(b) * s > 0.0) {
            for (double x = a; x <= b; x += h / 10.0) peak = std::max(peak, std::abs(disp(x)));
            a = b;
            b += h;
        }
        for (int i = 0; i < 60; ++i) {
            const double m = 0.5 * (a + b);
            (vel(m) * s > 0.0 ? a : b) = m;
        }
        t = b;
        u = disp(t);
        peak = std::max(peak, std::abs(u));
        if (t >= T) break;
    }
    return peak;
}

/// The friction at which the peak slip equals the allowable (peak slip falls with mu).
inline double critical_mu(double A, double f, double T, double allowable_m) {
    double lo = 0.01, hi = A;
    for (int i = 0; i < 50; ++i) {
        const double m = 0.5 * (lo + hi);
        (peak_slip_m(A, f, T, m) > allowable_m ? lo : hi) = m;
    }
    return 0.5 * (lo + hi);
}

}  // namespace freestand::test
