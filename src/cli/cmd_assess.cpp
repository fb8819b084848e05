// `freestand assess`: a case file to a verdict, with report.md, report.html and result.json
// (and report.pdf with --pdf).
#include <fmt/format.h>

#include <iostream>

#include "api/assess.hpp"
#include "cli/build_info.hpp"
#include "cli/command.hpp"
#include "cli/options.hpp"
#include "cli/run_options.hpp"
#include "core/publish.hpp"
#include "core/printable.hpp"
#include "report/verdict_line.hpp"

// The command's own namespace: the command files share a unity build (src/cli/CMakeLists.txt).
namespace freestand::cli::assess_command {
namespace {

const char* const usage =
    "CASE.toml [--out DIR] [--pga 0.1,0.2] [--pdf] [--threads T] [--cache DIR | --no-cache]";

int run(const std::vector<std::string>& args) {
    po::options_description desc("options");
    desc.add_options()("case", po::value<std::string>()->required(), "case file (TOML)")(
        "out", po::value<std::string>(),
        "output folder (default: out/<case stem>/ in the working directory)")(
        "pga", po::value<std::string>(), "PGA levels in g replacing the case's, e.g. 0.1,0.2")(
        "pdf", po::bool_switch(),
        "also write report.pdf: the HTML report paged for print (A4, page N of M), made by "
        "WeasyPrint (scripts/setup.sh installs it)");
    add_run_options(desc);
    const auto vm = parse_options("assess", usage, desc, args, {"case"});
    if (!vm) return 0;
    const RunContext run(*vm);
    api::AssessRequest request;
    request.case_file = (*vm)["case"].as<std::string>();
    if (vm->count("pga")) request.pga_g = parse_double_list((*vm)["pga"].as<std::string>(), "--pga");
    request.pdf = (*vm)["pdf"].as<bool>();
    request.commit = build_commit;
    request.run = run.settings();
    const std::filesystem::path out = vm->count("out")
                                          ? std::filesystem::path((*vm)["out"].as<std::string>())
                                          : std::filesystem::path("out") / request.case_file.stem();
    const api::AssessReport r = api::assess_report(request);
    run.finish("assess");
    core::publish_folder(out, r.files);
    const api::AssessResult& a = r.assessed;
    std::cout << report::verdict_line(a.result) << "\n";
    // Timing goes to stdout only, never into the reports (they must be byte-identical per input).
    std::string goal_samples;
    if (a.goal) {
        const fragility::Config& g = a.goal->meta.config;
        goal_samples = fmt::format(", performance goal {} samples",
                                   g.pga_g.size() * static_cast<std::size_t>(g.samples));
    }
    std::cout << fmt::format("wrote {} ({} histories generated, {} simulations{}) in {:.2f} s\n",
                             core::printable_name(out.string()), a.result.histories_generated,
                             a.result.simulations_run, goal_samples, r.assess_s);
    if (r.pdf_converter)
        std::cout << fmt::format("report.pdf made by {} in {:.2f} s\n",
                                 core::printable_name(r.pdf_converter->string()), r.pdf_s);
    return 0;
}

const CommandRegistrar reg{
    {"assess", "assess a case file: verdict, report.md, report.html, result.json", &run}};

}  // namespace
}  // namespace freestand::cli::assess_command
