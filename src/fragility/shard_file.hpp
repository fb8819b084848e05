#pragma once
/// The shard file of a `--shard K/N` run (docs/methods.md s.12), whatever its records: JSON
/// lines, the first a header {"freestand_shard": 1, "kind", "shard", "of", "run"} ("run":
/// everything that defines the whole run, identical in every shard), then one record per line.
/// Fragility samples (fragility/serialize.hpp) and batch components (batch/shard.hpp) are its
/// records; reading a set of shards checks that they make one whole run.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/errors.hpp"

namespace freestand::fragility {

/// DIR/shard-K-of-N.jsonl (DIR created), written atomically.
std::filesystem::path write_shard(const std::filesystem::path& dir, const std::string& kind,
                                  int k, int n, const nlohmann::ordered_json& run,
                                  const std::vector<nlohmann::ordered_json>& records);

/// One shard file's header and records.
struct ShardFile {
    std::string file;
    std::string kind;
    int k = 0, n = 0;
    nlohmann::json run;
    std::vector<nlohmann::json> records;
    std::vector<int> record_lines;  ///< each record's line in the file
};

/// A shard file's text, UTF-8 (a BOM dropped, UTF-16 refused: core::text::utf8_text); file
/// names it in messages. InputError naming file:line for a line that is not JSON, a first line
/// that is not a header, or no line at all.
ShardFile parse_shard(const std::string& text, const std::string& file);

struct ShardSet {
    std::string kind;
    nlohmann::json run;
    SourceLocation run_at;                  ///< the first shard's header: file, line 1
    std::vector<nlohmann::json> records;    ///< in shard order, then file order
    std::vector<SourceLocation> record_at;  ///< each record's file and line
};

/// The shards as one run: InputError when they mix kinds or runs (kind, shard count or "run"
/// differ), or do not cover 1..N exactly once (naming the missing or repeated shard).
ShardSet join_shards(std::vector<ShardFile> shards);

/// Every shard-*.jsonl in the given folders (in name order), or the files given, parsed
/// (parse_shard) and joined (join_shards). InputError for a folder without shard files;
/// IoError for a path that does not exist or cannot be read.
ShardSet read_shards(const std::vector<std::filesystem::path>& paths);

}  // namespace freestand::fragility
