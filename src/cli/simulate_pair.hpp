#pragma once
/// `freestand simulate` with a second unit (--block2, --mu2, --tunnel-height): two rigid planar
/// blocks under the same base motion and their relative displacement at the tunnel's height
/// (docs/methods.md s.10), printed as text or JSON (relative_max_m).
#include <nlohmann/json_fwd.hpp>

#include "cli/documents.hpp"
#include "cli/options.hpp"
#include "dynamics/simulate.hpp"

namespace freestand::cli {


/// The options `simulate` adds for the second unit.
void add_pair_options(po::options_description& desc);

/// True when any second-unit option is given (then run_pair_simulation runs).
bool pair_requested(const po::variables_map& vm);

/// Refuses (UsageError naming the option) a missing --block2, --mu2 or --tunnel-height, and
/// the options a pair does not take (--motion-y, --sine-y: the pair is planar; --out).
void require_pair_options(const po::variables_map& vm);

/// Runs both units under the excitation and prints as `simulate` does, with relative_max_m
/// (and its time, the residual) and each unit's summary. Refuses out-of-range second-unit
/// values and tunnel height (InputError naming the option).
int run_pair_simulation(const po::variables_map& vm, const dynamics::BlockModel& unit1,
                        const dynamics::Excitation& excitation, const dynamics::Options& options);

}  // namespace freestand::cli
