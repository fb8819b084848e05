// `freestand regress`: re-run every case and compare with the committed result.json goldens.
#include <fmt/format.h>

#include <algorithm>
#include <iostream>
#include <nlohmann/json.hpp>

#include "cli/build_info.hpp"
#include "cli/command.hpp"
#include "cli/options.hpp"
#include "cli/run_options.hpp"
#include "core/errors.hpp"
#include "core/file_io.hpp"
#include "report/regress.hpp"
#include "report/run.hpp"
#include "report/validation.hpp"
#include "validate/validate.hpp"

// The command's own namespace: the command files share a unity build (src/cli/CMakeLists.txt).
namespace freestand::cli::regress_command {
namespace {

namespace fs = std::filesystem;
const char* const usage =
    "[REPORTS_DIR] [--cases DIR] [--update] [--rtol 1e-6] [--threads T] [--cache DIR | --no-cache]";
constexpr std::size_t max_listed = 20;

std::vector<fs::path> case_files(const fs::path& dir) {
    if (!fs::is_directory(dir)) throw IoError(dir.string() + ": not a folder of case files");
    std::vector<fs::path> out;
    for (const auto& e : fs::directory_iterator(dir)) {
        if (e.is_regular_file() && e.path().extension() == ".toml") out.push_back(e.path());
    }
    std::sort(out.begin(), out.end());
    return out;
}

// A headline value (a JSON pointer into the document) as one line: a string as it is, anything
// else as JSON.
std::string headline_text(const nlohmann::ordered_json& doc, const char* headline) {
    const nlohmann::ordered_json::json_pointer at(headline);
    if (!doc.contains(at)) return "(none)";
    const auto& h = doc.at(at);
    return h.is_string() ? h.get<std::string>() : h.dump();
}

// Compares one fresh result.json with its golden; returns true when they match. headline is the
// fresh document's one-line summary ("/verdict" of a case, "/summary/text" of the validation).
bool check(const fs::path& golden_file, const std::string& fresh_json, const char* headline,
           double rtol) {
    const std::string name = golden_file.parent_path().filename().string();
    if (!fs::exists(golden_file)) {
        std::cout << fmt::format("MISSING {}: no golden {}\n", name, golden_file.string());
        return false;
    }
    nlohmann::ordered_json golden;
    try {
        golden = nlohmann::ordered_json::parse(core::read_text_file(golden_file));
    } catch (const nlohmann::json::parse_error& e) {
        throw InputError(SourceLocation{golden_file.string(), 0, ""},
                         std::string("not valid JSON: ") + e.what());
    }
    const auto fresh = nlohmann::ordered_json::parse(fresh_json);
    const auto diffs = report::compare_results(golden, fresh, rtol);
    const std::string fresh_headline = headline_text(fresh, headline);
    if (diffs.empty()) {
        std::cout << fmt::format("ok      {}: {}\n", name, fresh_headline);
        return true;
    }
    std::cout << fmt::format("CHANGED {}: {} difference(s)\n", name, diffs.size());
    const std::string golden_headline = headline_text(golden, headline);
    if (golden_headline != fresh_headline) {
        std::cout << fmt::format("  {}: {} -> {}\n", headline, golden_headline, fresh_headline);
    }
    for (std::size_t i = 0; i < std::min(diffs.size(), max_listed); ++i) {
        std::cout << fmt::format("  {}: {} -> {}\n", diffs[i].path, diffs[i].golden,
                                 diffs[i].fresh);
    }
    if (diffs.size() > max_listed)
        std::cout << fmt::format("  ... and {} more\n", diffs.size() - max_listed);
    return false;
}

const char* const validation_headline = "/summary/text";

// The validation against the thesis (reports/validation/), when the cases folder holds the
// shipped cases it assesses.
bool regress_validation(const fs::path& reports, const fs::path& cases, bool update, double rtol) {
    if (!validate::has_cases(cases)) {
        std::cout << fmt::format("skipped validation: {} lacks the shipped glove-box cases\n",
                                 cases.string());
        return true;
    }
    const validate::Validation v = validate::run(cases);
    const report::ValidationReport rendered =
        report::render_validation(v, report::validation_stamp(v, build_commit));
    const fs::path dir = reports / "validation";
    if (!update) return check(dir / "result.json", rendered.json, validation_headline, rtol);
    report::write_validation(dir, rendered);
    std::cout << fmt::format(
        "updated {}: {}\n", dir.string(),
        headline_text(nlohmann::ordered_json::parse(rendered.json), validation_headline));
    return true;
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
    const double rtol = parse_double((*vm)["rtol"].as<std::string>(), "--rtol");
    if (rtol < 0.0) throw UsageError(fmt::format("--rtol: expected a number >= 0; got {}", rtol));
    const fs::path reports = (*vm)["reports"].as<std::string>();
    const bool update = (*vm)["update"].as<bool>();
    bool all_ok = true;
    for (const fs::path& case_file : case_files((*vm)["cases"].as<std::string>())) {
        const report::CaseRun run =
            report::run_case(case_file, std::nullopt, build_commit, context.settings());
        const fs::path dir = reports / case_file.stem();
        if (update) {
            report::write_report(dir, run.rendered);
            std::cout << fmt::format("updated {}: {}\n", dir.string(),
                                     report::verdict_line(run.result));
        } else {
            all_ok = check(dir / "result.json", run.rendered.json, "/verdict", rtol) && all_ok;
        }
    }
    all_ok = regress_validation(reports, (*vm)["cases"].as<std::string>(), update, rtol) && all_ok;
    context.finish("regress");
    return all_ok ? 0 : static_cast<int>(ExitCode::failure);
}

const CommandRegistrar reg{{"regress",
                            "re-run every case and the validation (reports/validation/) and "
                            "compare with the golden result.json files",
                            &run}};

}  // namespace
}  // namespace freestand::cli::regress_command
