// `freestand regress`: re-run every case and compare with the committed result.json goldens.
#include <fmt/format.h>

#include <algorithm>
#include <iostream>

#include "api/regress.hpp"
#include "cli/build_info.hpp"
#include "cli/command.hpp"
#include "cli/options.hpp"
#include "cli/run_options.hpp"
#include "core/errors.hpp"
#include "report/render.hpp"
#include "report/validation.hpp"
#include "cli/usage_error.hpp"

// The command's own namespace: the command files share a unity build (src/cli/CMakeLists.txt).
namespace freestand::cli::regress_command {
namespace {

namespace fs = std::filesystem;
const char* const usage =
    "[REPORTS_DIR] [--cases DIR] [--update] [--rtol 1e-6] [--threads T] [--cache DIR | --no-cache]";
constexpr std::size_t max_listed = 20;

// One entry's lines, as it is done; an updated entry's folder published first.
void show(const api::RegressEntry& e, const fs::path& cases) {
    using Status = api::RegressEntry::Status;
    switch (e.status) {
    case Status::ok: std::cout << fmt::format("ok      {}: {}\n", e.name, e.fresh_headline); return;
    case Status::missing:
        std::cout << fmt::format("MISSING {}: no golden {}\n", e.name,
                                 (e.dir / "result.json").string());
        return;
    case Status::skipped:
        std::cout << fmt::format("skipped validation: {} lacks the shipped glove-box cases\n",
                                 cases.string());
        return;
    case Status::updated:
        if (e.report) report::write_report(e.dir, *e.report);
        if (e.validation) report::write_validation(e.dir, *e.validation);
        std::cout << fmt::format("updated {}: {}\n", e.dir.string(), e.fresh_headline);
        return;
    case Status::changed: break;
    }
    std::cout << fmt::format("CHANGED {}: {} difference(s)\n", e.name, e.differences.size());
    if (e.golden_headline != e.fresh_headline)
        std::cout << fmt::format("  {}: {} -> {}\n", e.headline, e.golden_headline,
                                 e.fresh_headline);
    for (std::size_t i = 0; i < std::min(e.differences.size(), max_listed); ++i) {
        const api::Difference& d = e.differences[i];
        std::cout << fmt::format("  {}: {} -> {}\n", d.path, d.golden, d.fresh);
    }
    if (e.differences.size() > max_listed)
        std::cout << fmt::format("  ... and {} more\n", e.differences.size() - max_listed);
}

int run(const std::vector<std::string>& args) {
    po::options_description desc("options");
    desc.add_options()("reports", po::value<std::string>()->default_value("reports"),
                       "folder of golden reports")(
        "cases", po::value<std::string>()->default_value("cases"), "folder of case files")(
        "update", po::bool_switch(),
        "rewrite the goldens (report.md, report.html, result.json, figures; and validation/)")(
        "rtol", po::value<std::string>()->default_value("1e-6"), "relative tolerance for numbers");
    add_run_options(desc);
    const auto vm = parse_options("regress", usage, desc, args, {"reports"});
    if (!vm) return 0;
    const RunContext context(*vm);
    api::RegressRequest request;
    request.rtol = parse_double((*vm)["rtol"].as<std::string>(), "--rtol");
    request.reports_dir = (*vm)["reports"].as<std::string>();
    request.cases_dir = (*vm)["cases"].as<std::string>();
    request.update = (*vm)["update"].as<bool>();
    request.commit = build_commit;
    request.run = context.settings();
    request.on_entry = [&](const api::RegressEntry& e) { show(e, request.cases_dir); };
    api::RegressResult result;
    try {
        result = api::regress(request);
    } catch (const InputError& e) {
        // The tolerance is the one request field given as a flag whose range the api checks.
        if (e.where().field == "rtol") throw UsageError("--rtol: " + e.message());
        throw;
    }
    context.finish("regress");
    return result.all_ok() ? 0 : static_cast<int>(ExitCode::failure);
}

const CommandRegistrar reg{{"regress",
                            "re-run every case and the validation (reports/validation/) and "
                            "compare with the golden result.json files",
                            &run}};

}  // namespace
}  // namespace freestand::cli::regress_command
