/// `freestand spectrum RECORD`: linear response spectrum of an acceleration record.
#include <iostream>
#include <nlohmann/json.hpp>

#include "cli/command.hpp"
#include "cli/options.hpp"
#include "cli/spectra_cli.hpp"
#include "core/measures.hpp"
#include "core/readers.hpp"
#include "spectra/response.hpp"

namespace freestand::cli {
namespace {

int run_spectrum(const std::vector<std::string>& args) {
    po::options_description desc("options");
    desc.add_options()("record", po::value<std::string>()->required(),
                       "acceleration record: .AT2 (PEER), .V2 (COSMOS) or .csv")(
        "json", po::bool_switch(), "print one JSON object instead of CSV");
    add_spectrum_grid_options(desc, "0.05",
                              "damping ratios in (0, 1), comma-separated, e.g. 0.05,0.10");
    const auto vm = parse_options("spectrum", "RECORD [options]", desc, args, {"record"});
    if (!vm) return 0;

    const std::vector<double> dampings = dampings_from(*vm);
    const std::vector<double> frequency_hz = frequencies_from(*vm);
    const core::Record record = core::read_record((*vm)["record"].as<std::string>());
    const spectra::ResponseSpectra rs = spectra::response_spectra(record, dampings, frequency_hz);

    if (!(*vm)["json"].as<bool>()) {
        print_psa_csv(rs.frequency_hz, rs.dampings, rs.psa_g);
        return 0;
    }
    const core::GroundMotion gm = core::measure(record);
    nlohmann::ordered_json j;
    j["record"] = record.name;
    j["source"] = record.source;
    j["component"] = record.component;
    j["dt_s"] = record.dt_s;
    j["npts"] = record.size();
    j["pga_g"] = gm.pga_g;
    j["pgv_mps"] = gm.pgv_mps;
    j["pgd_m"] = gm.pgd_m;
    j["arias_mps"] = gm.arias_mps;
    j["d5_75_s"] = gm.d5_75_s;
    j["d5_95_s"] = gm.d5_95_s;
    j["frequencies_hz"] = rs.frequency_hz;
    j["psa_g"] = by_damping(rs.dampings, rs.psa_g);
    j["sd_m"] = by_damping(rs.dampings, rs.sd_m);
    j["psv_mps"] = by_damping(rs.dampings, rs.psv_mps);
    std::cout << j.dump(2) << "\n";
    return 0;
}

const CommandRegistrar reg{
    {"spectrum", "response spectrum (PSA, SD, PSV) of an acceleration record", &run_spectrum}};

}  // namespace
}  // namespace freestand::cli
