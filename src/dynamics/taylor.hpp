#pragma once
/// Internal: Taylor-series steps of the contact phases (rock, slide-rock) on a base whose
/// acceleration is linear in time over the step (one piece of the piecewise-linear input).
///
/// The coefficients come from recurrences on the equations of motion (automatic
/// differentiation; Jorba & Zou 2005, "A software package for the numerical integration of
/// ODEs by means of high-order Taylor methods", Exp. Math. 14(1)): with phi = alpha - theta,
/// s = sin phi and c = cos phi obey s' = -c theta', c' = s theta', so
///   k s_k = -sum_{j=1..k} j theta_j c_{k-j},   k c_k = sum_{j=1..k} j theta_j s_{k-j},
/// and the k-th coefficient of theta'' (and u'') follows from products of lower coefficients.
/// A step then costs one short loop instead of the six right-hand sides (six sincos) of a
/// Runge-Kutta step, the order adapts to the tolerance, and the polynomial is its own dense
/// output. Written by hand: Boost.Odeint ships no Taylor stepper.
#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "dynamics/mechanics.hpp"

namespace freestand::dynamics::detail {

/// Highest Taylor order a step may use; past it the step is shortened instead.
inline constexpr int taylor_max_order = 24;
/// Lowest order accepted (the error estimate needs two non-trivial trailing terms).
inline constexpr int taylor_min_order = 4;

/// Value at x of the polynomial a[0] + a[1] x + ... + a[n] x^n.
inline double poly(const double* a, int n, double x) {
    double y = a[n];
    for (int k = n - 1; k >= 0; --k) y = y * x + a[k];
    return y;
}
/// First derivative at x of the same polynomial.
inline double poly_d1(const double* a, int n, double x) {
    if (n < 1) return 0.0;
    double y = n * a[n];
    for (int k = n - 1; k >= 1; --k) y = y * x + k * a[k];
    return y;
}
/// Second derivative at x of the same polynomial.
inline double poly_d2(const double* a, int n, double x) {
    if (n < 2) return 0.0;
    double y = n * (n - 1) * a[n];
    for (int k = n - 1; k >= 2; --k) y = y * x + k * (k - 1) * a[k];
    return y;
}

/// Value and first derivative at x of a[0] + ... + a[n] x^n in one Horner pass.
inline std::pair<double, double> poly_and_d1(const double* a, int n, double x) {
    double y = a[n], dy = 0.0;
    for (int k = n - 1; k >= 0; --k) {
        dy = dy * x + y;
        y = y * x + a[k];
    }
    return {y, dy};
}

/// A polynomial f(tau) = a[0] + ... + a[n] tau^n of a step (theta, or the slip velocity
/// signed by the slip direction), for the zero searches below.
struct Poly {
    const double* a = nullptr;
    int n = 0;
    double value(double tau) const { return poly(a, n, tau); }
    double d1(double tau) const { return poly_d1(a, n, tau); }
    double d2(double tau) const { return poly_d2(a, n, tau); }
    std::pair<double, double> value_d1(double tau) const { return poly_and_d1(a, n, tau); }
};

/// sin and cos of (phi0 - d) from sn0 = sin phi0 and c0 = cos phi0. For |d| <= 0.05 the Taylor
/// polynomials of sin d (to d^9) and cos d (to d^10) leave a remainder below d^11/11! = 1.2e-22,
/// far under one ulp, and the angle-difference formulas are exact to round-off; beyond, libm.
inline void sin_cos_shift(double sn0, double c0, double phi0, double d, double& sn, double& c) {
    if (std::abs(d) > 0.05) {
        sn = std::sin(phi0 - d);
        c = std::cos(phi0 - d);
        return;
    }
    const double d2 = d * d;
    const double sd =
        d * (1.0 + d2 * (-1.0 / 6 + d2 * (1.0 / 120 + d2 * (-1.0 / 5040 + d2 * (1.0 / 362880)))));
    const double cd =
        1.0 +
        d2 * (-0.5 + d2 * (1.0 / 24 + d2 * (-1.0 / 720 + d2 * (1.0 / 40320 + d2 * (-1.0 / 3628800)))));
    sn = sn0 * cd - c0 * sd;
    c = c0 * cd + sn0 * sd;
}

/// Contact state at a step start and the base over the step: xg'' = ax0 + ax1 tau and
/// G = G0 + G1 tau for 0 <= tau <= h.
struct ContactStart {
    Mode mode = Mode::rock;  ///< rock or slide_rock
    int s = 1, sigma = 1;
    double u = 0, v = 0, th = 0, om = 0;
    double sn = 0, c = 1;  ///< sin and cos of alpha_s - th
    double ax0 = 0, ax1 = 0, G0 = 0, G1 = 0;
};

/// Taylor polynomials of one step in tau = t - t_start: theta(tau) = sum th[k] tau^k, likewise u
/// (degree 0 while rocking: the contact point does not slip).
struct ContactSeries {
    int n = 0;   ///< degree of th
    int nu = 0;  ///< degree of u
    std::array<double, taylor_max_order + 1> th, u;
    /// theta and theta' at the end of the step the builder returned, summed with the terms.
    double th_end = 0.0, om_end = 0.0;

