#pragma once
/// How many steps cover a span: the one rounding rule of every engine that cuts a duration into
/// samples or sub-steps.
#include <cmath>

namespace freestand::core {

/// The number of steps of one unit that cover ratio (a span over a step, both > 0): its
/// ceiling, less a guard of 1e-9 step so that a span written as a whole number of steps
/// (5 s / 0.01 s = 500.00000000000006 in binary) is not counted one step longer.
inline double steps_covering(double ratio) { return std::ceil(ratio - 1e-9); }

}  // namespace freestand::core
