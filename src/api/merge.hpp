#pragma once
/// merge: the shards of a `--shard K/N` run (fragility or batch) into the run the single process
/// makes, byte for byte (docs/methods.md s.12).
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "batch/run.hpp"
#include "fragility/fragility.hpp"
#include "fragility/shard_file.hpp"
#include "report/json.hpp"

namespace freestand::api {

struct MergeRequest {
    /// Folders holding shard-K-of-N.jsonl files, or the files.
    std::vector<std::filesystem::path> shards;
};

/// A merged fragility run: what `fragility` computes on one machine.
struct MergedFragility {
    fragility::Result result;
    report::Stamp stamp;
};

struct MergeResult {
    MergeRequest request;
    std::string kind;                         ///< "fragility" or "batch"
    std::optional<MergedFragility> fragility;  ///< with kind "fragility"
    std::optional<batch::BatchRun> batch;      ///< with kind "batch"
};

/// The shards read (fragility::read_shards: every shard of one run, once) and every record
/// checked against the run before anything is aggregated (fragility::samples_from_json,
/// batch::merge_shards). InputError naming the file, line and field; IoError for an unreadable
/// path.
MergeResult merge(const MergeRequest& request);

/// A fragility run from its shards, already read.
MergedFragility merge_fragility(const fragility::ShardSet& set);

}  // namespace freestand::api
