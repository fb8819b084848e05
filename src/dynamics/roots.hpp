#pragma once
/// Internal: the root finders the event-driven integrators locate their events with (engine.hpp).
#include <boost/math/tools/toms748_solve.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace freestand::dynamics::detail {

/// Root of f in [a, b], f(a) = fa and f(b) = fb of opposite signs (or one of them 0: that end),
/// by TOMS 748 (Alefeld, Potra & Shi 1995) to `bits` bits; the midpoint of the final bracket.
template <class F>
double toms748_root(F f, double a, double b, double fa, double fb, unsigned bits = 50) {
    if (fa == 0.0) return a;
    if (fb == 0.0) return b;
    std::uintmax_t iters = 200;
    const auto r = boost::math::tools::toms748_solve(
        f, a, b, fa, fb, boost::math::tools::eps_tolerance<double>(bits), iters);
    return 0.5 * (r.first + r.second);
}

/// Root of a smooth f in a sign-changing bracket [a, b] by Newton's method with the derivative
/// g(t) = {f, f'} gives (the dense output carries theta and theta'), safeguarded by bisection
/// when a step leaves the bracket; stops at a step below 4 ulp, or below x_tol_s if given. 3-4
/// evaluations where TOMS 748 needs ~10 (it cannot use the derivative).
template <class G>
double newton_root(G g, double a, double b, double fa, double fb, double x_tol_s = 0.0) {
    if (fa == 0.0) return a;
    if (fb == 0.0) return b;
    const double ulp4 = 4.0 * std::numeric_limits<double>::epsilon();
    double x = a - fa * (b - a) / (fb - fa);  // secant start
    for (int it = 0; it < 100; ++it) {
        const auto [fx, dfx] = g(x);
        if (fx == 0.0) return x;
        if ((fx < 0.0) == (fa < 0.0)) {
            a = x;
            fa = fx;
        } else {
            b = x;
        }
        double xn = dfx != 0.0 ? x - fx / dfx : 0.5 * (a + b);
        if (std::abs(xn - x) <= std::max(ulp4 * std::abs(x), x_tol_s)) return std::clamp(xn, a, b);
        if (!(xn > a && xn < b)) xn = 0.5 * (a + b);
        if (b - a <= ulp4 * std::abs(x)) return xn;
        x = xn;
    }
    return x;
}

/// Smallest root of c0 + c1 t + c2 t^2 in (tmin, tmax]; +inf if none. c0 == 0 drops t = 0.
inline double first_quadratic_root(double c0, double c1, double c2, double tmin, double tmax) {
    const double inf = std::numeric_limits<double>::infinity();
    double r1 = inf, r2 = inf;
    if (c0 == 0.0) {
        if (c2 != 0.0) r1 = -c1 / c2;
    } else if (c2 == 0.0) {
        if (c1 != 0.0) r1 = -c0 / c1;
    } else {
        const double disc = c1 * c1 - 4.0 * c2 * c0;
        if (disc < 0.0) return inf;
        // Numerically stable pair (Press et al., Numerical Recipes 5.6).
        const double q = -0.5 * (c1 + std::copysign(std::sqrt(disc), c1));
        r1 = q / c2;
        r2 = q != 0.0 ? c0 / q : inf;
    }
    double best = inf;
    for (double r : {r1, r2})
        if (r > tmin && r <= tmax && r < best) best = r;
    return best;
}

}  // namespace freestand::dynamics::detail
