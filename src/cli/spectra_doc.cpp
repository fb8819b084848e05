// `spectrum` and `target`: their options and JSON documents (cli/documents.hpp).
#include <fmt/format.h>

#include "cli/design_options.hpp"
#include "cli/documents.hpp"
#include "cli/spectra_cli.hpp"
#include "core/errors.hpp"
#include "core/measures.hpp"

namespace freestand::cli {

po::variables_map parse_document_options(const std::string& command,
                                         const po::options_description& desc,
                                         const std::vector<std::string>& args) {
    for (const std::string& a : args)
        if (a == "--help" || a == "-h")
            throw UsageError(fmt::format("{}: --help is not an option here", command));
    return *parse_options(command, "", desc, args);
}

po::options_description spectrum_grid_options() {
    po::options_description desc("options");
    add_spectrum_grid_options(desc, "0.05",
                              "damping ratios in (0, 1), comma-separated, e.g. 0.05,0.10");
    return desc;
}

json spectrum_document(const core::Record& record, const po::variables_map& grid) {
    const std::vector<double> dampings = dampings_from(grid);
    const std::vector<double> frequency_hz = frequencies_from(grid);
    const spectra::ResponseSpectra rs = spectra::response_spectra(record, dampings, frequency_hz);
    const core::GroundMotion gm = core::measure(record);
    json j;
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
    return j;
}

po::options_description target_options() {
    po::options_description desc("options");
    desc.add_options()("design", po::value<std::string>()->required(),
                       "rg1.60 | asce7 | ec8 | is1893")(
        "vertical", po::bool_switch(), "rg1.60: vertical instead of horizontal spectrum");
    add_design_options(desc);
    add_spectrum_grid_options(desc, "0.05",
                              "damping ratios, comma-separated: rg1.60 0.005-0.10, ec8 (0, 1), "
                              "asce7 and is1893 0.05 only");
    return desc;
}

std::vector<spectra::Spectrum> target_spectra(const po::variables_map& vm) {
    const std::string design = vm["design"].as<std::string>();
    check_design_options(vm, "--design", design);
    const std::vector<double> dampings = dampings_from(vm);
    const std::vector<double> f = frequencies_from(vm);
    if ((design == "asce7" || design == "is1893") &&
        (dampings.size() != 1 || dampings[0] != 0.05))
        throw InputError(
            SourceLocation{"", 0, "--damping"},
            fmt::format("--design {} is defined at 5% only; expected --damping 0.05", design));
    std::vector<spectra::Spectrum> out;
    for (double d : dampings) {
        if (design == "rg1.60") require_in_range(d, 0.005, 0.10, SourceLocation{"", 0, "--damping"});
        out.push_back(design_spectrum(vm, "--design", design, d, vm["vertical"].as<bool>(), f));
    }
    return out;
}

json target_document(const po::variables_map& vm, const std::vector<spectra::Spectrum>& spectra) {
    std::vector<std::vector<double>> psa;
    psa.reserve(spectra.size());
    for (const auto& s : spectra) psa.push_back(s.psa_g);
    json j;
    j["design"] = vm["design"].as<std::string>();
    j["labels"] = json::array();
    for (const auto& s : spectra) j["labels"].push_back(s.label);
    j["frequencies_hz"] = frequencies_from(vm);
    j["psa_g"] = by_damping(dampings_from(vm), psa);
    return j;
}

}  // namespace freestand::cli
