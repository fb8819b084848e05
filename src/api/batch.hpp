#pragma once
/// batch: a facility's equipment list (batch/list.hpp), every component assessed as assess
/// assesses one (api::assess_report), on worker threads, each failure kept in its row
/// (README "Batch").
#include <array>
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "assess/run_settings.hpp"
#include "batch/list.hpp"
#include "batch/run.hpp"

namespace freestand::api {

struct BatchRequest {
    std::filesystem::path list;  ///< a folder of case files, or a .csv or .toml list
    /// {k, n}: only every n-th component from the k-th (1 <= k <= n); all when absent.
    std::optional<std::array<int, 2>> shard;
    std::string commit;        ///< the build's commit, for the stamps
    assess::RunSettings run;   ///< worker threads (0: every core), caches, progress
};

/// The request's list (batch::read_batch_list): InputError with field `list` for a path that is
/// no folder, .csv or .toml file, IoError when unreadable, InputError on bad content.
batch::BatchList read_list(const BatchRequest& request);

/// The indices into list.entries the request's shard assesses, in list order.
std::vector<std::size_t> shard_entries(const batch::BatchList& list, const BatchRequest& request);

/// Assesses the entries at indices on request.run.threads worker threads (more than the entries
/// are not started), returning their rows in the order of indices. Deterministic: the rows and
/// files are the same bytes whatever the thread count and the cache, since each case is
/// independent and its own seed drives its histories. A component that cannot be assessed (its
/// case file missing or bad, two [[unit]] tables, a numerical failure, an internal error) gets
/// its row with the error and its exit code class; the others run on. The progress reported is
/// the components', not each case's steps.
std::vector<batch::BatchRow> run_rows(const batch::BatchList& list,
                                      const std::vector<std::size_t>& indices,
                                      const BatchRequest& request);

/// Every entry of the list: batch::assemble(batch_stamp(list, commit), run_rows(all entries)).
batch::BatchRun run_batch(const batch::BatchList& list, const BatchRequest& request);

}  // namespace freestand::api
