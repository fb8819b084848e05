// `freestand merge DIR...`: the shards of a `--shard K/N` run (fragility or batch) into the
// outputs the single run writes, byte for byte (docs/methods.md s.12).
#include <fmt/format.h>

#include <iostream>

#include "batch/shard.hpp"
#include "cli/batch_output.hpp"
#include "cli/command.hpp"
#include "cli/fragility_output.hpp"
#include "cli/options.hpp"
#include "cli/shards.hpp"
#include "core/errors.hpp"
#include "fragility/serialize.hpp"

// The command's own namespace: the command files share a unity build (src/cli/CMakeLists.txt).
namespace freestand::cli::merge_command {
namespace {

const char* const usage = "DIR_OR_SHARD... --out DIR [--json]";

void merge_fragility(const ShardSet& set, const std::filesystem::path& out, bool json) {
    const SourceLocation header_at{set.run_at.file, set.run_at.line, "run.meta"};
    if (!set.run.is_object() || !set.run.contains("meta") || !set.run.contains("stamp"))
        throw InputError(SourceLocation{set.run_at.file, set.run_at.line, "run"},
                         "malformed fragility shard: expected {\"meta\", \"stamp\"}");
    const fragility::Meta meta = fragility::meta_from_json(set.run.at("meta"), header_at);
    report::Stamp stamp;
    try {
        stamp = report::stamp_from_json(set.run.at("stamp"));
    } catch (const nlohmann::json::exception& e) {
        throw InputError(SourceLocation{set.run_at.file, set.run_at.line, "run.stamp"},
                         fmt::format("malformed fragility shard ({})", e.what()));
    }
    // Every sample is checked against the run before anything is aggregated or written.
    std::vector<fragility::SampleResult> samples =
        fragility::samples_from_json(set.records, set.record_at, meta);
    fragility::Result r;
    try {
        r = fragility::aggregate(meta, std::move(samples));
    } catch (const std::invalid_argument& e) {
        throw InputError(SourceLocation{"", 0, "shards"}, e.what());
    }
    write_fragility_outputs(r, stamp, out, json);
}

int run(const std::vector<std::string>& args) {
    po::options_description desc("options");
    desc.add_options()("shards", po::value<std::vector<std::string>>()->required(),
                       "folders holding shard-K-of-N.jsonl files, or the files")(
        "out", po::value<std::string>()->required(), "output folder")(
        "json", po::bool_switch(), "print the result's JSON to stdout instead of the summary");
    const auto vm = parse_options("merge", usage, desc, args, {"shards..."});
    if (!vm) return 0;
    std::vector<std::filesystem::path> paths;
    for (const std::string& p : (*vm)["shards"].as<std::vector<std::string>>()) paths.emplace_back(p);
    const ShardSet set = read_shards(paths);
    const std::filesystem::path out = (*vm)["out"].as<std::string>();
    if (set.kind == "fragility") {
        merge_fragility(set, out, (*vm)["json"].as<bool>());
        return 0;
    }
    // A batch merges to the single run's folder and exit code (1 when a component failed).
    if (set.kind == "batch")
        return write_batch_outputs(batch::merge_shards(set.run, set.records, set.run_at,
                                                       set.record_at),
                                   out,
                                   (*vm)["json"].as<bool>(), "");
    throw InputError(SourceLocation{"", 0, "shards"},
                     fmt::format("shards of kind \"{}\"; this build merges \"fragility\" and "
                                 "\"batch\"",
                                 set.kind));
}

const CommandRegistrar reg{{"merge", "combine --shard K/N outputs into the single run's outputs", &run}};

}  // namespace
}  // namespace freestand::cli::merge_command
