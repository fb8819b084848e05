#pragma once
/// Internal: the bracketed root finder the event-driven integrators locate their events with.
#include <boost/math/tools/toms748_solve.hpp>
#include <cstdint>

namespace freestand::dynamics::detail {

/// Root of f in [a, b], f(a) = fa and f(b) = fb of opposite signs (or one of them 0: that end),
/// by TOMS 748 (Alefeld, Potra & Shi 1995) to `bits` bits; the midpoint of the final bracket.
template <class F>
double toms748_root(F f, double a, double b, double fa, double fb, int bits = 50) {
    if (fa == 0.0) return a;
    if (fb == 0.0) return b;
    std::uintmax_t iters = 200;
    const auto r = boost::math::tools::toms748_solve(
        f, a, b, fa, fb, boost::math::tools::eps_tolerance<double>(bits), iters);
    return 0.5 * (r.first + r.second);
}

}  // namespace freestand::dynamics::detail
