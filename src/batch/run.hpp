#pragma once
/// A batch's outcome (README "Batch"): a row per component of a list, assessed or failed
/// (api/batch.hpp runs them), and one output folder with the summary and every assessed
/// component's report folder, published as a whole (core::publish_folder).
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

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

/// A run from its stamp and every row in list order (a single run's, or a merge's).
BatchRun assemble(const report::SummaryStamp& stamp, std::vector<BatchRow> rows);

/// The batch folder's files: summary.md, summary.html, summary.csv, summary.json and
/// <name>/<file> for each file of each assessed component's report.
std::vector<core::OutputFile> batch_files(const BatchRun& run);

/// Publishes batch_files(run) as the whole content of dir. Throws IoError naming the path.
void write_batch(const std::filesystem::path& dir, const BatchRun& run);

/// One line per row for a terminal: "<name>: <component>: <verdict> (governing ..., margin ...,
/// decided by ...)" or "<name>: error: <message>", control characters shown as \xNN.
std::string row_line(const report::SummaryRow& row);

}  // namespace freestand::batch
