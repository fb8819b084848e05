// `fragility`: its sampling options and the run on one machine (cli/documents.hpp).
#include "cli/documents.hpp"

#include "cli/build_info.hpp"
#include "cli/run_options.hpp"
#include "core/file_io.hpp"
#include "core/sha256.hpp"

namespace freestand::cli {

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
        "seed", po::value<std::string>(), "run seed (default: the case's [options] seed)");
    add_run_options(desc);
    return desc;
}

fragility::Config fragility_config(const po::variables_map& vm, const assess::Case& c) {
    fragility::Config cfg;
    cfg.pga_g = parse_levels(vm["pga"].as<std::string>(), "--pga");
    // Whole numbers here; their ranges are the fragility config's to check (exit 3).
    constexpr double int_max = 2147483647.0;
    cfg.samples = static_cast<int>(parse_whole(vm["samples"].as<std::string>(), "--samples", 0, int_max));
    cfg.pool = static_cast<int>(parse_whole(vm["pool"].as<std::string>(), "--pool", 0, int_max));
    cfg.seed = vm.count("seed") ? parse_whole(vm["seed"].as<std::string>(), "--seed", 0, 9.0e15)
                                : c.options.seed;
    if (vm.count("records")) cfg.record_files = vm["records"].as<std::vector<std::string>>();
    return cfg;
}

report::Stamp fragility_stamp(const std::string& case_bytes, const std::string& case_file,
                              const assess::Case& c, const fragility::Config& config) {
    report::Stamp stamp =
        report::make_stamp(case_bytes, case_file, config.seed, build_commit);
    stamp.inputs = report::stamped_inputs(c);
    for (const std::string& f : config.record_files)
        stamp.inputs.push_back({f, core::sha256_hex(core::read_input_file(f))});
    return stamp;
}

FragilityRun fragility_result(const std::string& case_bytes,
                              const std::filesystem::path& case_file,
                              const po::variables_map& vm) {
    const assess::Case c = assess::parse_case(case_bytes, case_file.string());
    const fragility::Config cfg = fragility_config(vm, c);
    const RunContext run(vm);
    FragilityRun out{fragility::run_all(c, cfg, run.settings()),
                     fragility_stamp(case_bytes, case_file.string(), c, cfg)};
    run.finish("fragility");
    return out;
}

}  // namespace freestand::cli
