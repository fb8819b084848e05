// `freestand fragility`: P(overturn), P(slide > allowable), P(theta/alpha > 1/FS) against PGA
// (docs/methods.md s.9); one machine, a shard of a run, or MPI ranks.
#include <fmt/format.h>

#include <iostream>
#include <memory>

#include "api/fragility.hpp"
#include "cli/build_info.hpp"
#include "cli/command.hpp"
#include "cli/fragility_output.hpp"
#include "cli/mpi_split.hpp"
#include "cli/options.hpp"
#include "cli/progress.hpp"
#include "cli/run_options.hpp"
#include "core/errors.hpp"
#include "core/printable.hpp"
#include "fragility/shard_file.hpp"
#include "report/pdf.hpp"
#include "cli/usage_error.hpp"

// The command's own namespace: the command files share a unity build (src/cli/CMakeLists.txt).
namespace freestand::cli::fragility_command {
namespace {

const char* const usage =
    "CASE.toml [--pga 0.1:1.0:0.1] [--samples 100] [--records FILE...] [--pool 20] [--seed S] "
    "[--models planar|case] "
    "[--threads T] [--cache DIR | --no-cache] [--out DIR] [--json] [--shard K/N] [--pdf]";

po::options_description fragility_options() {
    po::options_description desc("options");
    desc.add_options()(
        "pga", po::value<std::string>()->default_value("0.1:1.0:0.1"),
        "PGA levels, g: START:STOP:STEP or a comma list")(
        "samples", po::value<std::string>()->default_value("100"), "samples per level")(
        "records", po::value<std::vector<std::string>>()->multitoken(),
        "a user suite of horizontal records (each sample draws one and scales it to the level; "
        "applied along x and y, no vertical); default: generated sets for the case's target")(
        "pool", po::value<std::string>()->default_value("20"),
        "generated three-component history sets the samples draw from")(
        "seed", po::value<std::string>(), "run seed (default: the case's [options] seed)")(
        "models", po::value<std::string>()->default_value("planar"),
        "planar: the rigid block in x and in y; case: as the case's levels decide (the flexible "
        "body where its flag is raised, the 3D body for a sample that rocks, biaxial sliding "
        "for one that only slides; generated sets only)");
    add_run_options(desc);
    desc.add_options()("case", po::value<std::string>()->required(), "case file (TOML)")(
        "out", po::value<std::string>(), "output folder (default: out/<case stem>-fragility/)")(
        "json", po::bool_switch(), "print fragility.json to stdout instead of the summary")(
        "shard", po::value<std::string>(),
        "K/N: compute only this share of the samples and write out/shard-K-of-N.jsonl for "
        "`freestand merge`")(
        "pdf", po::bool_switch(),
        "also write report.pdf: the HTML report paged for print (A4, page N of M), made by "
        "WeasyPrint (scripts/setup.sh installs it); not with --shard, which writes no report");
    return desc;
}

api::FragilityRequest fragility_request(const po::variables_map& vm) {
    api::FragilityRequest r;
    r.case_file = vm["case"].as<std::string>();
    r.pga_g = parse_levels(vm["pga"].as<std::string>(), "--pga");
    const std::string models = vm["models"].as<std::string>();
    if (models != "planar" && models != "case")
        throw UsageError(fmt::format("--models: expected planar or case; got \"{}\"", models));
    r.case_models = models == "case";
    // Whole numbers here; their ranges are the request's to check (exit 3).
    constexpr double int_max = 2147483647.0;
    r.samples = static_cast<int>(parse_whole(vm["samples"].as<std::string>(), "--samples", 0, int_max));
    r.pool = static_cast<int>(parse_whole(vm["pool"].as<std::string>(), "--pool", 0, int_max));
    if (vm.count("seed")) r.seed = parse_whole(vm["seed"].as<std::string>(), "--seed", 0, 9.0e15);
    if (vm.count("records")) r.record_files = vm["records"].as<std::vector<std::string>>();
    if (vm.count("shard")) {
        const auto share = parse_shard(vm["shard"].as<std::string>(), "--shard");
        r.shard_k = share[0];
        r.shard_n = share[1];
    }
    r.threads = threads_option(vm);
    r.cache_dir = cache_dir(vm);
    r.commit = build_commit;
    return r;
}

std::filesystem::path out_folder(const po::variables_map& vm) {
    if (vm.count("out")) return vm["out"].as<std::string>();
    const std::filesystem::path case_file = vm["case"].as<std::string>();
    return std::filesystem::path("out") / (case_file.stem().string() + "-fragility");
}

// The request's run with a progress bar on standard error (rank 0's only), its cache
// warnings after it.
api::FragilityResult run_with_progress(const api::FragilityRequest& request, const MpiSplit& mpi) {
    const auto bar = std::make_shared<StepProgressBar>();
    const assess::StepProgress progress = mpi.rank() == 0 ? progress_on(bar) : nullptr;
    api::FragilityResult result = api::fragility(request, progress);
    bar->finish();
    print_warnings("fragility", result.cache_warnings);
    return result;
}

// A rank that fails alone would leave the others waiting in the gather: every rank ends.
api::FragilityResult run_on_rank(const api::FragilityRequest& request, const MpiSplit& mpi) {
    try {
        return run_with_progress(request, mpi);
    } catch (const Error& e) {
        if (mpi.size() == 1) throw;
        std::cerr << "freestand fragility: error on MPI rank " << mpi.rank() << ": "
                  << core::printable(e.what()) << "\n";
        mpi.abort(static_cast<int>(e.code()));
    }
}

int write_share(const api::FragilityResult& result, const std::filesystem::path& out) {
    const api::FragilityRequest& r = result.request;
    const auto file =
        fragility::write_shard(out, "fragility", r.shard_k, r.shard_n,
                               api::shard_run_json(result.meta, result.stamp),
                               api::shard_records(result));
    std::cout << fmt::format("shard {} of {}: {} of {} samples written to {}\n", r.shard_k,
                             r.shard_n, result.samples.size(), result.total_samples,
                             file.string());
    return 0;
}

int run(const std::vector<std::string>& args) {
    const auto vm = parse_options("fragility", usage, fragility_options(), args, {"case"});
    if (!vm) return 0;
    const bool pdf = (*vm)["pdf"].as<bool>();
    const bool sharded = vm->count("shard") > 0;
    if (pdf && sharded)
        throw UsageError("--pdf makes report.pdf from report.html, which --shard does not write "
                         "(the merged run's report is made by `freestand merge`)");
    // A missing converter stops the command before the samples, not after them.
    std::optional<std::filesystem::path> converter;
    if (pdf) converter = report::find_pdf_converter();
    api::FragilityRequest request = fragility_request(*vm);
    const MpiSplit mpi;
    if (sharded && mpi.size() > 1)
        throw UsageError("--shard and MPI ranks split the samples two ways; give one");
    if (mpi.size() > 1) {
        request.shard_k = mpi.rank() + 1;
        request.shard_n = mpi.size();
    }
    const api::FragilityResult result = run_on_rank(request, mpi);
    const std::filesystem::path out = out_folder(*vm);
    if (sharded) return write_share(result, out);
    const bool json = (*vm)["json"].as<bool>();
    if (mpi.size() == 1) {
        write_fragility_outputs(*result.result, result.stamp, out, json, converter);
        return 0;
    }
    std::vector<fragility::SampleResult> all = mpi.gather_to_root(result.samples);
    if (mpi.rank() != 0) return 0;
    write_fragility_outputs(api::aggregate(result, std::move(all)), result.stamp, out, json,
                            converter);
    if (!json) std::cout << fmt::format("samples computed on {} MPI ranks\n", mpi.size());
    return 0;
}

const CommandRegistrar reg{
    {"fragility", "P(overturn), P(slide), P(rock) against PGA: fragility.json, report, samples.csv",
     &run}};

}  // namespace
}  // namespace freestand::cli::fragility_command
