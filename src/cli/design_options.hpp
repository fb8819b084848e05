#pragma once
/// The design-spectrum options `freestand target --design NAME` and `freestand generate
/// --target NAME` share: one set of option names read into one api::DesignValues.
#include "api/target.hpp"
#include "cli/options.hpp"

namespace freestand::cli {

/// Adds --pga, --sds, --sd1, --tl, --ag, --type, --ground, --soil.
void add_design_options(po::options_description& desc);

/// The design values given (the request checks which the design takes and their ranges).
api::DesignValues design_values(const po::variables_map& vm);

}  // namespace freestand::cli
