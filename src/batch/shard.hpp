#pragma once
/// A batch's shard lines (`batch --shard K/N`, docs/methods.md s.12) and their merge: the run's
/// header and one record per component carrying its whole summary row and its report folder's files
/// (names and bytes), so `freestand merge` rebuilds the single run's folder byte for byte without
/// assessing anything. Doubles are written in shortest round-trip form: the merged summary rounds
/// the very numbers the single run rounds.
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "batch/run.hpp"
#include "core/errors.hpp"

namespace freestand::batch {

/// The shard header's "run": the summary stamp and every component's name in list order;
/// identical in every shard of one run (fragility::join_shards compares it).
nlohmann::ordered_json shard_run_json(const report::SummaryStamp& stamp, const BatchList& list);

/// One record: {"index": its place in the list, "row": the summary row, "files": [[name,
/// contents], ...]}.
nlohmann::ordered_json shard_record(std::size_t index, const BatchRow& row);

/// The run the shards of a batch make. records: every shard's records, in any order; run_at and
/// record_at (one per record) say where the header and each record stand (file and line), for
/// the messages. Checks every value before anything is built, and throws InputError "malformed
/// batch shard" naming the file, line and field when the header or a record is malformed: a
/// missing key or a wrong type, a component name that cannot name a folder or is given twice,
/// a record's index outside the list or given twice, its name not the list's name at that
/// index, a component in no record; a row whose status and exit code disagree (assessed: exit
/// code 0, no error, the case's SHA-256; failed: an error and exit code 3, 4, 5 or 70), whose
/// verdict kind, verdict text and margin text disagree (assess::verdict_text_fits), whose
/// governing PGA is outside (0, 3] g or direction not x or y, whose margin is negative; report
/// files for a failed row or none for an assessed one, a file name that is not a plain name or
/// is listed twice.
BatchRun merge_shards(const nlohmann::json& run, const std::vector<nlohmann::json>& records,
                      const SourceLocation& run_at = {},
                      const std::vector<SourceLocation>& record_at = {});

/// The indices of a list of count entries that shard k of n computes: i with i % n == k - 1
/// (every n-th component, so slow ones spread over the shards).
std::vector<std::size_t> shard_indices(std::size_t count, int k, int n);

}  // namespace freestand::batch
