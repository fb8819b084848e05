#include "api/rock.hpp"

#include <fmt/format.h>

#include <cmath>

#include "api/classify.hpp"
#include "core/errors.hpp"
#include "core/limits.hpp"
#include "spectra/spectrum.hpp"

namespace freestand::api {
namespace rock_detail {

SourceLocation field(const char* name) { return SourceLocation{"", 0, name}; }

// A number, or null plus "<key>_reason".
void put(json& j, const std::string& key, const std::optional<double>& v, const std::string& why) {
    j[key] = number_or_null(v);
    if (!v) j[key + "_reason"] = why;
}

std::optional<rocking::DampedSpectra> read_set(const std::vector<std::filesystem::path>& files) {
    if (files.empty()) return std::nullopt;
    std::vector<spectra::Spectrum> set;
    for (const auto& path : files) set.push_back(spectra::read_spectrum_csv(path));
    return rocking::DampedSpectra(std::move(set));
}

// An optional number in [lo, hi) (hi = inf: [lo, inf)).
const std::optional<double>& in_range(const std::optional<double>& v, double lo, double hi,
                                      const char* name, bool lo_inclusive) {
    if (v) require_in_range(*v, lo, hi, field(name), lo_inclusive, false);
    return v;
}

rocking::RockingInput checked_input(const RockRequest& r) {
    rocking::RockingInput in;
    in.horizontal = read_set(r.spectrum_files);
    in.vertical.spectra = read_set(r.spectrum_v_files);
    in.vertical.ratio = in_range(r.v_ratio, 0.0, HUGE_VAL, "v_ratio", true).value_or(0.0);
    in.pga_h_g = in_range(r.pga_h_g, 0.0, HUGE_VAL, "pga_h_g", true);
    in.pga_v_g = in_range(r.av_g, 0.0, 1.0, "av_g", true);
    in.pgv_mps = in_range(r.pgv_mps, 0.0, HUGE_VAL, "pgv_mps", true);
    // The ranges a case file applies too (core/limits.hpp).
    in.mu_s = r.mu_s;
    if (in.mu_s) core::limits::require_in(*in.mu_s, core::limits::friction, field("mu_s"));
    in.restitution = r.restitution;
    if (in.restitution)
        core::limits::require_in(*in.restitution, core::limits::restitution, field("restitution"));
    // FS = alpha / theta0 >= 1 whenever theta0 < alpha, so a requirement below 1 checks nothing.
    in.fs_required = r.fs_required;
    require_in_range(in.fs_required, 1.0, HUGE_VAL, field("fs_required"), true, false);
    in.fixed_base_hz = in_range(r.fixed_base_hz, 0.0, HUGE_VAL, "fixed_base_hz", false);
    if (r.rock_band_hz) {
        const auto [lo, hi] = *r.rock_band_hz;
        if (!(lo > 0.0 && hi > lo))
            throw InputError(field("rock_band_hz"),
                             fmt::format("{},{} Hz; expected 0 < LO < HI", lo, hi));
        in.rock_band_lo_hz = lo;
        in.rock_band_hi_hz = hi;
    }
    return in;
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

json flexible_json(const rocking::RockingChecks& r) {
    const auto& f = *r.flexible;
    return json{{"applies", f.applies},        {"band_lo_hz", f.band_lo_hz},
                {"band_hi_hz", f.band_hi_hz},  {"peak_psa_g", f.peak_psa_g},
                {"peak_f_hz", f.peak_f_hz},    {"threshold_g", f.threshold_g},
                {"flagged", f.flagged},        {"reason", f.reason}};
}

}  // namespace rock_detail

RockResult rock(const RockRequest& request) {
    const block::Block blk = sliding::make_block(request.box);
    rocking::RockingInput in = rock_detail::checked_input(request);
    rocking::RockingChecks checks = rocking::rocking_checks(blk, in);
    return {std::move(in), std::move(checks)};
}

json to_json(const RockResult& result) {
    using rock_detail::put;
    const rocking::RockingChecks& r = result.checks;
    json j = rock_detail::edge_json(r.governing(), r.spectral_reason);
    j["governing_edge"] = edge_name(r.governing_edge);
    j["pga_h_g"] = number_or_null(r.pga_h_g);
    j["pga_h_source"] = r.pga_h_source;
    j["pga_v_g"] = r.pga_v_g;
    j["pga_v_source"] = r.pga_v_source;
    put(j, "housner_sv_mps", r.housner_sv_mps, r.spectral_reason);
    j["pgv_mps"] = number_or_null(result.input.pgv_mps);
    j["pgv_below_ishiyama"] = r.pgv_below_ishiyama ? json(*r.pgv_below_ishiyama) : json(nullptr);
    if (!r.pgv_below_ishiyama) j["pgv_below_ishiyama_reason"] = r.pgv_reason;
    j["mode"] = r.initiation ? json(sliding::to_string(r.initiation->governing().mode)) : json(nullptr);
    if (!r.initiation) j["mode_reason"] = r.initiation_reason;
    j["amplification_warning"] = r.amplification_warning;
    if (r.flexible) {
        j["flexible"] = rock_detail::flexible_json(r);
    } else {
        j["flexible"] = nullptr;
        j["flexible_reason"] = r.flexible_reason;
    }
    j["edges"] = json{{"left", rock_detail::edge_json(r.left, r.spectral_reason)},
                      {"right", rock_detail::edge_json(r.right, r.spectral_reason)}};
    return j;
}

}  // namespace freestand::api
