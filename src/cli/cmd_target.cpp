/// `freestand target --design ...`: a design spectrum (RG 1.60, ASCE 7, EC8, IS 1893) as a
/// matching target, printed like `freestand spectrum` or written in the spectrum file format.
#include <fmt/format.h>

#include <iostream>
#include <nlohmann/json.hpp>
#include <set>

#include "cli/command.hpp"
#include "cli/options.hpp"
#include "cli/spectra_cli.hpp"
#include "spectra/design.hpp"

namespace freestand::cli {
namespace {

/// Options each design accepts besides the common ones; anything else given is an error.
const std::map<std::string, std::set<std::string>> design_options{
    {"rg1.60", {"pga", "vertical"}},
    {"asce7", {"sds", "sd1", "tl"}},
    {"ec8", {"ag", "type", "ground"}},
    {"is1893", {"pga", "soil"}},
};

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

double number_option(const po::variables_map& vm, const std::string& design,
                     const std::string& name) {
    if (!vm.count(name))
        throw UsageError(
            fmt::format("--design {} needs --{} (see freestand target --help)", design, name));
    const double v = parse_double(vm[name].as<std::string>(), "--" + name);
    require_positive(v, SourceLocation{"", 0, "--" + name});
    return v;
}

void check_applicable(const po::variables_map& vm, const std::string& design) {
    const auto it = design_options.find(design);
    if (it == design_options.end())
        throw UsageError(
            fmt::format("--design: unknown design \"{}\"; expected one of rg1.60, asce7, "
                        "ec8, is1893",
                        design));
    for (const char* opt : {"pga", "sds", "sd1", "tl", "ag", "type", "ground", "soil"})
        if (vm.count(opt) && !it->second.count(opt))
            throw UsageError(fmt::format("--{} does not apply to --design {}", opt, design));
    if (vm["vertical"].as<bool>() && !it->second.count("vertical"))
        throw UsageError(fmt::format("--vertical does not apply to --design {}", design));
}

/// One design spectrum per damping.
std::vector<spectra::Spectrum> build(const po::variables_map& vm, const std::string& design,
                                     const std::vector<double>& dampings,
                                     const std::vector<double>& f) {
    std::vector<spectra::Spectrum> out;
    const auto five_percent_only = [&] {
        if (dampings.size() != 1 || dampings[0] != 0.05)
            throw InputError(
                SourceLocation{"", 0, "--damping"},
                fmt::format("--design {} is defined at 5% only; expected --damping 0.05", design));
    };
    if (design == "rg1.60") {
        const double pga = number_option(vm, design, "pga");
        for (double d : dampings) {
            require_in_range(d, 0.005, 0.10, SourceLocation{"", 0, "--damping"});
            out.push_back(spectra::rg160(pga, d, vm["vertical"].as<bool>(), f));
        }
    } else if (design == "asce7") {
        five_percent_only();
        const double sds = number_option(vm, design, "sds");
        const double sd1 = number_option(vm, design, "sd1");
        const double tl = number_option(vm, design, "tl");
        if (!(tl > sd1 / sds))  // checked here too so the message names the option
            throw InputError(SourceLocation{"", 0, "--tl"},
                             fmt::format("{} s; expected more than TS = SD1/SDS = {} s", tl,
                                         sd1 / sds));
        out.push_back(spectra::asce7(sds, sd1, tl, f));
    } else if (design == "ec8") {
        const double ag = number_option(vm, design, "ag");
        const std::string type = vm.count("type") ? vm["type"].as<std::string>() : "";
        if (type != "1" && type != "2")
            throw UsageError(fmt::format("--type: \"{}\"; --design ec8 needs --type 1 or 2", type));
        const std::string ground = vm.count("ground") ? vm["ground"].as<std::string>() : "";
        if (ground.size() != 1 || ground[0] < 'A' || ground[0] > 'E')
            throw UsageError(fmt::format(
                "--ground: \"{}\"; --design ec8 needs --ground A, B, C, D or E", ground));
        const auto t = type == "1" ? spectra::Ec8Type::type1 : spectra::Ec8Type::type2;
        for (double d : dampings) out.push_back(spectra::ec8(ag, t, ground[0], d, f));
    } else {
        five_percent_only();
        const std::string soil = vm.count("soil") ? vm["soil"].as<std::string>() : "";
        const std::map<std::string, spectra::Is1893Soil> soils{
            {"rock", spectra::Is1893Soil::rock},
            {"medium", spectra::Is1893Soil::medium},
            {"soft", spectra::Is1893Soil::soft}};
        if (!soils.count(soil))
            throw UsageError(fmt::format(
                "--soil: \"{}\"; --design is1893 needs --soil rock, medium or soft", soil));
        out.push_back(spectra::is1893(number_option(vm, design, "pga"), soils.at(soil), f));
    }
    return out;
}

int run_target(const std::vector<std::string>& args) {
    po::options_description desc("options");
    desc.add_options()("design", po::value<std::string>()->required(),
                       "rg1.60 | asce7 | ec8 | is1893")(
        "pga", po::value<std::string>(), "rg1.60, is1893: peak ground acceleration, g (> 0)")(
        "vertical", po::bool_switch(), "rg1.60: vertical instead of horizontal spectrum")(
        "sds", po::value<std::string>(), "asce7: SDS, g (> 0)")("sd1", po::value<std::string>(),
                                                                "asce7: SD1, g (> 0)")(
        "tl", po::value<std::string>(), "asce7: long-period transition TL, s (> SD1/SDS)")(
        "ag", po::value<std::string>(), "ec8: design ground acceleration a_g on rock, g (> 0)")(
        "type", po::value<std::string>(), "ec8: spectrum type 1 or 2")(
        "ground", po::value<std::string>(), "ec8: ground type A, B, C, D or E")(
        "soil", po::value<std::string>(), "is1893: rock, medium or soft")(
        "json", po::bool_switch(), "print one JSON object instead of CSV")(
        "output", po::value<std::string>(),
        "write the spectrum file format (one damping) to this path instead of printing");
    add_spectrum_grid_options(desc, "0.05",
                              "damping ratios, comma-separated: rg1.60 0.005-0.10, ec8 (0, 1), "
                              "asce7 and is1893 0.05 only");
    const auto vm = parse_options("target", "--design NAME [design options] [options]", desc, args);
    if (!vm) return 0;

    const std::string design = (*vm)["design"].as<std::string>();
    check_applicable(*vm, design);
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
