// `freestand batch`: a facility's equipment list assessed in one run (README "Batch").
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <iostream>
#include <optional>

#include "api/batch.hpp"
#include "batch/run.hpp"
#include "batch/shard.hpp"
#include "cli/batch_output.hpp"
#include "cli/build_info.hpp"
#include "cli/command.hpp"
#include "cli/options.hpp"
#include "cli/run_options.hpp"
#include "cli/shards.hpp"
#include "core/errors.hpp"
#include "core/parallel.hpp"
#include "cli/usage_error.hpp"

// The command's own namespace: the command files share a unity build (src/cli/CMakeLists.txt).
namespace freestand::cli::batch_command {
namespace {

const char* const usage =
    "LIST [--out DIR] [--threads T] [--cache DIR | --no-cache] [--json] [--shard K/N]\n\n"
    "LIST is a folder (every *.toml case in it, sorted by name, not sub-folders) or a list\n"
    "file: CSV (.csv, RFC 4180) with a header row naming the columns, or TOML (.toml) with one\n"
    "[[case]] table per component. Columns / keys: file (required; relative to the list's\n"
    "folder), name (the report folder; default the file's stem), pga_g (CSV: 0.1;0.2;0.3, TOML:\n"
    "an array), base_material (replaces the case's whole base description), seed,\n"
    "histories_per_level. A value given replaces the case file's, as if the file carried it.\n\n"
    "Writes DIR/summary.{md,html,csv,json} and DIR/<name>/ for each assessed component, the\n"
    "folder `freestand assess CASE --out DIR/<name>` writes, all published as a whole.\n"
    "A component that fails (missing or bad case file, numerical failure) gets its row with the\n"
    "error and its exit class, and the others run on. Exit 0 when every component was\n"
    "assessed, 1 when one failed; a bad list is exit 3 (2 a path that is no list, 5\n"
    "unreadable) before anything runs.\n\n"
    "--shard K/N assesses every N-th component from the K-th and writes only\n"
    "DIR/shard-K-of-N.jsonl; `freestand merge` of all N writes the folder this run would,\n"
    "byte for byte (give every shard the same LIST path and build)";

// Shard k of n: its components' rows and report files as JSON lines for `freestand merge`.
int run_shard(const batch::BatchList& list, const api::BatchRequest& request,
              const RunContext& run, const std::filesystem::path& out) {
    const std::vector<std::size_t> mine = api::shard_entries(list, request);
    const std::vector<batch::BatchRow> rows = api::run_rows(list, mine, request);
    run.finish("batch");
    std::vector<nlohmann::ordered_json> records;
    std::size_t failed = 0;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        records.push_back(batch::shard_record(mine[i], rows[i]));
        if (!rows[i].row.outcome) {
            ++failed;
            std::cout << batch::row_line(rows[i].row) << "\n";
        }
    }
    const auto [k, n] = *request.shard;
    const auto file = write_shard(out, "batch", k, n,
                                  batch::shard_run_json(batch::batch_stamp(list, build_commit), list),
                                  records);
    std::cout << fmt::format("shard {} of {}: {} of {} components ({} failed) written to {}\n",
                             k, n, rows.size(), list.entries.size(), failed, file.string());
    return failed == 0 ? 0 : static_cast<int>(ExitCode::failure);
}

// The list, a path that is no list being a usage error of the LIST argument.
batch::BatchList list_argument(const api::BatchRequest& request) {
    try {
        return api::read_list(request);
    } catch (const InputError& e) {
        if (e.where().field == "list") throw UsageError(e.where().file + ": " + e.message());
        throw;
    }
}

int run(const std::vector<std::string>& args) {
    po::options_description desc("options");
    desc.add_options()("list", po::value<std::string>()->required(),
                       "folder of case files, or a .csv or .toml list")(
        "out", po::value<std::string>()->default_value("out/batch"),
        "output folder (summary files and one report folder per component; with --shard, the "
        "folder of the shard file)")(
        "json", po::bool_switch(), "print the summary as JSON on stdout (also written as "
                                   "summary.json)")(
        "shard", po::value<std::string>(),
        "K/N: assess only this share of the components and write DIR/shard-K-of-N.jsonl for "
        "`freestand merge`");
    // Each worker thread assesses one component at a time; a case's own work shares the threads
    // left over.
    add_run_options(desc);
    const auto vm = parse_options("batch", usage, desc, args, {"list"});
    if (!vm) return 0;
    const RunContext run(*vm);
    const bool json = (*vm)["json"].as<bool>();
    api::BatchRequest request;
    request.list = (*vm)["list"].as<std::string>();
    if (vm->count("shard")) request.shard = parse_shard((*vm)["shard"].as<std::string>(), "--shard");
    if (request.shard && json)
        throw UsageError("--json prints the whole batch's summary; give it to `freestand merge`, "
                         "not to a --shard run");
    request.commit = build_commit;
    request.run = run.settings();
    const std::filesystem::path out = (*vm)["out"].as<std::string>();
    const batch::BatchList list = list_argument(request);
    if (request.shard) return run_shard(list, request, run, out);
    core::check_publish_target(out);
    const auto start = std::chrono::steady_clock::now();
    const batch::BatchRun r = api::run_batch(list, request);
    const double run_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    run.finish("batch");
    const auto threads = static_cast<std::size_t>(core::thread_count(request.run.threads));
    // Timing goes to stdout only, never into the outputs (byte-identical per input).
    return write_batch_outputs(
        r, out, json,
        fmt::format(", in {:.2f} s on {} thread(s)", run_s,
                    std::min<std::size_t>(threads, std::max<std::size_t>(1, r.summary.rows.size()))));
}

const CommandRegistrar reg{
    {"batch",
     "assess a list of components (a folder, CSV or TOML list): summary.md/html/csv/json and "
     "each component's report",
     &run}};

}  // namespace
}  // namespace freestand::cli::batch_command
