/// freestand slide: ASCE 4 and energy-conservation sliding estimates (docs/methods.md s.4).
#include <fmt/format.h>
#include <iostream>

#include "api/slide.hpp"
#include "cli/command.hpp"
#include "cli/options.hpp"
#include "cli/spectra_cli.hpp"
#include "cli/usage_error.hpp"

// The command's own namespace: the command files share a unity build (src/cli/CMakeLists.txt).
namespace freestand::cli::slide_command {
namespace {

po::options_description slide_options() {
    po::options_description desc("slide options");
    desc.add_options()
        ("mu", po::value<std::string>()->required(), "static friction coefficient mu in [0, 2]")
        ("av-g", po::value<std::string>()->default_value("0"), "peak vertical acceleration A_v, g")
        ("pgd-m", po::value<std::string>(), "peak ground displacement, m (energy method)")
        ("pga-g", po::value<std::string>(),
         "peak horizontal acceleration, g: energy method not applied when <= mu_e")
        ("fes-hz", po::value<std::string>(), "equivalent sliding frequency f_es, Hz")
        ("spectrum10", po::value<std::string>(),
         "10%-damped horizontal spectrum file(s) H1.csv[,H2.csv] to find f_es on")
        ("json", "print JSON");
    return desc;
}

api::SlideRequest slide_request(const po::variables_map& vm) {
    if (vm.count("fes-hz") == vm.count("spectrum10"))
        throw UsageError("give exactly one of --fes-hz and --spectrum10 (see freestand slide --help)");
    api::SlideRequest r;
    r.mu_s = parse_double(vm["mu"].as<std::string>(), "--mu");
    r.av_g = parse_double(vm["av-g"].as<std::string>(), "--av-g");
    r.pgd_m = opt_number(vm, "pgd-m");
    r.pga_h_g = opt_number(vm, "pga-g");
    r.fes_hz = opt_number(vm, "fes-hz");
    if (vm.count("spectrum10"))
        r.spectrum10_files = spectrum_paths(vm["spectrum10"].as<std::string>(), "--spectrum10");
    return r;
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
    const auto vm = parse_options(
        "slide", "--mu MU [--av-g AV] [--pgd-m D] (--fes-hz F | --spectrum10 H1.csv[,H2.csv])",
        slide_options(), args);
    if (!vm) return 0;
    const api::SlideResult result = api::slide(slide_request(*vm));
    if (vm->count("json"))
        std::cout << api::to_json(result).dump(2) << "\n";
    else
        print_text(result.estimate);
    return 0;
}

const CommandRegistrar reg{{"slide", "closed-form sliding estimates (ASCE 4, energy)", &run_slide}};

}  // namespace
}  // namespace freestand::cli::slide_command
