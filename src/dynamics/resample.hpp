#pragma once
/// Internal: a record read at any time, as the excitations put a second record (vertical, or
/// the second horizontal component) onto the first one's samples.
#include "core/record.hpp"

namespace freestand::dynamics::detail {

/// Linear interpolation of a record at time t (zero outside its span).
double sample_at(const core::Record& rec, double t);

}  // namespace freestand::dynamics::detail
