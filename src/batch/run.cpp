#include "batch/run.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "core/errors.hpp"
#include "core/printable.hpp"
#include "core/version.hpp"

namespace freestand::batch {

bool BatchRun::all_assessed() const { return failed() == 0; }

std::size_t BatchRun::failed() const {
    return static_cast<std::size_t>(
        std::count_if(summary.rows.begin(), summary.rows.end(),
                      [](const report::SummaryRow& r) { return !r.outcome; }));
}

report::SummaryStamp batch_stamp(const BatchList& list, const std::string& commit) {
    return {core::version(), commit, list.source, list.sha256};
}

BatchRun assemble(const report::SummaryStamp& stamp, std::vector<BatchRow> rows) {
    BatchRun run;
    run.summary.stamp = stamp;
    for (BatchRow& r : rows) {
        run.summary.rows.push_back(std::move(r.row));
        run.reports.push_back(std::move(r.files));
    }
    return run;
}

std::vector<core::OutputFile> batch_files(const BatchRun& run) {
    const report::RenderedSummary s = report::render_summary(run.summary);
    const std::vector<std::string>& names = report::summary_file_names();
    std::vector<core::OutputFile> files{
        {names[0], s.markdown}, {names[1], s.html}, {names[2], s.csv}, {names[3], s.json}};
    for (std::size_t i = 0; i < run.reports.size(); ++i) {
        for (const core::OutputFile& f : run.reports[i])
            files.push_back({run.summary.rows[i].name + "/" + f.name, f.contents});
    }
    return files;
}

void write_batch(const std::filesystem::path& dir, const BatchRun& run) {
    core::publish_folder(dir, batch_files(run));
}

std::string row_line(const report::SummaryRow& row) {
    // One line per row: the name's line breaks and bidirectional overrides are shown, not obeyed.
    if (!row.outcome) return core::printable_name(row.name) + ": error: " + core::printable(row.error);
    const report::SummaryOutcome& o = *row.outcome;
    std::string out = fmt::format("{}: {}: {} (governing {}, margin {}, decided by {})", row.name,
                                  o.component, o.verdict, o.governing_level, o.margin_text,
                                  o.decided_by);
    for (const std::string& c : o.open_conditions) out += "; open condition: " + c;
    // Case text (a component's name) must not drive the terminal.
    return core::printable_name(out);
}

}  // namespace freestand::batch
