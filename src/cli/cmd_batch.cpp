// `freestand batch`: a facility's equipment list assessed in one run (issue 14).
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <iostream>
#include <thread>

#include "batch/run.hpp"
#include "cli/build_info.hpp"
#include "cli/command.hpp"
#include "cli/options.hpp"
#include "core/errors.hpp"

namespace freestand::cli {
namespace {

const char* const usage =
    "LIST [--out DIR] [--threads T] [--json]\n\n"
    "LIST is a folder (every *.toml case in it, sorted by name, not sub-folders) or a list\n"
    "file: CSV (.csv, RFC 4180) with a header row naming the columns, or TOML (.toml) with one\n"
    "[[case]] table per component. Columns / keys: file (required; relative to the list's\n"
    "folder), name (the report folder; default the file's stem), pga_g (CSV: 0.1;0.2;0.3, TOML:\n"
    "an array), base_material (replaces the case's whole base description), seed,\n"
    "histories_per_level. A value given replaces the case file's, as if the file carried it.\n\n"
    "Writes DIR/summary.{md,html,csv,json} and DIR/<name>/ for each assessed component, the\n"
    "folder `freestand assess CASE --out DIR/<name>` writes, all published as a whole.\n"
    "A component that fails (missing or bad case file, numerical failure) gets its row with the\n"
    "error and the others run on. Exit 0 when every component was assessed, 1 when one failed;\n"
    "a bad list is exit 3 (2 a path that is no list, 5 unreadable) before anything runs";

unsigned parse_threads(const std::string& text) {
    const double t = parse_double(text, "--threads");
    if (!(t >= 1.0 && t <= 1024.0) || t != static_cast<double>(static_cast<unsigned>(t)))
        throw UsageError(fmt::format("--threads: expected a whole number in [1, 1024]; got {}",
                                     text));
    return static_cast<unsigned>(t);
}

int run(const std::vector<std::string>& args) {
    po::options_description desc("options");
    desc.add_options()("list", po::value<std::string>()->required(),
                       "folder of case files, or a .csv or .toml list")(
        "out", po::value<std::string>()->default_value("out/batch"),
        "output folder (summary files and one report folder per component)")(
        "threads", po::value<std::string>(),
        "worker threads, each assessing one component at a time (default: every core); the "
        "outputs are the same bytes whatever the count")(
        "json", po::bool_switch(), "print the summary as JSON on stdout (also written as "
                                   "summary.json)");
    const auto vm = parse_options("batch", usage, desc, args, {"list"});
    if (!vm) return 0;
    const unsigned threads = vm->count("threads")
                                 ? parse_threads((*vm)["threads"].as<std::string>())
                                 : std::max(1u, std::thread::hardware_concurrency());
    const std::filesystem::path out = (*vm)["out"].as<std::string>();
    const batch::BatchList list = batch::read_batch_list((*vm)["list"].as<std::string>());
    core::check_publish_target(out);
    const auto start = std::chrono::steady_clock::now();
    const batch::BatchRun r = batch::run_batch(list, threads, build_commit);
    batch::write_batch(out, r);
    const double run_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const std::size_t failed = static_cast<std::size_t>(
        std::count_if(r.summary.rows.begin(), r.summary.rows.end(),
                      [](const report::SummaryRow& row) { return !row.outcome; }));
    if ((*vm)["json"].as<bool>()) {
        std::cout << report::summary_json(r.summary).dump(2) << "\n";
    } else {
        for (const report::SummaryRow& row : r.summary.rows)
            std::cout << batch::row_line(row) << "\n";
        // Timing goes to stdout only, never into the outputs (byte-identical per input).
        std::cout << fmt::format("wrote {}: {} components, {} failed, in {:.2f} s on {} "
                                 "thread(s)\n",
                                 out.string(), r.summary.rows.size(), failed, run_s,
                                 std::min<std::size_t>(threads, r.summary.rows.size()));
    }
    return failed == 0 ? 0 : static_cast<int>(ExitCode::failure);
}

const CommandRegistrar reg{
    {"batch",
     "assess a list of components (a folder, CSV or TOML list): summary.md/html/csv/json and "
     "each component's report",
     &run}};

}  // namespace
}  // namespace freestand::cli
