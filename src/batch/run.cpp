#include "batch/run.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <exception>

#include "core/errors.hpp"
#include "core/file_io.hpp"
#include "core/parallel.hpp"
#include "core/printable.hpp"
#include "core/sha256.hpp"
#include "core/version.hpp"
#include "report/run.hpp"

namespace freestand::batch {

namespace {

// The error of a failed row; an input error of an overridden case says which values the list
// replaced, since they have no line in the case file.
void fail_row(report::SummaryRow& row, const BatchEntry& e, const BatchList& list,
              const std::string& message, ExitCode code, bool input) {
    row.error = message;
    if (input && !e.overrides.empty())
        row.error += fmt::format(" (with {} from {}:{})", row.overrides, list.source, e.line);
    row.exit_code = static_cast<int>(code);
}

BatchRow run_entry(const BatchEntry& e, const BatchList& list, const std::string& commit,
                  const assess::RunSettings& settings) {
    BatchRow out;
    report::SummaryRow& row = out.row;
    row.name = e.name;
    row.case_file = e.case_file.string();
    row.overrides = assess::describe(e.overrides);
    try {
        const std::string bytes = core::read_input_file(e.case_file);
        row.case_sha256 = core::sha256_hex(bytes);
        report::CaseRun run =
            report::run_case(bytes, e.case_file, e.overrides, commit, settings);
        // Both before either is kept: a row is assessed with its files or failed without.
        std::vector<core::OutputFile> files = report::report_files(run.rendered);
        report::SummaryOutcome outcome = report::summary_outcome(run.result);
        out.files = std::move(files);
        row.outcome = std::move(outcome);
    } catch (const InputError& err) {
        fail_row(row, e, list, err.what(), err.code(), true);
    } catch (const Error& err) {
        fail_row(row, e, list, err.what(), err.code(), false);
    } catch (const std::exception& err) {
        fail_row(row, e, list, std::string("internal error: ") + err.what(), ExitCode::internal,
                 false);
    } catch (...) {
        fail_row(row, e, list, "internal error: an unknown exception", ExitCode::internal, false);
    }
    return out;
}

}  // namespace

bool BatchRun::all_assessed() const { return failed() == 0; }

std::size_t BatchRun::failed() const {
    return static_cast<std::size_t>(
        std::count_if(summary.rows.begin(), summary.rows.end(),
                      [](const report::SummaryRow& r) { return !r.outcome; }));
}

report::SummaryStamp batch_stamp(const BatchList& list, const std::string& commit) {
    return {core::version(), commit, list.source, list.sha256};
}

std::vector<BatchRow> run_rows(const BatchList& list, const std::vector<std::size_t>& indices,
                               const assess::RunSettings& run, const std::string& commit) {
    const std::size_t n = indices.size();
    std::vector<BatchRow> rows(n);
    const auto threads = static_cast<std::size_t>(core::thread_count(run.threads));
    const std::size_t workers = std::clamp<std::size_t>(threads, 1, std::max<std::size_t>(n, 1));
    // One component per worker; a case's own histories and simulations share the threads left
    // over, so workers do not each take every core. No result depends on the counts. The
    // progress reported is the components', not each case's steps.
    assess::RunSettings inner = run;
    inner.threads = static_cast<int>(std::max<std::size_t>(1, threads / workers));
    inner.progress = nullptr;
    core::parallel_for(
        n, static_cast<int>(workers),
        [&](std::size_t i) { rows[i] = run_entry(list.entries.at(indices[i]), list, commit, inner); },
        [&](std::size_t done, std::size_t total) {
            if (run.progress) run.progress("components", done, total);
        });
    return rows;
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

BatchRun run_batch(const BatchList& list, const assess::RunSettings& run,
                   const std::string& commit) {
    std::vector<std::size_t> all(list.entries.size());
    for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
    return assemble(batch_stamp(list, commit), run_rows(list, all, run, commit));
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
