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
#include "fragility/fragility.hpp"
#include "report/json.hpp"
#include "rocking/summary.hpp"
#include "sliding/asce.hpp"
#include "sliding/initiation.hpp"

namespace freestand::cli {

using json = nlohmann::ordered_json;

/// Parses args (no command name) against desc: UsageError naming the option, as the command
/// line does ("see freestand COMMAND --help").
po::variables_map parse_document_options(const std::string& command,
                                         const po::options_description& desc,
                                         const std::vector<std::string>& args);

// --- closed forms -----------------------------------------------------------------------------

po::options_description slide_options();
struct SlideRun {
    sliding::SlidingInput input;
    sliding::SlidingEstimate estimate;
};
SlideRun slide_run(const po::variables_map& vm);
json slide_json(const SlideRun& run);

po::options_description rock_options();
struct RockRun {
    rocking::RockingInput input;
    rocking::RockingChecks checks;
};
RockRun rock_run(const po::variables_map& vm);
json rock_json(const RockRun& run);

// --- simulate (planar rigid block) ------------------------------------------------------------

/// The block, friction, restitution and integrator options of `simulate` (not the excitation).
po::options_description simulate_model_options();
/// The block the options describe (--block, --cg, --inertia).
block::Block simulate_block(const po::variables_map& vm);
/// The planar rigid-block model on blk (--mu, --mu-k, --restitution, --top).
dynamics::BlockModel simulate_model(const po::variables_map& vm, const block::Block& blk);
/// base with the integrator options (--integrator, --dt) applied.
dynamics::Options simulate_run_options(const po::variables_map& vm, dynamics::Options base);
/// `simulate --json`'s summary of one block.
json summary_json(const dynamics::Summary& s);

// --- fragility --------------------------------------------------------------------------------

/// --pga, --samples, --records, --pool, --seed and the run options (cli/run_options.hpp).
po::options_description fragility_options();
/// The sampling configuration; the seed defaults to the case's.
fragility::Config fragility_config(const po::variables_map& vm, const assess::Case& c);
/// The stamp of a fragility run: the case's bytes, the seed, the case's other inputs and the
/// records of a user suite, each hashed, and the build's commit.
report::Stamp fragility_stamp(const std::string& case_bytes, const std::string& case_file,
                              const assess::Case& c, const fragility::Config& config);
struct FragilityRun {
    fragility::Result result;
    report::Stamp stamp;
};
/// Every sample of the run on this machine, aggregated, with its stamp.
FragilityRun fragility_result(const std::string& case_bytes,
                              const std::filesystem::path& case_file,
                              const po::variables_map& vm);

}  // namespace freestand::cli
