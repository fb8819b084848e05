#pragma once
/// `freestand simulate` with a second horizontal component (--motion-y, --sine-y): the sine
/// syntax, and biaxial sliding's text and series CSV (docs/methods.md s.10).
#include <string>

#include "api/simulate.hpp"
#include "cli/usage_error.hpp"

namespace freestand::cli {

/// --sine / --sine-y value "A g,f Hz,T s[,ramp=t s][,phase=DEG]" (phase only if allow_phase);
/// phase_deg is returned in the spec. Throws UsageError naming option.
dynamics::SineSpec parse_sine_spec(const std::string& text, const std::string& option,
                                   bool allow_phase);

/// The series CSV of a biaxial run (--out).
std::string biaxial_series_csv(const api::BiaxialRun& run, const std::string& label);

/// The text `simulate` prints for a biaxial run.
void print_biaxial(const api::BiaxialRun& run);

}  // namespace freestand::cli
