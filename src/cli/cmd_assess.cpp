// `freestand assess`: a case file to a verdict, with report.md, report.html and result.json
// (and report.pdf with --pdf).
#include <fmt/format.h>

#include <chrono>
#include <iostream>

#include "cli/build_info.hpp"
#include "cli/command.hpp"
#include "cli/options.hpp"
#include "cli/run_options.hpp"
#include "core/publish.hpp"
#include "core/printable.hpp"
#include "report/pdf.hpp"
#include "report/run.hpp"

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
    const std::filesystem::path case_file = (*vm)["case"].as<std::string>();
    std::optional<std::vector<double>> pga;
    if (vm->count("pga")) pga = parse_double_list((*vm)["pga"].as<std::string>(), "--pga");
    const std::filesystem::path out = vm->count("out")
                                          ? std::filesystem::path((*vm)["out"].as<std::string>())
                                          : std::filesystem::path("out") / case_file.stem();
    // A missing converter stops the command before the assessment, not after it.
    std::optional<std::filesystem::path> converter;
    if ((*vm)["pdf"].as<bool>()) converter = report::find_pdf_converter();
    const auto start = std::chrono::steady_clock::now();
    const report::CaseRun r = report::run_case(case_file, pga, build_commit, run.settings());
    const double assess_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    run.finish("assess");
    std::vector<core::OutputFile> files = report::report_files(r.rendered);
    double pdf_s = 0;
    if (converter) {
        const auto pdf_start = std::chrono::steady_clock::now();
        files.push_back({"report.pdf", report::html_to_pdf(*converter, r.rendered.html)});
        pdf_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - pdf_start).count();
    }
    core::publish_folder(out, files);
    std::cout << report::verdict_line(r.result) << "\n";
    // Timing goes to stdout only, never into the reports (they must be byte-identical per input).
    std::string goal_samples;
    if (r.goal) {
        const fragility::Config& g = r.goal->meta.config;
        goal_samples = fmt::format(", performance goal {} samples",
                                   g.pga_g.size() * static_cast<std::size_t>(g.samples));
    }
    std::cout << fmt::format("wrote {} ({} histories generated, {} simulations{}) in {:.2f} s\n",
                             core::printable_name(out.string()), r.result.histories_generated, r.result.simulations_run,
                             goal_samples, assess_s);
    if (converter) std::cout << fmt::format("report.pdf made by {} in {:.2f} s\n",
                                            core::printable_name(converter->string()), pdf_s);
    return 0;
}

const CommandRegistrar reg{
    {"assess", "assess a case file: verdict, report.md, report.html, result.json", &run}};

}  // namespace
}  // namespace freestand::cli::assess_command
