#pragma once
/// `freestand simulate` with a second horizontal component (--motion-y, --sine-y): biaxial
/// sliding (docs/methods.md s.10), its JSON, text and series CSV.
#include <optional>
#include <string>

#include "cli/options.hpp"
#include "dynamics/biaxial.hpp"

namespace freestand::cli {

/// --sine / --sine-y value "A g,f Hz,T s[,ramp=t s][,phase=DEG]" (phase only if allow_phase);
/// phase_deg is returned in the spec. Throws UsageError naming option.
dynamics::SineSpec parse_sine_spec(const std::string& text, const std::string& option,
                                   bool allow_phase);

/// Runs the biaxial model for the parsed simulate options (--motion with --motion-y, or
/// --sine-y) and prints as `simulate` does. Refuses, naming the flags, a block that would rock
/// (dynamics::biaxial_rocking_reason): the biaxial model has no rocking.
int run_biaxial_simulation(const po::variables_map& vm, const block::Block& block,
                           const dynamics::Options& options);

}  // namespace freestand::cli
