#include "api/batch.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <exception>

#include "api/assess.hpp"
#include "batch/shard.hpp"
#include "core/errors.hpp"
#include "core/file_io.hpp"
#include "core/parallel.hpp"
#include "core/sha256.hpp"

namespace freestand::api {

namespace batch_detail {

// The error of a failed row; an input error of an overridden case says which values the list
// replaced, since they have no line in the case file.
void fail_row(report::SummaryRow& row, const batch::BatchEntry& e, const batch::BatchList& list,
              const std::string& message, ExitCode code, bool input) {
    row.error = message;
    if (input && !e.overrides.empty())
        row.error += fmt::format(" (with {} from {}:{})", row.overrides, list.source, e.line);
    row.exit_code = static_cast<int>(code);
}

batch::BatchRow run_entry(const batch::BatchEntry& e, const batch::BatchList& list,
                          const BatchRequest& request, const assess::RunSettings& settings) {
    batch::BatchRow out;
    report::SummaryRow& row = out.row;
    row.name = e.name;
    row.case_file = e.case_file.string();
    row.overrides = assess::describe(e.overrides);
    try {
        AssessRequest one;
        one.case_file = e.case_file;
        one.case_bytes = core::read_input_file(e.case_file);
        row.case_sha256 = core::sha256_hex(*one.case_bytes);
        one.overrides = e.overrides;
        one.single_component = true;
        one.commit = request.commit;
        one.run = settings;
        AssessReport r = assess_report(one);
        // Both before either is kept: a row is assessed with its files or failed without.
        report::SummaryOutcome outcome = report::summary_outcome(r.assessed.result);
        out.files = std::move(r.files);
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

}  // namespace batch_detail

batch::BatchList read_list(const BatchRequest& request) {
    return batch::read_batch_list(request.list);
}

std::vector<std::size_t> shard_entries(const batch::BatchList& list, const BatchRequest& request) {
    if (request.shard)
        return batch::shard_indices(list.entries.size(), (*request.shard)[0],
                                    (*request.shard)[1]);
    std::vector<std::size_t> all(list.entries.size());
    for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
    return all;
}

std::vector<batch::BatchRow> run_rows(const batch::BatchList& list,
                                      const std::vector<std::size_t>& indices,
                                      const BatchRequest& request) {
    const assess::RunSettings& run = request.run;
    const std::size_t n = indices.size();
    std::vector<batch::BatchRow> rows(n);
    const auto threads = static_cast<std::size_t>(core::thread_count(run.threads));
    const std::size_t workers = std::clamp<std::size_t>(threads, 1, std::max<std::size_t>(n, 1));
    // One component per worker; a case's own histories and simulations share the threads left
    // over, so workers do not each take every core. No result depends on the counts.
    assess::RunSettings inner = run;
    inner.threads = static_cast<int>(std::max<std::size_t>(1, threads / workers));
    inner.progress = nullptr;
    core::parallel_for(
        n, static_cast<int>(workers),
        [&](std::size_t i) {
            rows[i] = batch_detail::run_entry(list.entries.at(indices[i]), list, request, inner);
        },
        [&](std::size_t done, std::size_t total) {
            if (run.progress) run.progress("components", done, total);
        });
    return rows;
}

batch::BatchRun run_batch(const batch::BatchList& list, const BatchRequest& request) {
    BatchRequest whole = request;
    whole.shard.reset();
    return batch::assemble(batch::batch_stamp(list, request.commit),
                           run_rows(list, shard_entries(list, whole), request));
}

}  // namespace freestand::api
