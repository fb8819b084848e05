#pragma once
/// A batch's shard lines (`batch --shard K/N`, issue 14) and their merge: the run's header and
/// one record per component carrying its whole summary row and its report folder's files
/// (names and bytes), so `freestand merge` rebuilds the single run's folder byte for byte
/// without assessing anything. Doubles are written in shortest round-trip form: the merged
/// summary rounds the very numbers the single run rounds.
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "batch/run.hpp"

namespace freestand::batch {

/// The shard header's "run": the summary stamp and every component's name in list order;
/// identical in every shard of one run (cli::read_shards compares it).
nlohmann::ordered_json shard_run_json(const report::SummaryStamp& stamp, const BatchList& list);

/// One record: {"index": its place in the list, "row": the summary row, "files": [[name,
/// contents], ...]}.
nlohmann::ordered_json shard_record(std::size_t index, const BatchRow& row);

/// The run the shards of a batch make. records: every shard's records, in any order. Throws
/// InputError (field "shards") when the header or a record is malformed, a record's index is
/// outside the list or given twice, its name is not the list's name at that index, or a
/// component is in no record.
BatchRun merge_shards(const nlohmann::json& run, const std::vector<nlohmann::json>& records);

/// The indices of a list of count entries that shard k of n computes: i with i % n == k - 1
/// (every n-th component, so slow ones spread over the shards).
std::vector<std::size_t> shard_indices(std::size_t count, int k, int n);

}  // namespace freestand::batch
