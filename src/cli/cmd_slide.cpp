/// freestand slide: ASCE 4 and energy-conservation sliding estimates (docs/methods.md s.4).
#include <fmt/format.h>
#include <iostream>

#include "cli/command.hpp"
#include "cli/documents.hpp"
#include "cli/options.hpp"
#include "sliding/asce.hpp"

// The command's own namespace: the command files share a unity build (src/cli/CMakeLists.txt).
namespace freestand::cli::slide_command {
namespace {

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
    po::options_description desc = slide_options();
    desc.add_options()("json", "print JSON");
    const auto vm = parse_options(
        "slide", "--mu MU [--av-g AV] [--pgd-m D] (--fes-hz F | --spectrum10 H1.csv[,H2.csv])", desc,
        args);
    if (!vm) return 0;
    const SlideRun run = slide_run(*vm);
    if (vm->count("json"))
        std::cout << slide_json(run).dump(2) << "\n";
    else
        print_text(run.estimate);
    return 0;
}

const CommandRegistrar reg{{"slide", "closed-form sliding estimates (ASCE 4, energy)", &run_slide}};

}  // namespace
}  // namespace freestand::cli::slide_command
