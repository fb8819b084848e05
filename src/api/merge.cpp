#include "api/merge.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "batch/shard.hpp"
#include "core/errors.hpp"
#include "fragility/serialize.hpp"

namespace freestand::api {

MergedFragility merge_fragility(const fragility::ShardSet& set) {
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
    try {
        return {fragility::aggregate(meta, std::move(samples)), stamp};
    } catch (const std::invalid_argument& e) {
        throw InputError(SourceLocation{"", 0, "shards"}, e.what());
    }
}

MergeResult merge(const MergeRequest& request) {
    const fragility::ShardSet set = fragility::read_shards(request.shards);
    MergeResult out{request, set.kind, std::nullopt, std::nullopt};
    if (set.kind == "fragility")
        out.fragility = merge_fragility(set);
    else if (set.kind == "batch")
        out.batch = batch::merge_shards(set.run, set.records, set.run_at, set.record_at);
    else
        throw InputError(SourceLocation{"", 0, "shards"},
                         fmt::format("shards of kind \"{}\"; this build merges \"fragility\" and "
                                     "\"batch\"",
                                     set.kind));
    return out;
}

}  // namespace freestand::api
