/// freestand rock: closed-form rocking and overturning checks of a block (docs/methods.md s.5, s.5a).
#include <cmath>
#include <fmt/format.h>
#include <iostream>
#include <nlohmann/json.hpp>

#include "cli/command.hpp"
#include "cli/options.hpp"
#include "cli/spectra_cli.hpp"
#include "core/errors.hpp"
#include "rocking/summary.hpp"
#include "sliding/block_spec.hpp"
#include "spectra/spectrum.hpp"

namespace freestand::cli {
namespace {

using json = nlohmann::ordered_json;

const char* edge_name(block::Edge e) { return e == block::Edge::left ? "left" : "right"; }

json num(const std::optional<double>& v) { return v ? json(*v) : json(nullptr); }

// A number, or null plus "<key>_reason".
void put(json& j, const std::string& key, const std::optional<double>& v, const std::string& why) {
    j[key] = num(v);
    if (!v) j[key + "_reason"] = why;
}

// Geometry and per-edge checks; the equivalent-linear fields when a spectrum was given.
json edge_json(const rocking::EdgeChecks& c, const std::string& spectral_reason) {
    json j;
    j["edge"] = edge_name(c.edge);
    j["alpha_rad"] = c.alpha_rad;
    j["tan_alpha"] = c.tan_alpha;
    j["R_m"] = c.R_m;
    j["p_radps"] = c.p_radps;
    j["inertia_edge_kgm2"] = c.inertia_edge_kgm2;
    j["restitution"] = c.restitution;
    j["uplift_a_g"] = c.uplift_a_g;
    j["ishiyama_v_mps"] = c.ishiyama_v_mps;
    j["e_ot_jpkg"] = c.e_ot_jpkg;
    const std::string& why = spectral_reason;
    put(j, "housner_alpha_required_rad",
        c.housner ? std::optional<double>(c.housner->alpha_required_rad) : std::nullopt, why);
    put(j, "e_in_jpkg", c.housner ? std::optional<double>(c.housner->e_in_jpkg) : std::nullopt, why);
    j["housner_survives"] = c.housner ? json(c.housner->survives) : json(nullptr);
    if (!c.el) {
        put(j, "rock_asce_rad", std::nullopt, why);
        put(j, "overturn_fs", std::nullopt, why);
        return j;
    }
    const rocking::ElResult& e = *c.el;
    j["rock_asce_label"] = rocking::equivalent_linear_label;
    put(j, "beta_e", e.beta_e, e.beta_e_reason);
    j["damping_note"] = e.damping_note;
    j["gate_g"] = e.gate_g;
    j["gate_exceeded"] = e.gate_exceeded;
    put(j, "rock_asce_rad", e.theta0_rad, e.theta0_reason);
    put(j, "f_e_hz", e.f_e_hz, e.theta0_rad ? "no rocking (theta0 = 0)" : e.theta0_reason);
    put(j, "overturn_fs", e.fs, e.fs_reason);
    j["overturn_fs_required"] = e.fs_required;
    j["overturn_fs_ok"] = e.fs_ok;
    j["overturning_predicted"] = e.overturning_predicted;
    put(j, "spectral_margin", e.spectral_margin, e.spectral_margin_reason);
    return j;
}

json report_json(const rocking::RockingChecks& r, const rocking::RockingInput& in) {
    json j = edge_json(r.governing(), r.spectral_reason);
    j["governing_edge"] = edge_name(r.governing_edge);
    j["pga_h_g"] = num(r.pga_h_g);
    j["pga_h_source"] = r.pga_h_source;
    j["pga_v_g"] = r.pga_v_g;
    j["pga_v_source"] = r.pga_v_source;
    put(j, "housner_sv_mps", r.housner_sv_mps, r.spectral_reason);
    j["pgv_mps"] = num(in.pgv_mps);
    j["pgv_below_ishiyama"] = r.pgv_below_ishiyama ? json(*r.pgv_below_ishiyama) : json(nullptr);
    if (!r.pgv_below_ishiyama) j["pgv_below_ishiyama_reason"] = r.pgv_reason;
    j["mode"] = r.initiation ? json(sliding::to_string(r.initiation->governing().mode)) : json(nullptr);
    if (!r.initiation) j["mode_reason"] = r.initiation_reason;
    j["amplification_warning"] = r.amplification_warning;
    if (r.flexible) {
        const auto& f = *r.flexible;
        j["flexible"] = json{{"applies", f.applies},        {"band_lo_hz", f.band_lo_hz},
                             {"band_hi_hz", f.band_hi_hz},  {"peak_psa_g", f.peak_psa_g},
                             {"peak_f_hz", f.peak_f_hz},    {"threshold_g", f.threshold_g},
                             {"flagged", f.flagged},        {"reason", f.reason}};
    } else {
        j["flexible"] = nullptr;
        j["flexible_reason"] = r.flexible_reason;
    }
    j["edges"] = json{{"left", edge_json(r.left, r.spectral_reason)},
                      {"right", edge_json(r.right, r.spectral_reason)}};
    return j;
}

std::string opt_text(const std::optional<double>& v, const std::string& fmt_spec,
                     const std::string& why) {
    return v ? fmt::format(fmt::runtime(fmt_spec), *v) : "n/a (" + why + ")";
}

void print_text(const rocking::RockingChecks& r) {
    const auto& c = r.governing();
    std::cout << fmt::format("edge {}: alpha = {:.4g} rad, R = {:.4g} m, p = {:.4g} rad/s, r = {:.4g}\n",
                             edge_name(c.edge), c.alpha_rad, c.R_m, c.p_radps, c.restitution);
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

std::optional<rocking::DampedSpectra> read_set(const po::variables_map& vm, const char* option) {
    if (!vm.count(option)) return std::nullopt;
    std::vector<spectra::Spectrum> set;
    for (const auto& path : spectrum_paths(vm[option].as<std::string>(), std::string("--") + option))
        set.push_back(spectra::read_spectrum_csv(path));
    return rocking::DampedSpectra(std::move(set));
}

std::optional<double> opt_number(const po::variables_map& vm, const char* option) {
    if (!vm.count(option)) return std::nullopt;
    return parse_double(vm[option].as<std::string>(), std::string("--") + option);
}

// An optional number in [lo, hi) (hi = inf: [lo, inf)); range errors name the option the user
// typed rather than the library's field.
std::optional<double> opt_in_range(const po::variables_map& vm, const char* option, double lo,
                                   double hi, bool lo_inclusive) {
    const std::optional<double> v = opt_number(vm, option);
    if (v)
        require_in_range(*v, lo, hi, SourceLocation{"", 0, std::string("--") + option},
                         lo_inclusive, false);
    return v;
}

rocking::RockingInput read_input(const po::variables_map& vm) {
    rocking::RockingInput in;
    in.horizontal = read_set(vm, "spectrum");
    in.vertical.spectra = read_set(vm, "spectrum-v");
    in.vertical.ratio = opt_in_range(vm, "v-ratio", 0.0, HUGE_VAL, true).value_or(0.0);
    in.pga_h_g = opt_in_range(vm, "pga-g", 0.0, HUGE_VAL, true);
    in.pga_v_g = opt_in_range(vm, "av-g", 0.0, 1.0, true);
    in.pgv_mps = opt_in_range(vm, "pgv-mps", 0.0, HUGE_VAL, true);
    in.mu_s = opt_in_range(vm, "mu", 0.0, HUGE_VAL, true);
    in.restitution = opt_number(vm, "restitution");
    if (in.restitution)
        require_in_range(*in.restitution, 0.0, 1.0, SourceLocation{"", 0, "--restitution"}, false,
                         true);
    // FS = alpha / theta0 >= 1 whenever theta0 < alpha, so a requirement below 1 checks nothing.
    in.fs_required = opt_in_range(vm, "fs-required", 1.0, HUGE_VAL, true).value_or(1.5);
    in.fixed_base_hz = opt_in_range(vm, "fn-hz", 0.0, HUGE_VAL, false);
    if (vm.count("rock-band-hz")) {
        const auto band = parse_double_list(vm["rock-band-hz"].as<std::string>(), "--rock-band-hz");
        if (band.size() != 2) throw UsageError("--rock-band-hz: expected LO,HI in Hz");
        if (!(band[0] > 0.0 && band[1] > band[0]))
            throw InputError(SourceLocation{"", 0, "--rock-band-hz"},
                             fmt::format("{},{} Hz; expected 0 < LO < HI", band[0], band[1]));
        in.rock_band_lo_hz = band[0];
        in.rock_band_hi_hz = band[1];
    }
    return in;
}

int run_rock(const std::vector<std::string>& args) {
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
    const auto vm = parse_options("rock", "--block b=..,h=..[,m=..] [--spectrum F.csv] [options]", desc,
                                  args);
    if (!vm) return 0;
    const block::Block blk = block_from_options((*vm)["block"].as<std::string>(),
                                                opt_string(*vm, "cg"), opt_number(*vm, "inertia"));
    const rocking::RockingInput in = read_input(*vm);
    const rocking::RockingChecks r = rocking::rocking_checks(blk, in);
    if (vm->count("json"))
        std::cout << report_json(r, in).dump(2) << "\n";
    else
        print_text(r);
    return 0;
}

const CommandRegistrar reg{{"rock", "closed-form rocking and overturning checks of a block", &run_rock}};

}  // namespace
}  // namespace freestand::cli
