#pragma once
/// `freestand simulate --flexible f=HZ[,zeta=Z][,mass=FRACTION][,height=M]`: the reduced-order
/// flexible body (docs/methods.md s.10), its JSON, text and series CSV.
#include <nlohmann/json_fwd.hpp>
#include <string>

#include "cli/documents.hpp"
#include "cli/options.hpp"
#include "dynamics/flexible.hpp"

namespace freestand::cli {


/// --flexible's value as a mode: f (Hz) required, zeta, mass (fraction of M) and height (m above
/// the base) optional. UsageError naming --flexible for bad syntax, unknown keys or no f.
dynamics::FlexibleMode parse_flexible_mode(const std::string& text);

/// Runs the flexible model and prints as `simulate` does (JSON with --json). InputError naming
/// "--flexible KEY" for a value the model refuses.
int run_flexible_simulation(const po::variables_map& vm, const dynamics::BlockModel& rigid,
                            const dynamics::Excitation& excitation,
                            const dynamics::Options& options);

}  // namespace freestand::cli
