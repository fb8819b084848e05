/// freestand slide: ASCE 4 and energy-conservation sliding estimates (docs/methods.md s.4).
#include <cmath>
#include <fmt/format.h>
#include <iostream>
#include <nlohmann/json.hpp>

#include "cli/command.hpp"
#include "cli/options.hpp"
#include "cli/spectra_cli.hpp"
#include "core/errors.hpp"
#include "sliding/asce.hpp"
#include "sliding/spectrum_input.hpp"

namespace freestand::cli {
namespace {

using json = nlohmann::ordered_json;

// A number, or null plus "<key>_reason".
void put(json& j, const std::string& key, const std::optional<double>& v, const std::string& why) {
    j[key] = v ? json(*v) : json(nullptr);
    if (!v) j[key + "_reason"] = why;
}

std::string text_value(const std::optional<double>& v, const char* unit, const std::string& why) {
    return v ? fmt::format("{:.4g} {}", *v, unit) : "n/a (" + why + ")";
}

void print_text(const sliding::SlidingEstimate& e) {
    std::cout << fmt::format("mu_e = {:.6g}, C_s = {:.6g} m/s^2\n", e.mu_e, e.c_s_mps2);
    std::cout << "f_es: " << text_value(e.f_es_hz, "Hz", e.f_es_reason)
              << (e.f_es_hz ? " (" + e.f_es_source + ")" : "") << "\n";
    std::cout << "sliding, ASCE 4 equivalent-linear: "
              << text_value(e.slide_asce_m, "m", e.slide_asce_reason) << "\n";
    std::cout << "sliding, energy conservation:      "
              << text_value(e.slide_energy_m, "m", e.slide_energy_reason) << "\n";
}

int run_slide(const std::vector<std::string>& args) {
    po::options_description desc("slide options");
    desc.add_options()
        ("mu", po::value<std::string>()->required(), "static friction coefficient mu >= 0")
        ("av-g", po::value<std::string>()->default_value("0"), "peak vertical acceleration A_v, g")
        ("pgd-m", po::value<std::string>(), "peak ground displacement, m (energy method)")
        ("pga-g", po::value<std::string>(),
         "peak horizontal acceleration, g: energy method not applied when <= mu_e")
        ("fes-hz", po::value<std::string>(), "equivalent sliding frequency f_es, Hz")
        ("spectrum10", po::value<std::string>(),
         "10%-damped horizontal spectrum file(s) H1.csv[,H2.csv] to find f_es on")
        ("json", "print JSON");
    const auto vm = parse_options(
        "slide", "--mu MU [--av-g AV] [--pgd-m D] (--fes-hz F | --spectrum10 H1.csv[,H2.csv])", desc,
        args);
    if (!vm) return 0;
    if (vm->count("fes-hz") == vm->count("spectrum10"))
        throw UsageError("give exactly one of --fes-hz and --spectrum10 (see freestand slide --help)");
    sliding::SlidingInput in;
    in.mu_s = parse_double((*vm)["mu"].as<std::string>(), "--mu");
    require_in_range(in.mu_s, 0.0, HUGE_VAL, SourceLocation{"", 0, "--mu"}, true, false);
    in.av_g = parse_double((*vm)["av-g"].as<std::string>(), "--av-g");
    require_in_range(in.av_g, 0.0, 2.5, SourceLocation{"", 0, "--av-g"}, true, false);
    // Range checks here so the message names the option the user typed, not the library field.
    if (vm->count("pgd-m")) {
        in.pgd_m = parse_double((*vm)["pgd-m"].as<std::string>(), "--pgd-m");
        require_in_range(*in.pgd_m, 0.0, HUGE_VAL, SourceLocation{"", 0, "--pgd-m"}, true, false);
    }
    if (vm->count("pga-g")) {
        in.pga_h_g = parse_double((*vm)["pga-g"].as<std::string>(), "--pga-g");
        require_in_range(*in.pga_h_g, 0.0, HUGE_VAL, SourceLocation{"", 0, "--pga-g"}, true, false);
    }
    std::optional<double> fes_hz;
    if (vm->count("fes-hz")) {
        fes_hz = parse_double((*vm)["fes-hz"].as<std::string>(), "--fes-hz");
        require_positive(*fes_hz, SourceLocation{"", 0, "--fes-hz"});
    }
    const sliding::SlidingEstimate e =
        fes_hz
            ? sliding::estimate_sliding(in, *fes_hz)
            : sliding::estimate_sliding(
                  in, sliding::vector_horizontal_from_files(
                          spectrum_paths((*vm)["spectrum10"].as<std::string>(), "--spectrum10"),
                          sliding::asce_sliding_damping));
    if (!vm->count("json")) {
        print_text(e);
        return 0;
    }
    json j;
    j["method"] =
        "ASCE 4 equivalent-linear (ASCE 4-16) and energy-conservation (Saraswat 2017) sliding "
        "(docs/methods.md s.4)";
    j["mu_s"] = in.mu_s;
    j["av_g"] = in.av_g;
    j["mu_e"] = e.mu_e;
    j["c_s_mps2"] = e.c_s_mps2;
    put(j, "f_es_hz", e.f_es_hz, e.f_es_reason);
    j["f_es_source"] = e.f_es_source;
    j["slides"] = e.slides;
    put(j, "slide_asce_m", e.slide_asce_m, e.slide_asce_reason);
    j["pgd_m"] = in.pgd_m ? json(*in.pgd_m) : json(nullptr);
    put(j, "slide_energy_m", e.slide_energy_m, e.slide_energy_reason);
    std::cout << j.dump(2) << "\n";
    return 0;
}

const CommandRegistrar reg{{"slide", "closed-form sliding estimates (ASCE 4, energy)", &run_slide}};

}  // namespace
}  // namespace freestand::cli
