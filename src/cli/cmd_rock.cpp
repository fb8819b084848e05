/// freestand rock: closed-form rocking and overturning checks of a block (docs/methods.md s.5, s.5a).
#include <fmt/format.h>
#include <iostream>

#include "cli/command.hpp"
#include "api/classify.hpp"
#include "cli/documents.hpp"
#include "cli/options.hpp"
#include "rocking/summary.hpp"

// The command's own namespace: the command files share a unity build (src/cli/CMakeLists.txt).
namespace freestand::cli::rock_command {
namespace {

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
    po::options_description desc = rock_options();
    desc.add_options()("json", "print JSON");
    const auto vm = parse_options("rock", "--block b=..,h=..[,m=..] [--spectrum F.csv] [options]", desc,
                                  args);
    if (!vm) return 0;
    const RockRun run = rock_run(*vm);
    if (vm->count("json"))
        std::cout << rock_json(run).dump(2) << "\n";
    else
        print_text(run.checks);
    return 0;
}

const CommandRegistrar reg{{"rock", "closed-form rocking and overturning checks of a block", &run_rock}};

}  // namespace
}  // namespace freestand::cli::rock_command
