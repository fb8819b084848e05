#include "report/json.hpp"

#include <fmt/format.h>

#include <cmath>
#include <string>

#include "assess/verdict.hpp"
#include "report/sha256.hpp"

namespace freestand::report {

using nlohmann::ordered_json;
using namespace freestand::assess;

double round10(double v) {
    if (!std::isfinite(v) || v == 0.0) return v;
    return std::stod(fmt::format("{:.10g}", v));
}

namespace {

ordered_json num(double v) {
    if (!std::isfinite(v)) return nullptr;
    return round10(v);
}
ordered_json num(const std::optional<double>& v) { return v ? num(*v) : ordered_json(nullptr); }

ordered_json verdict_json(const Verdict& v) {
    ordered_json j;
    j["verdict"] = verdict_text(v);
    j["kind"] = to_string(v.kind);
    j["margin"] = num(v.margin);
    j["margin_basis"] = v.margin_basis;
    j["decided_by"] = to_string(v.decided_by);
    j["clearance_m"] = num(v.clearance_m);
    j["material"] = v.material.empty() ? ordered_json(nullptr) : ordered_json(v.material);
    return j;
}

ordered_json level_json(const LevelResult& l) {
    ordered_json j;
    j["pga_g"] = num(l.pga_g);
    j["pga_v_g"] = num(l.pga_v_g);
    j["direction"] = to_string(l.direction);
    j["mode"] = to_string(l.initiation.mode);
    j["a_ratio"] = num(l.initiation.a_ratio);
    j["mu_s"] = num(l.initiation.mu_s);
    j["tan_alpha"] = num(l.initiation.tan_alpha);
    j["mu_crit"] = num(l.initiation.mu_crit);
    j["flexible_flag"] = l.flexible.raised;
    j["flexible"] = {{"basis", l.flexible.basis},
                     {"band_lo_hz", num(l.flexible.band_lo_hz)},
                     {"band_hi_hz", num(l.flexible.band_hi_hz)},
                     {"peak_psa_in_band_g", num(l.flexible.peak_psa_in_band_g)},
                     {"uplift_a_g", num(l.flexible.uplift_a_g)},
                     {"reason", l.flexible.reason}};
    j["mu_e"] = num(l.sliding.mu_e);
    j["c_s_mps2"] = num(l.sliding.c_s_mps2);
    j["f_es_hz"] = num(l.sliding.f_es_hz);
    j["pgd_m"] = l.sliding.f_es_hz ? num(l.sliding.pgd_m) : ordered_json(nullptr);
    j["slide_asce_m"] = num(l.sliding.slide_asce_m);
    j["slide_energy_m"] = num(l.sliding.slide_energy_m);
    j["sliding_reason"] = l.sliding.reason;
    const auto& sim = l.simulation;
    j["simulated"] = sim.has_value();
    j["simulation_reason"] = l.simulation_reason;
    j["histories"] = sim ? ordered_json(sim->histories) : ordered_json(nullptr);
    j["slide_sim_max_m"] = sim ? num(sim->slide_max_max_m) : ordered_json(nullptr);
    j["slide_sim_mean_m"] = sim ? num(sim->slide_max_mean_m) : ordered_json(nullptr);
    j["slide_residual_max_m"] = sim ? num(sim->slide_residual_max_m) : ordered_json(nullptr);
    j["slide_residual_mean_m"] = sim ? num(sim->slide_residual_mean_m) : ordered_json(nullptr);
    j["rock_max_over_alpha"] = sim ? num(sim->rock_max_over_alpha_max) : ordered_json(nullptr);
    j["rock_mean_over_alpha"] = sim ? num(sim->rock_max_over_alpha_mean) : ordered_json(nullptr);
    j["overturned_fraction"] = sim ? num(sim->overturned_fraction) : ordered_json(nullptr);
    j["amplification_sim_max"] = sim ? num(sim->amplification_max) : ordered_json(nullptr);
    j["amplification_sim_mean"] = sim ? num(sim->amplification_mean) : ordered_json(nullptr);
    j["amplification_estimate"] = num(l.rocking.amplification_estimate);
    const Rocking& rk = l.rocking;
    j["rocking"] = {{"alpha_rad", num(rk.alpha_rad)},
                    {"R_m", num(rk.R_m)},
                    {"p_radps", num(rk.p_radps)},
                    {"restitution", num(rk.restitution)},
                    {"uplift_a_g", num(rk.uplift_a_g)},
                    {"ishiyama_v_mps", num(rk.ishiyama_v_mps)},
                    {"pgv_mps", num(rk.pgv_mps)},
                    {"el_gate_exceeded", rk.gate_passed},
                    {"el_theta_rad", num(rk.theta_rad)},
                    {"el_overturn_predicted", rk.overturn_predicted},
                    {"el_overturn_fs", num(rk.overturn_fs)},
                    {"el_spectral_margin", num(rk.spectral_margin)}};
    j["verdict"] = verdict_text(l.verdict);
    j["margin"] = num(l.verdict.margin);
    j["margin_basis"] = l.verdict.margin_basis;
    j["decided_by"] = to_string(l.verdict.decided_by);
    return j;
}

ordered_json case_json(const Case& c) {
    const Component& k = c.component;
    ordered_json comp;
    comp["name"] = k.name;
    comp["description"] = k.description;
    comp["mass_kg"] = num(k.mass_kg);
    comp["cg_height_m"] = num(k.cg_height_m);
    comp["cg_to_edge_x_m"] = {num(k.x.b_left_m), num(k.x.b_right_m)};
    comp["cg_to_edge_y_m"] = {num(k.y.b_left_m), num(k.y.b_right_m)};
    comp["inertia_cg_x_kgm2"] = num(k.x.inertia_cg_kgm2);
    comp["inertia_cg_y_kgm2"] = num(k.y.inertia_cg_kgm2);
    comp["inertia_source"] = k.x.inertia_source;
    comp["uniform_block"] = k.uniform_block;
    comp["footprint"] = k.footprint;
    comp["fixed_base_frequency_hz"] = num(k.fixed_base_frequency_hz);
    comp["free_rocking_band_hz"] =
        k.free_rocking_band_hz
            ? ordered_json{num((*k.free_rocking_band_hz)[0]), num((*k.free_rocking_band_hz)[1])}
            : ordered_json(nullptr);
    comp["base_material"] =
        k.base.material.empty() ? ordered_json(nullptr) : ordered_json(k.base.material);
    comp["mu_s"] = num(k.base.mu_s);
    comp["mu_k"] = num(k.base.mu_k);
    comp["restitution"] = num(k.base.restitution);
    comp["allowable_slide_m"] = num(k.allowable_slide_m);
    comp["required_overturn_fs"] = num(k.required_overturn_fs);
    ordered_json site;
    site["design"] = c.site.design;
    ordered_json pga = ordered_json::array();
    for (double p : c.site.pga_g) pga.push_back(num(p));
    site["pga_g"] = pga;
    site["vertical_ratio"] = num(c.site.vertical_ratio);
    site["sliding_damping"] = num(c.site.sliding_damping);
    site["g_mps2"] = num(c.site.g_mps2);
    ordered_json opt;
    opt["histories_per_level"] = c.options.histories_per_level;
    opt["seed"] = c.options.seed;
    ordered_json recs = ordered_json::array();
    for (const auto& p : c.options.seed_records) recs.push_back(p.filename().string());
    opt["seed_records"] = recs;
    opt["simulate"] = to_string(c.options.simulate);
    return ordered_json{{"component", comp}, {"site", site}, {"options", opt}};
}

}  // namespace

Stamp make_stamp(const std::string& case_bytes, const std::string& case_file, std::uint64_t seed,
                 const std::string& commit) {
    return Stamp{FREESTAND_VERSION, commit, sha256_hex(case_bytes), case_file, seed};
}

ordered_json to_json(const AssessmentResult& r, const Stamp& stamp) {
    ordered_json j;
    j["verdict"] = verdict_text(r.overall);
    j["overall"] = verdict_json(r.overall);
    if (!r.levels.empty()) {
        const LevelResult& g = r.levels[r.governing_level];
        j["governing"] = {{"pga_g", num(g.pga_g)}, {"direction", to_string(g.direction)}};
    }
    ordered_json levels = ordered_json::array();
    for (const LevelResult& l : r.levels) levels.push_back(level_json(l));
    j["levels"] = levels;
    ordered_json up;
    up["needed"] = r.upgrade.needed;
    up["recommended"] =
        r.upgrade.recommended ? ordered_json(*r.upgrade.recommended) : ordered_json(nullptr);
    ordered_json trials = ordered_json::array();
    for (const MaterialTrial& t : r.upgrade.trials) {
        ordered_json tj = verdict_json(t.verdict);
        tj["material"] = t.material;
        tj["mu_s"] = num(t.mu_s);
        tj["passes"] = passes(t.verdict);
        trials.push_back(tj);
    }
    up["trials"] = trials;
    j["upgrade"] = up;
    j["histories_generated"] = r.histories_generated;
    j["simulations_run"] = r.simulations_run;
    ordered_json checks = ordered_json::array();
    for (const HistoryCheck& h : r.history_checks) {
        checks.push_back({{"history", h.history},
                          {"component", h.component},
                          {"method", h.method},
                          {"passed", h.passed},
                          {"min_ratio", num(h.min_ratio)},
                          {"max_ratio", num(h.max_ratio)},
                          {"reason", h.reason}});
    }
    j["history_acceptance"] = checks;
    j["case"] = case_json(r.input);
    j["assumptions"] = r.assumptions;
    j["limits"] = r.limits;
    j["stamp"] = {{"tool", "freestand"},
                  {"version", stamp.tool_version},
                  {"commit", stamp.commit},
                  {"seed", stamp.seed},
                  {"input_sha256", stamp.input_sha256},
                  {"case_file", stamp.case_file}};
    return j;
}

}  // namespace freestand::report
