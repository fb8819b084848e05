#pragma once
/// How many steps cover a span, and where a step that nearly reaches a sample ends: the two
/// rounding rules of every engine that cuts a duration into samples or sub-steps.
#include <cmath>
#include <limits>

#include "core/tolerances.hpp"

namespace freestand::core {

/// The number of whole units that cover ratio (a span over a step, a count times a fraction, a
/// length in mm): its ceiling, less a guard of tol::rounding_guard unit so that a span written
/// as a whole number of steps (5 s / 0.01 s = 500.00000000000006 in binary) is not counted one
/// step longer.
inline double steps_covering(double ratio) { return std::ceil(ratio - tol::rounding_guard); }

/// The step h from t, lengthened to end exactly on the sample at sample_t when it would stop
/// short of it by less than its own rounding (1e-12 h) and a few ulps of sample_t: sample
/// times are k dt, a segment can be an ulp longer than dt, and a step an ulp short of the
/// sample would leave a step of ~1e-15 s after it (an ulp of t is 7e-15 s at 32 s).
inline double step_to_sample(double t, double h, double sample_t) {
    constexpr double eps = std::numeric_limits<double>::epsilon();
    constexpr double step_rounding = 1e-12;  // of h, the "1e-12 h" above
    return sample_t - (t + h) < step_rounding * h + 8.0 * eps * sample_t ? sample_t - t : h;
}

}  // namespace freestand::core