    double theta(double tau) const { return poly(th.data(), n, tau); }
    double omega(double tau) const { return poly_d1(th.data(), n, tau); }
    double theta_dd(double tau) const { return poly_d2(th.data(), n, tau); }
    /// theta and theta' together (one pass).
    std::pair<double, double> theta_omega(double tau) const { return poly_and_d1(th.data(), n, tau); }
    double slip(double tau) const { return poly(u.data(), nu, tau); }
    double slip_velocity(double tau) const { return poly_d1(u.data(), nu, tau); }
    double slip_accel(double tau) const { return poly_d2(u.data(), nu, tau); }
    Poly theta_poly() const { return {th.data(), n}; }
};

/// True if f(tau) > 0 on (0, h] follows from f(0) >= 0 and the bound
/// |sum_{k>=2} a_k tau^k| <= tau B, B = sum_{k>=2} |a_k| h^(k-1): then f(tau) >=
/// f(0) + tau (f'(0) - B). Holds on almost every step; a step that fails it needs the search
/// of zero_bracket.
inline bool stays_positive(Poly f, double h) {
    double B = 0.0, hk = 1.0;
    for (int k = 2; k <= f.n; ++k) {
        hk *= h;
        B += std::abs(f.a[k]) * hk;
    }
    const double slope = (f.n >= 1 ? f.a[1] : 0.0) - B;
    return slope > 0.0 ? f.a[0] >= 0.0 : f.a[0] + h * slope > 0.0;
}

/// True if f' < 0 or f'' < 0 throughout [0, tau] (bounds from |a_k|): then f, starting at
/// f(0) >= 0, has at most one zero on (0, tau], and a root found there by Newton's method is
/// the first.
inline bool monotone_or_concave(Poly f, double tau) {
    double w = f.n >= 1 ? f.a[1] : 0.0, dd = f.n >= 2 ? 2.0 * f.a[2] : 0.0, tk1 = 1.0;
    for (int k = 2; k <= f.n; ++k) {
        const double a = std::abs(f.a[k]);
        if (k >= 3) dd += k * (k - 1) * a * tk1;
        tk1 *= tau;
        w += k * a * tk1;
    }
    return w < 0.0 || dd < 0.0;
}

/// Bracket [a, b] in [0, h] of the first time f(tau) drops below -depth, with f(a) >= 0 and
/// f(b) < -depth (f(a) > 0 when f leaves 0 upwards); found = false if f >= -depth on [0, h]. f and f' are sampled at 8 points: a
/// sign change of f between them brackets the root, and a dip below and back between them is
/// caught at the minimum (f' from - to +, located by Newton on f'). A step can hold such a dip
/// when the block barely lifts off its edge (f = theta) or its slip barely reverses
/// (f = sigma u'): the end values alone would miss the impact or the stop.
struct ZeroBracket {
    bool found = false;
    double a = 0.0, b = 0.0, f_a = 0.0, f_b = 0.0;
};
inline ZeroBracket zero_bracket(Poly f, double h, double depth = 0.0) {
    constexpr int m = 8;
    ZeroBracket z;
    double ta = 0.0, fa = f.a[0];                         // last sample with f >= 0
    double tp = 0.0, dp = f.n >= 1 ? f.a[1] : 0.0;        // previous sample and its f'
    for (int j = 1; j <= m; ++j) {
        const double tb = j == m ? h : h * j / m;
        const auto [fb, db] = f.value_d1(tb);
        double tc = tb, fc = fb;
        if (!(fb < -depth) && dp < 0.0 && db > 0.0) {
            // Minimum inside: Newton on f' (slope f''), kept inside the interval.
            double lo = tp, hi = tb, x = tp + (tb - tp) * (-dp) / (db - dp);
            for (int it = 0; it < 50; ++it) {
                const double w = f.d1(x), dw = f.d2(x);
                (w < 0.0 ? lo : hi) = x;
                double xn = dw > 0.0 ? x - w / dw : 0.5 * (lo + hi);
                if (!(xn > lo && xn < hi)) xn = 0.5 * (lo + hi);
                if (std::abs(xn - x) <= 1e-15 * h) break;
                x = xn;
            }
            tc = x;
            fc = f.value(x);
        }
        if (fc < -depth) {
            if (ta == 0.0 && fa == 0.0 && f.n >= 2 && f.a[1] > 0.0) {
                // Leaving 0 upwards (f'(0) > 0): put the bracket's start on the excursion's
                // peak, near -f'(0) / f''(0), or on the highest of 16 points before tc.
                double best_t = 0.0, best_f = 0.0;
                if (f.a[2] < 0.0) {
                    best_t = std::min(-f.a[1] / (2.0 * f.a[2]), 0.5 * tc);
                    best_f = f.value(best_t);
                }
                for (int i = 1; i < 16 && !(best_f > 0.0); ++i) {
                    const double ti = tc * i / 16;
                    const double fi = f.value(ti);
                    if (fi > best_f) {
                        best_t = ti;
                        best_f = fi;
                    }
                }
                if (best_f > 0.0) {
                    ta = best_t;
                    fa = best_f;
                }
            }
            z = {true, ta, tc, fa, fc};
            return z;
        }
        if (fb >= 0.0) {
            ta = tb;
            fa = fb;
        }
        tp = tb;
        dp = db;
    }
    return z;
}

namespace taylor_detail {

inline constexpr int K = taylor_max_order + 1;

// 1 / k and 1 / ((k + 1) (k + 2)): the recurrences multiply (a division costs ~5x a multiply and
// sits on the critical path).
struct Reciprocals {
    std::array<double, K> of_k{}, of_k1k2{};
    constexpr Reciprocals() {
        for (int k = 1; k < K; ++k) of_k[static_cast<std::size_t>(k)] = 1.0 / k;
        for (int k = 0; k < K; ++k) of_k1k2[static_cast<std::size_t>(k)] = 1.0 / ((k + 1) * (k + 2));
    }
};
inline constexpr Reciprocals recip{};

// Coefficient k of a product: sum_j a_j b_{k-j}.
inline double conv(const double* a, const double* b, int k) {
    double y = 0.0;
    for (int j = 0; j <= k; ++j) y += a[j] * b[k - j];
    return y;
}

// Truncation test of one component x(tau) = sum a_k tau^k at degree n and step h. The error of
// the polynomial is about the first omitted term, T_n (h / rho) with T_k = |a_k| h^k and rho the
// radius of convergence; requiring T_n <= tol and T_{n-1} <= 20 tol (the same for x') bounds it
// by ~tol h / rho unless two consecutive coefficients vanish together.
struct Tolerance {
    double x_tol = 0.0, v_tol = 0.0;  // on x and on x'
    Tolerance(double x0, double v0, double rel_tol, double abs_tol)
        : x_tol(abs_tol + rel_tol * std::abs(x0)), v_tol(abs_tol + rel_tol * std::abs(v0)) {}
    // hn = h^n, hn1 = h^(n-1), hn2 = h^(n-2).
    bool pass(const double* a, int n, double hn, double hn1, double hn2) const {
        const double an = std::abs(a[n]), am = std::abs(a[n - 1]);
        return an * hn <= x_tol && n * an * hn1 <= v_tol && am * hn1 <= 20.0 * x_tol &&
               (n - 1) * am * hn2 <= 20.0 * v_tol;
    }
    // Largest factor by which the four terms of pass() exceed their bounds (> 1 where pass()
    // fails).
    double excess(const double* a, int n, double hn, double hn1, double hn2) const {
        const double an = std::abs(a[n]), am = std::abs(a[n - 1]);
        return std::max({an * hn / x_tol, n * an * hn1 / v_tol, am * hn1 / (20.0 * x_tol),
                         (n - 1) * am * hn2 / (20.0 * v_tol)});
    }
};

// Coefficient k >= 1 of s = sin(alpha - theta) and c = cos(alpha - theta) from theta's.
inline void sin_cos_coefficient(const double* th, double* sn, double* c, int k) {
    double ss = 0.0, cc = 0.0;
#pragma GCC unroll 16
    for (int j = 1; j <= k; ++j) {
        const double jt = j * th[j];
        ss += jt * c[k - j];
        cc += jt * sn[k - j];
    }
    const double inv = recip.of_k[static_cast<std::size_t>(k)];
    sn[k] = -ss * inv;
    c[k] = cc * inv;
}

// Coefficient k + 2 >= 3 of theta for rock from those of s and c (k >= 1):
// (k + 1)(k + 2) theta_{k+2} = -k_rock [G0 s_k + G1 s_{k-1} + A0 c_k + A1 c_{k-1}] with
// G = G0 + G1 tau and A = s_edge xg'' = A0 + A1 tau; neg_k_rock = -k_rock.
inline double rock_theta_coefficient(double neg_k_rock, const ContactStart& x0, double A0,
                                     double A1, const double* sn, const double* c, int k) {
    return neg_k_rock * (x0.G0 * sn[k] + x0.G1 * sn[k - 1] + A0 * c[k] + A1 * c[k - 1]) *
           recip.of_k1k2[static_cast<std::size_t>(k)];
}

// Step the tolerance allows at degree n = taylor_max_order given the excess there (> 1): the
// tested terms scale at least like h^(n-2), so the shorter step passes with margin
// (0.8^(n-2) ~ 0.007). Never longer than h; half of it if the excess is not a number.
inline double shortened(double h, double excess) {
    const double f = 0.8 * std::pow(excess, -1.0 / (taylor_max_order - 2));
    return f < 1.0 ? h * f : 0.5 * h;
}

// The rock series' constant terms from x0: theta, theta' and the slip's u (held: degree 0), sin
// and cos of alpha - theta; returns theta's coefficients.
inline double* start_rock_series(const ContactStart& x0, ContactSeries& S, double* sn, double* c) {
    double* th = S.th.data();
    th[0] = x0.th;
    th[1] = x0.om;
    S.u[0] = x0.u;
    S.nu = 0;
    sn[0] = x0.sn;
    c[0] = x0.c;
    return th;
}

// Rock: I_O theta'' = -M R [G s + s_edge xg'' c] (docs/methods.md s.3), G and xg'' linear in tau.
inline double rock_step(const Geometry& g, const ContactStart& x0, double h, double rel_tol,
                        double abs_tol, ContactSeries& S) {
    const auto i = static_cast<std::size_t>(Geometry::index(x0.s));
    const double kr = g.k_rock[i];
    const double A0 = static_cast<double>(x0.s) * x0.ax0, A1 = static_cast<double>(x0.s) * x0.ax1;
    double sn[K], c[K];
    double* th = start_rock_series(x0, S, sn, c);
    const Tolerance tol(x0.th, x0.om, rel_tol, abs_tol);
    th[2] = -kr * (x0.G0 * sn[0] + A0 * c[0]) * 0.5;
    double hn2 = 1.0, hn1 = h, hn = h * h;  // h^(n-2), h^(n-1), h^n for n = k + 2
    // theta(h) and theta'(h), summed as the terms come (no Horner pass afterwards).
    double th_end = th[0] + th[1] * h + th[2] * hn, om_end = th[1] + 2.0 * th[2] * h;
    for (int k = 1; k + 2 < K; ++k) {
        sin_cos_coefficient(th, sn, c, k);
        const int n = k + 2;
        th[n] = rock_theta_coefficient(-kr, x0, A0, A1, sn, c, k);
        hn2 = hn1;
        hn1 = hn;
        hn *= h;
        th_end += th[n] * hn;
        om_end += n * th[n] * hn1;
        if (n < taylor_min_order) continue;
        if (tol.pass(th, n, hn, hn1, hn2)) {
            S.n = n;
            S.th_end = th_end;
            S.om_end = om_end;
            return h;
        }
    }
    S.n = taylor_max_order;
    h = shortened(h, tol.excess(th, S.n, hn, hn1, hn2));
    S.th_end = S.theta(h);
    S.om_end = S.omega(h);
    return h;
}

// Slide-rock, eliminating N from the 3x3 system of mechanics.hpp:
//   theta'' = -D (G - R c theta'^2) / (R s D + s_edge I_c / M),  D = s_edge R s - sigma mu_k R c,
//   N / M = R s theta'' - R c theta'^2 + G,
//   u'' = -(s_edge R s theta'^2 + xg'') - sigma mu_k N / M - s_edge R c theta''.
inline double slide_rock_step(const Geometry& g, const ContactStart& x0, double h,
                              double rel_tol, double abs_tol, ContactSeries& S) {
    const auto i = static_cast<std::size_t>(Geometry::index(x0.s));
    const double ds = static_cast<double>(x0.s), dsig = static_cast<double>(x0.sigma);
    const double R = g.R[i], mu = g.mu_k;
    // s, c; theta''; theta', theta'^2, c theta'^2, s theta'^2; D; G - R c theta'^2; denominator.
    double sn[K], c[K], q[K], w[K], W[K], cW[K], sW[K], D[K], E[K], den[K];
    double* th = S.th.data();
    double* u = S.u.data();
    th[0] = x0.th;
    th[1] = x0.om;
    u[0] = x0.u;
    u[1] = x0.v;
    sn[0] = x0.sn;
    c[0] = x0.c;
    const Tolerance tol_th(x0.th, x0.om, rel_tol, abs_tol), tol_u(x0.u, x0.v, rel_tol, abs_tol);
    double hn2 = 1.0 / h, hn1 = 1.0, hn = h;
    bool met = false;
    for (int k = 0; k + 2 < K && !met; ++k) {
        if (k > 0) sin_cos_coefficient(th, sn, c, k);
        const double Gk = k == 0 ? x0.G0 : (k == 1 ? x0.G1 : 0.0);
        const double Ak = k == 0 ? x0.ax0 : (k == 1 ? x0.ax1 : 0.0);
        w[k] = (k + 1) * th[k + 1];
        W[k] = conv(w, w, k);
        cW[k] = conv(c, W, k);
        sW[k] = conv(sn, W, k);
        D[k] = ds * R * sn[k] - dsig * mu * R * c[k];
        E[k] = Gk - R * cW[k];
        den[k] = R * conv(sn, D, k) + (k == 0 ? ds * g.Ic / g.M : 0.0);
        double num = -conv(D, E, k);
        for (int j = 0; j < k; ++j) num -= q[j] * den[k - j];
        q[k] = num / den[0];
        const double nk = R * conv(sn, q, k) - R * cW[k] + Gk;
        const double udd = -(ds * R * sW[k] + Ak) - dsig * mu * nk - ds * R * conv(c, q, k);
        const double inv = recip.of_k1k2[static_cast<std::size_t>(k)];
        th[k + 2] = q[k] * inv;
        u[k + 2] = udd * inv;
        const int n = k + 2;
        hn2 = hn1;
        hn1 = hn;
        hn *= h;
        if (n < taylor_min_order) continue;
        met = tol_th.pass(th, n, hn, hn1, hn2) && tol_u.pass(u, n, hn, hn1, hn2);
        S.n = S.nu = n;
    }
    if (!met) {
        S.n = S.nu = taylor_max_order;
        h = shortened(h, std::max(tol_th.excess(th, S.n, hn, hn1, hn2), tol_u.excess(u, S.n, hn, hn1, hn2)));
    }
    S.th_end = S.theta(h);
    S.om_end = S.omega(h);
    return h;
}

}  // namespace taylor_detail

/// Degrees of the unrolled rock kernel; the adaptive loop above takes over past the highest.
inline constexpr int rock_degree_min = taylor_min_order, rock_degree_max = 12;

namespace taylor_detail {

// Rock series of fixed degree D, straight-line code (the loops have constant trip counts and
// are unrolled): the common step of a rocking record, where the degree the tolerance needs
// changes slowly. Returns whether degree D meets the tolerance; lower_ok tells whether D - 1
// would have.
template <int D>
bool rock_step_fixed(const Geometry& g, const ContactStart& x0, double h, const Tolerance& tol,
                     ContactSeries& S, bool& lower_ok) {
    static_assert(D >= rock_degree_min && D <= rock_degree_max);
    const auto i = static_cast<std::size_t>(Geometry::index(x0.s));
    const double kr = -g.k_rock[i];
    const double A0 = static_cast<double>(x0.s) * x0.ax0, A1 = static_cast<double>(x0.s) * x0.ax1;
    double sn[D - 1], c[D - 1], hp[D + 1];
    double* th = start_rock_series(x0, S, sn, c);
    hp[0] = 1.0;
#pragma GCC unroll 16
    for (int k = 1; k <= D; ++k) hp[k] = hp[k - 1] * h;
    th[2] = kr * (x0.G0 * sn[0] + A0 * c[0]) * 0.5;
#pragma GCC unroll 16
    for (int k = 1; k <= D - 2; ++k) {
        sin_cos_coefficient(th, sn, c, k);
        th[k + 2] = rock_theta_coefficient(kr, x0, A0, A1, sn, c, k);
    }
    double th_end = th[0], om_end = 0.0;
#pragma GCC unroll 16
    for (int k = 1; k <= D; ++k) {
        th_end += th[k] * hp[k];
        om_end += k * th[k] * hp[k - 1];
    }
    S.n = D;
    S.th_end = th_end;
    S.om_end = om_end;
    lower_ok = D > rock_degree_min && tol.pass(th, D - 1, hp[D - 1], hp[D - 2], hp[D - 3]);
    return tol.pass(th, D, hp[D], hp[D - 1], hp[D - 2]);
}

template <int... Ds>
bool rock_step_degree(int degree, const Geometry& g, const ContactStart& x0, double h,
                      const Tolerance& tol, ContactSeries& S, bool& lower_ok,
                      std::integer_sequence<int, Ds...>) {
    bool met = false;
    // The fold stops at the degree asked for; its value is only that stop.
    static_cast<void>(((degree == Ds + rock_degree_min
                            ? (met = rock_step_fixed<Ds + rock_degree_min>(g, x0, h, tol, S, lower_ok), true)
                            : false) ||
                       ...));
    return met;
}

}  // namespace taylor_detail

/// Rock degree carried from step to step by taylor_contact_step.
struct RockDegree {
    int degree = 6;        ///< the degree that met the tolerance last
    int lower_streak = 0;  ///< steps in a row on which one less would have done
};

/// Builds the Taylor polynomials of the contact phase from x0 for a step of at most h. Rock
/// tries the degree that met the tolerance last (raised when it fails, lowered when one less
/// would have done on 8 steps in a row), then the adaptive kernel; slide-rock raises the degree
/// from the lowest. Returns h, or a shorter step the tolerance allows at degree
/// taylor_max_order (then S holds that degree).
inline double taylor_contact_step(const Geometry& g, const ContactStart& x0, double h,
                                  double rel_tol, double abs_tol, ContactSeries& S,
                                  RockDegree& rock) {
    if (x0.mode != Mode::rock) return taylor_detail::slide_rock_step(g, x0, h, rel_tol, abs_tol, S);
    const taylor_detail::Tolerance tol(x0.th, x0.om, rel_tol, abs_tol);
    rock.degree = std::clamp(rock.degree, rock_degree_min, rock_degree_max);
    for (;;) {
        bool lower_ok = false;
        if (taylor_detail::rock_step_degree(
                rock.degree, g, x0, h, tol, S, lower_ok,
                std::make_integer_sequence<int, rock_degree_max - rock_degree_min + 1>{})) {
            rock.lower_streak = lower_ok ? rock.lower_streak + 1 : 0;
            if (rock.lower_streak >= 8) {
                --rock.degree;
                rock.lower_streak = 0;
            }
            return h;
        }
        if (rock.degree == rock_degree_max)
            return taylor_detail::rock_step(g, x0, h, rel_tol, abs_tol, S);
        ++rock.degree;
    }
}

}  // namespace freestand::dynamics::detail
