// `freestand generate`: spectrum-compatible acceleration histories and their acceptance report.
#include <fmt/format.h>

#include <iostream>

#include "cli/command.hpp"
#include "cli/documents.hpp"
#include "cli/options.hpp"
#include "core/errors.hpp"
#include "core/file_io.hpp"
#include "core/printable.hpp"
#include "core/readers.hpp"
#include "core/publish.hpp"
#include "motion/motion.hpp"

// The command's own namespace: the command files share a unity build (src/cli/CMakeLists.txt).
namespace freestand::cli::generate_command {
namespace {

const char* const usage =
    "--target rg1.60|asce7|ec8|is1893 [design options] | --target-file F.csv, --out DIR [options]";

int run(const std::vector<std::string>& args) {
    po::options_description desc = generate_options();
    desc.add_options()(
        "no-timing", po::bool_switch(), "write wall_s as null so match.json is byte-identical too")(
        "out", po::value<std::string>()->required(), "output folder");
    const auto vm = parse_options("generate", usage, desc, args);
    if (!vm) return 0;

    const GenerateRequest request = generate_request(*vm);
    const motion::GeneratedSet set = motion::generate_set(request.targets, request.options);
    const std::filesystem::path out = (*vm)["out"].as<std::string>();
    // The folder is published whole (core/publish.hpp): writing each CSV in turn would replace
    // h1.csv before finding that h2.csv is an input of the run, and would let two runs into
    // one folder mix their files.
    std::vector<core::OutputFile> files;
    for (const motion::GeneratedComponent& c : set.components)
        files.push_back({c.record.component + ".csv", core::csv_g_text(c.record)});
    const json j = match_document(request.targets, set, !(*vm)["no-timing"].as<bool>());
    files.push_back({"match.json", j.dump(2) + "\n"});
    core::publish_folder(out, files);
    std::cout << fmt::format("{} component(s) written to {}: {}\n", set.components.size(),
                             core::printable_name(out.string()),
                             set.passed ? "all pass SRP 3.7.1 and the realism checks"
                                        : "FAILING, see match.json");
    return set.passed ? 0 : static_cast<int>(ExitCode::failure);
}

const CommandRegistrar reg{
    {"generate", "spectrum-compatible acceleration histories (h1, h2, v) + match.json", &run}};

}  // namespace
}  // namespace freestand::cli::generate_command
