#pragma once
/// Running a batch (README "Batch"): every component of a list assessed as `freestand assess`
/// assesses it (report::run_case), on worker threads, each failure kept in its row; then one
/// output folder with the summary and every assessed component's report folder, published as a
/// whole (core::publish_folder).
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "assess/run_settings.hpp"
#include "batch/list.hpp"
#include "core/publish.hpp"
#include "report/summary.hpp"

namespace freestand::batch {

/// One component's outcome: its summary row and its report folder's files (report_files:
/// name and bytes; none when it failed).
struct BatchRow {
    report::SummaryRow row;
    std::vector<core::OutputFile> files;
};

/// What a batch found: the summary's rows in list order and each component's report files.
struct BatchRun {
    report::Summary summary;
    std::vector<std::vector<core::OutputFile>> reports;  ///< by row; empty when it failed

    /// True when every component was assessed.
    bool all_assessed() const;
    /// The number of rows that failed.
    std::size_t failed() const;
};

/// The stamp of a batch of list: the tool, the build's commit, the list as given and its hash.
report::SummaryStamp batch_stamp(const BatchList& list, const std::string& commit);

/// Assesses the entries at indices (into list.entries) on run.threads worker threads (0: every
/// core; more than the entries are not started), through run.cache, returning their rows in the
/// order of indices. Deterministic: the rows and files are the same bytes whatever the thread
/// count and the cache, since each case is independent and its own seed drives its histories. A component that cannot be
/// assessed (its case file missing or bad, a numerical failure, an internal error) gets its row
/// with the error and its exit code class; the others run on. commit is the build's, for the
/// stamps.
std::vector<BatchRow> run_rows(const BatchList& list, const std::vector<std::size_t>& indices,
                               const assess::RunSettings& run, const std::string& commit);

/// A run from its stamp and every row in list order (a single run's, or a merge's).
BatchRun assemble(const report::SummaryStamp& stamp, std::vector<BatchRow> rows);

/// Every entry of the list: assemble(batch_stamp(list, commit), run_rows(list, all, ...)).
BatchRun run_batch(const BatchList& list, const assess::RunSettings& run,
                   const std::string& commit);

/// The batch folder's files: summary.md, summary.html, summary.csv, summary.json and
/// <name>/<file> for each file of each assessed component's report.
std::vector<core::OutputFile> batch_files(const BatchRun& run);

/// Publishes batch_files(run) as the whole content of dir. Throws IoError naming the path.
void write_batch(const std::filesystem::path& dir, const BatchRun& run);

/// One line per row for a terminal: "<name>: <component>: <verdict> (governing ..., margin ...,
/// decided by ...)" or "<name>: error: <message>", control characters shown as \xNN.
std::string row_line(const report::SummaryRow& row);

}  // namespace freestand::batch
