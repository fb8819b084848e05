/// `freestand spectrum RECORD`: linear response spectrum of an acceleration record.
#include <iostream>

#include "api/spectrum.hpp"
#include "cli/command.hpp"
#include "cli/options.hpp"
#include "cli/spectra_cli.hpp"
#include "core/readers.hpp"

// The command's own namespace: the command files share a unity build (src/cli/CMakeLists.txt).
namespace freestand::cli::spectrum_command {
namespace {

po::options_description spectrum_options() {
    po::options_description desc("options");
    add_spectrum_grid_options(desc, "0.05",
                              "damping ratios in (0, 1), comma-separated, e.g. 0.05,0.10");
    desc.add_options()("record", po::value<std::string>()->required(),
                       "acceleration record: .AT2 (PEER), .V2 (COSMOS) or .csv")(
        "json", po::bool_switch(), "print one JSON object instead of CSV");
    return desc;
}

int run_spectrum(const std::vector<std::string>& args) {
    const auto vm = parse_options("spectrum", "RECORD [options]", spectrum_options(), args,
                                  {"record"});
    if (!vm) return 0;
    api::SpectrumRequest request;
    request.record = core::read_record((*vm)["record"].as<std::string>());
    request.dampings = dampings_from(*vm);
    request.grid = grid_from(*vm);
    const api::SpectrumResult result = api::spectrum(request);
    if ((*vm)["json"].as<bool>()) {
        std::cout << api::to_json(result).dump(2) << "\n";
        return 0;
    }
    const spectra::ResponseSpectra& rs = result.spectra;
    print_psa_csv(rs.frequency_hz, rs.dampings, rs.psa_g);
    return 0;
}

const CommandRegistrar reg{
    {"spectrum", "response spectrum (PSA, SD, PSV) of an acceleration record", &run_spectrum}};

}  // namespace
}  // namespace freestand::cli::spectrum_command
