#pragma once
/// `freestand simulate --flexible f=HZ[,zeta=Z][,mass=FRACTION][,height=M]`: the reduced-order
/// flexible body's option syntax, text and series CSV (docs/methods.md s.10).
#include <string>

#include "api/simulate.hpp"
#include "cli/usage_error.hpp"

namespace freestand::cli {

/// --flexible's value as a mode: f (Hz) required, zeta, mass (fraction of M) and height (m above
/// the base) optional. UsageError naming --flexible for bad syntax, unknown keys or no f.
dynamics::FlexibleMode parse_flexible_mode(const std::string& text);

/// The series CSV of a flexible run (--out).
std::string flexible_series_csv(const api::FlexibleRun& run, const std::string& label);

/// The text `simulate` prints for a flexible run.
void print_flexible(const api::FlexibleRun& run);

}  // namespace freestand::cli
