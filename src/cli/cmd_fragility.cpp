// `freestand fragility`: P(overturn), P(slide > allowable), P(theta/alpha > 1/FS) against PGA
// (docs/methods.md s.9); one machine, a shard of a run, or MPI ranks.
#include <fmt/format.h>

#include <cmath>
#include <iostream>
#include <thread>

#include "cli/command.hpp"
#include "cli/documents.hpp"
#include "cli/fragility_output.hpp"
#include "cli/mpi_split.hpp"
#include "cli/options.hpp"
#include "cli/run_options.hpp"
#include "cli/shards.hpp"
#include "core/errors.hpp"
#include "core/file_io.hpp"
#include "core/printable.hpp"
#include "fragility/serialize.hpp"
#include "report/pdf.hpp"

// The command's own namespace: the command files share a unity build (src/cli/CMakeLists.txt).
namespace freestand::cli::fragility_command {
namespace {

const char* const usage =
    "CASE.toml [--pga 0.1:1.0:0.1] [--samples 100] [--records FILE...] [--pool 20] [--seed S] "
    "[--threads T] [--cache DIR | --no-cache] [--out DIR] [--json] [--shard K/N] [--pdf]";

int run(const std::vector<std::string>& args) {
    po::options_description desc = fragility_options();
    desc.add_options()("case", po::value<std::string>()->required(), "case file (TOML)")(
        "out", po::value<std::string>(), "output folder (default: out/<case stem>-fragility/)")(
        "json", po::bool_switch(), "print fragility.json to stdout instead of the summary")(
        "shard", po::value<std::string>(),
        "K/N: compute only this share of the samples and write out/shard-K-of-N.jsonl for "
        "`freestand merge`")(
        "pdf", po::bool_switch(),
        "also write report.pdf: the HTML report paged for print (A4, page N of M), made by "
        "WeasyPrint (scripts/setup.sh installs it); not with --shard, which writes no report");
    const auto vm = parse_options("fragility", usage, desc, args, {"case"});
    if (!vm) return 0;
    const bool pdf = (*vm)["pdf"].as<bool>();
    if (pdf && vm->count("shard"))
        throw UsageError("--pdf makes report.pdf from report.html, which --shard does not write "
                         "(the merged run's report is made by `freestand merge`)");
    // A missing converter stops the command before the samples, not after them.
    std::optional<std::filesystem::path> converter;
    if (pdf) converter = report::find_pdf_converter();
    const std::filesystem::path case_file = (*vm)["case"].as<std::string>();
    const std::string bytes = core::read_input_file(case_file);
    const assess::Case c = assess::parse_case(bytes, case_file.string());
    const fragility::Config cfg = fragility_config(*vm, c);
    const RunContext run(*vm);
    const std::filesystem::path out =
        vm->count("out") ? std::filesystem::path((*vm)["out"].as<std::string>())
                         : std::filesystem::path("out") / (case_file.stem().string() + "-fragility");
    fragility::Runner runner(c, cfg);
    const fragility::Meta meta = fragility::make_meta(c, cfg);
    const report::Stamp stamp = fragility_stamp(bytes, case_file.string(), c, cfg);

    // Which samples this process computes: all; a shard's share; or an MPI rank's share.
    std::array<int, 2> share{1, 1};
    if (vm->count("shard")) share = parse_shard((*vm)["shard"].as<std::string>(), "--shard");
    const MpiSplit mpi;
    if (vm->count("shard") && mpi.size() > 1)
        throw UsageError("--shard and MPI ranks split the samples two ways; give one");
    if (mpi.size() > 1) share = {mpi.rank() + 1, mpi.size()};
    std::vector<std::size_t> mine;
    for (std::size_t g = 0; g < runner.total(); ++g)
        if (static_cast<int>(g % static_cast<std::size_t>(share[1])) == share[0] - 1)
            mine.push_back(g);

    runner.prepare(run.settings());
    std::vector<fragility::SampleResult> samples;
    try {
        samples = fragility::run_samples(runner, mine, run.settings().threads,
                                         [&](std::size_t done, std::size_t total) {
                                             if (mpi.rank() == 0 && run.settings().progress)
                                                 run.settings().progress("samples", done, total);
                                         });
    } catch (const Error& e) {
        if (mpi.size() == 1) throw;
        std::cerr << "freestand fragility: error on MPI rank " << mpi.rank() << ": "
                  << core::printable(e.what()) << "\n";
        mpi.abort(static_cast<int>(e.code()));
    }
    run.finish("fragility");

    if (vm->count("shard")) {
        std::vector<nlohmann::ordered_json> records;
        for (const auto& s : samples) records.push_back(fragility::to_json(s));
        const auto file = write_shard(out, "fragility", share[0], share[1],
                                      fragility_run_json(meta, stamp), records);
        std::cout << fmt::format("shard {} of {}: {} of {} samples written to {}\n", share[0],
                                 share[1], samples.size(), runner.total(), file.string());
        return 0;
    }
    if (mpi.size() > 1) {
        samples = mpi.gather_to_root(samples);
        if (mpi.rank() != 0) return 0;
    }
    const bool json = (*vm)["json"].as<bool>();
    write_fragility_outputs(fragility::aggregate(meta, std::move(samples)), stamp, out, json,
                            converter);
    if (mpi.size() > 1 && !json)
        std::cout << fmt::format("samples computed on {} MPI ranks\n", mpi.size());
    return 0;
}

const CommandRegistrar reg{
    {"fragility", "P(overturn), P(slide), P(rock) against PGA: fragility.json, report, samples.csv",
     &run}};

}  // namespace
}  // namespace freestand::cli::fragility_command
