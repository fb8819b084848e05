/// freestand rock: closed-form rocking and overturning checks of a block (docs/methods.md s.5, s.5a).
#include <fmt/format.h>
#include <iostream>

#include "api/classify.hpp"
#include "api/rock.hpp"
#include "cli/command.hpp"
#include "cli/options.hpp"
#include "cli/spectra_cli.hpp"
#include "cli/usage_error.hpp"

// The command's own namespace: the command files share a unity build (src/cli/CMakeLists.txt).
namespace freestand::cli::rock_command {
namespace {

po::options_description rock_options() {
    po::options_description desc("rock options");
    desc.add_options()
        ("block", po::value<std::string>()->required(), "box b=HALF_WIDTH,h=HALF_HEIGHT[,m=KG] (m)")
        ("cg", po::value<std::string>(), "CG x=OFFSET_TO_RIGHT,h=HEIGHT (m); needs --inertia")
        ("inertia", po::value<std::string>(), "I_c about the CG, kg m^2 (needs m=)")
        ("spectrum", po::value<std::string>(),
         "horizontal spectrum file(s) F.csv[,F2.csv..], one per damping (SA_VH or one component)")
        ("spectrum-v", po::value<std::string>(), "vertical spectrum file(s), one per damping")
        ("v-ratio", po::value<std::string>(), "SA_V / SA_H when no vertical spectrum is given")
        ("pga-g", po::value<std::string>(), "peak horizontal acceleration, g (default: spectrum ZPA)")
        ("av-g", po::value<std::string>(), "peak vertical acceleration, g, applied downward")
        ("pgv-mps", po::value<std::string>(), "peak ground velocity, m/s (Ishiyama check)")
        ("mu", po::value<std::string>(), "static friction mu_s (initiating mode)")
        ("restitution", po::value<std::string>(), "measured restitution r (default Housner's)")
        ("fs-required", po::value<std::string>(), "required alpha/theta0 (default 1.5)")
        ("fn-hz", po::value<std::string>(), "fixed-base natural frequency, Hz (flexible screen)")
        ("rock-band-hz", po::value<std::string>(), "free-rocking band LO,HI, Hz (flexible screen)")
        ("json", "print JSON");
    return desc;
}

std::vector<std::filesystem::path> opt_paths(const po::variables_map& vm, const char* option) {
    if (!vm.count(option)) return {};
    return spectrum_paths(vm[option].as<std::string>(), std::string("--") + option);
}

api::RockRequest rock_request(const po::variables_map& vm) {
    api::RockRequest r;
    r.box = box_from_options(vm["block"].as<std::string>(), opt_string(vm, "cg"),
                             opt_number(vm, "inertia"));
    r.spectrum_files = opt_paths(vm, "spectrum");
    r.spectrum_v_files = opt_paths(vm, "spectrum-v");
    r.v_ratio = opt_number(vm, "v-ratio");
    r.pga_h_g = opt_number(vm, "pga-g");
    r.av_g = opt_number(vm, "av-g");
    r.pgv_mps = opt_number(vm, "pgv-mps");
    r.mu_s = opt_number(vm, "mu");
    r.restitution = opt_number(vm, "restitution");
    r.fs_required = opt_number(vm, "fs-required").value_or(r.fs_required);
    r.fixed_base_hz = opt_number(vm, "fn-hz");
    if (vm.count("rock-band-hz")) {
        const auto band = parse_double_list(vm["rock-band-hz"].as<std::string>(), "--rock-band-hz");
        if (band.size() != 2) throw UsageError("--rock-band-hz: expected LO,HI in Hz");
        r.rock_band_hz = std::array<double, 2>{band[0], band[1]};
    }
    return r;
}

std::string opt_text(const std::optional<double>& v, const std::string& fmt_spec,
                     const std::string& why) {
    return v ? fmt::format(fmt::runtime(fmt_spec), *v) : "n/a (" + why + ")";
}

void print_text(const rocking::RockingChecks& r) {
    const auto& c = r.governing();
    std::cout << fmt::format("edge {}: alpha = {:.4g} rad, R = {:.4g} m, p = {:.4g} rad/s, r = {:.4g}\n",
                             api::edge_name(c.edge), c.alpha_rad, c.R_m, c.p_radps, c.restitution);
    std::cout << fmt::format("uplift threshold: {:.4g} g\n", c.uplift_a_g);
    std::cout << fmt::format("Ishiyama velocity bound: {:.4g} m/s{}\n", c.ishiyama_v_mps,
                             r.pgv_below_ishiyama ? (*r.pgv_below_ishiyama ? " (PGV below: cannot overturn)"
                                                                          : " (PGV at or above)")
                                                  : "");
    std::cout << "Housner slenderness that survives: "
              << opt_text(c.housner ? std::optional<double>(c.housner->alpha_required_rad) : std::nullopt,
                          "{:.4g} rad", r.spectral_reason)
              << (c.housner ? (c.housner->survives ? " (alpha above it: survives)"
                                                   : " (alpha below it: may overturn)")
                            : "")
              << "\n";
    if (c.el) {
        const auto& e = *c.el;
        std::cout << "rocking angle (" << rocking::equivalent_linear_label << "): "
                  << opt_text(e.theta0_rad, "{:.4g} rad", e.theta0_reason) << "\n";
        std::cout << "factor of safety alpha/theta0: " << opt_text(e.fs, "{:.3g}", e.fs_reason)
                  << fmt::format(" (required {:.3g}: {})\n", e.fs_required, e.fs_ok ? "ok" : "NOT MET");
        std::cout << "spectral margin: "
                  << opt_text(e.spectral_margin, "{:.4g}", e.spectral_margin_reason) << "\n";
    } else {
        std::cout << "equivalent-linear rocking estimate: n/a (" << r.spectral_reason << ")\n";
    }
    if (r.initiation)
        std::cout << "initiating mode: " << sliding::to_string(r.initiation->governing().mode) << "\n";
    if (!r.amplification_warning.empty()) std::cout << "note: " << r.amplification_warning << "\n";
    if (r.flexible) std::cout << "flexible-body screen: " << r.flexible->reason << "\n";
}

int run_rock(const std::vector<std::string>& args) {
    const auto vm = parse_options("rock", "--block b=..,h=..[,m=..] [--spectrum F.csv] [options]",
                                  rock_options(), args);
    if (!vm) return 0;
    const api::RockResult result = api::rock(rock_request(*vm));
    if (vm->count("json"))
        std::cout << api::to_json(result).dump(2) << "\n";
    else
        print_text(result.checks);
    return 0;
}

const CommandRegistrar reg{{"rock", "closed-form rocking and overturning checks of a block", &run_rock}};

}  // namespace
}  // namespace freestand::cli::rock_command
