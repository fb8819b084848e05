#pragma once
/// Running a batch (issue 14): every component of a list assessed as `freestand assess`
/// assesses it (report::run_case), on worker threads, each failure kept in its row; then one
/// output folder with the summary and every assessed component's report folder, published as a
/// whole (core::publish_folder).
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "batch/list.hpp"
#include "core/publish.hpp"
#include "report/render.hpp"
#include "report/summary.hpp"

namespace freestand::batch {

/// What a batch found: the summary's rows in list order and each assessed component's report.
struct BatchRun {
    report::Summary summary;
    std::vector<std::optional<report::Rendered>> reports;  ///< by row; absent when it failed

    /// True when every component was assessed.
    bool all_assessed() const;
};

/// Assesses every entry on `threads` worker threads (>= 1; more than the entries are not
/// started). Deterministic: the rows, reports and summary are the same bytes whatever the
/// thread count, since each case is independent and its own seed drives its histories. A
/// component that cannot be assessed (its case file missing or bad, a numerical failure, an
/// internal error) gets its row with the error and its exit code class; the others run on.
/// commit is the build's, for the stamps.
BatchRun run_batch(const BatchList& list, unsigned threads, const std::string& commit);

/// The batch folder's files: summary.md, summary.html, summary.csv, summary.json and
/// <name>/<file> for each file of each assessed component's report (report::report_files).
std::vector<core::OutputFile> batch_files(const BatchRun& run);

/// Publishes batch_files(run) as the whole content of dir. Throws IoError naming the path.
void write_batch(const std::filesystem::path& dir, const BatchRun& run);

/// One line per row for a terminal: "<name>: <component>: <verdict> (governing ..., margin ...,
/// decided by ...)" or "<name>: error: <message>".
std::string row_line(const report::SummaryRow& row);

}  // namespace freestand::batch
