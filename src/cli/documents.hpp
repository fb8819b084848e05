#pragma once
/// The commands' computations from their parsed options, and the JSON documents they print with
/// --json. The command line (cmd_*.cpp) and the Python module (python/) both call these, so a
/// call from Python goes through the same option checks, gives the same errors and the same
/// numbers as the command.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli/options.hpp"
#include "assess/case.hpp"
#include "core/record.hpp"
#include "dynamics/simulate.hpp"
#include "report/json.hpp"
#include "motion/motion.hpp"
#include "spectra/response.hpp"

namespace freestand::cli {

using json = nlohmann::ordered_json;

/// Parses args (no command name) against desc: UsageError naming the option, as the command
/// line does ("see freestand COMMAND --help").
po::variables_map parse_document_options(const std::string& command,
                                         const po::options_description& desc,
                                         const std::vector<std::string>& args);

// --- spectrum, target -------------------------------------------------------------------------

/// --damping, --fmin, --fmax, --per-decade, --frequencies (`spectrum`'s defaults).
po::options_description spectrum_grid_options();
/// `spectrum --json`: the record's measures and its PSA, SD and PSV per damping on the grid of
/// the options.
json spectrum_document(const core::Record& record, const po::variables_map& grid);

/// `target`'s options (design name, design values, grid, --vertical).
po::options_description target_options();
/// The design spectra the options name, one per damping.
std::vector<spectra::Spectrum> target_spectra(const po::variables_map& vm);
/// `target --json`.
json target_document(const po::variables_map& vm, const std::vector<spectra::Spectrum>& spectra);

// --- generate ---------------------------------------------------------------------------------

po::options_description generate_options();
struct GenerateRequest {
    motion::TargetSet targets;
    motion::GenerateOptions options;
};
/// Targets (design or file, with the realism ranges) and generation options from the options.
GenerateRequest generate_request(const po::variables_map& vm);
/// match.json; wall_s is null unless timing.
json match_document(const motion::TargetSet& targets, const motion::GeneratedSet& set,
                    bool timing);

}  // namespace freestand::cli
