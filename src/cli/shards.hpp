#pragma once
/// Shard files of `--shard K/N` runs and their reading by `freestand merge`: JSON lines, the
/// first a header {"freestand_shard": 1, "kind", "shard", "of", "run"} (run: everything that
/// defines the whole run, identical in every shard), then one record per line.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/errors.hpp"

namespace freestand::cli {

/// DIR/shard-K-of-N.jsonl, written atomically.
std::filesystem::path write_shard(const std::filesystem::path& dir, const std::string& kind,
                                  int k, int n, const nlohmann::ordered_json& run,
                                  const std::vector<nlohmann::ordered_json>& records);

struct ShardSet {
    std::string kind;
    nlohmann::json run;
    SourceLocation run_at;                 ///< the first shard's header: file, line 1
    std::vector<nlohmann::json> records;  ///< in shard order, then file order
    std::vector<SourceLocation> record_at;  ///< each record's file and line
};

/// Every shard-*.jsonl in the given folders (or the files given), UTF-8 (a BOM dropped, UTF-16
/// refused: core::text::utf8_text). InputError naming file:line for a malformed line; InputError when the shards mix kinds or runs, or do not cover 1..N
/// exactly once (naming the missing or repeated shard); IoError for an unreadable path.
ShardSet read_shards(const std::vector<std::filesystem::path>& paths);

}  // namespace freestand::cli
