// `freestand generate`: spectrum-compatible acceleration histories and their acceptance report.
#include <fmt/format.h>

#include <iostream>

#include "api/generate.hpp"
#include "cli/command.hpp"
#include "cli/design_options.hpp"
#include "cli/options.hpp"
#include "core/errors.hpp"
#include "core/file_io.hpp"
#include "core/printable.hpp"
#include "core/publish.hpp"
#include "core/readers.hpp"
#include "cli/usage_error.hpp"

// The command's own namespace: the command files share a unity build (src/cli/CMakeLists.txt).
namespace freestand::cli::generate_command {
namespace {

const char* const usage =
    "--target rg1.60|asce7|ec8|is1893 [design options] | --target-file F.csv, --out DIR [options]";

po::options_description generate_options() {
    po::options_description desc("options");
    desc.add_options()("target", po::value<std::string>(), "rg1.60 | asce7 | ec8 | is1893")(
        "target-file", po::value<std::string>(),
        "5%-damped target spectrum CSV (\"# damping: 0.05\")")(
        "target-file-10", po::value<std::string>(),
        "optional 10%-damped target CSV (reported only)");
    add_design_options(desc);
    desc.add_options()(
        "vertical-ratio", po::value<std::string>(),
        "vertical PGA / horizontal: rg1.60 scales its vertical spectrum to this ZPA (default 1, "
        "RG 1.60's own); other targets: ratio x horizontal (default 2/3)")(
        "seed-record", po::value<std::vector<std::string>>(),
        "seed record(s) to match, one per component (repeat or comma-separate); default synthetic")(
        "components", po::value<std::string>(),
        "comma list of h1,h2,v (default h1,h2,v; with seed "
        "records, as many as records given)")("duration", po::value<std::string>(),
                                              "synthetic: duration, s (default 20, >= 20)")(
        "dt", po::value<std::string>(), "synthetic: time step, s (default 0.005, <= 0.01)")(
        "seed", po::value<std::string>()->default_value("1"), "random seed (non-negative integer)")(
        "va-range", po::value<std::string>(),
        "realism: PGV/PGA range MIN,MAX, m/s per g (rg1.60 default 0.8,2.0; others unchecked)")(
        "adv2-range", po::value<std::string>(),
        "realism: PGA PGD/PGV^2 range MIN,MAX (rg1.60 default 2,8; others unchecked)")(
        "da-max", po::value<std::string>(),
        "realism: largest PGD/PGA, m per g (rg1.60 default 1.3; others unchecked)")(
        "no-timing", po::bool_switch(), "write wall_s as null so match.json is byte-identical too")(
        "out", po::value<std::string>()->required(), "output folder");
    return desc;
}

std::optional<motion::Range> range(const po::variables_map& vm, const char* option) {
    if (!vm.count(option)) return std::nullopt;
    const std::vector<double> v =
        parse_double_list(vm[option].as<std::string>(), std::string("--") + option);
    if (v.size() != 2)
        throw UsageError(
            fmt::format("--{}: expected MIN,MAX (two numbers), got {}", option, v.size()));
    return motion::Range{v[0], v[1]};
}

api::GenerateRequest generate_request(const po::variables_map& vm) {
    api::GenerateRequest r;
    if (vm.count("target")) r.target = vm["target"].as<std::string>();
    r.design = design_values(vm);
    if (vm.count("target-file")) r.target_file = vm["target-file"].as<std::string>();
    if (vm.count("target-file-10")) r.target_file_10 = vm["target-file-10"].as<std::string>();
    r.vertical_ratio = opt_number(vm, "vertical-ratio");
    if (vm.count("seed-record"))
        for (const std::string& group : vm["seed-record"].as<std::vector<std::string>>())
            for (const std::string& file : split_list(group)) r.seed_records.emplace_back(file);
    if (vm.count("components")) r.components = split_list(vm["components"].as<std::string>());
    r.duration_s = opt_number(vm, "duration");
    r.dt_s = opt_number(vm, "dt");
    r.seed = parse_whole(vm["seed"].as<std::string>(), "--seed", 0, 9.0e15);
    r.va_range_mps_per_g = range(vm, "va-range");
    r.adv2_range = range(vm, "adv2-range");
    r.da_max_m_per_g = opt_number(vm, "da-max");
    r.timing = !vm["no-timing"].as<bool>();
    return r;
}

int run(const std::vector<std::string>& args) {
    const auto vm = parse_options("generate", usage, generate_options(), args);
    if (!vm) return 0;

    const api::GenerateResult result = api::generate(generate_request(*vm));
    const motion::GeneratedSet& set = result.set;
    const std::filesystem::path out = (*vm)["out"].as<std::string>();
    // The folder is published whole (core/publish.hpp): writing each CSV in turn would replace
    // h1.csv before finding that h2.csv is an input of the run, and would let two runs into
    // one folder mix their files.
    std::vector<core::OutputFile> files;
    for (const motion::GeneratedComponent& c : set.components)
        files.push_back({c.record.component + ".csv", core::csv_g_text(c.record)});
    files.push_back({"match.json", api::to_json(result).dump(2) + "\n"});
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
