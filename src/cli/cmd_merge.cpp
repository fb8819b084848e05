// `freestand merge DIR...`: the shards of a `--shard K/N` run (fragility or batch) into the
// outputs the single run writes, byte for byte (docs/methods.md s.12).
#include "api/merge.hpp"
#include "cli/batch_output.hpp"
#include "cli/command.hpp"
#include "cli/fragility_output.hpp"
#include "cli/options.hpp"

// The command's own namespace: the command files share a unity build (src/cli/CMakeLists.txt).
namespace freestand::cli::merge_command {
namespace {

const char* const usage = "DIR_OR_SHARD... --out DIR [--json]";

po::options_description merge_options() {
    po::options_description desc("options");
    desc.add_options()("shards", po::value<std::vector<std::string>>()->required(),
                       "folders holding shard-K-of-N.jsonl files, or the files")(
        "out", po::value<std::string>()->required(), "output folder")(
        "json", po::bool_switch(), "print the result's JSON to stdout instead of the summary");
    return desc;
}

int run(const std::vector<std::string>& args) {
    const auto vm = parse_options("merge", usage, merge_options(), args, {"shards..."});
    if (!vm) return 0;
    api::MergeRequest request;
    for (const std::string& p : (*vm)["shards"].as<std::vector<std::string>>())
        request.shards.emplace_back(p);
    const api::MergeResult merged = api::merge(request);
    const std::filesystem::path out = (*vm)["out"].as<std::string>();
    const bool json = (*vm)["json"].as<bool>();
    if (merged.fragility) {
        write_fragility_outputs(merged.fragility->result, merged.fragility->stamp, out, json);
        return 0;
    }
    // A batch merges to the single run's folder and exit code (1 when a component failed).
    return write_batch_outputs(*merged.batch, out, json, "");
}

const CommandRegistrar reg{{"merge", "combine --shard K/N outputs into the single run's outputs", &run}};

}  // namespace
}  // namespace freestand::cli::merge_command
