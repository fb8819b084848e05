/// `freestand spectrum RECORD`: linear response spectrum of an acceleration record.
#include <iostream>

#include "cli/command.hpp"
#include "cli/documents.hpp"
#include "cli/options.hpp"
#include "cli/spectra_cli.hpp"
#include "core/readers.hpp"
#include "spectra/response.hpp"

// The command's own namespace: the command files share a unity build (src/cli/CMakeLists.txt).
namespace freestand::cli::spectrum_command {
namespace {

int run_spectrum(const std::vector<std::string>& args) {
    po::options_description desc = spectrum_grid_options();
    desc.add_options()("record", po::value<std::string>()->required(),
                       "acceleration record: .AT2 (PEER), .V2 (COSMOS) or .csv")(
        "json", po::bool_switch(), "print one JSON object instead of CSV");
    const auto vm = parse_options("spectrum", "RECORD [options]", desc, args, {"record"});
    if (!vm) return 0;
    const core::Record record = core::read_record((*vm)["record"].as<std::string>());
    if ((*vm)["json"].as<bool>()) {
        std::cout << spectrum_document(record, *vm).dump(2) << "\n";
        return 0;
    }
    const std::vector<double> dampings = dampings_from(*vm);
    const spectra::ResponseSpectra rs =
        spectra::response_spectra(record, dampings, frequencies_from(*vm));
    print_psa_csv(rs.frequency_hz, rs.dampings, rs.psa_g);
    return 0;
}

const CommandRegistrar reg{
    {"spectrum", "response spectrum (PSA, SD, PSV) of an acceleration record", &run_spectrum}};

}  // namespace
}  // namespace freestand::cli::spectrum_command
