/// `freestand target --design ...`: a design spectrum (RG 1.60, ASCE 7, EC8, IS 1893) as a
/// matching target, printed like `freestand spectrum` or written in the spectrum file format.
#include <fmt/format.h>

#include <iostream>
#include <nlohmann/json.hpp>
#include <set>

#include "cli/command.hpp"
#include "cli/design_options.hpp"
#include "cli/options.hpp"
#include "cli/spectra_cli.hpp"
#include "spectra/design.hpp"

namespace freestand::cli {
namespace {

/// Where each design's formulas come from (written into --output files).
const std::map<std::string, std::string> design_source{
    {"rg1.60",
     "US NRC Regulatory Guide 1.60 Rev. 2, Tables I and II: control points A 33 Hz, "
     "B 9 Hz, C 2.5 Hz (vertical 3.5 Hz), D 0.25 Hz (36 in ground displacement per 1 g), "
     "log-log lines, PSA = PGA above 33 Hz, constant SD below 0.25 Hz (docs/methods.md s.8)"},
    {"asce7",
     "ASCE 7-16 section 11.4.6 design response spectrum: T0 = 0.2 SD1/SDS, TS = SD1/SDS, "
     "SD1/T to TL, SD1 TL/T^2 beyond (docs/methods.md s.8)"},
    {"ec8",
     "EN 1998-1:2004 3.2.2.2 horizontal elastic spectrum, eqs. (3.2)-(3.6), recommended "
     "S, TB, TC, TD of Tables 3.2 (Type 1) and 3.3 (Type 2) (docs/methods.md s.8)"},
    {"is1893",
     "IS 1893 (Part 1) Sa/g at 5% damping: 1 + 15 T below 0.1 s, 2.5 plateau, "
     "then 1.0/T, 1.36/T, 1.67/T (rock, medium, soft) to 4 s, constant beyond (docs/methods.md s.8)"},
};
const std::map<std::string, std::string> design_scaling{
    {"rg1.60",
     "PSA is proportional to PGA: multiply psa_g by the design PGA in g over the PGA of the label"},
    {"asce7", "PSA is proportional to SDS and SD1 scaled together (same TS); TL fixed"},
    {"ec8",
     "PSA is proportional to a_g: multiply psa_g by the design a_g in g over the a_g of the label"},
    {"is1893",
     "PSA is proportional to PGA: multiply psa_g by the design PGA in g over the PGA of the label"},
};

/// The command line without --output and its path, so a regenerated file does not name itself.
std::string join_args(const std::vector<std::string>& args) {
    std::string out;
    for (std::size_t i = 0; i < args.size(); ++i) {
        if (args[i] == "--output") {
            ++i;
            continue;
        }
        if (args[i].rfind("--output=", 0) == 0) continue;
        out += (out.empty() ? "" : " ") + args[i];
    }
    return out;
}

/// One design spectrum per damping.
std::vector<spectra::Spectrum> build(const po::variables_map& vm, const std::string& design,
                                     const std::vector<double>& dampings,
                                     const std::vector<double>& f) {
    check_design_options(vm, "--design", design);
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

int run_target(const std::vector<std::string>& args) {
    po::options_description desc("options");
    desc.add_options()("design", po::value<std::string>()->required(),
                       "rg1.60 | asce7 | ec8 | is1893")(
        "vertical", po::bool_switch(), "rg1.60: vertical instead of horizontal spectrum");
    add_design_options(desc);
    desc.add_options()("json", po::bool_switch(), "print one JSON object instead of CSV")(
        "output", po::value<std::string>(),
        "write the spectrum file format (one damping) to this path instead of printing");
    add_spectrum_grid_options(desc, "0.05",
                              "damping ratios, comma-separated: rg1.60 0.005-0.10, ec8 (0, 1), "
                              "asce7 and is1893 0.05 only");
    const auto vm = parse_options("target", "--design NAME [design options] [options]", desc, args);
    if (!vm) return 0;

    const std::string design = (*vm)["design"].as<std::string>();
    check_design_options(*vm, "--design", design);
    const std::vector<double> dampings = dampings_from(*vm);
    const std::vector<double> f = frequencies_from(*vm);
    const std::vector<spectra::Spectrum> spectra_out = build(*vm, design, dampings, f);

    if (vm->count("output")) {
        if (spectra_out.size() != 1)
            throw UsageError("--output writes one spectrum; give a single --damping value");
        spectra::write_spectrum_csv(spectra_out[0], (*vm)["output"].as<std::string>(),
                                    {"source: " + design_source.at(design),
                                     "units: frequency_hz in Hz, psa_g in g (g = 9.81 m/s^2)",
                                     "scaling: " + design_scaling.at(design),
                                     "generated by: freestand target " + join_args(args)});
        return 0;
    }
    std::vector<std::vector<double>> psa;
    psa.reserve(spectra_out.size());
    for (const auto& s : spectra_out) psa.push_back(s.psa_g);
    if (!(*vm)["json"].as<bool>()) {
        print_psa_csv(f, dampings, psa);
        return 0;
    }
    nlohmann::ordered_json j;
    j["design"] = design;
    j["labels"] = nlohmann::ordered_json::array();
    for (const auto& s : spectra_out) j["labels"].push_back(s.label);
    j["frequencies_hz"] = f;
    j["psa_g"] = by_damping(dampings, psa);
    std::cout << j.dump(2) << "\n";
    return 0;
}

const CommandRegistrar reg{{"target",
                            "design spectrum (RG 1.60, ASCE 7, EC8, IS 1893) as a matching target",
                            &run_target}};

}  // namespace
}  // namespace freestand::cli
