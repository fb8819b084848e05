// `freestand validate`: the thesis's tests and worked examples against freestand's models
// (docs/methods.md s.13), printed as a table and written as report.md, report.html, result.json.
#include <fmt/format.h>

#include <chrono>
#include <iostream>

#include "api/validate.hpp"
#include "cli/build_info.hpp"
#include "cli/command.hpp"
#include "cli/options.hpp"
#include "core/printable.hpp"
#include "report/validation.hpp"

// The command's own namespace: the command files share a unity build (src/cli/CMakeLists.txt).
namespace freestand::cli::validate_command {
namespace {

namespace fs = std::filesystem;
const char* const usage = "[--out DIR] [--cases DIR] [--json]";

int run(const std::vector<std::string>& args) {
    po::options_description desc("options");
    desc.add_options()("out", po::value<std::string>()->default_value("out/validation"),
                       "output folder")(
        "cases", po::value<std::string>()->default_value("cases"),
        "folder of the shipped glove-box cases")(
        "json", po::bool_switch(), "print result.json instead of the table");
    const auto vm = parse_options("validate", usage, desc, args);
    if (!vm) return 0;
    api::ValidateRequest request;
    request.cases_dir = (*vm)["cases"].as<std::string>();
    request.commit = build_commit;
    const fs::path out = (*vm)["out"].as<std::string>();
    const auto start = std::chrono::steady_clock::now();
    const api::ValidateResult result = api::validate(request);
    report::write_validation(out, result.reports);
    const double run_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::cout << ((*vm)["json"].as<bool>() ? result.reports.json
                                          : report::validation_text(result.validation));
    // Timing goes to stderr: stdout and the reports are byte-identical for the same inputs.
    std::cerr << fmt::format("wrote {} ({} rows) in {:.2f} s\n", core::printable_name(out.string()),
                             result.validation.rows.size(), run_s);
    return 0;
}

const CommandRegistrar reg{
    {"validate", "run the thesis's tests and worked examples against freestand's models", &run}};

}  // namespace
}  // namespace freestand::cli::validate_command
