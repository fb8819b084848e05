// `slide` and `rock`: their options, runs and JSON documents (cli/documents.hpp).
#include <fmt/format.h>

#include <cmath>

#include "cli/documents.hpp"
#include "api/classify.hpp"
#include "cli/spectra_cli.hpp"
#include "core/errors.hpp"
#include "core/limits.hpp"
#include "rocking/checks.hpp"
#include "sliding/block_spec.hpp"
#include "sliding/spectrum_input.hpp"

namespace freestand::cli {

using api::edge_name;

namespace {

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

// An optional number within a range a case file applies too (core/limits.hpp), named as the
// option the user typed.
std::optional<double> opt_limited(const po::variables_map& vm, const char* option,
                                  const core::limits::Range& range) {
    const std::optional<double> v = opt_number(vm, option);
    if (v) core::limits::require_in(*v, range, SourceLocation{"", 0, std::string("--") + option});
    return v;
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
    in.mu_s = opt_limited(vm, "mu", core::limits::friction);
    in.restitution = opt_limited(vm, "restitution", core::limits::restitution);
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

}  // namespace

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
         "10%-damped horizontal spectrum file(s) H1.csv[,H2.csv] to find f_es on");
    return desc;
}

SlideRun slide_run(const po::variables_map& vm) {
    if (vm.count("fes-hz") == vm.count("spectrum10"))
        throw UsageError("give exactly one of --fes-hz and --spectrum10 (see freestand slide --help)");
    sliding::SlidingInput in;
    in.mu_s = parse_double(vm["mu"].as<std::string>(), "--mu");
    core::limits::require_in(in.mu_s, core::limits::friction, SourceLocation{"", 0, "--mu"});
    in.av_g = parse_double(vm["av-g"].as<std::string>(), "--av-g");
    require_in_range(in.av_g, 0.0, 2.5, SourceLocation{"", 0, "--av-g"}, true, false);
    // Range checks here so the message names the option the user typed, not the library field.
    if (vm.count("pgd-m")) {
        in.pgd_m = parse_double(vm["pgd-m"].as<std::string>(), "--pgd-m");
        require_in_range(*in.pgd_m, 0.0, HUGE_VAL, SourceLocation{"", 0, "--pgd-m"}, true, false);
    }
    if (vm.count("pga-g")) {
        in.pga_h_g = parse_double(vm["pga-g"].as<std::string>(), "--pga-g");
        require_in_range(*in.pga_h_g, 0.0, HUGE_VAL, SourceLocation{"", 0, "--pga-g"}, true, false);
    }
    std::optional<double> fes_hz;
    if (vm.count("fes-hz")) {
        fes_hz = parse_double(vm["fes-hz"].as<std::string>(), "--fes-hz");
        require_positive(*fes_hz, SourceLocation{"", 0, "--fes-hz"});
    }
    const sliding::SlidingEstimate e =
        fes_hz
            ? sliding::estimate_sliding(in, *fes_hz)
            : sliding::estimate_sliding(
                  in, sliding::vector_horizontal_from_files(
                          spectrum_paths(vm["spectrum10"].as<std::string>(), "--spectrum10"),
                          sliding::asce_sliding_damping));
    return {in, e};
}

json slide_json(const SlideRun& run) {
    const sliding::SlidingInput& in = run.input;
    const sliding::SlidingEstimate& e = run.estimate;
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
    return j;
}

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
        ("rock-band-hz", po::value<std::string>(), "free-rocking band LO,HI, Hz (flexible screen)");
    return desc;
}

RockRun rock_run(const po::variables_map& vm) {
    const block::Block blk = block_from_options(vm["block"].as<std::string>(),
                                                opt_string(vm, "cg"), opt_number(vm, "inertia"));
    rocking::RockingInput in = read_input(vm);
    rocking::RockingChecks checks = rocking::rocking_checks(blk, in);
    return {std::move(in), std::move(checks)};
}

json rock_json(const RockRun& run) { return report_json(run.checks, run.input); }

}  // namespace freestand::cli
