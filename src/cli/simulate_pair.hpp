#pragma once
/// `freestand simulate` with a second unit (--block2, --mu2, --tunnel-height): two rigid planar
/// blocks under the same base motion and their relative displacement at the tunnel's height
/// (docs/methods.md s.10): the options, the second unit's request and the text.
#include "api/simulate.hpp"
#include "cli/options.hpp"
#include "cli/usage_error.hpp"

namespace freestand::cli {

/// The options `simulate` adds for the second unit.
void add_pair_options(po::options_description& desc);

/// True when any second-unit option is given.
bool pair_requested(const po::variables_map& vm);

/// Refuses (UsageError naming the option) a missing --block2, --mu2 or --tunnel-height, and
/// the options a pair does not take (--motion-y, --sine-y: the pair is planar; --out).
void require_pair_options(const po::variables_map& vm);

/// The second unit of the options (pair_requested and require_pair_options hold). A missing
/// box key is named as the second unit's (unit2.*, cli/flag_names.hpp).
api::JoinedUnit joined_unit(const po::variables_map& vm);

/// The text `simulate` prints for a pair.
void print_pair(const api::PairRun& run);

}  // namespace freestand::cli
